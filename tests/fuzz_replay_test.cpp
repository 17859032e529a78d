// Replays every kept fuzz input through the same function the libFuzzer executable calls:
// the seed corpus of each target (tests/fuzz/corpus/<target>/) and every input a fuzzer ever
// found a fault with (tests/fuzz/regressions/<target>/, kept after the fix). Needs no libFuzzer.
#include "tests/fuzz/fuzz_targets.hpp"

#include "cardreader/layout.hpp"

#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using parsons::fuzz::FuzzTarget;

namespace {

std::vector<fs::path> kept_inputs(const std::string& kind, std::string_view target) {
    std::vector<fs::path> files;
    const fs::path dir =
        parsons::test::source_path("tests/fuzz/" + kind + "/" + std::string(target));
    if (fs::is_directory(dir)) {
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.is_regular_file() && entry.path().filename() != "README.md") {
                files.push_back(entry.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

void replay(std::string_view name) {
    const FuzzTarget* target = parsons::fuzz::fuzz_target_named(name);
    REQUIRE(target != nullptr);
    const auto seeds = kept_inputs("corpus", name);
    CHECK(seeds.size() >= 2);
    auto inputs = seeds;
    const auto regressions = kept_inputs("regressions", name);
    inputs.insert(inputs.end(), regressions.begin(), regressions.end());
    for (const auto& file : inputs) {
        const std::string bytes = parsons::test::read_bytes(file);
        INFO(file.string() << " (" << bytes.size() << " bytes)");
        CHECK_NOTHROW(
            target->run({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}));
    }
}

} // namespace

TEST_CASE("Fuzz replay: the targets are the ones CMake builds, each with a seed corpus", "[fuzz]") {
    std::set<std::string> in_cmake;
    std::istringstream list(PARSONS_FUZZ_TARGETS);
    for (std::string name; std::getline(list, name, ',');) {
        in_cmake.insert(name);
    }
    std::set<std::string> in_code;
    for (const FuzzTarget& t : parsons::fuzz::fuzz_targets()) {
        in_code.insert(std::string(t.name));
    }
    CHECK(in_code == in_cmake);
    for (const auto& entry :
         fs::directory_iterator(parsons::test::source_path("tests/fuzz/corpus"))) {
        INFO(entry.path().string());
        CHECK(in_code.count(entry.path().filename().string()) == 1);
    }
}

TEST_CASE("Fuzz replay: every kept .cbn input gives cards or a DeckError", "[fuzz][cbn]") {
    replay("cbn");
}

TEST_CASE("Fuzz replay: every kept .bin input gives cards or a DeckError", "[fuzz][bin]") {
    replay("bin");
}

TEST_CASE("Fuzz replay: every kept text card image gives cards or a DeckError", "[fuzz][text]") {
    replay("text");
}

TEST_CASE("Fuzz replay: every kept listing gives cards or a DeckError", "[fuzz][listing]") {
    replay("listing");
}

TEST_CASE("Fuzz replay: every kept perforated tape gives cards or a DeckError", "[fuzz][tape]") {
    replay("tape");
}

TEST_CASE("Fuzz replay: every kept five-card deck gives cards or a DeckError", "[fuzz][five]") {
    replay("five");
}

TEST_CASE("Fuzz replay: every kept airfoil file gives a smooth airfoil or a DeckError",
          "[fuzz][airfoil]") {
    replay("airfoil");
}

TEST_CASE("Fuzz replay: every kept G-code program is refused naming its line, or every move and "
          "arc starts where the last ended and ends where it says",
          "[fuzz][gcode]") {
    replay("gcode");
}

TEST_CASE("Fuzz replay: every kept profile is refused with a ProfileError or runs the machine",
          "[fuzz][profile]") {
    replay("profile");
}

TEST_CASE("Fuzz replay: every kept deck recipe runs to completion or to a stop with a reason",
          "[fuzz][machine]") {
    replay("machine");
}

TEST_CASE("Fuzz replay: the machine target's condition-card seeds make decks with condition "
          "cards, and its kept regression still makes the deck it was kept for",
          "[fuzz][conditions]") {
    for (const char* seed : {"conditions-tool-change-on-path", "conditions-never-met",
                             "conditions-dwell-and-spindle"}) {
        INFO(seed);
        const std::string bytes = parsons::test::read_bytes(
            parsons::test::source_path(std::string("tests/fuzz/corpus/machine/") + seed));
        parsons::axes::MachineProfile profile = parsons::axes::default_profile();
        const auto cards = parsons::fuzz::machine_deck(
            {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, profile);
        CHECK(profile.condition_cards);
        const auto conditions = std::count_if(cards.begin(), cards.end(), [](const auto& c) {
            return parsons::cardreader::is_condition_card(c, parsons::cardreader::fig8_layout());
        });
        CHECK(conditions >= 1);
        CHECK(conditions < static_cast<long>(cards.size()));
    }
    // The input kept before condition cards existed: no condition card, four motion cards.
    const std::string kept = parsons::test::read_bytes(
        parsons::test::source_path("tests/fuzz/regressions/machine/tilt-real-position-differs"));
    parsons::axes::MachineProfile profile = parsons::axes::default_profile();
    const auto cards = parsons::fuzz::machine_deck(
        {reinterpret_cast<const std::uint8_t*>(kept.data()), kept.size()}, profile);
    CHECK_FALSE(profile.condition_cards);
    CHECK(cards.size() == 4);
}

TEST_CASE("Fuzz replay: the machine target's tapping seed makes a deck with tap cards under "
          "spindle synchronisation, and its spindle byte's faults reach the run",
          "[fuzz][tapping]") {
    const std::string bytes = parsons::test::read_bytes(
        parsons::test::source_path("tests/fuzz/corpus/machine/tapping-two-tools"));
    const parsons::fuzz::Bytes input{reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                     bytes.size()};
    parsons::axes::MachineProfile profile = parsons::axes::default_profile();
    std::vector<parsons::relaylogic::Fault> faults;
    const auto cards = parsons::fuzz::machine_deck(input, profile, &faults);
    CHECK(profile.spindle_sync);
    CHECK(faults.empty());
    REQUIRE(cards.size() == 4); // motion, tap, motion, tap
    int taps = 0;
    for (const auto& card : cards) {
        const auto decoded = parsons::cardreader::decode(card, parsons::cardreader::fig8_layout());
        REQUIRE(decoded);
        if (decoded.orders.kind == parsons::cardreader::CardKind::tap) {
            ++taps;
            CHECK(decoded.orders.tap.axis == parsons::cardreader::Axis::vertical);
            CHECK(decoded.orders.tap.depth == 100);
        }
    }
    CHECK(taps == 2);
    // The same input with the spindle byte's fault bits: stale-ratio and transfer-hang.
    std::string faulty = bytes;
    faulty.at(faulty.size() - 11) = static_cast<char>(0x03 | 0x10 | 0x20);
    parsons::axes::MachineProfile p2 = parsons::axes::default_profile();
    std::vector<parsons::relaylogic::Fault> f2;
    parsons::fuzz::machine_deck(
        {reinterpret_cast<const std::uint8_t*>(faulty.data()), faulty.size()}, p2, &f2);
    CHECK(f2.size() == 2);
}

TEST_CASE("Fuzz replay: the machine target's press-interlock seed makes a sync deck under the "
          "feeder's interlock, which holds the press alike at both paces",
          "[fuzz][press_sync][press-interlock]") {
    const std::string bytes = parsons::test::read_bytes(
        parsons::test::source_path("tests/fuzz/corpus/machine/press-interlock"));
    parsons::axes::MachineProfile profile = parsons::axes::default_profile();
    const auto cards = parsons::fuzz::machine_deck(
        {reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()}, profile);
    CHECK(profile.press_sync);
    CHECK(profile.press.feeder_hold_lag_in == 0.002);
    std::vector<parsons::cardreader::CardOrders> orders;
    for (const auto& card : cards) {
        const auto decoded = parsons::cardreader::decode(card, parsons::cardreader::fig8_layout());
        REQUIRE(decoded);
        orders.push_back(decoded.orders);
    }
    REQUIRE(orders.size() == 4); // sync, motion, sync, motion
    const auto fast = parsons::test::run_orders(orders, profile);
    const auto slow = parsons::test::run_orders(orders, profile, nullptr, {},
                                                parsons::relaylogic::Pace::impulse_level);
    parsons::test::require_same(fast, slow);
    REQUIRE(fast.press);
    REQUIRE(fast.press->feeder_interlock);
    CHECK(fast.press->feeder_interlock->holds >= 1);
    CHECK(fast.press->feeder_interlock->holds == slow.press->feeder_interlock->holds);
    CHECK(fast.press->feeder_interlock->held_s == slow.press->feeder_interlock->held_s);
}

TEST_CASE("Fuzz replay: every kept command line leaves its inputs as they were, refuses an output "
          "that is an input or another output, and is never an internal error",
          "[fuzz][cli][never-lose]") {
    replay("cli");
}

TEST_CASE("Never lose a file: random command lines of every command that writes, their outputs "
          "named as inputs, as each other, through links, - and /dev/null: no input changes, "
          "every clash is refused, no temporary file stays (the cli target, a fixed sample)",
          "[fuzz][cli][never-lose]") {
    const parsons::fuzz::FuzzTarget* cli = parsons::fuzz::fuzz_target_named("cli");
    REQUIRE(cli != nullptr);
#ifdef PARSONS_SANITIZE
    constexpr int kLines = 150;
#else
    constexpr int kLines = 600;
#endif
    std::mt19937 rng(27);
    for (int i = 0; i < kLines; ++i) {
        std::vector<std::uint8_t> bytes(2 + rng() % 14);
        for (auto& b : bytes) {
            b = static_cast<std::uint8_t>(rng());
        }
        INFO("line " << i);
        CHECK_NOTHROW(cli->run({bytes.data(), bytes.size()}));
    }
}

TEST_CASE("Fuzz replay: every kept command line of hostile option values ends with exit 0, 2 or "
          "3, in its own scratch folder",
          "[fuzz][argv]") {
    replay("argv");
}

TEST_CASE("Command line: random command lines of every command's options, from the completion's "
          "definitions, with hostile values (NaN, infinities, hex, huge numbers, empty and long "
          "words, folders, missing files): exit 0, 2 or 3, never 1 or a signal (the argv target, "
          "a fixed sample)",
          "[fuzz][argv]") {
    const parsons::fuzz::FuzzTarget* argv = parsons::fuzz::fuzz_target_named("argv");
    REQUIRE(argv != nullptr);
    const char* lines_asked = std::getenv("PARSONS_ARGV_LINES");
#ifdef PARSONS_SANITIZE
    const int lines = lines_asked != nullptr ? std::atoi(lines_asked) : 60;
#else
    const int lines = lines_asked != nullptr ? std::atoi(lines_asked) : 300;
#endif
    std::mt19937 rng(53);
    for (int i = 0; i < lines; ++i) {
        std::vector<std::uint8_t> bytes(2 + rng() % 20);
        for (auto& b : bytes) {
            b = static_cast<std::uint8_t>(rng());
        }
        INFO("line " << i);
        CHECK_NOTHROW(argv->run({bytes.data(), bytes.size()}));
    }
}
