#include "cardreader/listing_format.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/listing_fields.hpp"
#include "cardreader/segment_listing.hpp"
#include "cardreader/sync_listing.hpp"
#include "cardreader/tap_listing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <istream>
#include <ostream>
#include <vector>

namespace parsons::cardreader {
namespace {

constexpr std::size_t kFieldCount = 10;
constexpr std::size_t kMaxLineBytes = 4096;

using detail::all_digits;
using detail::parse_inches;
using detail::split_fields;
using detail::trim;

} // namespace

Thousandths detail::parse_inches(std::string_view text, std::string_view field,
                                 const std::string& file, std::int64_t line) {
    auto fail = [&](const std::string& why) {
        return DeckError::at_line(file, line, fmt::format("{} '{}': {}", field, text, why));
    };
    if (!text.empty() && text.front() == '-') {
        throw fail("inches are never negative (the motion column gives the direction)");
    }
    const auto dot = text.find('.');
    const std::string_view whole = text.substr(0, dot);
    const std::string_view decimals =
        dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
    if (!all_digits(whole) || (!decimals.empty() && !all_digits(decimals))) {
        throw fail("not a number of inches (write d.ddd, e.g. 8.785)");
    }
    if (decimals.size() != 3) {
        throw fail("needs exactly three decimals, d.ddd (the card holds thousandths)");
    }
    const auto nonzero = whole.find_first_not_of('0');
    const std::string_view significant =
        nonzero == std::string_view::npos ? std::string_view{} : whole.substr(nonzero);
    if (significant.size() > 1) {
        throw fail("over 9.999 inches (the four-digit counters and storage banks hold "
                   "0.000 .. 9.999)");
    }
    int value = significant.empty() ? 0 : (significant.front() - '0') * 1000;
    value += (decimals[0] - '0') * 100 + (decimals[1] - '0') * 10 + (decimals[2] - '0');
    return static_cast<Thousandths>(value);
}

namespace {

struct ListingRow {
    int card = 0;
    Spindle spindle = Spindle::off;
    Axis axis = Axis::table;
    AxisOrder order;
};

ListingRow parse_row(std::string_view text, const std::string& file, std::int64_t line) {
    auto fields = split_fields(text);
    if (fields.size() != kFieldCount) {
        throw DeckError::at_line(file, line,
                                 fmt::format("expected 10 comma-separated fields ({}), found {}",
                                             kListingHeader, fields.size()));
    }
    auto fail = [&](const std::string& why) { return DeckError::at_line(file, line, why); };
    ListingRow row;
    if (!all_digits(fields[0]) || fields[0].size() > 4) {
        throw fail(fmt::format("card number '{}' is not 0..9999", fields[0]));
    }
    row.card = std::stoi(std::string(fields[0]));

    if (fields[1].empty()) {
        row.spindle = Spindle::off;
    } else if (fields[1] == "0") {
        row.spindle = Spindle::forward;
    } else if (fields[1] == "1") {
        row.spindle = Spindle::reverse;
    } else {
        throw fail(
            fmt::format("spindle '{}' is not 0 (forward), 1 (reverse) or blank (off)", fields[1]));
    }

    auto axis = axis_named(fields[2]);
    if (!axis) {
        throw fail(
            fmt::format("unknown axis '{}' (table, cross, vertical, swivel or tilt)", fields[2]));
    }
    row.axis = *axis;

    if (fields[3] == "+") {
        row.order.motion = Motion::forward;
    } else if (fields[3] == "-") {
        row.order.motion = Motion::reverse;
    } else {
        throw fail(fmt::format("motion '{}' is not + (forward) or - (reverse)", fields[3]));
    }

    if (fields[4] != "1" && fields[4] != "2" && fields[4] != "3") {
        throw fail(fmt::format("speed '{}' is not 1, 2 or 3", fields[4]));
    }
    row.order.start_speed = fields[4][0] - '0';

    for (std::size_t i = 0; i < 2; ++i) {
        if (!fields[5 + i].empty()) {
            row.order.slow_down.at(i) =
                parse_inches(fields[5 + i], i == 0 ? "slow1" : "slow2", file, line);
        }
    }
    if (fields[7].empty()) {
        throw fail("stop is blank (stop and check are always punched)");
    }
    row.order.stop = parse_inches(fields[7], "stop", file, line);
    if (fields[8].empty()) {
        throw fail("check is blank (stop and check are always punched)");
    }
    row.order.check = parse_inches(fields[8], "check", file, line);

    for (char c : fields[9]) {
        if (c < '1' || c > '5') {
            throw fail(fmt::format("sequence position '{}' is not 1..5", c));
        }
        const auto bit = static_cast<SequencePattern>(1u << (c - '1'));
        if ((row.order.sequence & bit) != 0) {
            throw fail(fmt::format("sequence position {} is given twice", c));
        }
        row.order.sequence = static_cast<SequencePattern>(row.order.sequence | bit);
    }
    return row;
}

bool is_condition_row(std::string_view text) {
    const auto fields = split_fields(text);
    return fields.size() >= 2 && fields[1] == "if";
}

constexpr std::size_t kConditionFieldCount = 8;

// card,if,event,axis,sense,position,action,parameter
std::pair<int, ConditionOrder> parse_condition_row(std::string_view text, const std::string& file,
                                                   std::int64_t line) {
    auto fields = split_fields(text);
    auto fail = [&](const std::string& why) { return DeckError::at_line(file, line, why); };
    // card,if,event,cancel: the end of an every-condition (an addition beyond the seed's claims)
    const bool cancel = fields.size() == 4 && fields[3] == "cancel";
    if (!cancel && fields.size() != kConditionFieldCount &&
        fields.size() != kConditionFieldCount + 1) {
        throw fail(fmt::format("a condition row has 8 comma-separated fields "
                               "(card,if,event,axis,sense,position,action,parameter), a 9th for "
                               "its mode (once or every), or 4 for a cancel "
                               "(card,if,event,cancel), found {}",
                               fields.size()));
    }
    if (!all_digits(fields[0]) || fields[0].size() > 4) {
        throw fail(fmt::format("card number '{}' is not 0..9999", fields[0]));
    }
    ConditionOrder c;
    if (!all_digits(fields[2]) || fields[2].size() > 2 || std::stoi(std::string(fields[2])) == 0) {
        throw fail(fmt::format("event '{}' is not an identifier 1..99", fields[2]));
    }
    c.event = std::stoi(std::string(fields[2]));
    if (cancel) {
        c.mode = ConditionMode::cancel;
        return {std::stoi(std::string(fields[0])), c};
    }
    if (fields.size() == kConditionFieldCount + 1) {
        if (fields[8] == "every") {
            c.mode = ConditionMode::every;
        } else if (fields[8] != "once") {
            throw fail(fmt::format("mode '{}' is not once or every (a cancel is the row "
                                   "card,if,event,cancel)",
                                   fields[8]));
        }
    }
    const auto axis = axis_named(fields[3]);
    if (!axis) {
        throw fail(
            fmt::format("unknown axis '{}' (table, cross, vertical, swivel or tilt)", fields[3]));
    }
    c.axis = *axis;
    if (fields[4] == "+") {
        c.sense = PassingSense::forward;
    } else if (fields[4] == "-") {
        c.sense = PassingSense::reverse;
    } else if (fields[4] == "*") {
        c.sense = PassingSense::either;
    } else {
        throw fail(
            fmt::format("sense '{}' is not + (forward), - (reverse) or * (either)", fields[4]));
    }
    if (fields[5].empty()) {
        throw fail("position is blank (a condition always has its position)");
    }
    c.position = parse_inches(fields[5], "position", file, line);
    const auto action = action_named(fields[6]);
    if (!action) {
        throw fail(fmt::format("unknown action '{}' (spindle-forward, spindle-reverse, "
                               "spindle-stop, coolant-on, coolant-off, tool-change, dwell, lamp)",
                               fields[6]));
    }
    c.action = *action;
    if (c.action == ActionKind::dwell) {
        const auto held = axis_named(fields[7]);
        if (!held) {
            throw fail(fmt::format("dwell holds an axis: '{}' is not table, cross, vertical, "
                                   "swivel or tilt",
                                   fields[7]));
        }
        c.parameter = static_cast<int>(axis_index(*held)) + 1;
    } else if (!fields[7].empty()) {
        if (!all_digits(fields[7]) || fields[7].size() > 4) {
            throw fail(fmt::format("parameter '{}' is not a number 0..9999", fields[7]));
        }
        c.parameter = std::stoi(std::string(fields[7]));
    }
    if (auto error = parameter_error(c.action, c.parameter)) {
        throw fail(*error);
    }
    return {std::stoi(std::string(fields[0])), c};
}

class ListingSource : public CardSource {
public:
    ListingSource(std::istream& in, std::string file, const CardLayout& layout)
        : reader_(in, file), file_(std::move(file)), layout_(layout) {}

    std::optional<Card> next() override {
        auto listed = reader_.next();
        if (!listed) {
            return std::nullopt;
        }
        // A field the layout lacks is named at the row that asks for it.
        for (Axis a : kAxes) {
            const auto& order = listed->orders.axis(a);
            if (order.slow_down[1] && !layout_.find(FieldKind::slow_down_2, a)) {
                throw DeckError::at_line(
                    file_, listed->axis_line.at(axis_index(a)),
                    fmt::format("layout {} has no second slow-down field for the {} axis (only "
                                "the table has two)",
                                layout_.name, axis_name(a)));
            }
        }
        EncodeResult encoded = encode(listed->orders, layout_);
        if (!encoded) {
            throw DeckError::at_line(file_, listed->first_line, *encoded.error);
        }
        return encoded.card;
    }

private:
    ListingReader reader_;
    std::string file_;
    const CardLayout& layout_;
};

class ListingSink : public CardSink {
public:
    ListingSink(std::ostream& out, std::string file, const CardLayout& layout)
        : out_(out), file_(std::move(file)), layout_(layout) {}

    void write(const Card& card) override {
        ++card_;
        DecodeResult decoded = decode(card, layout_);
        if (!decoded) {
            throw DeckError::at_card_column(file_, card_, decoded.bad_punch->column,
                                            decoded.bad_punch->what);
        }
        if (card_ == 1) {
            out_ << kListingHeader << '\n';
        }
        for (int i = 0; i < decoded.orders.condition_count; ++i) {
            out_ << condition_row(decoded.orders, i) << '\n';
        }
        if (decoded.orders.kind == CardKind::sync) {
            for (const std::string& row : sync_rows(decoded.orders)) {
                out_ << row << '\n';
            }
        }
        if (decoded.orders.kind == CardKind::tap) {
            out_ << tap_row(decoded.orders) << '\n';
        }
        if (decoded.orders.kind == CardKind::segment) {
            out_ << segment_row(decoded.orders) << '\n';
        }
        for (Axis a : kAxes) {
            if (decoded.orders.kind == CardKind::motion) {
                out_ << listing_row(decoded.orders, a) << '\n';
            }
        }
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

private:
    std::ostream& out_;
    std::string file_;
    const CardLayout& layout_;
    std::int64_t card_ = 0;
};

} // namespace

ListingReader::ListingReader(std::istream& in, std::string file)
    : in_(in), file_(std::move(file)) {}

namespace {

// What is wrong with a header line: the first word that differs, or the count.
template <typename Words>
std::string header_mismatch(const Words& names, const Words& expected) {
    for (std::size_t i = 0; i < std::min(names.size(), expected.size()); ++i) {
        if (names[i] != expected[i]) {
            return fmt::format("expected the header line '{}' first: its field {} is '{}', not "
                               "'{}'",
                               kListingHeader, i + 1, names[i], expected[i]);
        }
    }
    return fmt::format("expected the header line '{}' first: it has {} fields, not {}",
                       kListingHeader, names.size(), expected.size());
}

} // namespace

std::optional<std::string> ListingReader::next_data_line() {
    std::string line;
    while (true) {
        line.clear();
        int ch = 0;
        bool any = false;
        while ((ch = in_.get()) != std::char_traits<char>::eof() && ch != '\n') {
            any = true;
            if (line.size() >= kMaxLineBytes) {
                throw DeckError::at_line(
                    file_, line_ + 1, fmt::format("line is longer than {} bytes", kMaxLineBytes));
            }
            if (ch == 0) {
                throw DeckError::at_line(file_, line_ + 1, "NUL byte: this is not a text listing");
            }
            line += static_cast<char>(ch);
        }
        if (!any && ch == std::char_traits<char>::eof()) {
            return std::nullopt;
        }
        ++line_;
        if (line_ == 1 && line.starts_with("\xEF\xBB\xBF")) {
            line.erase(0, 3); // a spreadsheet's "CSV UTF-8" begins with a byte-order mark
        }
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        const auto hash = line.find('#');
        std::string_view data = trim(std::string_view(line).substr(0, hash));
        if (data.empty()) {
            continue;
        }
        if (!header_seen_) {
            auto names = split_fields(data);
            auto expected = split_fields(kListingHeader);
            if (names != expected) {
                throw DeckError::at_line(file_, line_, header_mismatch(names, expected));
            }
            header_seen_ = true;
            continue;
        }
        return std::string(data);
    }
}

std::optional<ListedCard> ListingReader::next_condition_card(std::string first) {
    ListedCard card;
    card.orders.kind = CardKind::condition;
    card.first_line = line_;
    std::string text = std::move(first);
    while (true) {
        auto [number, condition] = parse_condition_row(text, file_, line_);
        if (card.orders.condition_count == 0) {
            card.orders.number = number;
        } else if (number != card.orders.number) {
            pending_ = std::move(text); // the next card begins
            return card;
        }
        if (card.orders.condition_count == kConditionsPerCard) {
            throw DeckError::at_line(file_, line_,
                                     fmt::format("card {} has a sixth condition row (a condition "
                                                 "card holds five; begin another card)",
                                                 number));
        }
        card.orders.conditions.at(static_cast<std::size_t>(card.orders.condition_count++)) =
            condition;
        auto next = next_data_line();
        if (!next) {
            return card;
        }
        if (!is_condition_row(*next)) {
            pending_ = std::move(*next);
            return card;
        }
        text = std::move(*next);
    }
}

std::optional<ListedCard> ListingReader::next_sync_card(std::string first) {
    ListedCard card;
    card.orders.kind = CardKind::sync;
    card.first_line = line_;
    SyncRowLines lines;
    SyncOrder order;
    int number = 0;
    read_sync_row(first, file_, line_, number, order, lines);
    card.orders.number = number;
    while (auto next = next_data_line()) {
        const auto field = split_fields(*next)[0];
        const bool same_card = is_sync_row(*next) && all_digits(field) && field.size() <= 4 &&
                               std::stoi(std::string(field)) == number;
        if (!same_card) {
            pending_ = std::move(*next); // the next card begins
            break;
        }
        read_sync_row(*next, file_, line_, number, order, lines);
    }
    card.orders.sync = order;
    return card;
}

std::optional<ListedCard> ListingReader::next_tap_card(std::string first) {
    ListedCard card;
    card.orders.kind = CardKind::tap;
    card.first_line = line_;
    auto [number, order] = read_tap_row(first, file_, line_);
    card.orders.number = number;
    card.orders.tap = order;
    if (auto next = next_data_line()) {
        const auto field = split_fields(*next)[0];
        if (is_tap_row(*next) && all_digits(field) && field.size() <= 4 &&
            std::stoi(std::string(field)) == number) {
            throw DeckError::at_line(file_, line_,
                                     fmt::format("card {} has a second tap row (first on line "
                                                 "{}): a tap card taps one hole; give the next "
                                                 "its own card number",
                                                 number, card.first_line));
        }
        pending_ = std::move(*next); // the next card begins
    }
    return card;
}

std::optional<ListedCard> ListingReader::next_segment_card(std::string first) {
    ListedCard card;
    card.orders.kind = CardKind::segment;
    card.first_line = line_;
    auto [number, order] = read_segment_row(first, file_, line_);
    card.orders.number = number;
    card.orders.segment = order;
    return card;
}

std::optional<ListedCard> ListingReader::next() {
    ListedCard card;
    std::array<bool, kAxisCount> seen{};
    int rows = 0;
    while (rows < kAxisCount) {
        std::optional<std::string> text;
        if (pending_) {
            text = std::move(pending_);
            pending_.reset();
        } else {
            text = next_data_line();
        }
        const std::string_view kind = !text                     ? ""
                                      : is_condition_row(*text) ? "condition"
                                      : is_sync_row(*text)      ? "sync"
                                      : is_tap_row(*text)       ? "tap"
                                      : is_segment_row(*text)   ? "segment"
                                                                : "";
        if (!kind.empty()) {
            if (rows == 0) {
                return kind == "condition" ? next_condition_card(std::move(*text))
                       : kind == "sync"    ? next_sync_card(std::move(*text))
                       : kind == "tap"     ? next_tap_card(std::move(*text))
                                           : next_segment_card(std::move(*text));
            }
            auto missing = std::find(seen.begin(), seen.end(), false) - seen.begin();
            throw DeckError::at_line(
                file_, line_,
                fmt::format("a {} row begins, but card {} (from line {}) has no row for the {} "
                            "axis",
                            kind, card.orders.number, card.first_line,
                            axis_name(kAxes.at(static_cast<std::size_t>(missing)))));
        }
        if (!text) {
            if (rows == 0) {
                return std::nullopt;
            }
            for (Axis a : kAxes) {
                if (!seen.at(axis_index(a))) {
                    throw DeckError::at_line(
                        file_, line_,
                        fmt::format("card {} (from line {}) ends without a row for the {} axis",
                                    card.orders.number, card.first_line, axis_name(a)));
                }
            }
        }
        ListingRow row = parse_row(*text, file_, line_);
        if (rows == 0) {
            card.orders.number = row.card;
            card.orders.spindle = row.spindle;
            card.first_line = line_;
        } else if (row.card != card.orders.number) {
            auto missing = std::find(seen.begin(), seen.end(), false) - seen.begin();
            throw DeckError::at_line(
                file_, line_,
                fmt::format("card {} begins, but card {} (from line {}) has no row for the {} axis",
                            row.card, card.orders.number, card.first_line,
                            axis_name(kAxes.at(static_cast<std::size_t>(missing)))));
        } else if (row.spindle != card.orders.spindle) {
            throw DeckError::at_line(
                file_, line_,
                fmt::format("card {}: spindle {} here but {} on line {} (one spindle column a "
                            "card)",
                            row.card, spindle_name(row.spindle), spindle_name(card.orders.spindle),
                            card.first_line));
        }
        const auto i = axis_index(row.axis);
        if (seen.at(i)) {
            throw DeckError::at_line(file_, line_,
                                     fmt::format("card {} has a second row for the {} axis (first "
                                                 "on line {})",
                                                 row.card, axis_name(row.axis),
                                                 card.axis_line.at(i)));
        }
        seen.at(i) = true;
        card.axis_line.at(i) = line_;
        card.orders.axes.at(i) = row.order;
        ++rows;
    }
    return card;
}

std::string listing_row(const CardOrders& orders, Axis axis) {
    const AxisOrder& o = orders.axis(axis);
    auto inches = [](const std::optional<Thousandths>& v) {
        return v ? format_inches(*v) : std::string{};
    };
    std::string_view spindle = orders.spindle == Spindle::forward   ? "0"
                               : orders.spindle == Spindle::reverse ? "1"
                                                                    : "";
    return fmt::format("{},{},{},{},{},{},{},{},{},{}", orders.number, spindle, axis_name(axis),
                       o.motion == Motion::forward ? "+" : "-", o.start_speed,
                       inches(o.slow_down[0]), inches(o.slow_down[1]), format_inches(o.stop),
                       format_inches(o.check), format_sequence(o.sequence));
}

std::string condition_row(const CardOrders& orders, int index) {
    const ConditionOrder& c = orders.conditions.at(static_cast<std::size_t>(index));
    if (c.mode == ConditionMode::cancel) {
        return fmt::format("{},if,{},cancel", orders.number, c.event);
    }
    std::string parameter;
    if (c.action == ActionKind::dwell) {
        parameter = axis_name(kAxes.at(static_cast<std::size_t>(c.parameter - 1)));
    } else if (c.parameter != 0) {
        parameter = std::to_string(c.parameter);
    }
    return fmt::format("{},if,{},{},{},{},{},{}{}", orders.number, c.event, axis_name(c.axis),
                       sense_symbol(c.sense), format_inches(c.position), action_name(c.action),
                       parameter, c.mode == ConditionMode::every ? ",every" : "");
}

std::unique_ptr<CardSource> make_listing_source(std::istream& in, std::string file,
                                                const CardLayout& layout) {
    return std::make_unique<ListingSource>(in, std::move(file), layout);
}

std::unique_ptr<CardSink> make_listing_sink(std::ostream& out, std::string file,
                                            const CardLayout& layout) {
    return std::make_unique<ListingSink>(out, std::move(file), layout);
}

} // namespace parsons::cardreader
