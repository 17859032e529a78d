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

// One check of a deck: what the cards have moved each axis to, and the findings so far, printed
// as they come (text) or gathered for --json.
class DeckCheck {
public:
    DeckCheck(const CheckFlags& f, const axes::MachineProfile& profile)
        : f_(f), profile_(profile), reviewer_(deck_reviewer(profile)), text_(!f.json) {}
    void card(const Card& card, const CardLayout& layout);
    void finish() {
        for (const ReviewNote& n : reviewer_.finish()) {
            deck_error(n, nullptr);
        }
    }
    ExitCode report(const InputDeck& deck, const CardLayout& layout);

private:
    void deck_error(const ReviewNote& n, const Json& number);
    void bad_punch(const DecodeResult& decoded);
    void double_punches(const relaylogic::SensedCard& sensed);
    void review(const CardOrders& o);
    void judge(const CardOrders& o, Axis a, double move, bool returns);
    bool runs_through() const {
        return passing_ == 0 && bad_ == 0 && stops_ == 0 && deck_errors_ == 0;
    }

    const CheckFlags& f_;
    const axes::MachineProfile& profile_;
    DeckReviewer reviewer_;
    const bool text_;
    std::array<double, kAxisCount> at_{};
    std::int64_t index_ = 0;
    std::int64_t passing_ = 0;
    std::int64_t warnings_ = 0;
    std::int64_t stops_ = 0; // findings the machine will stop on
    std::int64_t bad_ = 0;
    Json findings_ = Json::array();
    std::optional<std::string> first_deck_error_;
    std::int64_t deck_errors_ = 0;
};

// A condition, sync or tap card's deck error (additions): `run` refuses the deck, so check
// exits 2.
void DeckCheck::deck_error(const ReviewNote& n, const Json& number) {
    ++deck_errors_;
    first_deck_error_ = first_deck_error_.value_or(
        DeckError::at_card_column(f_.input, n.card, n.column, n.message).what());
    if (text_) {
        fmt::print("card {}: DECK ERROR: column {}: {}\n", n.card, n.column, n.message);
    }
    Json found = finding(n.card, number, "deck_error", n.axis, n.message);
    found["column"] = n.column;
    findings_.push_back(std::move(found));
}

void DeckCheck::card(const Card& card, const CardLayout& layout) {
    ++index_;
    // The reader as the profile has it: parsons-1952 senses a double punch as two relays.
    const relaylogic::SensedCard sensed =
        relaylogic::sense_card(card, layout, profile_.refuse_double_punch);
    const DecodeResult& decoded = sensed.decoded;
    if (!decoded) {
        bad_punch(decoded);
        return;
    }
    double_punches(sensed);
    const CardOrders& o = decoded.orders;
    review(o);
    if (o.kind == CardKind::tap) {
        const TapOrder& t = o.tap;
        judge(o, t.axis, (t.motion == Motion::forward ? 1 : -1) * t.depth / 1000.0, true);
        return;
    }
    for (Axis a : kAxes) {
        const AxisOrder& x = o.axis(a);
        judge(o, a, (x.motion == Motion::forward ? 1 : -1) * x.check / 1000.0, false);
    }
}

void DeckCheck::bad_punch(const DecodeResult& decoded) {
    ++bad_;
    const std::string message = fmt::format("column {}: {} (the reader stops the machine here: "
                                            "bad-punch refusal, an addition of this emulator)",
                                            decoded.bad_punch->column, decoded.bad_punch->what);
    if (text_) {
        fmt::print("card {}: BAD PUNCH: {}\n", index_, message);
    }
    Json found = finding(index_, nullptr, "bad_punch", std::nullopt, message);
    found["column"] = decoded.bad_punch->column;
    findings_.push_back(std::move(found));
    reviewer_.skip();
}

void DeckCheck::double_punches(const relaylogic::SensedCard& sensed) {
    for (int column : sensed.double_columns) {
        ++warnings_;
        const std::string message =
            fmt::format("column {}: double punch: the reader closes two relays of the bank, "
                        "as a 1952 reader would (profile {}; parsons-safe refuses the card)",
                        column, profile_.name);
        if (text_) {
            fmt::print("card {}: warning: {}\n", index_, message);
        }
        Json found =
            finding(index_, sensed.decoded.orders.number, "double_punch", std::nullopt, message);
        found["column"] = column;
        findings_.push_back(std::move(found));
    }
}

// The careful operator's warnings of `parsons show` (deck_review).
void DeckCheck::review(const CardOrders& o) {
    for (const ReviewNote& n : reviewer_.review(o)) {
        if (n.deck_error) {
            deck_error(n, n.card == index_ ? Json(o.number) : Json(nullptr));
            continue;
        }
        ++(n.stops ? stops_ : warnings_);
        if (text_) {
            fmt::print("card {} (number {:04}): {}: {}{}\n", index_, o.number,
                       n.stops ? "STOP" : "warning",
                       n.axis ? fmt::format("{}: ", axis_name(*n.axis)) : "", n.message);
        }
        findings_.push_back(
            finding(index_, o.number, n.stops ? "stop" : "warning", n.axis, n.message));
    }
}

// The axis moves `move` inches from where it stands; a tap comes back (`returns`).
void DeckCheck::judge(const CardOrders& o, Axis a, double move, bool returns) {
    const auto& p = profile_.axes.at(axis_index(a));
    double& pos = at_.at(axis_index(a));
    const double to = pos + move;
    std::string past;
    double limit = 0;
    const char* limit_kind = "";
    if (p.soft_limits && (to > p.soft_max_in || to < p.soft_min_in)) {
        limit = to > p.soft_max_in ? p.soft_max_in : p.soft_min_in;
        limit_kind = "soft_limit";
        past = fmt::format("its soft limit {:.3f} in (movement range {:.3f} .. {:.3f} in)", limit,
                           p.soft_min_in, p.soft_max_in);
    } else if (to > p.travel_max_in || to < p.travel_min_in) {
        limit = to > p.travel_max_in ? p.travel_max_in : p.travel_min_in;
        limit_kind = "limit_switch";
        past = fmt::format("its limit switch at {:.3f} in", limit);
    }
    if (!past.empty()) {
        ++passing_;
        const std::string message =
            fmt::format("{} {} {:+.3f} in, from {:.3f} to {:.3f} in, past {}", axis_name(a),
                        returns ? "taps" : "moves", move, pos, to, past);
        if (text_) {
            fmt::print("card {} (number {:04}): {}\n", index_, o.number, message);
        }
        Json found = finding(index_, o.number, "limit", a, message);
        found["from_in"] = rounded_inches(pos);
        found["to_in"] = rounded_inches(to);
        found["limit_in"] = rounded_inches(limit);
        found["limit_kind"] = limit_kind;
        findings_.push_back(std::move(found));
    }
    pos = returns ? pos : to;
}

// The totals (text) or the document (--json); the exit code.
ExitCode DeckCheck::report(const InputDeck& deck, const CardLayout& layout) {
    if (text_) {
        fmt::print("{} card{} checked: {} move{} past a limit, {} with bad punches, {} other "
                   "finding{} the machine stops on, {} warning{}\n",
                   index_, index_ == 1 ? "" : "s", passing_, passing_ == 1 ? "" : "s", bad_, stops_,
                   stops_ == 1 ? "" : "s", warnings_, warnings_ == 1 ? "" : "s");
        if (deck_errors_ > 0) {
            fmt::print("{} deck error{} in condition, sync or tap cards: run refuses the deck\n",
                       deck_errors_, deck_errors_ == 1 ? "" : "s");
        }
    } else {
        Json doc = json_document("check");
        doc["deck"] = f_.input;
        doc["format"] = std::string(format_name(deck.options().format));
        doc["layout"] = layout.name;
        doc["profile"] = profile_.name;
        doc["cards_checked"] = index_;
        doc["findings"] = std::move(findings_);
        doc["past_limit"] = passing_;
        doc["bad_punches"] = bad_;
        doc["stops"] = stops_;
        doc["warnings"] = warnings_;
        doc["deck_errors"] = deck_errors_;
        doc["will_run_through"] = runs_through();
        print_json_document(doc);
    }
    if (first_deck_error_) {
        throw DeckError(*first_deck_error_ +
                        (deck_errors_ > 1
                             ? fmt::format(" (and {} more deck errors)", deck_errors_ - 1)
                             : std::string{}));
    }
    return runs_through() ? ExitCode::ok : ExitCode::machine_stop;
}

ExitCode run_check(const CheckFlags& f) {
    axes::MachineProfile profile = load_profile(f.profile);
    apply_limits(profile, f.limits);
    InputDeck deck(f.input, f.deck);
    const CardLayout& layout = *deck.options().layout;
    DeckCheck check(f, profile);
    while (auto card = deck.cards().next()) {
        check.card(*card, layout);
    }
    check.finish();
    return check.report(deck, layout);
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
