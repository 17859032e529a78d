// The G words of RS-274 that parsons knows (decks/gcode_program.hpp; docs/gcode.md): each one's
// modal group, and why it is refused when it is.
#pragma once

#include <optional>

namespace parsons::decks::gcode_words {

// Modal groups of the G words parsons reads; two words of one group on a line are refused.
enum class Group { motion, plane, units, distance, arc_distance, feed_mode, other };

struct GInfo {
    Group group;
    const char* refusal; // nullptr: read; else why it is refused
};

// What G`g` is, or nothing when parsons does not know it.
std::optional<GInfo> g_code(double g);

} // namespace parsons::decks::gcode_words
