// The tapping job and its thread proof (decks/tapping_job.hpp, outputs/proofs/thread_proof.hpp):
// the point of EP 0360190 (Mitsubishi, claim 1) on a plate — two taps of different pitch on two
// spindle heads with different gear ratios cut the right pitch whether the ratio reaches memory
// 12a transferred by PC 130 or stored in advance, and a head exchange that sends no ratio
// (stale-ratio) cuts a wrong pitch that the proof names hole by hole; a transfer that never
// completes stops the machine. Also the generator's cards and its refusals. The proof's
// arithmetic on synthetic helices: thread_proof_test.cpp.
#include "tests/machine_support.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include "cli/gen_tapping.hpp"
#include "decks/template_job.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "relaylogic/faults.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <set>

using namespace parsons;
using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::TempDir;

using parsons::test::kPitch1;
using parsons::test::kPitch2;

namespace {

// ---- The job run in-process ----

struct ProvedPlate {
    relaylogic::RunResult result;
    cli::ThreadProof proof;
    decks::TappingJob job;
};

ProvedPlate run_job(decks::TappingOptions o, const std::vector<std::string>& faults,
                    relaylogic::Pace pace = relaylogic::Pace::fast_forward) {
    const cli::GeneratedTappingJob g =
        cli::generate_tapping_job(o, axes::extended_profile(), "", "");
    std::vector<cardreader::Card> punched;
    for (const auto& c : g.deck.cards) {
        const auto e = cardreader::encode(c, cardreader::fig8_layout());
        REQUIRE_FALSE(e.error);
        punched.push_back(e.card);
    }
    test::VectorDeck deck(punched);
    relaylogic::ControlCabinet cabinet(g.profile, cardreader::fig8_layout());
    cabinet.set_pace(pace);
    cabinet.record_tap_samples(true);
    for (const auto& f : faults) {
        cabinet.add_fault(relaylogic::parse_fault(f));
    }
    ProvedPlate p;
    p.result = cabinet.run(deck);
    p.job = g.job;
    REQUIRE(p.result.tapping);
    p.proof = cli::prove_threads(*p.result.tapping, g.job, g.profile.spindle, std::nullopt);
    return p;
}

decks::TappingOptions options(axes::RatioSource source, int rows = 2) {
    decks::TappingOptions o;
    o.rows = rows;
    o.ratio_source = source;
    return o;
}

void every_hole_within(const ProvedPlate& p, std::size_t holes) {
    INFO(cli::thread_summary(p.proof));
    CHECK(p.result.completed);
    CHECK_FALSE(p.result.stop);
    REQUIRE(p.proof.holes.size() == holes);
    CHECK(p.proof.flagged() == 0);
    for (const cli::ProvedHole& h : p.proof.holes) {
        INFO("hole " << h.hole_number());
        CHECK(h.record.completed);
        REQUIRE(h.measure.measured);
        // down to the thread's depth (the reversal stops it within a thousandth or two)
        CHECK(h.record.deepest_in == Approx(h.record.depth_in).margin(0.002));
        CHECK(std::abs(h.measure.worst_error_percent) < 5.0);
        CHECK(std::abs(h.measure.mean_error_percent) < 1.0);
        CHECK(h.record.ratio_used == Approx(h.record.head_ratio));
        CHECK(h.measure.revolutions > 4.9); // the zone judged is whole threads deep
    }
}

} // namespace

TEST_CASE("Tapping job: the generator punches whole 1952 motion cards and a tap card a hole, "
          "tool 1 on the first row and tool 2 on the second at the fastest S the drive follows",
          "[tapping_job]") {
    const auto profile = axes::extended_profile();
    const decks::TappingDeck d = decks::make_tapping_deck({}, profile);
    REQUIRE(d.cards.size() == 12);
    REQUIRE(d.holes.size() == 6);
    std::array<int, 5> at{}; // where each axis stands, thousandths
    for (const auto& c : d.cards) {
        INFO("card " << c.number);
        const auto e = cardreader::encode(c, cardreader::fig8_layout());
        REQUIRE_FALSE(e.error);
        const auto back = cardreader::decode(e.card, cardreader::fig8_layout());
        REQUIRE(back);
        CHECK(back.orders.kind == c.kind);
        if (c.kind == cardreader::CardKind::tap) {
            CHECK(back.orders.tap == c.tap);
            continue;
        }
        cardreader::SequencePattern all = 0;
        for (cardreader::Axis a : cardreader::kAxes) {
            const auto& o = c.axis(a);
            const int from = at.at(cardreader::axis_index(a));
            CHECK(o.check == std::abs(o.stop - from));
            if (o.check == 0) {
                CHECK(o.stop == from);
                CHECK_FALSE(o.slow_down[0]);
            } else {
                CHECK(o.start_speed < 3); // the defaults keep the hazard off every move
            }
            CHECK(o.sequence != 0);
            all |= o.sequence;
            at.at(cardreader::axis_index(a)) = o.stop;
            CHECK(back.orders.axis(a) == o);
        }
        CHECK(all == 0b11111);
    }
    const std::array<int, 6> tools = {1, 1, 1, 2, 2, 2};
    for (std::size_t i = 0; i < d.holes.size(); ++i) {
        const decks::TappingHole& h = d.holes[i];
        const auto& card = d.cards.at(static_cast<std::size_t>(h.card) - 1);
        INFO("hole " << h.hole);
        REQUIRE(card.kind == cardreader::CardKind::tap);
        CHECK(h.tool == tools.at(i));
        CHECK(card.tap.tool == h.tool);
        CHECK(card.tap.axis == cardreader::Axis::vertical);
        CHECK(card.tap.motion == cardreader::Motion::reverse);
        CHECK(card.tap.depth == 600); // clearance 0.100 + thread 0.500
        CHECK(card.tap.pitch == (h.tool == 1 ? 5000 : 6250));
        CHECK(card.tap.rpm == 240); // motor 27's fastest: 3.0 and 5.0 in/min, under 5.4
        CHECK(h.feed_in_per_min <= profile.sync_drive.max_in_per_min);
        CHECK(h.start_in == Approx(1.350));
        CHECK(h.surface_in == Approx(1.250));
    }
    // The rows go back and forth: hole 4 stands over hole 3, one row up.
    CHECK(d.holes[3].x_in == Approx(d.holes[2].x_in));
    CHECK(d.holes[3].y_in == Approx(d.holes[2].y_in + 1.125));
}

TEST_CASE("Tapping job: S is the fastest at which pitch x S x ratio stays within the follower "
          "drive's maximum, and an --rpm above motor 27's or the drive's is refused",
          "[tapping_job]") {
    axes::MachineProfile slow = axes::extended_profile();
    slow.sync_drive.max_in_per_min = 3.0;
    const decks::TappingDeck d = decks::make_tapping_deck({}, slow);
    // tool 1: 0.05 x S / 4 <= 3.0 -> 240 (motor); tool 2: 0.0625 x S / 3 <= 3.0 -> 144
    CHECK(d.holes.front().rpm == 240);
    CHECK(d.holes.back().rpm == 144);
    CHECK(d.holes.back().feed_in_per_min <= 3.0);
    decks::TappingOptions o;
    o.rpm = 300;
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, axes::extended_profile()),
                      Catch::Contains("motor 27 turns at most 240"));
    o.rpm = 200;
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, slow), Catch::Contains("give --rpm 144 or less"));
}

TEST_CASE("Tapping job: the job file holds every hole and reads back", "[tapping_job]") {
    const cli::GeneratedTappingJob g = cli::generate_tapping_job(options(axes::RatioSource::stored),
                                                                 axes::extended_profile(), "", "");
    CHECK(g.profile.spindle_sync);
    CHECK(g.profile.spindle.ratio_source == axes::RatioSource::stored);
    const decks::TappingJob back = decks::tapping_job_from_json(decks::tapping_job_to_json(g.job));
    CHECK(back.ratio_source == axes::RatioSource::stored);
    REQUIRE(back.holes.size() == 6);
    CHECK(back.holes[4].card == g.job.holes[4].card);
    CHECK(back.holes[4].tap_pitch_in == Approx(kPitch2));
    CHECK(back.holes[4].head_ratio == Approx(1.0 / 3.0));
    CHECK(back.hole_on_card(g.job.holes[2].card)->hole == 3);
    CHECK(back.hole_on_card(1) == nullptr); // card 1 is a motion card
    CHECK_THROWS_WITH(decks::tapping_job_from_json(R"({"job": "press-feeder"})"),
                      Catch::Contains("expected \"tapping\""));
    CHECK_THROWS_WITH(decks::tapping_job_from_json(R"({"job": "tapping"})"),
                      Catch::Contains("ratio_source: missing"));
}

TEST_CASE("Tapping job: gen tapping writes a deck that check passes under its profile with no "
          "warnings, and refuses a plate it cannot tap with exit 2",
          "[tapping_job][cli]") {
    TempDir dir;
    const std::string deck = dir.str("plate.csv");
    const auto gen = run_parsons("gen tapping -o " + q(deck));
    INFO(gen.output);
    REQUIRE(gen.exit_code == 0);
    const auto check = run_parsons("check " + q(deck) + " --profile " + q(deck + ".profile.json"));
    INFO(check.output);
    CHECK(check.exit_code == 0);
    CHECK(check.output.find("the machine runs the deck through") != std::string::npos);
    CHECK(check.output.find("0 machine stop, 0 observed, 0 double punches, 0 advice") !=
          std::string::npos);
    const auto listing = test::read_bytes(dir.path("plate.csv"));
    CHECK_THAT(listing, Catch::Contains("2,tap,1,vertical,reverse,0.600,0.05000,240"));
    const auto profile = nlohmann::json::parse(test::read_bytes(deck + ".profile.json"));
    CHECK(profile["spindle_sync"] == true);
    CHECK(profile["spindle"]["ratio_source"] == "transferred");
    // The same again is the same bytes.
    const std::string again = dir.str("again.csv");
    REQUIRE(run_parsons("gen tapping -o " + q(again)).exit_code == 0);
    CHECK(test::read_bytes(dir.path("again.csv")) == listing);
    REQUIRE(run_parsons("gen tapping --ratio-source stored -o " + q(dir.str("s.csv"))).exit_code ==
            0);
    CHECK(nlohmann::json::parse(test::read_bytes(
              dir.path("s.csv.profile.json")))["spindle"]["ratio_source"] == "stored");
    for (const char* args :
         {"--tools 3", "--tools 7", "--clearance 0.005", "--thread-depth 0.15", "--rpm 300",
          "--surface 0.2", "--rows 0", "--ratio-source sideways", "--first-x 9.5"}) {
        INFO(args);
        const auto r = run_parsons(std::string("gen tapping ") + args + " -o " + q(deck));
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("gen tapping") != std::string::npos);
    }
}

// ---- End to end: the cabinet runs the taps ----

TEST_CASE("Tapping job: every hole's pitch is within tolerance with the ratio transferred by "
          "PC 130 and with the ratio stored per tool",
          "[tapping_job][end_to_end]") {
    for (axes::RatioSource source : {axes::RatioSource::transferred, axes::RatioSource::stored}) {
        INFO("ratio " << decks::ratio_source_name(source));
        const ProvedPlate p = run_job(options(source), {});
        every_hole_within(p, 6);
        const relaylogic::TappingResult& t = *p.result.tapping;
        CHECK(t.head_exchanges == 1); // tool 1 is on the spindle when the run starts
        CHECK(t.tool_on_spindle == 2);
        CHECK(t.ratio_in_memory == Approx(1.0 / 3.0));
        CHECK(t.transfers == (source == axes::RatioSource::transferred ? 1 : 0));
        for (const cli::ProvedHole& h : p.proof.holes) {
            CHECK(h.measure.mean_pitch_in ==
                  Approx(h.record.tool == 1 ? kPitch1 : kPitch2).epsilon(0.01));
        }
    }
}

TEST_CASE("Tapping job: at impulse level the holes are cut as in fast-forward",
          "[tapping_job][end_to_end]") {
    const ProvedPlate fast = run_job(options(axes::RatioSource::transferred), {});
    const ProvedPlate slow =
        run_job(options(axes::RatioSource::transferred), {}, relaylogic::Pace::impulse_level);
    every_hole_within(slow, 6);
    REQUIRE(slow.proof.holes.size() == fast.proof.holes.size());
    for (std::size_t i = 0; i < fast.proof.holes.size(); ++i) {
        CHECK(slow.proof.holes[i].measure.worst_error_percent ==
              Approx(fast.proof.holes[i].measure.worst_error_percent).margin(1e-9));
    }
    CHECK(slow.result.machine_seconds == Approx(fast.result.machine_seconds).margin(1e-9));
}

TEST_CASE("Tapping job: a head exchange that sends no ratio (stale-ratio) cuts the wrong pitch "
          "in exactly the holes tapped with that head, and the proof names each with the ratio "
          "used",
          "[tapping_job][end_to_end]") {
    // Three rows: tool 1, tool 2, tool 1 (exchanges 1 and 2).
    SECTION("the first exchange: tool 2's row computed with tool 1's ratio, -25 %") {
        const ProvedPlate p =
            run_job(options(axes::RatioSource::transferred, 3), {"stale-ratio:1"});
        INFO(cli::thread_summary(p.proof));
        CHECK(p.result.completed);
        REQUIRE(p.proof.holes.size() == 9);
        for (const cli::ProvedHole& h : p.proof.holes) {
            INFO("hole " << h.hole_number());
            const bool stale = h.hole_number() >= 4 && h.hole_number() <= 6;
            CHECK(h.flagged == stale);
            REQUIRE(h.measure.measured);
            if (stale) {
                CHECK(h.record.tool == 2);
                CHECK(h.record.ratio_used == Approx(0.25));
                CHECK(h.record.head_ratio == Approx(1.0 / 3.0));
                // 0.0625 x 0.25 / (1/3) = 0.046875 in a revolution
                CHECK(h.measure.mean_pitch_in == Approx(0.046875).epsilon(0.01));
                CHECK(h.measure.mean_error_percent == Approx(-25.0).margin(1.0));
                CHECK(h.measure.worst_error_percent < -20.0);
            } else {
                CHECK(std::abs(h.measure.worst_error_percent) < 5.0);
            }
        }
        CHECK(p.proof.flagged() == 3);
        const auto lines = cli::wrong_pitch_lines(p.proof);
        REQUIRE(lines.size() == 3);
        CHECK_THAT(lines[0], Catch::StartsWith("hole 4 (card "));
        CHECK_THAT(lines[0], Catch::Contains("against the tap's 0.06250 in"));
        CHECK_THAT(lines[0], Catch::Contains("memory 12a held gear ratio 0.2500, head 2's is "
                                             "0.3333"));
    }
    SECTION("with the ratios stored per tool there is no transfer to miss") {
        const ProvedPlate p = run_job(options(axes::RatioSource::stored, 3), {"stale-ratio:1"});
        every_hole_within(p, 9);
        REQUIRE(p.result.faults.size() == 1);
        CHECK_FALSE(p.result.faults.front().acted);
    }
    SECTION("the second exchange: tool 1's row computed with tool 2's ratio, +33 %") {
        const ProvedPlate p =
            run_job(options(axes::RatioSource::transferred, 3), {"stale-ratio:2"});
        REQUIRE(p.proof.holes.size() == 9);
        for (const cli::ProvedHole& h : p.proof.holes) {
            INFO("hole " << h.hole_number());
            CHECK(h.flagged == (h.hole_number() >= 7));
            if (h.hole_number() >= 7) {
                CHECK(h.record.ratio_used == Approx(1.0 / 3.0));
                CHECK(h.measure.mean_pitch_in == Approx(kPitch1 * 4.0 / 3.0).epsilon(0.01));
            }
        }
    }
}

TEST_CASE("Tapping job: run --thread-proof reports the tapping block, a stale ratio is exit 3 "
          "naming each hole, and a hung transfer stops the machine with transfer_timeout",
          "[tapping_job][cli][end_to_end]") {
    TempDir dir;
    const std::string deck = dir.str("plate.csv");
    REQUIRE(run_parsons("gen tapping -o " + q(deck)).exit_code == 0);
    const std::string job = q(deck + ".job.json");
    const auto good = run_parsons("run " + q(deck) + " --thread-proof " + job + " --report " +
                                  q(dir.str("r.json")));
    INFO(good.output);
    CHECK(good.exit_code == 0);
    CHECK_THAT(good.output, Catch::Contains("thread proof   6 holes"));
    CHECK_THAT(good.output, Catch::Contains("0 flagged"));
    const auto report = nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    const auto& t = report["tapping"];
    CHECK(t["head_exchanges"] == 1);
    CHECK(t["transfers"] == 1);
    CHECK(t["holes_flagged"] == 0);
    REQUIRE(t["holes"].size() == 6);
    CHECK(t["holes"][3]["hole"] == 4);
    CHECK(t["holes"][3]["tool"] == 2);
    CHECK(t["holes"][3]["flagged"] == false);

    const auto stale = run_parsons("run " + q(deck) + " -q --thread-proof " + job +
                                   " --fault stale-ratio:1 --report " + q(dir.str("s.json")));
    INFO(stale.output);
    CHECK(stale.exit_code == 3);
    CHECK_THAT(stale.output, Catch::Contains("thread proof: wrong pitch in 3 of 6 holes"));
    for (int hole : {4, 5, 6}) {
        CHECK_THAT(stale.output, Catch::Contains(fmt::format("hole {} (card ", hole)));
    }
    CHECK_THAT(stale.output, Catch::Contains("held gear ratio 0.2500, head 2's is 0.3333"));
    CHECK(stale.output.find("hole 3 (card") == std::string::npos);
    const auto s = nlohmann::json::parse(test::read_bytes(dir.path("s.json")));
    CHECK(s["status"] == "completed");
    CHECK(s["tapping"]["holes_flagged"] == 3);
    CHECK(s["tapping"]["worst_hole"]["hole"].get<int>() >= 4);

    const auto hang = run_parsons("run " + q(deck) + " --thread-proof " + job +
                                  " --fault transfer-hang:1 --report " + q(dir.str("h.json")));
    INFO(hang.output);
    CHECK(hang.exit_code == 3);
    CHECK_THAT(hang.output, Catch::Contains("transfer_timeout"));
    const auto h = nlohmann::json::parse(test::read_bytes(dir.path("h.json")));
    CHECK(h["stop"]["reason"] == "transfer_timeout");
    CHECK(h["stop"]["card_number"] == 8);      // hole 4's tap card: the first head exchange
    CHECK(h["tapping"]["holes_flagged"] == 0); // the three holes cut before are right
    // Hole 4 was begun, never cut: the summary names the tool its card called for.
    REQUIRE(h["tapping"]["holes"].size() == 4);
    CHECK(h["tapping"]["holes"][3]["tool_called"] == 2);
    CHECK(h["tapping"]["holes"][3]["tool"] == 0);
    CHECK(h["tapping"]["holes"][3]["measured"] == false);
    CHECK_THAT(hang.output, Catch::Contains("hole 4 (card 0008, tool 2)") &&
                                Catch::Contains("not cut: the machine stopped before the tap "
                                                "began"));

    // The stored way: the same plate under its own profile.
    const std::string stored = dir.str("stored.csv");
    REQUIRE(run_parsons("gen tapping --ratio-source stored -o " + q(stored)).exit_code == 0);
    const auto st = run_parsons("run " + q(stored) + " -q --thread-proof " +
                                q(stored + ".job.json") + " --report " + q(dir.str("st.json")));
    INFO(st.output);
    CHECK(st.exit_code == 0);
    const auto sj = nlohmann::json::parse(test::read_bytes(dir.path("st.json")));
    CHECK(sj["tapping"]["transfers"] == 0);
    CHECK(sj["tapping"]["holes_flagged"] == 0);
}

TEST_CASE("Tapping job: --thread-proof is refused with --resume, under a profile without "
          "spindle synchronisation, and --thread-tolerance without it",
          "[tapping_job][cli]") {
    TempDir dir;
    const std::string deck = dir.str("plate.csv");
    REQUIRE(run_parsons("gen tapping --rows 1 --holes-per-row 1 -o " + q(deck)).exit_code == 0);
    const std::string job = q(deck + ".job.json");
    test::write_bytes(dir.path("s.json"), "{}");
    const auto resumed = run_parsons("run " + q(deck) + " -q --resume " + q(dir.str("s.json")) +
                                     " --thread-proof " + job);
    CHECK(resumed.exit_code == 2);
    CHECK_THAT(resumed.output, Catch::Contains("--thread-proof with --resume"));
    const auto plain =
        run_parsons("run " + q(deck) + " -q --profile parsons-safe --thread-proof " + job);
    CHECK(plain.exit_code == 2);
    CHECK_THAT(plain.output, Catch::Contains("no spindle synchronisation"));
    const auto alone = run_parsons("run " + q(deck) + " -q --thread-tolerance 2");
    CHECK(alone.exit_code == 2);
    CHECK_THAT(alone.output, Catch::Contains("--thread-tolerance"));
    const auto bad =
        run_parsons("run " + q(deck) + " -q --thread-proof " + job + " --thread-tolerance 0");
    CHECK(bad.exit_code == 2);
    test::write_bytes(dir.path("j.json"), R"({"job": "tapping", "ratio_source": "sideways"})");
    const auto unreadable =
        run_parsons("run " + q(deck) + " -q --thread-proof " + q(dir.str("j.json")));
    CHECK(unreadable.exit_code == 2);
    CHECK_THAT(unreadable.output, Catch::Contains("ratio_source"));
}

TEST_CASE("Tapping job: docs/report.md names every key of the tapping block",
          "[tapping_job][cli][docs][end_to_end]") {
    TempDir dir;
    const std::string deck = dir.str("plate.csv");
    REQUIRE(run_parsons("gen tapping --rows 2 --holes-per-row 1 -o " + q(deck)).exit_code == 0);
    REQUIRE(run_parsons("run " + q(deck) + " -q --thread-proof " + q(deck + ".job.json") +
                        " --fault stale-ratio:1 --report " + q(dir.str("r.json")))
                .exit_code == 3);
    const auto report = nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    std::set<std::string> keys;
    std::function<void(const nlohmann::json&)> collect = [&](const nlohmann::json& j) {
        if (j.is_object()) {
            for (const auto& [k, v] : j.items()) {
                keys.insert(k);
                collect(v);
            }
        } else if (j.is_array()) {
            for (const auto& v : j) {
                collect(v);
            }
        }
    };
    collect(report.at("tapping"));
    for (const char* expected :
         {"ratio_in_memory", "worst_error_percent", "findings", "worst_hole", "reverse_seconds"}) {
        CHECK(keys.count(expected) == 1);
    }
    const std::string doc = test::read_bytes(test::source_path("docs/report.md"));
    CHECK(doc.find("`tapping`") != std::string::npos);
    for (const std::string& key : keys) {
        INFO(key);
        CHECK(doc.find("`" + key + "`") != std::string::npos);
    }
}

TEST_CASE("Tapping job: a spacing, clearance or thread depth far past the counters' range is "
          "refused as too big, with the size it would need, not as too small",
          "[tapping_job][limits]") {
    using Catch::Matchers::Contains;
    const auto profile = axes::extended_profile();
    decks::TappingOptions o;
    o.spacing_x_in = 5e9; // the second hole at 5e9 in: no int holds its thousandths
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("the holes' table positions (--first-x, --spacing-x): 5.000e9 in "
                               "is outside the counters' range, 0.000 to 9.999 in"));
    o.spacing_x_in = 4.437; // the third hole at 9.999 in, the counters' last thousandth
    CHECK(decks::make_tapping_deck(o, profile).holes.at(2).x_in == Approx(9.999));
    o.spacing_x_in = 4.4375; // at 10.000 in
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("(--first-x, --spacing-x): 10.000 in is outside"));
    o = {};
    o.spacing_y_in = 1e300;
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("(--first-y, --spacing-y): 1.000e300 in is outside"));
    o = {};
    o.clearance_in = 1e300;
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("--clearance 1e+300: more than the counters' range, 0.000 to 9.999 "
                               "in, can hold"));
    o = {};
    o.thread_depth_in = 10;
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("--thread-depth 10: more than the counters' range"));
    o.thread_depth_in = 9.999; // within the range: refused for the hole's bottom, as before
    CHECK_THROWS_WITH(decks::make_tapping_deck(o, profile),
                      Contains("the hole's bottom would lie below the vertical's zero"));
}

TEST_CASE("Tapping job: faults[].acted of stale-ratio and transfer-hang is the fact the thread "
          "proof and the stop use: the holes cut with a ratio not their head's, the transfer "
          "that stopped the machine",
          "[tapping_job][faults][cli]") {
    TempDir dir;
    const std::string deck = dir.str("plate.csv");
    REQUIRE(run_parsons("gen tapping -o " + q(deck)).exit_code == 0);
    const std::string job = q(deck + ".job.json");
    const auto fault = [&](const std::string& spec) {
        const auto r = run_parsons("run " + q(deck) + " -q --thread-proof " + job + " --fault " +
                                   spec + " --report " + q(dir.str("r.json")));
        INFO(spec << "\n" << r.output);
        CHECK(r.exit_code == 3);
        return nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    };
    const auto stale = fault("stale-ratio:1");
    REQUIRE(stale["faults"].size() == 1);
    CHECK(stale["faults"][0]["acted"] == true);
    std::string flagged; // the cards of the holes the proof flags, as the effect lists them
    for (const auto& h : stale["tapping"]["holes"]) {
        if (h["flagged"] == true) {
            flagged += (flagged.empty() ? "" : ", ") + fmt::format("{:04}", h["number"].get<int>());
        }
    }
    CHECK(stale["tapping"]["holes_flagged"] == 3);
    CHECK_THAT(stale["faults"][0]["effect"].get<std::string>(),
               Catch::Contains("head exchange 1 transferred no gear ratio to memory 12a: 3 holes "
                               "tapped with a ratio not its head's (cards " +
                               flagged + ")"));
    const auto hang = fault("transfer-hang:1");
    CHECK(hang["stop"]["reason"] == "transfer_timeout");
    CHECK(hang["faults"][0]["acted"] == true);
    CHECK_THAT(hang["faults"][0]["effect"].get<std::string>(),
               Catch::Contains("gear ratio transfer 1 never completed") &&
                   Catch::Contains("(transfer_timeout)"));
    // A second exchange or transfer the plate never makes: not acted.
    for (const char* spec : {"stale-ratio:2", "transfer-hang:2"}) {
        const auto r = run_parsons("run " + q(deck) + " -q --thread-proof " + job + " --fault " +
                                   spec + " --report " + q(dir.str("n.json")));
        INFO(spec << "\n" << r.output);
        CHECK(r.exit_code == 0);
        const auto n = nlohmann::json::parse(test::read_bytes(dir.path("n.json")));
        CHECK(n["faults"][0]["acted"] == false);
        CHECK(n["faults"][0]["effect"] == "never came into play in this run");
    }
}
