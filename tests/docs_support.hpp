// What the docs tests share beyond tests/test_support.hpp.
#pragma once

#include <string>
#include <vector>

namespace parsons::test {

// The subcommands a --help lists (CLI11: a "SUBCOMMANDS:" heading, two-space indented names).
std::vector<std::string> subcommands(const std::string& help);

} // namespace parsons::test
