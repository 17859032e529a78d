// The listing's fields (listing_format.hpp): trimming, splitting at commas, digit tests and
// d.ddd inches, shared by the motion and condition rows (listing_format.cpp), the sync rows
// (sync_listing.cpp) and the tap rows (tap_listing.cpp).
#pragma once

#include "cardreader/orders.hpp"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cardreader::detail {

inline std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
        return {};
    }
    const auto last = s.find_last_not_of(" \t");
    return s.substr(first, last - first + 1);
}

inline std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t start = 0;
    while (true) {
        const auto comma = line.find(',', start);
        fields.push_back(trim(line.substr(start, comma - start)));
        if (comma == std::string_view::npos) {
            break;
        }
        start = comma + 1;
    }
    return fields;
}

inline bool all_digits(std::string_view s) {
    return !s.empty() &&
           std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Parses a d.ddd inch value (listing_format.cpp), or throws DeckError naming file, line and
// `field` with the reason.
Thousandths parse_inches(std::string_view text, std::string_view field, const std::string& file,
                         std::int64_t line);

} // namespace parsons::cardreader::detail
