#include "cardreader/tap_listing.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/listing_fields.hpp"
#include "cardreader/tap_card.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {
namespace {

using detail::all_digits;
using detail::split_fields;

constexpr std::size_t kTapFieldCount = 8;
constexpr int kPitchDecimals = 5;

// "0.05000" -> 5000 (hundred-thousandths of an inch per tool revolution), or why not.
int parse_pitch(std::string_view text, const std::string& file, std::int64_t line) {
    auto fail = [&](const std::string& why) {
        return DeckError::at_line(file, line, fmt::format("pitch '{}': {}", text, why));
    };
    const auto dot = text.find('.');
    const std::string_view whole = text.substr(0, dot);
    const std::string_view decimals =
        dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
    if (!all_digits(whole) || !all_digits(decimals)) {
        throw fail("not a number of inches (write 0.ddddd per tool revolution, e.g. 0.05000)");
    }
    if (decimals.size() != kPitchDecimals) {
        throw fail("needs exactly five decimals, 0.ddddd (the card holds hundred-thousandths)");
    }
    if (whole.find_first_not_of('0') != std::string_view::npos) {
        throw fail("over 0.99999 in per tool revolution (the card's five digits hold 0.00001 .. "
                   "0.99999)");
    }
    const int value = std::stoi(std::string(decimals));
    if (value == 0) {
        throw fail("a pitch of 0 feeds nothing");
    }
    return value;
}

int parse_count(std::string_view text, std::string_view what, std::size_t digits, int max,
                const std::string& file, std::int64_t line) {
    if (!all_digits(text) || text.size() > digits || std::stoi(std::string(text)) < 1 ||
        std::stoi(std::string(text)) > max) {
        throw DeckError::at_line(file, line, fmt::format("{} '{}' is not 1..{}", what, text, max));
    }
    return std::stoi(std::string(text));
}

} // namespace

bool is_tap_row(std::string_view text) {
    const auto fields = split_fields(text);
    return fields.size() >= 2 && fields[1] == "tap";
}

std::pair<int, TapOrder> read_tap_row(std::string_view text, const std::string& file,
                                      std::int64_t line) {
    const auto fields = split_fields(text);
    auto fail = [&](const std::string& why) { return DeckError::at_line(file, line, why); };
    if (fields.size() < kTapFieldCount) {
        throw fail(fmt::format("a tap row has 8 comma-separated fields "
                               "(card,tap,TOOL,AXIS,SENSE,DEPTH,PITCH,RPM), then the rigid-tapping "
                               "words if any (index, retract=K, peck=D.DDD), found {}",
                               fields.size()));
    }
    if (!all_digits(fields[0]) || fields[0].size() > 4) {
        throw fail(fmt::format("card number '{}' is not 0..9999", fields[0]));
    }
    TapOrder t;
    t.tool = parse_count(fields[2], "tool", 2, kMaxTapTool, file, line);
    const auto axis = axis_named(fields[3]);
    if (!axis) {
        throw fail(
            fmt::format("unknown axis '{}' (table, cross, vertical, swivel or tilt)", fields[3]));
    }
    t.axis = *axis;
    if (fields[4] == "forward") {
        t.motion = Motion::forward;
    } else if (fields[4] == "reverse") {
        t.motion = Motion::reverse;
    } else {
        throw fail(fmt::format("sense '{}' is not forward (counters count up into the work) or "
                               "reverse (count down)",
                               fields[4]));
    }
    if (fields[5].empty()) {
        throw fail("depth is blank (a tap card always has its depth)");
    }
    t.depth = detail::parse_inches(fields[5], "depth", file, line);
    if (t.depth == 0) {
        throw fail(fmt::format("depth '{}': a tap of depth 0 taps nothing", fields[5]));
    }
    t.pitch = parse_pitch(fields[6], file, line);
    t.rpm = parse_count(fields[7], "speed", 4, kMaxTapRpm, file, line);
    // The rigid-tapping additions, each a word after RPM, each at most once.
    bool retract_given = false;
    bool peck_given = false;
    for (std::size_t i = kTapFieldCount; i < fields.size(); ++i) {
        const std::string_view word = fields[i];
        if (word == "index") {
            if (t.index_wait) {
                throw fail("'index' given twice");
            }
            t.index_wait = true;
        } else if (word.substr(0, 8) == "retract=") {
            const std::string_view k = word.substr(8);
            if (retract_given) {
                throw fail("'retract=' given twice");
            }
            if (k.size() != 1 || k[0] < '1' || k[0] > '0' + kMaxTapRetract) {
                throw fail(fmt::format("retract multiple '{}' is not 1..{} (the return stroke at "
                                       "that multiple of S)",
                                       k, kMaxTapRetract));
            }
            t.retract = k[0] - '0';
            retract_given = true;
        } else if (word.substr(0, 5) == "peck=") {
            // Rigid peck tapping (an addition; columns 21-24): the peck depth Q, d.ddd in.
            if (peck_given) {
                throw fail("'peck=' given twice");
            }
            const std::string_view q = word.substr(5);
            t.peck = q.empty() ? 0 : detail::parse_inches(q, "peck depth", file, line);
            if (t.peck == 0) {
                throw fail(fmt::format("peck depth '{}': a peck of 0 taps nothing (leave the "
                                       "word out for one pass)",
                                       q));
            }
            peck_given = true;
        } else {
            throw fail(fmt::format("unknown word '{}' after the tap row's speed (the rigid-tapping "
                                   "additions: index, retract=K, peck=D.DDD)",
                                   word));
        }
    }
    return {std::stoi(std::string(fields[0])), t};
}

std::string tap_row(const CardOrders& orders) {
    const TapOrder& t = orders.tap;
    std::string row =
        fmt::format("{},tap,{},{},{},{},{},{}", orders.number, t.tool, axis_name(t.axis),
                    t.motion == Motion::forward ? "forward" : "reverse", format_inches(t.depth),
                    format_pitch(t.pitch), t.rpm);
    if (t.index_wait) {
        row += ",index";
    }
    if (t.retract > 1) {
        row += fmt::format(",retract={}", t.retract);
    }
    if (t.peck > 0) {
        row += ",peck=" + format_inches(t.peck);
    }
    return row;
}

} // namespace parsons::cardreader
