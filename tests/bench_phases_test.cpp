// parsons bench's split of a run by phase of the card cycle (relaylogic/phase_clock.hpp) and its
// count of heap allocations (cli/support/allocation_count.hpp): docs/performance.md.
#include "cli/commands.hpp"
#include "cli/support/allocation_count.hpp"
#include "relaylogic/phase_clock.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace {

const std::string kPhasesSampleDeck =
    std::string(PARSONS_SOURCE_DIR) + "/decks/samples/patent-example.csv";

parsons::cli::RunRequest quiet_request(parsons::relaylogic::PhaseClock* clock) {
    parsons::cli::RunRequest r;
    r.input = kPhasesSampleDeck;
    r.quiet = true;
    r.phases = clock;
    return r;
}

} // namespace

TEST_CASE("Bench phases: a run timed by phase is the same run, and each phase of the card cycle "
          "has the time of its own events",
          "[bench][phases]") {
    using parsons::relaylogic::Phase;
    parsons::relaylogic::RunResult plain;
    parsons::relaylogic::RunResult timed;
    REQUIRE(parsons::cli::run_deck(quiet_request(nullptr), &plain) == parsons::cli::ExitCode::ok);
    parsons::relaylogic::PhaseClock clock;
    REQUIRE(parsons::cli::run_deck(quiet_request(&clock), &timed) == parsons::cli::ExitCode::ok);
    // The clock changes nothing the machine does.
    CHECK(timed.machine_seconds == plain.machine_seconds);
    REQUIRE(timed.axes.size() == plain.axes.size());
    for (std::size_t i = 0; i < plain.axes.size(); ++i) {
        CHECK(timed.axes[i].impulses == plain.axes[i].impulses);
        CHECK(timed.axes[i].real_in == plain.axes[i].real_in);
    }
    // Four cards read, relays picked, axes moved and the sequence shaft stepped: each phase has
    // time; parsons-1952 carries no attachment, so that phase has none.
    for (Phase p : {Phase::setup, Phase::read_decode, Phase::reader_relays, Phase::motion,
                    Phase::sequence, Phase::report}) {
        INFO(parsons::relaylogic::phase_name(p));
        CHECK(clock.spent(p) > 0);
    }
    CHECK(clock.spent(Phase::attachments) == 0);
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < parsons::relaylogic::kPhases; ++i) {
        sum += clock.spent(static_cast<Phase>(i));
    }
    CHECK(sum == clock.total());
}

TEST_CASE("Bench phases: the clock gives the time between two marks to the phase in force, and "
          "a nested phase gives it back",
          "[bench][phases]") {
    using parsons::relaylogic::Phase;
    parsons::relaylogic::PhaseClock clock;
    clock.start(Phase::motion);
    {
        const parsons::relaylogic::InPhase reading(&clock, Phase::read_decode);
        CHECK(clock.spent(Phase::motion) > 0);
        CHECK(clock.spent(Phase::read_decode) == 0);
    }
    CHECK(clock.spent(Phase::read_decode) > 0);
    const std::uint64_t motion = clock.spent(Phase::motion);
    clock.stop(); // back in motion: its time grows
    CHECK(clock.spent(Phase::motion) > motion);
    // No clock: nothing to mark, nothing breaks.
    const parsons::relaylogic::InPhase none(nullptr, Phase::report);
}

TEST_CASE("Bench phases: the allocation count counts each operator new, where the build counts",
          "[bench][allocations]") {
    const std::uint64_t before = parsons::cli::allocations();
    auto one = std::make_unique<int>(1);
    auto two = std::make_unique<double>(2.0);
    const std::uint64_t after = parsons::cli::allocations();
    if (parsons::cli::allocations_counted()) {
        CHECK(after - before == 2);
    } else {
        CHECK(after == before); // AddressSanitizer's own operator new: nothing counted
    }
    CHECK(*one + *two == 3.0);
}

TEST_CASE("Bench phases: bench --json gives the short moves' time a card by phase, summing to the "
          "whole, and their allocations a card and a run",
          "[bench][phases][cli]") {
    const auto r = run_parsons("bench --json --runs 1 --long-cards 4 --trace-cards 2 "
                               "--short-cards 2000 --memory-cards 1000 --press-cycles 10");
    INFO(r.output.substr(0, 2000));
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.output);
    const auto& shorts = j.at("short_moves");
    const auto& phases = shorts.at("us_per_card_by_phase");
    CHECK(phases.size() == parsons::relaylogic::kPhases);
    double sum = 0;
    for (const auto& [name, us] : phases.items()) {
        INFO(name);
        CHECK(us.get<double>() >= 0);
        sum += us.get<double>();
    }
    const double us_per_card = shorts.at("seconds").get<double>() / 2000 * 1e6;
    CHECK(sum == Approx(us_per_card).epsilon(1e-9));
    CHECK(phases.at("reader cycle's relays").get<double>() > 0);
    CHECK(phases.at("axes' motion").get<double>() > 0);
    CHECK(phases.at("sequence and zeroizing").get<double>() > 0);
    // The bare stepping-chain loop, in the same run: the impulse level's impulses through one
    // axis's two counters alone, each reading then 0.000-9.999 (both wrap at 9.999), and the
    // impulse level's rate as a share of the loop's.
    const auto& bare = j.at("bare_loop");
    const auto& il = j.at("impulse_level");
    const auto impulses = il.at("impulses").get<std::int64_t>();
    CHECK(bare.at("impulses").get<std::int64_t>() == impulses);
    CHECK(bare.at("counters_read").get<std::int64_t>() == 2 * (impulses % 10000));
    CHECK(bare.at("impulses_per_s").get<double>() ==
          Approx(static_cast<double>(impulses) / bare.at("seconds").get<double>()));
    CHECK(il.at("ratio_to_bare_loop").get<double>() ==
          Approx(il.at("impulses_per_s").get<double>() / bare.at("impulses_per_s").get<double>()));
    // A card's own allocations against a run's (two decks, 1,000 and 2,000 cards): counted
    // where the build counts; the run makes some (its profile, its cabinet, its deck reader).
    if (parsons::cli::allocations_counted()) {
        CHECK(shorts.at("allocations_per_card").get<double>() >= 0);
        CHECK(shorts.at("allocations_per_run").get<double>() > 0);
    } else {
        CHECK(shorts.at("allocations_per_card").is_null());
    }
}
