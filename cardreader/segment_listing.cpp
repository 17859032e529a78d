#include "cardreader/segment_listing.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/listing_fields.hpp"
#include "cardreader/segment_card.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {
namespace {

using detail::all_digits;
using detail::split_fields;

constexpr std::size_t kSegmentFieldCount = 6;

// "20.0" -> 200 (tenths of an inch a minute), or why not.
int parse_feed(std::string_view text, const std::string& file, std::int64_t line) {
    auto fail = [&](const std::string& why) {
        return DeckError::at_line(file, line, fmt::format("feed '{}': {}", text, why));
    };
    const auto dot = text.find('.');
    const std::string_view whole = text.substr(0, dot);
    const std::string_view tenth =
        dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
    if (whole.empty() || !all_digits(whole) || !all_digits(tenth) ||
        (dot != std::string_view::npos && tenth.empty())) {
        throw fail("not a speed in inches a minute (write dd.d, e.g. 20.0)");
    }
    if (tenth.size() > 1) {
        throw fail("has more than one decimal (the card holds tenths of an inch a minute)");
    }
    const std::string_view digits =
        whole.substr(std::min(whole.find_first_not_of('0'), whole.size()));
    if (digits.size() > 2) {
        throw fail("over 99.9 in/min (the card's three digits hold 00.1 .. 99.9)");
    }
    const int value = (digits.empty() ? 0 : std::stoi(std::string(digits))) * 10 +
                      (tenth.empty() ? 0 : tenth[0] - '0');
    if (value == 0) {
        throw fail("a segment at no speed is never travelled (0.1 .. 99.9 in/min)");
    }
    return value;
}

} // namespace

bool is_segment_row(std::string_view text) {
    const auto fields = split_fields(text);
    return fields.size() >= 2 && fields[1] == "segment";
}

std::pair<int, SegmentOrder> read_segment_row(std::string_view text, const std::string& file,
                                              std::int64_t line) {
    const auto fields = split_fields(text);
    auto fail = [&](const std::string& why) { return DeckError::at_line(file, line, why); };
    if (fields.size() != kSegmentFieldCount) {
        throw fail(fmt::format("a segment row has 6 comma-separated fields "
                               "(card,segment,X,Y,Z,F), found {}",
                               fields.size()));
    }
    if (!all_digits(fields[0]) || fields[0].empty() || fields[0].size() > 4) {
        throw fail(fmt::format("card number '{}' is not 0..9999", fields[0]));
    }
    SegmentOrder g;
    for (int i = 0; i < kSegmentAxes; ++i) {
        const std::string_view f = fields.at(static_cast<std::size_t>(2 + i));
        const std::string what = fmt::format("{} end point", segment_axis_letter(i));
        if (f.empty()) {
            throw fail(fmt::format("{} is blank (a segment card always has its end point)", what));
        }
        g.to.at(static_cast<std::size_t>(i)) = detail::parse_inches(f, what, file, line);
    }
    g.feed = parse_feed(fields[5], file, line);
    return {std::stoi(std::string(fields[0])), g};
}

std::string segment_row(const CardOrders& orders) {
    const SegmentOrder& g = orders.segment;
    return fmt::format("{},segment,{},{},{},{}", orders.number, format_inches(g.to[0]),
                       format_inches(g.to[1]), format_inches(g.to[2]), format_feed(g.feed));
}

} // namespace parsons::cardreader
