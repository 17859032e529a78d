// The cases of `parsons sweep` (cli/sweep_command.cpp): a generator family and a grid of its
// keys' values, each case one deck to generate and run. The grid is its own CSV file too
// (--cases-out, --cases), one case a row, so that a sweep can be split and run anywhere
// (docs/performance.md, "Sweeps").
//
//   --set KEY=VALUE       one value for every case
//   --vary KEY=V1,V2,...  the values listed
//   --vary KEY=A:B:N      N values from A to B, evenly spaced (both ends included)
//
// The grid is every combination, in the order the --vary options were given: the first varies
// slowest, as nested loops. Cases are numbered from 1 in that order.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace parsons::cli {

// One key of the grid and its values, with the option that gave it, for messages.
struct SweepKey {
    std::string key;
    std::vector<std::string> values;
    std::string given; // "--set chord=6" or "--vary stations=20:80:4"
};

// Reads "KEY=VALUE" (--set) and "KEY=V1,V2 | A:B:N" (--vary). Throws DeckError naming the
// option and what is wrong.
SweepKey parse_set(const std::string& spec);
SweepKey parse_vary(const std::string& spec);

struct SweepCase {
    long number = 0;
    std::string family;
    std::vector<std::string> values; // one for each of SweepGrid::keys
};

struct SweepGrid {
    std::vector<std::string> keys;
    std::vector<SweepCase> cases;
};

// The most cases a grid may have.
inline constexpr std::size_t kMaxSweepCases = 1000000;

// Every combination of the keys' values. Throws DeckError when a key is given twice or the grid
// is larger than kMaxSweepCases.
SweepGrid expand_grid(const std::string& family, const std::vector<SweepKey>& keys);

// The grid as CSV: "case,family,KEY,..." then one row a case.
std::string grid_csv(const SweepGrid& grid);
// A cases file, as grid_csv writes it (any subset of its rows, in any order). Throws DeckError
// naming the file and line.
SweepGrid read_cases(const std::string& path);

// A CSV field: as it is, or in double quotes (doubled inside) when it holds a comma, a quote or
// a line break, or begins or ends with a space.
std::string csv_field(const std::string& text);

} // namespace parsons::cli
