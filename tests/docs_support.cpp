#include "tests/docs_support.hpp"

#include "tests/test_support.hpp"

#include <regex>

namespace parsons::test {

std::vector<std::string> subcommands(const std::string& help) {
    std::vector<std::string> out;
    bool in = false;
    for (const std::string& line : lines_of(help)) {
        if (line.find("SUBCOMMANDS:") != std::string::npos ||
            line.find("Subcommands:") != std::string::npos) {
            in = true;
            continue;
        }
        if (in) {
            std::smatch m;
            if (std::regex_search(line, m, std::regex(R"(^  ([a-z][a-z-]*)\b)"))) {
                out.push_back(m[1]);
            } else if (line.find_first_not_of(" \t") != std::string::npos) {
                in = false;
            }
        }
    }
    return out;
}

} // namespace parsons::test
