// parsons check DECK: the whole-program check a later control made before running a part
// program (Mitsubishi's movement range, EP 0360190): every card whose move would take an axis
// past a soft limit (the profile's, or --limit) or past a limit switch, listed before anything
// runs; with the careful operator's warnings of `parsons show` (deck_review) beside them.
//
// The moves are the cards' own: each axis travels its check in the sense of its motion
// column, from where the last card left it (every axis starts the deck at zero); a tap card
// (an addition after EP 0360190) takes its feed axis its depth into the work and back. Coast
// and screw error are the run's business, not the check's.
//
// Exit 0: the deck will run through (warnings of risks may stand). Exit 3: the machine will
// stop on it: a card passes a limit, a bad punch, or a review finding marked STOP (a card
// number out of order, a check that is not the travel, a certain sequence stall, the coast of
// the card before). Exit 2: the deck or a flag cannot be read.
//
// With --json the findings are one document for scripts instead (docs/json-output.md).
#include "cli/commands.hpp"
#include "cli/support/json_output.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/card_reader.hpp"

#include <fmt/format.h>

namespace parsons::cli {
namespace {

using namespace cardreader;

struct CheckFlags {
    std::string input;
    std::string profile;
    std::vector<std::string> limits;
    bool json = false;
    DeckFlags deck;
};

// One finding for --json: what the text line says, with its kind and the card it is on.
Json finding(std::int64_t card, const Json& number, std::string_view kind, std::optional<Axis> axis,
             const std::string& message) {
    return {{"card", card},
            {"number", number},
            {"kind", std::string(kind)},
            {"axis", axis ? Json(std::string(axis_name(*axis))) : Json(nullptr)},
            {"message", message}};
}

ExitCode run_check(const CheckFlags& f) {
    axes::MachineProfile profile = load_profile(f.profile);
    apply_limits(profile, f.limits);
    InputDeck deck(f.input, f.deck);
    const CardLayout& layout = *deck.options().layout;
    DeckReviewer reviewer = deck_reviewer(profile);
    std::array<double, kAxisCount> at{};
    std::int64_t index = 0;
    std::int64_t passing = 0;
    std::int64_t warnings = 0;
    std::int64_t stops = 0; // findings the machine will stop on
    std::int64_t bad = 0;
    const bool text = !f.json;
    Json findings = Json::array();
    std::optional<std::string> first_deck_error;
    std::int64_t deck_errors = 0;
    // A condition, sync or tap card's deck error (additions): `run` refuses the deck, so check
    // exits 2.
    auto deck_error = [&](const ReviewNote& n, const Json& number) {
        ++deck_errors;
        first_deck_error = first_deck_error.value_or(
            DeckError::at_card_column(f.input, n.card, n.column, n.message).what());
        if (text) {
            fmt::print("card {}: DECK ERROR: column {}: {}\n", n.card, n.column, n.message);
        }
        Json found = finding(n.card, number, "deck_error", n.axis, n.message);
        found["column"] = n.column;
        findings.push_back(std::move(found));
    };
    while (auto card = deck.cards().next()) {
        ++index;
        // The reader as the profile has it: parsons-1952 senses a double punch as two relays.
        const relaylogic::SensedCard sensed =
            relaylogic::sense_card(*card, layout, profile.refuse_double_punch);
        const DecodeResult& decoded = sensed.decoded;
        if (!decoded) {
            ++bad;
            const std::string message =
                fmt::format("column {}: {} (the reader stops the machine here: bad-punch "
                            "refusal, an addition of this emulator)",
                            decoded.bad_punch->column, decoded.bad_punch->what);
            if (text) {
                fmt::print("card {}: BAD PUNCH: {}\n", index, message);
            }
            Json found = finding(index, nullptr, "bad_punch", std::nullopt, message);
            found["column"] = decoded.bad_punch->column;
            findings.push_back(std::move(found));
            reviewer.skip();
            continue;
        }
        for (int column : sensed.double_columns) {
            ++warnings;
            const std::string message =
                fmt::format("column {}: double punch: the reader closes two relays of the bank, "
                            "as a 1952 reader would (profile {}; parsons-safe refuses the card)",
                            column, profile.name);
            if (text) {
                fmt::print("card {}: warning: {}\n", index, message);
            }
            Json found =
                finding(index, decoded.orders.number, "double_punch", std::nullopt, message);
            found["column"] = column;
            findings.push_back(std::move(found));
        }
        const CardOrders& o = decoded.orders;
        for (const ReviewNote& n : reviewer.review(o)) {
            if (n.deck_error) {
                deck_error(n, n.card == index ? Json(o.number) : Json(nullptr));
                continue;
            }
            ++(n.stops ? stops : warnings);
            if (text) {
                fmt::print("card {} (number {:04}): {}: {}{}\n", index, o.number,
                           n.stops ? "STOP" : "warning",
                           n.axis ? fmt::format("{}: ", axis_name(*n.axis)) : "", n.message);
            }
            findings.push_back(
                finding(index, o.number, n.stops ? "stop" : "warning", n.axis, n.message));
        }
        // The axis moves `move` inches from where it stands; a tap comes back (`returns`).
        auto judge = [&](Axis a, double move, bool returns) {
            const auto& p = profile.axes.at(axis_index(a));
            double& pos = at.at(axis_index(a));
            const double to = pos + move;
            std::string past;
            double limit = 0;
            const char* limit_kind = "";
            if (p.soft_limits && (to > p.soft_max_in || to < p.soft_min_in)) {
                limit = to > p.soft_max_in ? p.soft_max_in : p.soft_min_in;
                limit_kind = "soft_limit";
                past = fmt::format("its soft limit {:.3f} in (movement range {:.3f} .. {:.3f} in)",
                                   limit, p.soft_min_in, p.soft_max_in);
            } else if (to > p.travel_max_in || to < p.travel_min_in) {
                limit = to > p.travel_max_in ? p.travel_max_in : p.travel_min_in;
                limit_kind = "limit_switch";
                past = fmt::format("its limit switch at {:.3f} in", limit);
            }
            if (!past.empty()) {
                ++passing;
                const std::string message =
                    fmt::format("{} {} {:+.3f} in, from {:.3f} to {:.3f} in, past {}", axis_name(a),
                                returns ? "taps" : "moves", move, pos, to, past);
                if (text) {
                    fmt::print("card {} (number {:04}): {}\n", index, o.number, message);
                }
                Json found = finding(index, o.number, "limit", a, message);
                found["from_in"] = rounded_inches(pos);
                found["to_in"] = rounded_inches(to);
                found["limit_in"] = rounded_inches(limit);
                found["limit_kind"] = limit_kind;
                findings.push_back(std::move(found));
            }
            pos = returns ? pos : to;
        };
        if (o.kind == CardKind::tap) {
            const TapOrder& t = o.tap;
            judge(t.axis, (t.motion == Motion::forward ? 1 : -1) * t.depth / 1000.0, true);
            continue;
        }
        for (Axis a : kAxes) {
            const AxisOrder& x = o.axis(a);
            judge(a, (x.motion == Motion::forward ? 1 : -1) * x.check / 1000.0, false);
        }
    }
    for (const ReviewNote& n : reviewer.finish()) {
        deck_error(n, nullptr);
    }
    const bool runs_through = passing == 0 && bad == 0 && stops == 0 && deck_errors == 0;
    if (text) {
        fmt::print("{} card{} checked: {} move{} past a limit, {} with bad punches, {} other "
                   "finding{} the machine stops on, {} warning{}\n",
                   index, index == 1 ? "" : "s", passing, passing == 1 ? "" : "s", bad, stops,
                   stops == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s");
        if (deck_errors > 0) {
            fmt::print("{} deck error{} in condition, sync or tap cards: run refuses the deck\n",
                       deck_errors, deck_errors == 1 ? "" : "s");
        }
    } else {
        Json doc = json_document("check");
        doc["deck"] = f.input;
        doc["format"] = std::string(format_name(deck.options().format));
        doc["layout"] = layout.name;
        doc["profile"] = profile.name;
        doc["cards_checked"] = index;
        doc["findings"] = std::move(findings);
        doc["past_limit"] = passing;
        doc["bad_punches"] = bad;
        doc["stops"] = stops;
        doc["warnings"] = warnings;
        doc["deck_errors"] = deck_errors;
        doc["will_run_through"] = runs_through;
        print_json_document(doc);
    }
    if (first_deck_error) {
        throw DeckError(*first_deck_error +
                        (deck_errors > 1
                             ? fmt::format(" (and {} more deck errors)", deck_errors - 1)
                             : std::string{}));
    }
    return runs_through ? ExitCode::ok : ExitCode::machine_stop;
}

} // namespace

void add_check_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<CheckFlags>();
    CLI::App* cmd = app.add_subcommand(
        "check", "Before running: list every card whose move would pass a soft limit or a "
                 "limit switch, with the deck's warnings");
    cmd->add_option("DECK", flags->input, "The deck to check")->required();
    cmd->add_option("--profile", flags->profile, "Machine profile JSON (see 'parsons profile')");
    cmd->add_option("--limit", flags->limits,
                    "Soft limits of the job, AXIS=MIN:MAX inches (e.g. table=0:9.5)");
    add_json_flag(*cmd, flags->json);
    add_input_flags(*cmd, flags->deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck will run through (warnings of risks "
                                                "may stand)"},
                                 {ExitCode::machine_stop,
                                  "the machine will stop on the deck: a card passes a limit, a "
                                  "bad punch, or a finding marked STOP (a condition, sync or tap "
                                  "card's deck error, which run refuses, is exit 2)"}}) +
                "Examples:\n"
                "  parsons check decks/samples/patent-example.csv --limit table=0:9.5\n"
                "  parsons check decks/samples/patent-example.csv --limit cross=0:2   (card 1 "
                "passes it: exit 3)\n"
                "  parsons check decks/samples/patent-example.csv --limit table=0:8.9 --json   "
                "(exit 3)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_check(*flags); }; });
}

} // namespace parsons::cli
