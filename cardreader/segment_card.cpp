#include "cardreader/segment_card.hpp"

#include "cardreader/field_reading.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace parsons::cardreader {
namespace {

using detail::Problems;

constexpr std::array<Axis, kSegmentAxes> kSegmentAxis = {Axis::table, Axis::cross, Axis::vertical};
constexpr std::array<std::string_view, kSegmentAxes> kLetters = {"X", "Y", "Z"};

const LayoutField& segment_field(const CardLayout& layout, FieldKind kind,
                                 std::optional<Axis> axis = std::nullopt) {
    if (const LayoutField* f = layout.find_segment(kind, axis)) {
        return *f;
    }
    throw std::logic_error("segment card field missing from the layout");
}

int letter_of(Axis a) {
    for (int i = 0; i < kSegmentAxes; ++i) {
        if (kSegmentAxis.at(static_cast<std::size_t>(i)) == a) {
            return i;
        }
    }
    return 0;
}

// A digit field that is always punched: its value, or 0 with the fault added to `problems`.
int read_punched(const Card& card, const LayoutField& f, std::string_view blank,
                 Problems& problems) {
    Problems own;
    const std::optional<int> value = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return 0;
    }
    if (!value) {
        problems.add(f.first_column, fmt::format("{} is blank: {}", segment_field_label(f), blank));
        return 0;
    }
    return *value;
}

} // namespace

Axis segment_axis(int i) {
    return kSegmentAxis.at(static_cast<std::size_t>(i));
}

std::string_view segment_axis_letter(int i) {
    return kLetters.at(static_cast<std::size_t>(i));
}

void add_segment_fields(CardLayout& layout) {
    for (int i = 0; i < kSegmentAxes; ++i) {
        layout.segment_fields.push_back({FieldKind::segment_end, segment_axis(i), 2 + 4 * i, 4});
    }
    layout.segment_fields.push_back({FieldKind::segment_feed, std::nullopt, 14, 3});
}

std::string segment_field_label(const LayoutField& field) {
    if (field.kind == FieldKind::segment_end) {
        return fmt::format("segment {}", kLetters.at(static_cast<std::size_t>(
                                             letter_of(field.axis.value_or(Axis::table)))));
    }
    return field.kind == FieldKind::segment_feed ? "segment feed" : "segment field";
}

std::string_view segment_field_short_label(FieldKind kind) {
    return kind == FieldKind::segment_feed ? "FEED F" : kind == FieldKind::segment_end ? "END" : "";
}

DecodeResult decode_segment_card(const Card& card, const CardLayout& layout) {
    DecodeResult result;
    Problems problems;
    CardOrders& o = result.orders;
    o.kind = CardKind::segment;
    detail::find_strays(card, layout.segment_allowed_rows, layout, CardKind::segment, problems);
    o.number = detail::read_card_number(card, layout, problems);
    SegmentOrder& g = o.segment;
    for (int i = 0; i < kSegmentAxes; ++i) {
        g.to.at(static_cast<std::size_t>(i)) = static_cast<Thousandths>(read_punched(
            card, segment_field(layout, FieldKind::segment_end, segment_axis(i)),
            "the segment's end point, d.ddd in (0.000 where the axis stands at the reference "
            "point)",
            problems));
    }
    const LayoutField& feed = segment_field(layout, FieldKind::segment_feed);
    g.feed =
        read_punched(card, feed, "the nominal speed F along the segment, dd.d in/min", problems);
    if (g.feed == 0 && !problems.first()) {
        problems.add(feed.first_column,
                     fmt::format("{} is 000: a segment at no speed is never travelled (00.1-99.9 "
                                 "in/min)",
                                 segment_field_label(feed)));
    }
    result.bad_punch = problems.first();
    return result;
}

std::optional<std::string> segment_order_error(const SegmentOrder& g) {
    for (int i = 0; i < kSegmentAxes; ++i) {
        const Thousandths v = g.to.at(static_cast<std::size_t>(i));
        if (v > kMaxThousandths) {
            return fmt::format("segment {} {} is not 0.000..9.999 in",
                               kLetters.at(static_cast<std::size_t>(i)), v);
        }
    }
    if (g.feed < 1 || g.feed > kMaxSegmentFeed) {
        return fmt::format("segment feed {} is not 1..999 tenths of an inch a minute", g.feed);
    }
    return std::nullopt;
}

std::optional<std::string> encode_segment_card(const SegmentOrder& g, const CardLayout& layout,
                                               Card& card) {
    if (layout.extension_column == 0) {
        return fmt::format("layout {} has no extension column for segment cards", layout.name);
    }
    if (auto error = segment_order_error(g)) {
        return error;
    }
    card.punch(layout.extension_column, Row::r4);
    std::optional<std::string> error;
    auto number = [&](const LayoutField& f, int value) {
        if (auto e = detail::punch_number(card, f, value); e && !error) {
            error = std::move(e);
        }
    };
    for (int i = 0; i < kSegmentAxes; ++i) {
        number(segment_field(layout, FieldKind::segment_end, segment_axis(i)),
               g.to.at(static_cast<std::size_t>(i)));
    }
    number(segment_field(layout, FieldKind::segment_feed), g.feed);
    return error;
}

EncodeResult segment_card(const SegmentOrder& order, int number, const CardLayout& layout) {
    CardOrders orders;
    orders.kind = CardKind::segment;
    orders.number = number;
    orders.segment = order;
    return encode(orders, layout);
}

} // namespace parsons::cardreader
