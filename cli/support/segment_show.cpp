#include "cli/support/segment_show.hpp"

#include "cardreader/segment_card.hpp"

#include <fmt/format.h>

namespace parsons::cli {

using namespace cardreader;

void print_segment_card(std::int64_t index, const CardOrders& o, const CardLayout& layout) {
    fmt::print("card {} · card number {:04} (columns 77-80) · SEGMENT CARD (column 76 row 4; an "
               "addition after EP 0636958, Black & Decker)\n",
               index, o.number);
    fmt::print("  {:<8} {:<14} {}\n", "columns", "field", "punched");
    const SegmentOrder& g = o.segment;
    for (const LayoutField& f : layout.segment_fields) {
        const std::string columns = fmt::format("{}-{}", f.first_column, f.last_column());
        std::string value;
        if (f.kind == FieldKind::segment_feed) {
            value = fmt::format("F {} in/min: the nominal speed along the segment",
                                format_feed(g.feed));
        } else {
            int i = 0;
            while (i + 1 < kSegmentAxes && segment_axis(i) != f.axis) {
                ++i;
            }
            value = fmt::format(
                "{} {} in: the end point on the {} axis's stepper motor", segment_axis_letter(i),
                format_inches(g.to.at(static_cast<std::size_t>(i))), axis_name(segment_axis(i)));
        }
        fmt::print("  {:<8} {:<14} {}\n", columns, field_label(f), value);
    }
}

nlohmann::json segment_card_json(std::int64_t index, const CardOrders& o) {
    const SegmentOrder& g = o.segment;
    return {{"index", index},
            {"number", o.number},
            {"kind", "segment"},
            {"to", {{"X", g.to[0] / 1000.0}, {"Y", g.to[1] / 1000.0}, {"Z", g.to[2] / 1000.0}}},
            {"feed_in_per_min", g.feed / 10.0},
            {"warnings", nlohmann::json::array()}};
}

} // namespace parsons::cli
