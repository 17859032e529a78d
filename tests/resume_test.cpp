// Stop, save, resume (Mitsubishi's suspend and restart, EP 0360190), Ctrl-C, and nothing lost.
//
// A resumed run must finish exactly as an uninterrupted run of the corrected deck: the same
// report, and from the moment the stopped card was fed, the same trace, event for event.
#include "tests/card_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include "axes/state_json.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;
using nlohmann::json;

namespace {

json read_json(const std::filesystem::path& p) {
    return json::parse(read_bytes(p));
}

// A report without the profile's provenance, which a resumed run tells differently (its
// limits came from the saved state): what the machine did, and nothing else.
json machine_result(const std::filesystem::path& p) {
    json j = read_json(p);
    j.erase("profile_applied");
    return j;
}

// Starts `parsons ARGS`, waits until its VCD (`trace`, written under a temporary name while the
// run goes on) has begun, then `delay` more, sends `signal`, and returns the exit status.
int run_and_signal(const std::string& args, const std::filesystem::path& trace, int signal,
                   std::chrono::milliseconds delay) {
    const pid_t pid = fork();
    if (pid == 0) {
        const std::string command =
            std::string("exec '") + PARSONS_EXE + "' " + args + " >/dev/null 2>&1";
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto partial =
        trace.parent_path() / ("." + trace.filename().string() + ".partial-" + std::to_string(pid));
    for (int i = 0; i < 600; ++i) { // up to a minute (a sanitizer build starts slowly)
        std::error_code ec;
        if (std::filesystem::exists(partial, ec) && std::filesystem::file_size(partial, ec) > 0) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::this_thread::sleep_for(delay);
    kill(pid, signal);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

class Events : public MachineObserver {
public:
    void on_signal_defined(const SignalInfo& info, std::uint32_t initial) override {
        names.push_back(info.scope + "." + info.name);
        initial_values.push_back(initial);
    }
    void on_signal(double t, SignalId id, std::uint32_t, std::uint32_t v) override {
        events.emplace_back(t, id, v);
    }
    std::vector<std::string> names;
    std::vector<std::uint32_t> initial_values;
    std::vector<std::tuple<double, SignalId, std::uint32_t>> events;
};

// A deck read from the bytes of its file: cards as they are (.cbn), or five a step (.five).
struct FileDeck {
    FileDeck(const std::vector<CardOrders>& cards, DeckFormat format)
        : in(deck_bytes(punched(cards), format)) {
        DeckOptions options;
        options.format = format;
        source = open_card_source(in, options);
    }
    std::istringstream in;
    std::unique_ptr<CardSource> source;
};

} // namespace

TEST_CASE("Resume: after a soft-limit stop, resumed with wider limits, the run ends with the "
          "report of an uninterrupted run",
          "[resume][cli]") {
    TempDir dir;
    write_bytes(dir.path("deck.csv"), long_listing(6));
    const std::string deck = q(dir.str("deck.csv"));
    // The cross shuttles 1.085 <-> 2.985 in: a range up to 2.5 in stops card 1; the table's
    // range up to 9.2 in stops card 1 too. Use the vertical: 0.5 <-> 1.5, stopped by 1.2 in.
    auto stopped = run_parsons("run " + deck + " --limit vertical=0:1.2 --save-state " +
                               q(dir.str("state.json")) + " -q");
    REQUIRE(stopped.exit_code == 3);
    const json state = read_json(dir.path("state.json"));
    CHECK(state["stop"]["reason"] == "soft_limit");
    CHECK(state["resume_card"] == 1);
    CHECK(state["profile"]["axes"]["vertical"]["soft_limits_in"] == json::array({0, 1.2}));
    CHECK(state["resume"]["signals"].contains("table.absolute_counter_104"));

    auto resumed =
        run_parsons("run " + deck + " --resume " + q(dir.str("state.json")) +
                    " --limit vertical=0:1.6 --report " + q(dir.str("resumed.json")) + " -q");
    auto straight = run_parsons("run " + deck + " --limit vertical=0:1.6 --report " +
                                q(dir.str("straight.json")) + " -q");
    CHECK(resumed.exit_code == 0);
    CHECK(straight.exit_code == 0);
    CHECK(machine_result(dir.path("resumed.json")) == machine_result(dir.path("straight.json")));
}

TEST_CASE("Resume: a machine stopped part way through a deck goes on from the stopped card "
          "exactly: the same result and, from the card's feed, the same trace (cards or five "
          "cards a step, separate or on a ribbon)",
          "[resume]") {
    // Card 3 is punched wrong (its check one short): the machine stops there. The corrected
    // deck, resumed from the saved state, must run as the corrected deck run straight.
    std::vector<CardOrders> good;
    std::array<int, 5> at{0, 0, 0, 0, 0};
    const std::array<int, 6> table = {4985, 1385, 6985, 3585, 3485, 8985}; // no bank hazard
    for (int n = 0; n < 6; ++n) {
        CardOrders o = idle_card(n + 1, at);
        const int to = table.at(static_cast<std::size_t>(n));
        const int sign = to > at[0] ? 1 : -1;
        o.axis(Axis::table) = std::abs(to - at[0]) > 300
                                  ? order(at[0], to, 1, to - sign * 200, to - sign * 100, 1)
                                  : order(at[0], to, 3, {}, {}, 1);
        at[0] = to;
        good.push_back(o);
    }
    std::vector<CardOrders> bad = good;
    bad.at(2).axis(Axis::table).check =
        static_cast<Thousandths>(bad.at(2).axis(Axis::table).check - 1);
    const DeckFormat format = GENERATE(DeckFormat::cbn, DeckFormat::five);
    auto profile = axes::default_profile();
    profile.ribbon_feed = GENERATE(false, true);
    INFO(format_name(format) << (profile.ribbon_feed ? " on a ribbon" : ""));

    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        // The faulty run, saving its resume point.
        FileDeck faulty(bad, format);
        ControlCabinet first(profile, fig8_layout());
        first.set_pace(pace);
        first.record_card_times(true);
        Events first_events; // keeps the signal values, as run --save-state does
        first.keep_resume_point(true);
        first.attach(&first_events);
        const RunResult stopped = first.run(*faulty.source);
        REQUIRE(stopped.stop);
        CHECK(stopped.stop->card == 3);
        const json saved = json::parse(first.resume_point().dump()); // through the text

        // Straight through the corrected deck.
        FileDeck corrected(good, format);
        ControlCabinet straight(profile, fig8_layout());
        straight.set_pace(pace);
        straight.record_card_times(true);
        Events straight_events;
        straight.attach(&straight_events);
        const RunResult whole = straight.run(*corrected.source);
        REQUIRE(whole.completed);

        // Resumed with the corrected deck.
        FileDeck again(good, format);
        ControlCabinet resumed(profile, fig8_layout());
        resumed.set_pace(pace);
        resumed.record_card_times(true);
        resumed.resume(saved);
        Events resumed_events;
        resumed.attach(&resumed_events);
        const RunResult rest = resumed.run(*again.source);
        REQUIRE(rest.completed);

        CHECK(rest.cards_read == whole.cards_read);
        CHECK(rest.machine_seconds == whole.machine_seconds);
        for (std::size_t i = 0; i < 5; ++i) {
            CHECK(rest.axes.at(i).counter_in == whole.axes.at(i).counter_in);
            CHECK(rest.axes.at(i).real_in == whole.axes.at(i).real_in);
            CHECK(rest.axes.at(i).impulses == whole.axes.at(i).impulses);
        }
        REQUIRE(rest.cards.size() == whole.cards.size());
        for (std::size_t i = 0; i < rest.cards.size(); ++i) {
            CHECK(rest.cards.at(i).start_s == whole.cards.at(i).start_s);
            CHECK(rest.cards.at(i).end_s == whole.cards.at(i).end_s);
        }
        // The trace: the resumed run starts from the values the straight run showed as card 3
        // was fed, and every event after is the same.
        const double fed = axes::exact(saved.at("machine_seconds"));
        std::vector<std::tuple<double, SignalId, std::uint32_t>> tail;
        std::vector<std::uint32_t> values = straight_events.initial_values;
        for (const auto& e : straight_events.events) {
            if (std::get<0>(e) < fed) {
                values.at(std::get<1>(e)) = std::get<2>(e);
            } else {
                tail.push_back(e);
            }
        }
        CHECK(resumed_events.initial_values == values);
        CHECK(resumed_events.events.size() == tail.size());
        CHECK(resumed_events.events == tail);
    }
}

TEST_CASE("Ctrl-C: a long run stops at the next event with a valid report, a complete VCD and "
          "a state that resumes to the uninterrupted result",
          "[resume][signals][cli]") {
    TempDir dir;
    write_bytes(dir.path("deck.csv"), long_listing(400));
    REQUIRE(run_parsons("punch " + q(dir.str("deck.csv")) + " -o " + q(dir.str("deck.cbn")))
                .exit_code == 0);
    const std::string deck = q(dir.str("deck.cbn"));
    const int status = run_and_signal(
        "run " + deck + " --impulse-level --trace " + q(dir.str("run.vcd")) + " --report " +
            q(dir.str("report.json")) + " --save-state " + q(dir.str("state.json")) + " -q",
        dir.path("run.vcd"), SIGINT, std::chrono::milliseconds(200));
    REQUIRE(status == 130);
    const json report = read_json(dir.path("report.json"));
    CHECK(report["status"] == "stopped");
    CHECK(report["stop"]["reason"] == "interrupted");
    CHECK(report["cards_read"].get<long>() < 400);
    // The VCD is whole: header, the initial dump, and value changes up to the last time.
    const std::string vcd = read_bytes(dir.path("run.vcd"));
    CHECK(vcd.find("$enddefinitions $end") != std::string::npos);
    CHECK(vcd.find("$dumpvars") != std::string::npos);
    CHECK(vcd.back() == '\n');
    const auto last_time = vcd.rfind("\n#");
    REQUIRE(last_time != std::string::npos);
    CHECK(std::stod(vcd.substr(last_time + 2)) > 0);
    // No partial file is left beside the outputs.
    for (const auto& entry : std::filesystem::directory_iterator(dir.path("."))) {
        CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
    }

    auto resumed = run_parsons("run " + deck + " --resume " + q(dir.str("state.json")) +
                               " --report " + q(dir.str("resumed.json")) + " -q");
    auto straight = run_parsons("run " + deck + " --report " + q(dir.str("straight.json")) + " -q");
    CHECK(resumed.exit_code == 0);
    CHECK(straight.exit_code == 0);
    CHECK(machine_result(dir.path("resumed.json")) == machine_result(dir.path("straight.json")));
}

TEST_CASE("Nothing lost: a run killed outright leaves no file under an output's name",
          "[resume][signals][cli]") {
    TempDir dir;
    write_bytes(dir.path("deck.csv"), long_listing(400));
    const int status =
        run_and_signal("run " + q(dir.str("deck.csv")) + " --impulse-level --trace " +
                           q(dir.str("run.vcd")) + " --report " + q(dir.str("report.json")) +
                           " --events " + q(dir.str("events.jsonl")) + " -q",
                       dir.path("run.vcd"), SIGKILL, std::chrono::milliseconds(200));
    CHECK(status == 128 + SIGKILL);
    CHECK_FALSE(std::filesystem::exists(dir.path("run.vcd")));
    CHECK_FALSE(std::filesystem::exists(dir.path("report.json")));
    CHECK_FALSE(std::filesystem::exists(dir.path("events.jsonl")));
}

TEST_CASE("Resume: a state that is not one, or a deck too short for it, is refused with exit 2",
          "[resume][cli]") {
    TempDir dir;
    const std::string sample = q(source_path("decks/samples/patent-example.csv"));
    write_bytes(dir.path("junk.json"), "{\"resume\": 5}");
    auto junk = run_parsons("run " + sample + " --resume " + q(dir.str("junk.json")));
    CHECK(junk.exit_code == 2);
    CHECK_THAT(junk.output, Catch::Contains("junk.json"));
    write_bytes(dir.path("text.json"), "not json");
    CHECK(run_parsons("run " + sample + " --resume " + q(dir.str("text.json"))).exit_code == 2);
    auto both = run_parsons("run " + sample + " --resume " + q(dir.str("junk.json")) +
                            " --fault feed-twice:1");
    CHECK(both.exit_code == 2);
    CHECK_THAT(both.output, Catch::Contains("carries its machine profile and faults"));
}

TEST_CASE("Resume: a saved state carries the holes tapped before it, so a resumed run reports "
          "them as the run it goes on from did",
          "[resume][tapping][cli]") {
    // Card 2 taps; card 3 moves the vertical 0.100 in with a check of 0.099: the machine stops
    // there, saving its state. Resumed on the same deck, it reads card 3 again and stops again:
    // the report must still hold card 2's hole (the property test found them dropped).
    TempDir dir;
    write_bytes(dir.path("deck.csv"), deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n") +
                                          motion_rows(3, "1.100", "0.099"));
    const std::string deck = q(dir.str("deck.csv"));
    const auto stopped =
        run_parsons("run " + deck + " --profile parsons-extended --save-state " +
                    q(dir.str("state.json")) + " --report " + q(dir.str("first.json")) + " -q");
    REQUIRE(stopped.exit_code == 3);
    const json first = read_json(dir.path("first.json"));
    REQUIRE(first["stop"]["card"] == 3);
    REQUIRE(first["tapping"]["holes"].size() == 1);
    CHECK(first["tapping"]["holes"][0]["completed"] == true);
    CHECK(read_json(dir.path("state.json"))["resume"]["tapping"]["holes"].size() == 1);

    const auto resumed = run_parsons("run " + deck + " --resume " + q(dir.str("state.json")) +
                                     " --report " + q(dir.str("resumed.json")) + " -q");
    CHECK(resumed.exit_code == 3);
    const json again = read_json(dir.path("resumed.json"));
    CHECK(again["stop"] == first["stop"]);
    CHECK(again["tapping"] == first["tapping"]);
}
