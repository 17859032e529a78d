// `parsons check` against `parsons run`, on random decks: check runs the deck on the emulator
// (cli/support/deck_prediction.hpp), so its verdict is run's, card for card. Each random deck of
// tests/random_decks.hpp (every profile reading, slip and the other faults, backlash and the rest
// of the measuring chain, condition, sync and tap cards, cards, five cards a step and tape) is
// written to a file with its profile, then checked and run as a user would type it: the exit
// codes, the stop card, its number, reason, axis and lamps must be the same.
#include "tests/random_decks.hpp"
#include "tests/test_support.hpp"

#include "axes/profile_json.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <map>
#include <random>

using namespace parsons;
using namespace parsons::test;
using nlohmann::json;

namespace {

std::string extension(cardreader::DeckFormat f) {
    switch (f) {
    case cardreader::DeckFormat::tape:
        return ".tape";
    case cardreader::DeckFormat::five:
        return ".five";
    default:
        return ".cbn";
    }
}

json read_json(const TempDir& dir, const std::string& name) {
    return json::parse(read_bytes(dir.path(name)));
}

} // namespace

TEST_CASE("Check: its verdict and stop are run's on 400 random decks, every profile reading, "
          "fault, measuring chain and medium",
          "[check][agreement][cli][heavy]") {
    std::mt19937 rng(29001);
    std::mt19937 crng(29002);
    std::mt19937 srng(29003);
    std::mt19937 trng(29004);
    TempDir dir;
    std::map<std::string, int> stops; // by reason: the decks must meet many kinds of stop
    int through = 0;
    int refused = 0;
    int with_faults = 0;
    int with_backlash = 0;
    std::map<std::string, int> media;
    const int decks = share_of_cases(400); // a quarter under the sanitizers (test_support.hpp)
    for (int n = 0; n < decks; ++n) {
        INFO("deck " << n);
        const Case c = random_case(rng, crng, srng, trng);
        const std::string deck = "deck" + extension(c.medium);
        write_bytes(dir.path(deck), deck_bytes(punched_cards(c), c.medium));
        write_bytes(dir.path("profile.json"), axes::profile_to_json(c.profile));
        std::string flags = " --profile " + q(dir.str("profile.json"));
        for (const auto& f : c.faults) {
            flags += " --fault " + q(f.spec);
        }
        ++media[extension(c.medium)];
        with_faults += c.faults.empty() ? 0 : 1;
        for (const auto& a : c.profile.axes) {
            if (a.backlash_in > 0) {
                ++with_backlash;
                break;
            }
        }
        const ProcessResult checked = run_shell("PARSONS check " + q(dir.str(deck)) + flags +
                                                " --json > " + q(dir.str("check.json")));
        const ProcessResult ran = run_shell("PARSONS run " + q(dir.str(deck)) + flags +
                                            " -q --report " + q(dir.str("report.json")));
        INFO("check: " << checked.output << "\nrun: " << ran.output);
        REQUIRE(checked.exit_code == ran.exit_code);
        if (ran.exit_code == 2) {
            ++refused; // run refuses the deck (a deck error): check says the same, exit 2
            continue;
        }
        REQUIRE((ran.exit_code == 0 || ran.exit_code == 3));
        const json verdict = read_json(dir, "check.json").at("verdict");
        const json report = read_json(dir, "report.json");
        REQUIRE(verdict.at("runs_through") == (report.at("status") == "completed"));
        REQUIRE(verdict.at("cards_run") == report.at("cards_read"));
        REQUIRE(verdict.at("machine_seconds") == report.at("machine_seconds"));
        if (ran.exit_code == 0) {
            ++through;
            REQUIRE(verdict.at("stop").is_null());
            continue;
        }
        const json& said = verdict.at("stop");
        const json& stop = report.at("stop");
        REQUIRE(said.at("card") == stop.at("card"));
        REQUIRE(said.at("number") == stop.at("card_number"));
        REQUIRE(said.at("reason") == stop.at("reason"));
        REQUIRE(said.at("axis") == stop.at("axis"));
        REQUIRE(said.at("message") == stop.at("message"));
        REQUIRE(said.at("lamps") == stop.at("lamps"));
        // The chain ends with the stop itself, and tells at least one relay event before it
        // whenever an axis ran on the stop's card.
        const json& chain = verdict.at("chain");
        REQUIRE(chain.size() >= 1);
        CHECK(chain.back().get<std::string>().find("the machine stopped: " +
                                                   stop.at("reason").get<std::string>()) == 0);
        ++stops[stop.at("reason").get<std::string>()];
    }
    INFO("through " << through << ", refused " << refused << ", stops " << stops.size());
    for (const auto& [reason, count] : stops) {
        INFO(reason << " " << count);
    }
    // The decks meet what the agreement is about: decks that run through, stops of many kinds,
    // faults, backlash and every medium (all 400 of them: a share is too few to say).
    if (!whole_share()) {
        return;
    }
    CHECK(through >= 60);
    CHECK(stops.size() >= 6);
    CHECK(stops["check_mismatch"] >= 10);
    CHECK(stops["sequence_stall"] >= 3);
    CHECK(with_faults >= 60);
    CHECK(with_backlash >= 30);
    CHECK(media.size() == 3);
}
