// parsons show DECK [--svg DIR] [--json]: interpret every card field by field, as the operator
// reads the printed card, with warnings for what the machine will stop on; pictures of the
// cards. With --json the same, as one document for scripts (docs/json-output.md).
#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/deck_prediction.hpp"
#include "cli/support/json_output.hpp"
#include "cli/support/segment_show.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output_file.hpp"

#include "cardreader/card_svg.hpp"
#include "cardreader/condition_card.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/tap_card.hpp"
#include "relaylogic/card_reader.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace parsons::cli {
namespace {

using namespace parsons::cardreader;

struct ShowFlags {
    std::string input;
    std::string svg_dir;
    std::string profile;
    bool json = false;
    DeckFlags deck;
};

// The first and last columns of an axis's section of the card.
std::pair<int, int> axis_column_span(const CardLayout& layout, Axis a) {
    int first = kColumns;
    int last = 1;
    for (const LayoutField& f : layout.fields) {
        if (f.axis == a) {
            first = std::min(first, f.first_column);
            last = std::max(last, f.last_column());
        }
    }
    return {first, last};
}

std::string axis_columns(const CardLayout& layout, Axis a) {
    const auto [first, last] = axis_column_span(layout, a);
    return fmt::format("{}-{}", first, last);
}

std::string sequence_text(SequencePattern p) {
    std::string digits = format_sequence(p);
    std::string text;
    for (char c : digits) {
        text += text.empty() ? "" : ",";
        text += c;
    }
    return text.empty() ? "none" : text;
}

// A condition card (an addition after EP 0640901), one line per condition.
void print_condition_card(std::int64_t index, const CardOrders& o) {
    fmt::print("card {} · card number {:04} (columns 77-80) · CONDITION CARD (column 76 row 1; "
               "an addition after EP 0640901, Siemens)\n",
               index, o.number);
    fmt::print("  {:<5} {:<8} {:<6} {:<9} {:<9} {:<10} {:<16} {}\n", "cond.", "columns", "event",
               "axis", "sense", "position", "action", "parameter");
    for (int i = 0; i < o.condition_count; ++i) {
        const ConditionOrder& c = o.conditions.at(static_cast<std::size_t>(i));
        const int first = 1 + i * kConditionSlotColumns;
        const int mode = first + kConditionModeOffset;
        if (c.mode == ConditionMode::cancel) { // an addition beyond the seed's claims
            fmt::print("  {:<5} {:<8} {:<6} cancel (column {} row 2): ends every-condition {}\n",
                       i + 1, fmt::format("{}-{}", first, mode), c.event, mode, c.event);
            continue;
        }
        fmt::print("  {:<5} {:<8} {:<6} {:<9} {:<9} {:<10} {:<16} {}{}\n", i + 1,
                   fmt::format("{}-{}", first, c.mode == ConditionMode::every ? mode : first + 12),
                   c.event, axis_name(c.axis),
                   fmt::format("{} {}", sense_symbol(c.sense), sense_name(c.sense)),
                   format_inches(c.position), action_name(c.action),
                   parameter_text(c.action, c.parameter).empty()
                       ? std::string("-")
                       : parameter_text(c.action, c.parameter),
                   c.mode == ConditionMode::every
                       ? fmt::format(" · every (column {} row 1): armed for every motion card "
                                     "until cancelled",
                                     mode)
                       : std::string());
    }
}

Json condition_card_json(std::int64_t index, const CardOrders& o) {
    Json conditions = Json::array();
    for (int i = 0; i < o.condition_count; ++i) {
        const ConditionOrder& c = o.conditions.at(static_cast<std::size_t>(i));
        const int first = 1 + i * kConditionSlotColumns;
        const int mode = first + kConditionModeOffset;
        if (c.mode == ConditionMode::cancel) { // an addition beyond the seed's claims
            conditions.push_back({{"columns", {{"first", first}, {"last", mode}}},
                                  {"event", c.event},
                                  {"mode", "cancel"}});
            continue;
        }
        conditions.push_back(
            {{"columns",
              {{"first", first}, {"last", c.mode == ConditionMode::every ? mode : first + 12}}},
             {"event", c.event},
             {"axis", std::string(axis_name(c.axis))},
             {"sense", std::string(sense_name(c.sense))},
             {"position", inches_json(c.position)},
             {"action", std::string(action_name(c.action))},
             {"parameter", c.parameter}});
        if (c.mode != ConditionMode::once) { // an addition beyond the seed's claims
            conditions.back()["mode"] = std::string(mode_name(c.mode));
        }
    }
    return {{"index", index},
            {"number", o.number},
            {"kind", "condition"},
            {"conditions", conditions},
            {"warnings", Json::array()}};
}

// A sync card (an addition after EP 0436887), field by field: its columns, what is punched there
// and what it orders.
std::vector<std::array<std::string, 3>> sync_card_fields(const CardOrders& o,
                                                         const CardLayout& layout) {
    std::vector<std::array<std::string, 3>> rows;
    const SyncOrder& s = o.sync;
    for (const LayoutField& f : layout.sync_fields) {
        const std::string columns = f.width == 1
                                        ? std::to_string(f.first_column)
                                        : fmt::format("{}-{}", f.first_column, f.last_column());
        std::string value;
        switch (f.kind) {
        case FieldKind::position_sync:
            value = s.position_sync ? "G101: hold the motion card until the crank reaches the "
                                      "angle"
                                    : "";
            break;
        case FieldKind::sync_angle:
            value = s.position_sync
                        ? fmt::format("{} degrees from top dead centre (or from where a "
                                      "reset order cleared register 14)",
                                      s.angle_deg)
                        : "";
            break;
        case FieldKind::loop_mark:
            value = s.loop ? "M99: the reader goes back" : "";
            break;
        case FieldKind::loop_target:
            value = s.loop ? fmt::format("to card number {:04}", s.loop_to) : "";
            break;
        case FieldKind::loop_count:
            value =
                s.loop ? fmt::format("{} time{}", s.loop_count, s.loop_count == 1 ? "" : "s") : "";
            break;
        case FieldKind::register_reset:
            value = s.register_reset ? "16A: register 14 clears as the card is read (the "
                                       "reference the crank angle counts from)"
                                     : "";
            break;
        case FieldKind::travel_per_pulse:
            if (const auto& t = s.travel_per_pulse.at(axis_index(f.axis.value_or(Axis::table)))) {
                value = fmt::format("G95: {} in per detector pulse", format_travel_per_pulse(*t));
            }
            break;
        default:
            break;
        }
        rows.push_back({columns, field_label(f), value.empty() ? "-" : value});
    }
    return rows;
}

void print_sync_card(std::int64_t index, const CardOrders& o, const CardLayout& layout) {
    fmt::print("card {} · card number {:04} (columns 77-80) · SYNC CARD (column 76 row 2; an "
               "addition after EP 0436887, Mitsubishi)\n",
               index, o.number);
    fmt::print("  {:<8} {:<25} {}\n", "columns", "field", "punched");
    for (const auto& [columns, label, value] : sync_card_fields(o, layout)) {
        fmt::print("  {:<8} {:<25} {}\n", columns, label, value);
    }
}

Json sync_card_json(std::int64_t index, const CardOrders& o) {
    const SyncOrder& s = o.sync;
    Json speed = Json::object();
    for (Axis a : kAxes) {
        if (const auto& t = s.travel_per_pulse.at(axis_index(a))) {
            speed[std::string(axis_name(a))] = *t / 100000.0;
        }
    }
    return {{"index", index},
            {"number", o.number},
            {"kind", "sync"},
            {"position_sync", s.position_sync ? Json(s.angle_deg) : Json(nullptr)},
            {"speed_sync", speed},
            {"loop", s.loop ? Json{{"to", s.loop_to}, {"count", s.loop_count}} : Json(nullptr)},
            {"register_reset", s.register_reset},
            {"warnings", Json::array()}};
}

// A tap card (an addition after EP 0360190), field by field: its columns, what is punched there
// and what it orders.
std::vector<std::array<std::string, 3>> tap_card_fields(const CardOrders& o,
                                                        const CardLayout& layout) {
    std::vector<std::array<std::string, 3>> rows;
    const TapOrder& t = o.tap;
    for (const LayoutField& f : layout.tap_fields) {
        const std::string columns = f.width == 1
                                        ? std::to_string(f.first_column)
                                        : fmt::format("{}-{}", f.first_column, f.last_column());
        std::string value;
        switch (f.kind) {
        case FieldKind::tap_tool:
            value = fmt::format("T{:02}: PC 130 puts on the spindle head that holds it; memory "
                                "12a gets its gear ratio",
                                t.tool);
            break;
        case FieldKind::tap_axis:
            value = fmt::format("{}: the {} axis feeds in step with the tool",
                                axis_index(t.axis) + 1, axis_name(t.axis));
            break;
        case FieldKind::tap_sense:
            value = t.motion == Motion::forward
                        ? "row 0: forward into the work (its counters count up)"
                        : "row 1: reverse into the work (its counters count down)";
            break;
        case FieldKind::tap_depth:
            value = fmt::format("{} in into the work, and back out as the spindle reverses",
                                format_inches(t.depth));
            break;
        case FieldKind::tap_pitch:
            value = fmt::format("{} in per tool revolution", format_pitch(t.pitch));
            break;
        case FieldKind::tap_rpm:
            value = fmt::format("S {} rev/min of spindle motor 27", t.rpm);
            break;
        case FieldKind::tap_index:
            value = t.index_wait ? "1: the feed waits for encoder 32's index (an addition)"
                                 : "blank: the feed follows from the tool's first turn";
            break;
        case FieldKind::tap_retract:
            value = t.retract > 1
                        ? fmt::format("{}: out at {} x S = {} rev/min, the feed following (an "
                                      "addition)",
                                      t.retract, t.retract, t.retract * t.rpm)
                        : std::string("blank: out at S, as in");
            break;
        case FieldKind::tap_peck:
            value = tap_peck_text(t);
            break;
        default:
            break;
        }
        rows.push_back({columns, field_label(f), value});
    }
    return rows;
}

void print_tap_card(std::int64_t index, const CardOrders& o, const CardLayout& layout,
                    const axes::MachineProfile& profile) {
    fmt::print("card {} · card number {:04} (columns 77-80) · TAP CARD (column 76 row 3; an "
               "addition after EP 0360190, Mitsubishi)\n",
               index, o.number);
    fmt::print("  {:<8} {:<14} {}\n", "columns", "field", "punched");
    for (const auto& [columns, label, value] : tap_card_fields(o, layout)) {
        fmt::print("  {:<8} {:<14} {}\n", columns, label, value);
    }
    const TapOrder& t = o.tap;
    if (const axes::SpindleHead* head = profile.spindle.head(t.tool)) {
        fmt::print("  the tool turns S x A = {} x {:.4g} = {:.1f} rev/min (A: head {}'s gear ratio "
                   "in profile {}), so the {} axis feeds {} x {:.1f} = {:.2f} in/min\n",
                   t.rpm, head->ratio, t.rpm * head->ratio, t.tool, profile.name, axis_name(t.axis),
                   format_pitch(t.pitch), t.rpm * head->ratio,
                   SpindleLimits::feed_in_per_min(t.pitch, t.rpm, head->ratio));
    }
}

Json tap_card_json(std::int64_t index, const CardOrders& o) {
    const TapOrder& t = o.tap;
    Json j = {{"index", index},
              {"number", o.number},
              {"kind", "tap"},
              {"tool", t.tool},
              {"axis", std::string(axis_name(t.axis))},
              {"sense", t.motion == Motion::forward ? "forward" : "reverse"},
              {"depth", inches_json(t.depth)},
              {"pitch", t.pitch / 100000.0},
              {"rpm", t.rpm},
              {"index_wait", t.index_wait},
              {"retract", t.retract},
              {"warnings", Json::array()}};
    if (t.peck > 0) { // rigid peck tapping (an addition): columns 21-24, only when punched
        j["peck_in"] = inches_json(t.peck);
        j["pecks"] = tap_passes(t);
    }
    return j;
}

void print_card(std::int64_t index, const DecodeResult& decoded, const CardLayout& layout,
                const axes::MachineProfile& profile) {
    const CardOrders& o = decoded.orders;
    if (o.kind == CardKind::condition && decoded) {
        print_condition_card(index, o);
        return;
    }
    if (o.kind == CardKind::sync && decoded) {
        print_sync_card(index, o, layout);
        return;
    }
    if (o.kind == CardKind::tap && decoded) {
        print_tap_card(index, o, layout, profile);
        return;
    }
    if (o.kind == CardKind::segment && decoded) {
        print_segment_card(index, o, layout);
        return;
    }
    fmt::print("card {} · card number {:04} (columns 77-80) · spindle {} (column 1)\n", index,
               o.number, spindle_name(o.spindle));
    fmt::print("  {:<9} {:<8} {:<12} {:<6} {:<12} {:<12} {:<6} {:<6} {}\n", "axis", "columns",
               "motion", "speed", "slow-down 1", "slow-down 2", "stop", "check", "sequence");
    for (Axis a : kAxes) {
        const AxisOrder& ax = o.axis(a);
        auto slow = [&](std::size_t i) -> std::string {
            FieldKind kind = i == 0 ? FieldKind::slow_down_1 : FieldKind::slow_down_2;
            if (!layout.find(kind, a)) {
                return "(no field)";
            }
            const auto& v = ax.slow_down.at(i);
            return v ? format_inches(*v) : "-";
        };
        fmt::print("  {:<9} {:<8} {:<12} {:<6} {:<12} {:<12} {:<6} {:<6} {}\n", axis_name(a),
                   axis_columns(layout, a),
                   ax.motion == Motion::forward ? "+ forward" : "- reverse", ax.start_speed,
                   slow(0), slow(1), format_inches(ax.stop), format_inches(ax.check),
                   sequence_text(ax.sequence));
    }
}

// The card as print_card shows it, for --json. A slow-down the layout has no field for is
// null, as a blank one is; slow_down_fields says how many the layout gives the axis.
Json card_json(std::int64_t index, const CardOrders& o, const CardLayout& layout) {
    if (o.kind == CardKind::condition) {
        return condition_card_json(index, o);
    }
    if (o.kind == CardKind::sync) {
        return sync_card_json(index, o);
    }
    if (o.kind == CardKind::tap) {
        return tap_card_json(index, o);
    }
    if (o.kind == CardKind::segment) {
        return segment_card_json(index, o);
    }
    Json axes = Json::object();
    for (Axis a : kAxes) {
        const AxisOrder& ax = o.axis(a);
        Json sequence = Json::array();
        for (int k = 1; k <= kSequencePositions; ++k) {
            if ((ax.sequence & (1U << (k - 1))) != 0) {
                sequence.push_back(k);
            }
        }
        const auto [first, last] = axis_column_span(layout, a);
        const int slow_fields = (layout.find(FieldKind::slow_down_1, a) ? 1 : 0) +
                                (layout.find(FieldKind::slow_down_2, a) ? 1 : 0);
        axes[std::string(axis_name(a))] = {{"columns", {{"first", first}, {"last", last}}},
                                           {"motion", ax.motion == Motion::forward ? "+" : "-"},
                                           {"speed", ax.start_speed},
                                           {"slow_down_fields", slow_fields},
                                           {"slow_down_1", inches_json(ax.slow_down.at(0))},
                                           {"slow_down_2", inches_json(ax.slow_down.at(1))},
                                           {"stop", inches_json(ax.stop)},
                                           {"check", inches_json(ax.check)},
                                           {"sequence", sequence}};
    }
    return {{"index", index},
            {"number", o.number},
            {"spindle", std::string(spindle_name(o.spindle))},
            {"axes", axes},
            {"warnings", Json::array()}};
}

// The names show --svg writes: card-0001.svg, ... card-10000.svg.
bool card_picture_name(const std::string& name) {
    const std::string head = "card-";
    const std::string tail = ".svg";
    if (name.size() < head.size() + 4 + tail.size() || name.rfind(head, 0) != 0 ||
        name.compare(name.size() - tail.size(), tail.size(), tail) != 0) {
        return false;
    }
    const std::string digits = name.substr(head.size(), name.size() - head.size() - tail.size());
    return digits.find_first_not_of("0123456789") == std::string::npos;
}

// One showing of a deck, card by card: each card as the profile's reader senses it, its notes
// (advice, double punches, what the run observed) and the run's stop where it comes, printed as
// they come (text) or gathered for --json; deck errors and bad punches refused at the end.
class DeckShow {
public:
    DeckShow(const ShowFlags& f, const axes::MachineProfile& profile, const CardLayout& layout,
             std::optional<Prediction> run)
        : f_(f), profile_(profile), layout_(layout), reviewer_(deck_reviewer(profile)),
          run_(std::move(run)), text_(!f.json) {
        if (run_) {
            for (const StoryNote& n : run_->notes) {
                observed_.emplace(n.card, &n);
            }
            stop_ = run_->result.stop ? &*run_->result.stop : nullptr;
        }
    }

    // Shows one card; returns its document entry.
    Json card(const Card& card) {
        ++index_;
        // The reader as the profile has it: parsons-1952 senses a double punch as two relays.
        const relaylogic::SensedCard sensed =
            relaylogic::sense_card(card, layout_, profile_.refuse_double_punch);
        const DecodeResult& decoded = sensed.decoded;
        last_ = decoded;
        if (text_) {
            print_card(index_, decoded, layout_, profile_);
        }
        // A card with a bad punch is given by its index and the punch alone: its other
        // fields were not all read.
        Json doc = decoded ? card_json(index_, decoded.orders, layout_)
                           : Json{{"index", index_},
                                  {"bad_punch",
                                   {{"column", decoded.bad_punch->column},
                                    {"what", decoded.bad_punch->what}}}};
        if (decoded) {
            review(sensed, doc);
        } else {
            bad_punch(decoded);
        }
        const auto [first, last] = observed_.equal_range(index_);
        for (auto it = first; it != last; ++it) {
            note(doc, "observed in the run", it->second->axis, it->second->message);
        }
        show_stop(doc);
        if (text_) {
            fmt::print("\n");
        }
        return doc;
    }

    // After the last card: a condition or sync card with no motion card after it.
    void finish(Json& cards) {
        for (const ReviewNote& n : reviewer_.finish()) {
            deck_error(n);
            if (!cards.empty()) {
                cards.back()["deck_errors"].push_back(
                    {{"card", n.card}, {"column", n.column}, {"message", n.message}});
            }
        }
    }

    void summary(Json& doc) const {
        if (text_) {
            fmt::print("{} card{} read, {} note{}, {} with bad punches; {}\n", index_,
                       index_ == 1 ? "" : "s", notes_, notes_ == 1 ? "" : "s", bad_cards_,
                       !run_   ? std::string("run refuses the deck")
                       : stop_ ? fmt::format("the machine stops at card {} ('parsons check' "
                                             "tells why)",
                                             stop_->card)
                               : std::string("the machine runs it through"));
            return;
        }
        doc["cards_read"] = index_;
        doc["warning_count"] = notes_;
        doc["runs_through"] = run_ ? Json(stop_ == nullptr) : Json(nullptr);
        doc["bad_punch_cards"] = bad_cards_;
    }

    std::int64_t cards() const { return index_; }
    // The last card shown, as the reader decoded it.
    const DecodeResult& last() const { return last_; }

    // A deck run refuses (a deck error, as run refuses it before any axis moves): refused as a
    // DeckError (exit 2), after the deck is shown. A bad punch is not refused: the reader stops
    // the machine on it, a machine stop like any other, which show tells (the card's BAD PUNCH
    // line, the summary's stop) and `check` judges (exit 3; docs/stop-codes.md).
    void refuse() const {
        if (first_deck_error_) {
            throw DeckError(*first_deck_error_ +
                            (deck_errors_ > 1
                                 ? fmt::format(" (and {} more deck errors)", deck_errors_ - 1)
                                 : std::string{}));
        }
    }

private:
    void review(const relaylogic::SensedCard& sensed, Json& doc) {
        for (int column : sensed.double_columns) {
            note(doc, "double punch", std::nullopt,
                 fmt::format("column {}: the reader closes two relays of the bank, as a 1952 "
                             "reader would (profile {}; parsons-safe refuses the card)",
                             column, profile_.name));
        }
        for (const ReviewNote& n : reviewer_.review(sensed.decoded.orders)) {
            if (n.deck_error) {
                deck_error(n);
                doc["deck_errors"].push_back(
                    {{"card", n.card}, {"column", n.column}, {"message", n.message}});
                continue;
            }
            note(doc, "advice", n.axis, n.message);
        }
    }

    void bad_punch(const DecodeResult& decoded) {
        ++bad_cards_;
        if (text_) {
            fmt::print("  BAD PUNCH: column {}: {} (the reader stops the machine here)\n",
                       decoded.bad_punch->column, decoded.bad_punch->what);
        }
        reviewer_.skip();
    }

    // The run's stop, on the card it comes on.
    void show_stop(Json& doc) const {
        if (stop_ == nullptr) {
            return;
        }
        if (stop_->card == index_) {
            if (text_) {
                fmt::print("  the machine stops here: {}: {}\n",
                           relaylogic::stop_reason_name(stop_->reason), stop_->message);
            }
            doc["stop"] = {
                {"reason", std::string(relaylogic::stop_reason_name(stop_->reason))},
                {"axis", stop_->axis ? Json(std::string(axis_name(*stop_->axis))) : Json(nullptr)},
                {"message", stop_->message},
                {"lamps", stop_->lamps}};
        } else if (text_ && index_ == stop_->card + 1) {
            fmt::print("  (the machine stops at card {} and reads no card after it)\n",
                       stop_->card);
        }
    }

    // A condition, sync or tap card's deck error (additions): printed where it is found,
    // refused at the end.
    void deck_error(const ReviewNote& n) {
        ++deck_errors_;
        const std::string where =
            DeckError::at_card_column(f_.input, n.card, n.column, n.message).what();
        first_deck_error_ = first_deck_error_.value_or(where);
        if (text_) {
            fmt::print("  DECK ERROR: card {}, column {}: {}\n", n.card, n.column, n.message);
        }
    }

    void note(Json& doc, const char* kind, std::optional<Axis> axis, const std::string& message) {
        ++notes_;
        if (text_) {
            fmt::print("  {}: {}{}\n", kind, axis ? fmt::format("{}: ", axis_name(*axis)) : "",
                       message);
        }
        doc["warnings"].push_back(
            {{"card", index_},
             {"axis", axis ? Json(std::string(axis_name(*axis))) : Json(nullptr)},
             {"message", message},
             {"kind", kind}});
    }

    const ShowFlags& f_;
    const axes::MachineProfile& profile_;
    const CardLayout& layout_;
    DeckReviewer reviewer_;
    std::optional<Prediction> run_;
    std::multimap<std::int64_t, const StoryNote*> observed_;
    const relaylogic::StopInfo* stop_ = nullptr;
    const bool text_;
    std::int64_t index_ = 0;
    std::int64_t notes_ = 0;
    std::optional<std::string> first_deck_error_;
    std::int64_t deck_errors_ = 0;
    std::int64_t bad_cards_ = 0;
    DecodeResult last_;
};

// --svg: the card's picture, DIR/card-0001.svg, captioned with what the reader read.
void write_card_picture(const ShowFlags& f, const InputDeck& deck, const Card& card,
                        const DecodeResult& decoded, std::int64_t index) {
    const CardLayout& layout = *deck.options().layout;
    CardPictureNotes pic;
    const CardKind kind = decoded ? decoded.orders.kind : CardKind::motion;
    pic.caption =
        fmt::format("{} · card {} · card number {:04} · layout {}{}",
                    std::filesystem::path(f.input).filename().string(), index,
                    decoded.orders.number, layout.name,
                    kind == CardKind::condition ? " · condition card (an addition after EP 0640901)"
                    : kind == CardKind::sync    ? " · sync card (an addition after EP 0436887)"
                    : kind == CardKind::tap     ? " · tap card (an addition after EP 0360190)"
                    : kind == CardKind::segment ? " · segment card (an addition after EP 0636958)"
                                                : "");
    pic.bad_punch = decoded.bad_punch;
    write_file(file_in_folder(f.svg_dir, fmt::format("card-{:04}.svg", index)),
               card_svg(card, layout, pic, deck.options().code));
}

// What the machine does with the deck comes from running it (cli/support/deck_prediction.hpp),
// as `check` runs it; a deck `run` refuses has no run, and is shown, then refused.
std::optional<Prediction> run_for_show(const ShowFlags& f, InputDeck& deck) {
    try {
        return predict_deck({f.input, f.deck, f.profile, {}, {}, ""}, deck);
    } catch (const DeckError&) {
        deck.rewind();
        return std::nullopt;
    }
}

ExitCode run_show(const ShowFlags& f) {
    FilePlan plan;
    plan.read("DECK", f.input);
    plan.read("--profile", AppliedProfile::file_read(f.profile));
    plan.write_folder("--svg", f.svg_dir, card_picture_name);
    plan.check();
    const axes::MachineProfile profile = load_profile(f.profile);
    InputDeck deck(f.input, f.deck);
    const CardLayout& layout = *deck.options().layout;
    if (!f.svg_dir.empty()) {
        make_folder(f.svg_dir);
    }
    Json doc = json_document("show");
    if (!f.json) {
        fmt::print("deck {} ({}, layout {})\n\n", f.input, format_name(deck.options().format),
                   layout.name);
    }
    doc["deck"] = f.input;
    doc["format"] = std::string(format_name(deck.options().format));
    doc["layout"] = layout.name;
    DeckShow show(f, profile, layout, run_for_show(f, deck));
    Json cards = Json::array();
    while (auto card = deck.cards().next()) {
        Json card_doc = show.card(*card);
        if (!f.svg_dir.empty()) {
            write_card_picture(f, deck, *card, show.last(), show.cards());
        }
        cards.push_back(std::move(card_doc));
    }
    show.finish(cards);
    show.summary(doc);
    if (f.json) {
        doc["cards"] = std::move(cards);
        doc["svg_dir"] = f.svg_dir.empty() ? Json(nullptr) : Json(f.svg_dir);
        // A deck with deck errors is still shown whole, then refused (exit 2), as the text is.
        print_json_document(doc);
    } else if (!f.svg_dir.empty()) {
        fmt::print("card pictures: {} .. card-{:04}.svg\n",
                   (std::filesystem::path(f.svg_dir) / "card-0001.svg").string(), show.cards());
    }
    show.refuse();
    return ExitCode::ok;
}

} // namespace

void add_show_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<ShowFlags>();
    CLI::App* cmd = app.add_subcommand(
        "show", "Interpret each card field by field, with warnings; optionally draw the cards");
    cmd->add_option("DECK", flags->input, "The deck to read")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--svg", flags->svg_dir,
                    "Write one picture per card, DIR/card-0001.svg, ... (created if missing)")
        ->type_name(std::string(kDirValue));
    cmd->add_option("--profile", flags->profile,
                    "Machine profile (a built-in name or a JSON file; see 'parsons profile'): the "
                    "cards are sensed and the deck run as under it, for the notes and the stop")
        ->type_name(std::string(kProfileValue));
    add_json_flag(*cmd, flags->json);
    add_input_flags(*cmd, flags->deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was shown (its warnings, its bad "
                                                "punches and the machine's stop do not change "
                                                "the code; 'parsons check' judges)"}}) +
                "Examples:\n"
                "  parsons show decks/samples/patent-example.csv\n"
                "  parsons show decks/samples/patent-example.csv --svg cards\n"
                "  parsons show decks/samples/patent-example.csv --json");
    cmd->callback([&selected, flags] { selected = [flags] { return run_show(*flags); }; });
}

} // namespace parsons::cli
