// The one rule every number on the command line keeps (docs/stop-codes.md, "Numbers on the
// command line"): a number is written in decimal, and it is finite. CLI11 alone would read
// `--chord 0x6` as 6 (strtold), `--rows 010` as 8 (strtoll, base 0), and take `nan`, `inf` and
// `1e400` (infinite) as numbers a generator then computes with; and the options parsons reads
// itself (--limit's AXIS=MIN:MAX) had a rule of their own. Every number option and every number
// inside an option's text is judged here, once, and refused (exit 2) naming the option and
// saying why.
#pragma once

#include "cli/support/cli11_fwd.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cli {

enum class NumberKind {
    whole, // an optional sign and digits: --rows 3, --rpm 240
    real,  // and an optional point, fraction and exponent: --chord 6, -0.5, 1.5e-3
};

// Why `text` is not a number of this kind, or nothing when it is one. Refused: an empty value;
// hexadecimal (0x6) and any other base; nan; inf and infinity; a value too large for any
// quantity (1e400: past the largest double, about 1.8e308; a whole number past 2,147,483,647);
// a fraction or exponent in a whole number; anything else that is not a decimal number.
std::optional<std::string> number_problem(std::string_view text, NumberKind kind);

// Holds the rule on every number option of `app` and its subcommands: the options whose type
// name is CLI11's for a number (INT, UINT, FLOAT; an option given its own type name must be
// judged by its command with number_problem, as --limit's MIN and MAX are). A whole number's
// leading zeros are dropped before CLI11 converts it, so 010 is ten, not octal eight.
void apply_number_rule(CLI::App& app);

} // namespace parsons::cli
