// parsons run as a user types it: exit codes, the summary, the report, the output files.
#include "tests/test_support.hpp"

#include "axes/machine_profile.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>

#include <array>
#include <filesystem>

using parsons::test::kSample;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::string sample_with(const std::string& from, const std::string& to) {
    std::string text = read_bytes(source_path(kSample));
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("Run: the sample deck completes, exit 0, every axis on the last card's stop",
          "[run][cli]") {
    TempDir dir;
    auto r = run_parsons("run " + q(source_path(kSample)) + " --report " + q(dir.str("r.json")) +
                         " --trace " + q(dir.str("t.vcd")) + " --events " + q(dir.str("e.jsonl")) +
                         " --path " + q(dir.str("p.csv")) + " --plot " + q(dir.str("p.svg")));
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("status         completed") != std::string::npos);
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(report["status"] == "completed");
    CHECK(report["cards_read"] == 4);
    CHECK(report["stop"].is_null());
    CHECK(report["machine_seconds"].get<double>() > 0);
    const std::map<std::string, double> last_stops = {
        {"table", 0.100}, {"cross", 0.0}, {"vertical", 0.0}, {"swivel", 0.0}, {"tilt", 0.0}};
    for (const auto& [axis, stop] : last_stops) {
        INFO(axis);
        CHECK(report["axes"][axis]["position"].get<double>() == Approx(stop).margin(1e-9));
        CHECK(std::abs(report["axes"][axis]["position_error"].get<double>()) < 0.0005);
    }
    CHECK(report["cards"].size() == 4);
    for (const char* f : {"t.vcd", "e.jsonl", "p.csv", "p.svg"}) {
        INFO(f);
        CHECK(std::filesystem::file_size(dir.path(f)) > 100);
    }
}

TEST_CASE("Run: a wrong check exits 3 with a summary naming card, axis, reason and lamps",
          "[run][cli]") {
    TempDir dir;
    write_bytes(dir.path("bad.csv"), sample_with("2,0,table,-,1,8.585,8.485,8.385,0.600,12",
                                                 "2,0,table,-,1,8.585,8.485,8.385,0.610,12"));
    auto r = run_parsons("run " + q(dir.str("bad.csv")) + " --report " + q(dir.str("r.json")));
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("status         STOPPED: check_mismatch") != std::string::npos);
    CHECK(r.output.find("card           2 (number 0002)") != std::string::npos);
    CHECK(r.output.find("axis           table") != std::string::npos);
    CHECK(r.output.find("lamps lit      indicator 268, table lamp 270 (absolute comparer 122' "
                        "conducting)") != std::string::npos);
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(report["status"] == "stopped");
    CHECK(report["stop"]["reason"] == "check_mismatch");
    CHECK(report["stop"]["card"] == 2);
    CHECK(report["stop"]["axis"] == "table");
}

TEST_CASE("Run: cards out of order exit 3 with out_of_order_card", "[run][cli]") {
    TempDir dir;
    std::string text = read_bytes(source_path(kSample));
    for (std::size_t at = text.find("\n3,"); at != std::string::npos; at = text.find("\n3,")) {
        text.replace(at, 3, "\n7,");
    }
    write_bytes(dir.path("order.csv"), text);
    auto r = run_parsons("run " + q(dir.str("order.csv")));
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("STOPPED: out_of_order_card") != std::string::npos);
    CHECK(r.output.find("card number 0007 follows 0002") != std::string::npos);
}

TEST_CASE("Run: a dropped impulse exits 3 with missed_impulse", "[run][cli]") {
    auto r = run_parsons("run " + q(source_path(kSample)) + " --fault drop-impulse:cross:500");
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("STOPPED: missed_impulse") != std::string::npos);
    CHECK(r.output.find("axis           cross") != std::string::npos);
}

TEST_CASE("Run: an unreadable deck, a bad fault or a bad profile exit 2 naming where",
          "[run][cli][bad-input]") {
    TempDir dir;
    write_bytes(dir.path("short.cbn"), std::string("\xC0\x40", 2));
    auto unreadable = run_parsons("run " + q(dir.str("short.cbn")) + " --report " +
                                  q(dir.str("r.json")) + " --trace " + q(dir.str("t.vcd")));
    CHECK(unreadable.exit_code == 2);
    CHECK(unreadable.output.find("short.cbn: card 1, byte 3 (offset 0x2): truncated card") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("r.json")));
    CHECK_FALSE(std::filesystem::exists(dir.path("t.vcd")));

    auto fault = run_parsons("run " + q(source_path(kSample)) + " --fault drop-impulse:tabel:3");
    CHECK(fault.exit_code == 2);
    CHECK(fault.output.find("unknown axis 'tabel'") != std::string::npos);

    write_bytes(dir.path("p.json"), R"({"axes": {"table": {"sped_in_per_min": [1, 2, 3]}}})");
    auto profile =
        run_parsons("run " + q(source_path(kSample)) + " --profile " + q(dir.str("p.json")));
    CHECK(profile.exit_code == 2);
    CHECK(profile.output.find("p.json: axes.table.sped_in_per_min: unknown key") !=
          std::string::npos);
    write_bytes(dir.path("broken.json"), "{\"delay_258_s\": ");
    auto broken =
        run_parsons("run " + q(source_path(kSample)) + " --profile " + q(dir.str("broken.json")));
    CHECK(broken.exit_code == 2);
    CHECK(broken.output.find("broken.json: not valid JSON at byte") != std::string::npos);
    // Found by the profile fuzzer: a number no double holds was an internal error (exit 1).
    write_bytes(dir.path("huge.json"), R"({"delay_258_s": 1e400})");
    auto huge = run_parsons("profile --profile " + q(dir.str("huge.json")));
    CHECK(huge.exit_code == 2);
    CHECK(huge.output.find("huge.json: a number too large to read (over 1.8e308)") !=
          std::string::npos);
    // Found by the profile fuzzer: a card cycle of 1e15 s put machine time where a double
    // cannot tell one impulse from the next (the two paces disagreed; at 6e45 s a run hung).
    write_bytes(dir.path("slow.json"), R"({"reader_cycle_s": 1e15})");
    auto slow = run_parsons("profile --profile " + q(dir.str("slow.json")));
    CHECK(slow.exit_code == 2);
    CHECK(slow.output.find(
              "slow.json: reader_cycle_s: must be a number above 0 and at most 60, not 1e+15") !=
          std::string::npos);
    // Screw errors of +-1e308 in overflowed their interpolation and put the part at infinity.
    write_bytes(dir.path("screw.json"), R"({"axes": {"table": {"screw_error_in": [[0, 2]]}}})");
    auto screw = run_parsons("profile --profile " + q(dir.str("screw.json")));
    CHECK(screw.exit_code == 2);
    CHECK(screw.output.find("screw.json: axes.table.screw_error_in[0][1]: must be a number at "
                            "least -1 and at most 1, not 2") != std::string::npos);
}

TEST_CASE("Profile: the printed default reads back, and a partial file changes only its keys",
          "[run][cli][profile]") {
    TempDir dir;
    auto printed = run_parsons("profile");
    REQUIRE(printed.exit_code == 0);
    const auto j = nlohmann::json::parse(printed.output);
    CHECK(j["name"] == "parsons-1952");
    CHECK(j["axes"]["table"]["speed_in_per_min"][0] == 5.4);
    write_bytes(dir.path("default.json"), printed.output);
    CHECK(run_parsons("profile --profile " + q(dir.str("default.json"))).output == printed.output);
    write_bytes(dir.path("fast.json"), R"({"max_stepping_rate_per_s": 50})");
    const auto fast =
        nlohmann::json::parse(run_parsons("profile --profile " + q(dir.str("fast.json"))).output);
    CHECK(fast["max_stepping_rate_per_s"] == 50);
    CHECK(fast["delay_258_s"] == j["delay_258_s"]);
}

TEST_CASE("Run: lost stepping-switch steps are reported as position error", "[run][cli]") {
    TempDir dir;
    write_bytes(dir.path("fast.json"),
                R"({"axes": {"table": {"speed_in_per_min": [15, 1.8, 0.6]}}})");
    auto r = run_parsons("run " + q(source_path(kSample)) + " --profile " +
                         q(dir.str("fast.json")) + " --report " + q(dir.str("r.json")));
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(report["axes"]["table"]["lost_steps"].get<long>() > 0);
    // The summary names the lost steps as the cause, with their count and the counters' share.
    CHECK_THAT(r.output, Catch::Contains("stepping-switch steps lost (impulses came faster than "
                                         "the switches can step)") &&
                             Catch::Contains("warning: table ends -0.00"));
    CHECK_THAT(r.output,
               Catch::Contains(std::to_string(report["axes"]["table"]["lost_steps"].get<long>()) +
                               " stepping-switch steps lost"));
}

TEST_CASE("Run: a completed run whose axis ends off its counters says so", "[run][cli]") {
    TempDir dir;
    // Slow-downs equal to the stop, and a delay 258 too short for them: the one equality steps
    // the switch three times, from speed 1 to off, and the table coasts on; the last card, so
    // no later check can catch it.
    write_bytes(dir.path("short.json"), R"({"delay_258_s": 0.002})");
    write_bytes(dir.path("over.csv"), "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n"
                                      "1,0,table,+,1,0.500,0.500,0.500,0.500,1\n"
                                      "1,0,cross,+,3,,,0.000,0.000,2\n"
                                      "1,0,vertical,+,3,,,0.000,0.000,3\n"
                                      "1,0,swivel,+,3,,,0.000,0.000,4\n"
                                      "1,0,tilt,+,3,,,0.000,0.000,5\n");
    auto r =
        run_parsons("run " + q(dir.str("over.csv")) + " --profile " + q(dir.str("short.json")));
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("warning: table ends") != std::string::npos);
}

TEST_CASE("Run report: each card's time is the one the profile gives, worked out by hand (card "
          "cycle, speed-up, travel at speed 3, the five steps of shaft 280, relay release)",
          "[cli][report]") {
    TempDir dir;
    // Only the table moves, at speed 3, in sequence position 1; every other axis stands.
    std::string listing = "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n";
    const std::array<const char*, 3> table = {"+,3,,,0.000,0.000", "+,3,,,0.100,0.100",
                                              "+,3,,,0.300,0.200"};
    const std::array<const char*, 4> others = {"cross", "vertical", "swivel", "tilt"};
    for (int card = 1; card <= 3; ++card) {
        listing += std::to_string(card) + ",,table," + table.at(card - 1) + ",1\n";
        for (int i = 0; i < 4; ++i) {
            listing += std::to_string(card) + ",," + others.at(i) + ",+,3,,,0.000,0.000," +
                       std::to_string(i + 2) + "\n";
        }
    }
    write_bytes(dir.path("deck.csv"), listing);
    const double cycle = 0.75, shaft = 0.07, release = 0.008, v = 1.2 / 60, accel = 0.3,
                 braking = 0.25;
    write_bytes(dir.path("p.json"),
                R"({"reader_cycle_s": 0.75, "sequence_shaft_step_s": 0.07,
                    "axes": {"table": {"speed_in_per_min": [5.4, 1.8, 1.2],
                                       "acceleration_in_per_s2": 0.3,
                                       "braking_in_per_s2": 0.25}}})");
    auto r = run_parsons("run " + q(dir.str("deck.csv")) + " --profile " + q(dir.str("p.json")) +
                         " --report " + q(dir.str("r.json")));
    REQUIRE(r.exit_code == 0);
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    const auto& cards = report["cards"];
    REQUIRE(cards.size() == 3);
    // A move from rest at x0 to the stop's crossing c (half a thousandth before the stop):
    // speed-up to v at `accel`, the rest at v; after it the table coasts v^2 / 2 braking on.
    auto move_s = [&](double x0, double c) {
        return v / accel + (c - x0 - v * v / (2 * accel)) / v;
    };
    const double coast = v * v / (2 * braking);
    const std::array<double, 3> expected = {
        cycle + 5 * shaft,
        cycle + move_s(0, 0.0995) + 5 * shaft,
        cycle + move_s(0.0995 + coast, 0.2995) + 5 * shaft,
    };
    double start = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        INFO("card " << i + 1);
        CHECK(cards[i]["start_seconds"].get<double>() == Approx(start).margin(1e-9));
        CHECK(cards[i]["machine_seconds"].get<double>() == Approx(expected.at(i)).margin(1e-9));
        start += expected.at(i) + release;
    }
    // The reader finds no card; the clock ends there, or where delay 258's hold after the last
    // stop (tilt's, one step of shaft 280 before the last card ends) runs out, if later.
    const double delay_258 = parsons::axes::default_profile().delay_258_s;
    const double last_stop = start - release - shaft;
    CHECK(report["machine_seconds"].get<double>() ==
          Approx(std::max(start, last_stop + delay_258)).margin(1e-9));
}
