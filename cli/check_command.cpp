// parsons check DECK: the whole-program check a later control made before running a part
// program (Mitsubishi's movement range, seeds/001): every card whose move would take an axis
// past a soft limit (the profile's, or --limit) or past a limit switch, listed before anything
// runs; with the careful operator's warnings of `parsons show` (deck_review) beside them.
//
// The moves are the cards' own: each axis travels its check in the sense of its motion
// column, from where the last card left it (every axis starts the deck at zero). Coast and
// screw error are the run's business, not the check's.
//
// Exit 0: the deck will run through (warnings of risks may stand). Exit 3: the machine will
// stop on it: a card passes a limit, a bad punch, or a review finding marked STOP (a card
// number out of order, a check that is not the travel, a certain sequence stall, the coast of
// the card before). Exit 2: the deck or a flag cannot be read.
#include "cli/commands.hpp"

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
    DeckFlags deck;
};

ExitCode run_check(const CheckFlags& f) {
    axes::MachineProfile profile = load_profile(f.profile);
    apply_limits(profile, f.limits);
    InputDeck deck(f.input, f.deck);
    const CardLayout& layout = *deck.options().layout;
    DeckReviewer reviewer(review_dynamics(profile));
    std::array<double, kAxisCount> at{};
    long index = 0;
    long passing = 0;
    long warnings = 0;
    long stops = 0; // findings the machine will stop on
    long bad = 0;
    while (auto card = deck.cards().next()) {
        ++index;
        // The reader as the profile has it: parsons-1952 senses a double punch as two relays.
        const relaylogic::SensedCard sensed =
            relaylogic::sense_card(*card, layout, profile.refuse_double_punch);
        const DecodeResult& decoded = sensed.decoded;
        if (!decoded) {
            ++bad;
            fmt::print("card {}: BAD PUNCH: column {}: {} (the reader stops the machine here: "
                       "bad-punch refusal, an addition of this emulator)\n",
                       index, decoded.bad_punch->column, decoded.bad_punch->what);
            reviewer.skip();
            continue;
        }
        for (int column : sensed.double_columns) {
            ++warnings;
            fmt::print("card {}: warning: column {}: double punch: the reader closes two relays "
                       "of the bank, as a 1952 reader would (profile {}; parsons-safe refuses "
                       "the card)\n",
                       index, column, profile.name);
        }
        const CardOrders& o = decoded.orders;
        for (const ReviewNote& n : reviewer.review(o)) {
            ++(n.stops ? stops : warnings);
            fmt::print("card {} (number {:04}): {}: {}{}\n", index, o.number,
                       n.stops ? "STOP" : "warning",
                       n.axis ? fmt::format("{}: ", axis_name(*n.axis)) : "", n.message);
        }
        for (Axis a : kAxes) {
            const auto& p = profile.axes.at(axis_index(a));
            const AxisOrder& x = o.axis(a);
            double& pos = at.at(axis_index(a));
            const double move = (x.motion == Motion::forward ? 1 : -1) * x.check / 1000.0;
            const double to = pos + move;
            std::string past;
            if (p.soft_limits && (to > p.soft_max_in || to < p.soft_min_in)) {
                past = fmt::format("its soft limit {:.3f} in (movement range {:.3f} .. {:.3f} in)",
                                   to > p.soft_max_in ? p.soft_max_in : p.soft_min_in,
                                   p.soft_min_in, p.soft_max_in);
            } else if (to > p.travel_max_in || to < p.travel_min_in) {
                past = fmt::format("its limit switch at {:.3f} in",
                                   to > p.travel_max_in ? p.travel_max_in : p.travel_min_in);
            }
            if (!past.empty()) {
                ++passing;
                fmt::print("card {} (number {:04}): {} moves {:+.3f} in, from {:.3f} to {:.3f} in, "
                           "past {}\n",
                           index, o.number, axis_name(a), move, pos, to, past);
            }
            pos = to;
        }
    }
    fmt::print("{} card{} checked: {} move{} past a limit, {} with bad punches, {} other "
               "finding{} the machine stops on, {} warning{}\n",
               index, index == 1 ? "" : "s", passing, passing == 1 ? "" : "s", bad, stops,
               stops == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s");
    return passing > 0 || bad > 0 || stops > 0 ? ExitCode::machine_stop : ExitCode::ok;
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
    add_input_flags(*cmd, flags->deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck will run through (warnings of risks "
                                                "may stand)"},
                                 {ExitCode::machine_stop,
                                  "the machine will stop on the deck: a card passes a limit, a "
                                  "bad punch, or a finding marked STOP"}}) +
                "Examples:\n"
                "  parsons check deck.cbn --limit table=0:9.5\n"
                "  parsons check decks/samples/patent-example.csv --limit cross=0:2   (card 1 "
                "passes it: exit 3)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_check(*flags); }; });
}

} // namespace parsons::cli
