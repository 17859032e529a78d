// Soft limits, the movement range of Mitsubishi's control (EP 0360190): the machine stops with
// soft_limit BEFORE the part passes a limit, and `parsons check` lists the offending cards.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cli/support/deck_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

axes::MachineProfile with_table_range(double lo, double hi) {
    auto p = axes::default_profile();
    p.axes.at(0).soft_limits = true;
    p.axes.at(0).soft_min_in = lo;
    p.axes.at(0).soft_max_in = hi;
    return p;
}

} // namespace

TEST_CASE("Soft limits: a card whose move would end past the range stops before any axis moves",
          "[softlimit]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 9800, 1, 9600, 9700, 1);
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        const RunResult r = run_orders({c}, with_table_range(0, 9.5), nullptr, {}, pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::soft_limit);
        CHECK(r.stop->axis == Axis::table);
        CHECK(r.stop->card == 1);
        CHECK_THAT(r.stop->message, Catch::Contains("from 0.0000 to 9.8000 in, past its soft "
                                                    "limit 9.500 in") &&
                                        Catch::Contains("stopped before any axis moved"));
        CHECK(r.axes.at(0).impulses == 0);
    }
    // Inside the range, the same card runs.
    CHECK(run_orders({c}, with_table_range(0, 9.9)).completed);
}

TEST_CASE("Soft limits: an axis that could no longer brake inside the range is switched off "
          "and comes to rest before the limit",
          "[softlimit]") {
    // The stop is inside the range, but the slow-downs sit 0.002 and 0.001 in before it: the
    // table arrives near speed 1 and would coast 0.02 in past 8.985 in.
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 8985, 1, 8983, 8984, 1);
    const double limit = 8.990;
    CHECK(run_orders({c}).axes.at(0).real_in > limit); // without a range it passes 8.990
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        const RunResult r = run_orders({c}, with_table_range(-0.1, limit), nullptr, {}, pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::soft_limit);
        CHECK(r.stop->axis == Axis::table);
        CHECK_THAT(r.stop->message, Catch::Contains("could no longer brake to rest inside its "
                                                    "soft limit 8.990 in"));
        CHECK(r.axes.at(0).real_in <= limit); // at rest, and not past the limit
        CHECK(r.axes.at(0).real_in > limit - 0.03);
    }
}

TEST_CASE("Soft limits: parsons check lists every card that would pass a limit, run --limit "
          "stops there",
          "[softlimit][cli]") {
    const std::string sample = source_path("decks/samples/patent-example.csv");
    auto r = run_parsons("check " + q(sample) + " --limit table=0:8.9");
    CHECK(r.exit_code == 3);
    CHECK_THAT(
        r.output,
        Catch::Contains("card 1 (number 0001): past a limit: table moves +8.985 in, from 0.000 "
                        "to 8.985 in, past its soft limit 8.900 in"));
    CHECK_THAT(
        r.output,
        Catch::Contains("card 3 (number 0003): past a limit: table moves +0.600 in, from 8.385 "
                        "to 8.985 in"));
    CHECK_THAT(r.output, Catch::Contains("4 cards checked: 2 moves past a limit"));

    auto clean = run_parsons("check " + q(sample) + " --limit table=0:9.5");
    CHECK(clean.exit_code == 0);
    CHECK_THAT(clean.output, Catch::Contains("0 moves past a limit"));

    auto run = run_parsons("run " + q(sample) + " --limit table=0:8.9 -q");
    CHECK(run.exit_code == 3);
    CHECK_THAT(run.output, Catch::Contains("soft_limit: card 1 (number 0001), table"));

    for (const std::string bad : {"table=9:1", "table=0-9", "spindle=0:1", "table=a:9"}) {
        auto e = run_parsons("run " + q(sample) + " --limit " + bad);
        CHECK(e.exit_code == 2);
        CHECK_THAT(e.output, Catch::Contains("--limit '" + bad + "'"));
    }
}

TEST_CASE("Soft limits: a move that ends exactly on the limit is allowed, one 0.001 in past it "
          "is stopped before any axis moves",
          "[softlimit]") {
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        CardOrders on = idle_card(1, {0, 0, 0, 0, 0});
        on.axis(Axis::table) = order(0, 500, 3);
        const RunResult allowed = run_orders({on}, with_table_range(-0.4, 0.5), nullptr, {}, pace);
        CHECK(allowed.completed);
        CHECK(allowed.axes.at(0).counter_in == Approx(0.500));
        CHECK(allowed.axes.at(0).real_in <= 0.5);
        // Going down onto the lower limit, too: the card is judged from where the part really
        // stands (0.49975 after the coast), so the limit is put exactly where -0.400 ends.
        CardOrders down = idle_card(2, {500, 0, 0, 0, 0});
        down.axis(Axis::table) = order(500, 100, 3);
        const double low_end = allowed.axes.at(0).real_in + (-400 / 1000.0);
        CHECK(run_orders({on, down}, with_table_range(low_end, 0.5), nullptr, {}, pace).completed);
        const RunResult low =
            run_orders({on, down}, with_table_range(low_end + 0.001, 0.5), nullptr, {}, pace);
        REQUIRE(low.stop);
        CHECK(low.stop->reason == StopReason::soft_limit);
        CHECK(low.stop->card == 2);
        CardOrders past = idle_card(1, {0, 0, 0, 0, 0});
        past.axis(Axis::table) = order(0, 501, 3);
        const RunResult r = run_orders({past}, with_table_range(-0.4, 0.5), nullptr, {}, pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::soft_limit);
        CHECK(r.axes.at(0).impulses == 0);
    }
}

TEST_CASE("Soft limits: parsons check lists no card whose move ends exactly on a soft limit, and "
          "names the limit a card passes",
          "[softlimit][check][cli][mutation]") {
    TempDir dir;
    // Up to 0.500, down 0.400 to 0.100, up 0.400 to 0.500 again: each end exactly on a limit of
    // table=0.1:0.5 (0.5 - 0.4 is not 0.1 in binary: the cards are counted in thousandths).
    write_bytes(dir.path("edge.csv"), std::string(kHeader) + "1,0,table,+,3,,,0.500,0.500,1\n" +
                                          idle_rest(1) + "2,0,table,-,3,,,0.100,0.400,1\n" +
                                          idle_rest(2) + "3,0,table,+,3,,,0.500,0.400,1\n" +
                                          idle_rest(3));
    const std::string deck = q(dir.str("edge.csv"));
    const auto on = run_parsons("check " + deck + " --limit table=0.1:0.5");
    INFO(on.output);
    CHECK_THAT(on.output, Catch::Contains("3 cards checked: 0 moves past a limit"));
    CHECK(count(on.output, "past a limit:") == 0);
    // A thousandth inside at the top: cards 1 and 3 pass it, each named by the maximum it passes.
    const auto over = run_parsons("check " + deck + " --limit table=0.1:0.499");
    INFO(over.output);
    CHECK_THAT(over.output, Catch::Contains("card 1 (number 0001): past a limit: table moves "
                                            "+0.500 in, from 0.000 to 0.500 in, past its soft "
                                            "limit 0.499 in (movement range 0.100 .. 0.499 in)"));
    CHECK_THAT(over.output, Catch::Contains("card 3 (number 0003): past a limit: table moves "
                                            "+0.400 in, from 0.100 to 0.500 in, past its soft "
                                            "limit 0.499 in"));
    CHECK_THAT(over.output, Catch::Contains("3 cards checked: 2 moves past a limit"));
    // And a thousandth inside at the bottom: card 2, named by the minimum.
    const auto under = run_parsons("check " + deck + " --limit table=0.101:0.5");
    INFO(under.output);
    CHECK_THAT(under.output, Catch::Contains("card 2 (number 0002): past a limit: table moves "
                                             "-0.400 in, from 0.500 to 0.100 in, past its soft "
                                             "limit 0.101 in"));
    CHECK_THAT(under.output, Catch::Contains("3 cards checked: 1 move past a limit"));
}

TEST_CASE(
    "Soft limits: --limit AXIS=A:A, an empty range, is refused, and the least range is 0.001 in",
    "[softlimit][cli][mutation]") {
    auto profile = axes::default_profile();
    CHECK_THROWS_WITH(cli::apply_limits(profile, {"table=2:2"}),
                      "--limit 'table=2:2': the minimum must be below the maximum (expected "
                      "AXIS=MIN:MAX in inches, e.g. table=0:9.5)");
    CHECK_THROWS_WITH(cli::apply_limits(profile, {"cross=2.5:2.5000"}),
                      Catch::Contains("the minimum must be below the maximum"));
    CHECK_FALSE(profile.axes.at(0).soft_limits); // nothing set by a refused range
    CHECK(cli::apply_limits(profile, {"table=2:2.001"}) == std::vector<Axis>{Axis::table});
    CHECK(profile.axes.at(0).soft_limits);
    CHECK(profile.axes.at(0).soft_min_in == 2.0);
    CHECK(profile.axes.at(0).soft_max_in == 2.001);
    // On the command line: exit 2, naming the option.
    const auto r = run_parsons("check " + q(source_path("decks/samples/patent-example.csv")) +
                               " --limit tilt=1:1");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("--limit 'tilt=1:1': the minimum must be below"));
}

TEST_CASE("Soft limits: a movement range held in a profile file (the range memory of EP 0360190 "
          "claim 3, filled before the run) stops the run as --limit does, and a resume widens it "
          "with --limit (claim 2)",
          "[softlimit][cli]") {
    const std::string sample = source_path("decks/samples/patent-example.csv");
    const TempDir dir;
    using std::filesystem::path;
    const path range = dir.path("range.json");
    write_bytes(range, R"({"axes": {"table": {"soft_limits_in": [0, 8.9]}}})");
    auto run = run_parsons("run " + q(sample) + " -q --profile " + q(range.string()));
    CHECK(run.exit_code == 3);
    CHECK_THAT(run.output, Catch::Contains("soft_limit: card 1 (number 0001), table") &&
                               Catch::Contains("(movement range 0.000 .. 8.900 in)"));

    const path vertical = dir.path("vertical.json");
    const path state = dir.path("suspend.json");
    write_bytes(vertical, R"({"axes": {"vertical": {"soft_limits_in": [0, 2.5]}}})");
    auto stopped = run_parsons("run " + q(sample) + " -q --profile " + q(vertical.string()) +
                               " --save-state " + q(state.string()));
    CHECK(stopped.exit_code == 3);
    CHECK_THAT(stopped.output, Catch::Contains("soft_limit: card 3 (number 0003), vertical"));
    auto resumed = run_parsons("run " + q(sample) + " -q --resume " + q(state.string()) +
                               " --limit vertical=-0.5:3");
    CHECK(resumed.exit_code == 0);
}
