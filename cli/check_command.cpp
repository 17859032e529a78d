// parsons check DECK: what the machine will do with the deck, before it is run for real. The
// deck is run on the emulator itself (cli/support/deck_prediction.hpp: fast-forward, the
// profile, --limit, --feed and --fault that `parsons run` would use), so the verdict is the
// machine's: it runs the deck through, or it stops at card N for reason R with the lamps lit,
// and then the chain of relay events that led to the stop, told from the run's trace
// (outputs/report/machine_story.hpp). Nothing here decides what the machine does.
//
// Beside the verdict, each line says what it is: `observed`, something the run did that the
// deck's author should know (an equality at a number no field punches, a stop met on a speed
// that only slows the axis); `past a limit`, the program check of a later control (Mitsubishi's
// movement range, EP 0360190): every card whose own numbers take an axis past a soft limit or a
// limit switch, from the cards, counted from where the card before ordered it; `double punch`,
// a column the reader reads as two closed relays; `advice`, how the deck is written (a start
// speed that does not match its slow-downs, a slow-down not on the way), no prediction.
//
// Exit 0: the machine runs the deck through. Exit 3: it stops on it (docs/stop-codes.md). Exit
// 2: the deck or a flag cannot be read, or `run` would refuse the deck (a condition, sync or
// tap card's deck error). With --json, one document for scripts (docs/json-output.md).
#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/deck_prediction.hpp"
#include "cli/support/json_output.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/report/run_report.hpp"

#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/card_reader.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace parsons::cli {
namespace {

using namespace cardreader;

struct CheckFlags {
    PredictionRequest request;
    bool json = false;
};

// One line of the check, on one card: what kind of line it is, and what it says.
struct Finding {
    std::int64_t card = 0;
    int number = -1;
    std::string kind; // observed, limit, double_punch, advice
    std::optional<Axis> axis;
    std::string message;
    Json extra = Json::object(); // --json only: column, from_in, to_in, limit_in, limit_kind
};

std::string kind_label(const std::string& kind) {
    return kind == "limit" ? "past a limit" : kind == "double_punch" ? "double punch" : kind;
}

// The cards read one by one for what is on them: the reader's own sensing (a double punch),
// the program check of the movement range (EP 0360190) and the advice of the deck review.
class CardReading {
public:
    explicit CardReading(const axes::MachineProfile& profile)
        : profile_(profile), reviewer_(deck_reviewer(profile)) {}

    void card(const Card& card, const CardLayout& layout) {
        ++index_;
        const relaylogic::SensedCard sensed =
            relaylogic::sense_card(card, layout, profile_.refuse_double_punch);
        if (!sensed.decoded) {
            reviewer_.skip(); // the reader stops the machine on it: the run says so
            known_ = false;
            return;
        }
        const CardOrders& o = sensed.decoded.orders;
        for (int column : sensed.double_columns) {
            Finding f{index_, o.number, "double_punch", std::nullopt,
                      fmt::format("column {}: the reader closes two relays of the bank, as a "
                                  "1952 reader would (profile {}; parsons-safe refuses the card)",
                                  column, profile_.name)};
            f.extra["column"] = column;
            found.push_back(std::move(f));
        }
        for (ReviewNote& n : reviewer_.review(o)) {
            if (!n.deck_error) {
                found.push_back({index_, o.number, "advice", n.axis, std::move(n.message)});
            }
        }
        if (o.kind == CardKind::tap) {
            const TapOrder& t = o.tap;
            judge(o, t.axis, (t.motion == Motion::forward ? 1 : -1) * std::int64_t{t.depth}, true);
        } else if (o.kind == CardKind::motion) {
            for (Axis a : kAxes) {
                const AxisOrder& x = o.axis(a);
                judge(o, a, (x.motion == Motion::forward ? 1 : -1) * std::int64_t{x.check}, false);
            }
        }
    }
    std::int64_t cards() const { return index_; }
    std::vector<Finding> found;

private:
    // The axis moves `move` thousandths from where the cards have put it; a tap comes back.
    // Counted in thousandths, as the cards punch them: 0.500 - 0.400 ends on 0.100 exactly.
    void judge(const CardOrders& o, Axis a, std::int64_t move, bool returns) {
        const auto& p = profile_.axes.at(axis_index(a));
        std::int64_t& at = at_.at(axis_index(a));
        const double from = static_cast<double>(at) / 1000.0;
        const double to = static_cast<double>(at + move) / 1000.0;
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
        if (!past.empty() && known_) {
            Finding f{index_, o.number, "limit", a,
                      fmt::format("{} {} {:+.3f} in, from {:.3f} to {:.3f} in, past {}",
                                  axis_name(a), returns ? "taps" : "moves",
                                  static_cast<double>(move) / 1000.0, from, to, past)};
            f.extra["from_in"] = counter_reading(from);
            f.extra["to_in"] = counter_reading(to);
            f.extra["limit_in"] = counter_reading(limit);
            f.extra["limit_kind"] = limit_kind;
            found.push_back(std::move(f));
        }
        at = returns ? at : at + move;
    }

    const axes::MachineProfile& profile_;
    DeckReviewer reviewer_;
    std::array<std::int64_t, kAxisCount> at_{}; // thousandths from the reference zero
    std::int64_t index_ = 0;
    bool known_ = true; // false after a card the reader could not read: positions unknown
};

std::string lamps_text(const std::vector<std::string>& lamps) {
    std::string text;
    for (const std::string& l : lamps) {
        text += (text.empty() ? "" : ", ") + l;
    }
    return text.empty() ? "none" : text;
}

std::string verdict_text(const Prediction& p) {
    const relaylogic::RunResult& r = p.result;
    if (!r.stop) {
        return fmt::format("the machine runs the deck through: {} card{} in {:.3f} s of machine "
                           "time\n",
                           r.cards_read, r.cards_read == 1 ? "" : "s", r.machine_seconds);
    }
    const relaylogic::StopInfo& s = *r.stop;
    std::string text = fmt::format(
        "the machine stops at card {}{}{}: {}: {}\n  lamps lit: {}\n", s.card,
        s.card_number >= 0 ? fmt::format(" (number {:04})", s.card_number) : std::string(),
        s.axis ? fmt::format(", {}", axis_name(*s.axis)) : std::string(),
        relaylogic::stop_reason_name(s.reason), s.message, lamps_text(s.lamps));
    text += "  how it came to stop, from the run's relay events:\n";
    for (const std::string& line : p.chain) {
        text += "    " + line + "\n";
    }
    return text;
}

Json verdict_json(const Prediction& p) {
    const relaylogic::RunResult& r = p.result;
    Json v = {{"runs_through", !r.stop.has_value()},
              {"cards_run", r.cards_read},
              {"machine_seconds", time_s(r.machine_seconds)},
              {"stop", nullptr},
              {"chain", p.chain}};
    if (r.stop) {
        const relaylogic::StopInfo& s = *r.stop;
        v["stop"] = {{"card", s.card},
                     {"number", s.card_number >= 0 ? Json(s.card_number) : Json(nullptr)},
                     {"reason", std::string(relaylogic::stop_reason_name(s.reason))},
                     {"axis", s.axis ? Json(std::string(axis_name(*s.axis))) : Json(nullptr)},
                     {"message", s.message},
                     {"lamps", s.lamps}};
    }
    return v;
}

ExitCode run_check(const CheckFlags& f) {
    const PredictionRequest& rq = f.request;
    FilePlan plan;
    plan.read("DECK", rq.input);
    plan.read("--profile", AppliedProfile::file_read(rq.profile));
    plan.check();
    InputDeck deck(rq.input, rq.deck);
    const Prediction p = predict_deck(rq, deck);

    CardReading reading(p.profile);
    while (auto card = deck.cards().next()) {
        reading.card(*card, *deck.options().layout);
    }
    std::vector<Finding> found = reading.found;
    for (const StoryNote& n : p.notes) {
        found.push_back({n.card, n.number, "observed", n.axis, n.message});
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const Finding& a, const Finding& b) { return a.card < b.card; });
    std::map<std::string, std::int64_t> counts;
    for (const Finding& x : found) {
        ++counts[x.kind];
    }
    const bool stops = p.result.stop.has_value();
    if (!f.json) {
        for (const Finding& x : found) {
            fmt::print("card {} (number {:04}): {}: {}{}\n", x.card, x.number, kind_label(x.kind),
                       x.axis && x.kind != "limit" ? fmt::format("{}: ", axis_name(*x.axis)) : "",
                       x.message);
        }
        fmt::print("{}", verdict_text(p));
        fmt::print("{} card{} checked: {} move{} past a limit, {} machine stop, {} observed, {} "
                   "double punch{}, {} advice (profile {})\n",
                   reading.cards(), reading.cards() == 1 ? "" : "s", counts["limit"],
                   counts["limit"] == 1 ? "" : "s", stops ? 1 : 0, counts["observed"],
                   counts["double_punch"], counts["double_punch"] == 1 ? "" : "es",
                   counts["advice"], p.profile.name);
    } else {
        Json doc = json_document("check");
        doc["deck"] = rq.input;
        doc["format"] = p.format;
        doc["layout"] = p.layout;
        doc["profile"] = p.profile.name;
        doc["cards_checked"] = reading.cards();
        Json findings = Json::array();
        for (const Finding& x : found) {
            Json j = {{"card", x.card},
                      {"number", x.number >= 0 ? Json(x.number) : Json(nullptr)},
                      {"kind", x.kind},
                      {"axis", x.axis ? Json(std::string(axis_name(*x.axis))) : Json(nullptr)},
                      {"message", x.message}};
            j.update(x.extra);
            findings.push_back(std::move(j));
        }
        doc["findings"] = std::move(findings);
        doc["past_limit"] = counts["limit"];
        doc["observed"] = counts["observed"];
        doc["double_punches"] = counts["double_punch"];
        doc["advice"] = counts["advice"];
        doc["verdict"] = verdict_json(p);
        doc["will_run_through"] = !stops;
        print_json_document(doc);
    }
    return stops ? ExitCode::machine_stop : ExitCode::ok;
}

} // namespace

void add_check_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<CheckFlags>();
    PredictionRequest& rq = flags->request;
    CLI::App* cmd = app.add_subcommand(
        "check", "Before running: run the deck on the emulator and say whether the machine runs "
                 "it through or where it stops and why, from the relay events; with every card "
                 "past a limit and advice on the deck");
    cmd->add_option("DECK", rq.input, "The deck to check")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--profile", rq.profile, "Machine profile JSON (see 'parsons profile')")
        ->type_name(std::string(kProfileValue));
    cmd->add_option("--limit", rq.limits,
                    "Soft limits of the job, AXIS=MIN:MAX inches (e.g. table=0:9.5)")
        ->type_name("AXIS=MIN:MAX");
    cmd->add_option("--fault", rq.faults,
                    "Inject a fault, as 'parsons run --fault' does (repeatable; docs/faults.md)")
        ->type_name("FAULT");
    cmd->add_option("--feed", rq.feed,
                    "cards or ribbon, as 'parsons run --feed' (a tape deck always feeds as a "
                    "ribbon)")
        ->check(CLI::IsMember({"cards", "ribbon"}));
    add_json_flag(*cmd, flags->json);
    add_input_flags(*cmd, rq.deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the machine runs the deck through (advice may "
                                                "stand)"},
                                 {ExitCode::machine_stop,
                                  "the machine stops on the deck: the stop, its lamps and the "
                                  "relay events that led to it are printed (a condition, sync or "
                                  "tap card's deck error, which run refuses, is exit 2)"}}) +
                "Examples:\n"
                "  parsons check decks/samples/patent-example.csv --limit table=0:9.5\n"
                "  parsons check decks/samples/patent-example.csv --limit cross=0:2   (card 1 "
                "passes it: exit 3)\n"
                "  parsons check decks/samples/patent-example.csv --fault "
                "drop-impulse:table:120   (exit 3)\n"
                "  parsons check decks/samples/patent-example.csv --limit table=0:8.9 --json   "
                "(exit 3)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_check(*flags); }; });
}

} // namespace parsons::cli
