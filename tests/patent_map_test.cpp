// docs/patent-map.md points every numeral of US 2,820,187 at its code or says why none (issue
// 50, item 4): the list below is every reference numeral of the patent's description, taken
// from its text (cols. 1-13; the figures' and claims' numbers, the column line numbers printed
// into the text and the plain digits of examples left out), and each must stand in the first
// cell of a row of the patent's own sections of the map.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <set>
#include <string>

namespace {

// The numerals of the description, as the text prints them (103 and 299 are misprints of 108
// and 290; the map says so on their rows).
const std::set<int> kPatentNumerals = {
    10,  12,  14,  15,  16,  18,  19,  20,  22,  24,  25,  26,  28,  30,  32,  34,  36,  38,
    40,  42,  44,  45,  46,  50,  52,  54,  56,  58,  60,  62,  70,  72,  74,  76,  78,  80,
    82,  84,  86,  88,  90,  92,  96,  98,  100, 102, 103, 104, 106, 108, 110, 112, 114, 116,
    118, 120, 122, 124, 126, 128, 130, 132, 134, 136, 138, 140, 142, 144, 146, 148, 150, 152,
    154, 156, 158, 160, 162, 164, 165, 166, 168, 170, 172, 174, 176, 178, 180, 182, 184, 186,
    188, 200, 202, 204, 206, 208, 210, 212, 214, 216, 218, 220, 222, 223, 224, 226, 228, 230,
    232, 234, 236, 238, 240, 242, 244, 246, 248, 250, 252, 254, 256, 257, 258, 260, 262, 264,
    265, 266, 268, 270, 272, 274, 276, 278, 280, 282, 284, 286, 288, 290, 292, 294, 298, 299,
    300, 302, 304, 310, 311, 312, 314, 316, 318, 320, 322, 323, 324, 326, 328, 330, 332, 333,
    334, 336, 338, 340, 342, 344, 346, 350, 351, 352, 354, 356, 358, 360, 362, 364, 368, 372};

// The numerals the first cells of the map's US 2,820,187 sections list (not the later patents'
// sections nor the emulator's additions), ranges ("226–234") included; each row's last cell is
// its file or why nothing carries it.
std::set<int> mapped(std::istream& map) {
    const std::regex row(R"(^\|([^|]*)\|.*\|([^|]*)\|\s*$)");
    const std::regex number(R"(\d+)");
    const std::regex range("(\\d+)\\s*(?:–|-)\\s*(\\d+)");
    std::set<int> listed;
    std::string section;
    std::string line;
    while (std::getline(map, line)) {
        if (line.rfind("## ", 0) == 0) {
            section = line;
            continue;
        }
        std::smatch m;
        if (section.find("EP 0") != std::string::npos ||
            section.find("additions") != std::string::npos || !std::regex_match(line, m, row) ||
            m[2].str().find_first_not_of(" -") == std::string::npos) {
            continue;
        }
        const std::string first = m[1];
        for (std::sregex_iterator it(first.begin(), first.end(), number), end; it != end; ++it) {
            listed.insert(std::stoi(it->str()));
        }
        for (std::sregex_iterator it(first.begin(), first.end(), range), end; it != end; ++it) {
            for (int n = std::stoi((*it)[1]); n <= std::stoi((*it)[2]); ++n) {
                listed.insert(n);
            }
        }
    }
    return listed;
}

} // namespace

TEST_CASE("Patent map: every numeral of US 2,820,187's description has a row in the patent's own "
          "sections of docs/patent-map.md, with its code or why none",
          "[docs]") {
    std::ifstream map(std::string(PARSONS_SOURCE_DIR) + "/docs/patent-map.md");
    REQUIRE(map);
    const std::set<int> listed = mapped(map);
    for (const int n : kPatentNumerals) {
        INFO("numeral " << n);
        CHECK(listed.count(n) == 1);
    }
}
