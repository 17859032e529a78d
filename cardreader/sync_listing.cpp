#include "cardreader/sync_listing.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/listing_fields.hpp"
#include "cardreader/sync_card.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {
namespace {

using detail::all_digits;
using detail::split_fields;

constexpr int kTravelDecimals = 5;

// "0.00417" -> 417 (hundred-thousandths of an inch), or why not.
int parse_travel(std::string_view text, const std::string& file, std::int64_t line) {
    auto fail = [&](const std::string& why) {
        return DeckError::at_line(file, line, fmt::format("travel per pulse '{}': {}", text, why));
    };
    const auto dot = text.find('.');
    const std::string_view whole = text.substr(0, dot);
    const std::string_view decimals =
        dot == std::string_view::npos ? std::string_view{} : text.substr(dot + 1);
    if (!all_digits(whole) || !all_digits(decimals)) {
        throw fail("not a number of inches (write 0.ddddd, e.g. 0.00417)");
    }
    if (decimals.size() != kTravelDecimals) {
        throw fail("needs exactly five decimals, 0.ddddd (the card holds hundred-thousandths)");
    }
    if (whole.find_first_not_of('0') != std::string_view::npos) {
        throw fail("over 0.99999 in per pulse (the card's five digits hold 0.00001 .. 0.99999)");
    }
    const int value = std::stoi(std::string(decimals));
    if (value == 0) {
        throw fail("a travel per pulse of 0 (leave the axis out for no speed sync)");
    }
    return value;
}

int parse_number(std::string_view text, std::string_view what, int min, int max,
                 const std::string& file, std::int64_t line) {
    if (!all_digits(text) || text.size() > 4 || std::stoi(std::string(text)) < min ||
        std::stoi(std::string(text)) > max) {
        throw DeckError::at_line(file, line,
                                 fmt::format("{} '{}' is not {}..{}", what, text, min, max));
    }
    return std::stoi(std::string(text));
}

} // namespace

bool is_sync_row(std::string_view text) {
    const auto fields = split_fields(text);
    return fields.size() >= 2 && fields[1] == "sync";
}

void read_sync_row(std::string_view text, const std::string& file, std::int64_t line, int& number,
                   SyncOrder& order, SyncRowLines& lines) {
    const auto fields = split_fields(text);
    auto fail = [&](const std::string& why) { return DeckError::at_line(file, line, why); };
    auto expect = [&](std::size_t count, std::string_view form) {
        if (fields.size() != count) {
            throw fail(fmt::format("a sync {} row has {} comma-separated fields ({}), found {}",
                                   fields[2], count, form, fields.size()));
        }
    };
    if (fields.size() < 3) {
        throw fail("a sync row is card,sync,position,ANGLE or card,sync,speed,AXIS,TRAVEL or "
                   "card,sync,loop,TARGET,COUNT or card,sync,reset");
    }
    if (!all_digits(fields[0]) || fields[0].size() > 4) {
        throw fail(fmt::format("card number '{}' is not 0..9999", fields[0]));
    }
    number = std::stoi(std::string(fields[0]));
    auto again = [&](std::string_view what, std::int64_t first) {
        return fail(fmt::format("card {} has a second {} (first on line {})", number, what, first));
    };
    if (fields[2] == "position") {
        expect(4, "card,sync,position,ANGLE");
        if (!all_digits(fields[3]) || fields[3].size() > 3 ||
            std::stoi(std::string(fields[3])) > kMaxSyncAngle) {
            throw fail(fmt::format("angle '{}' outside 0-359 (whole degrees of the crank from top "
                                   "dead centre)",
                                   fields[3]));
        }
        if (lines.position != 0) {
            throw again("position row", lines.position);
        }
        lines.position = line;
        order.position_sync = true;
        order.angle_deg = std::stoi(std::string(fields[3]));
    } else if (fields[2] == "speed") {
        expect(5, "card,sync,speed,AXIS,TRAVEL");
        const auto axis = axis_named(fields[3]);
        if (!axis) {
            throw fail(fmt::format("unknown axis '{}' (table, cross, vertical, swivel or tilt)",
                                   fields[3]));
        }
        const int travel = parse_travel(fields[4], file, line);
        std::int64_t& first = lines.speed.at(axis_index(*axis));
        if (first != 0) {
            throw again(fmt::format("speed row for the {} axis", axis_name(*axis)), first);
        }
        first = line;
        order.travel_per_pulse.at(axis_index(*axis)) = travel;
    } else if (fields[2] == "loop") {
        expect(5, "card,sync,loop,TARGET,COUNT");
        order.loop_to = parse_number(fields[3], "loop target", 0, 9999, file, line);
        order.loop_count = parse_number(fields[4], "loop count", 1, kMaxLoopCount, file, line);
        if (lines.loop != 0) {
            throw again("loop row", lines.loop);
        }
        lines.loop = line;
        order.loop = true;
    } else if (fields[2] == "reset") {
        expect(3, "card,sync,reset");
        if (lines.reset != 0) {
            throw again("reset row", lines.reset);
        }
        lines.reset = line;
        order.register_reset = true;
    } else {
        throw fail(
            fmt::format("unknown sync order '{}' (position, speed, loop or reset)", fields[2]));
    }
    if (order.loop && (order.synchronises() || order.register_reset)) {
        throw fail(fmt::format("card {}: a loop and {} on one card (a loop card stands alone, "
                               "like the seed's M99 block: give the loop a card number of its "
                               "own)",
                               number,
                               order.synchronises() ? "synchronisation" : "a register reset"));
    }
}

std::vector<std::string> sync_rows(const CardOrders& orders) {
    const SyncOrder& s = orders.sync;
    std::vector<std::string> rows;
    if (s.register_reset) {
        rows.push_back(fmt::format("{},sync,reset", orders.number));
    }
    if (s.position_sync) {
        rows.push_back(fmt::format("{},sync,position,{}", orders.number, s.angle_deg));
    }
    for (Axis a : kAxes) {
        if (const auto& f = s.travel_per_pulse.at(axis_index(a))) {
            rows.push_back(fmt::format("{},sync,speed,{},{}", orders.number, axis_name(a),
                                       format_travel_per_pulse(*f)));
        }
    }
    if (s.loop) {
        rows.push_back(fmt::format("{},sync,loop,{},{}", orders.number, s.loop_to, s.loop_count));
    }
    return rows;
}

} // namespace parsons::cardreader
