// The docs stand on their own: README.md, the pages of docs/ and the source folders send the
// reader to no file outside the repository (the design notes and the patent texts the project
// was started from live elsewhere; their rules are restated in docs/design-rules.md and the
// patents are cited by publication number), and every rule they cite has its heading there:
// "docs/design-rules.md rule 5" in a comment, or a link to
// design-rules.md#rule-5-speed-switch-236-and-delay-258 in a page, whose anchor must be the
// heading's own.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

using parsons::test::lines_of;
using parsons::test::read_bytes;
using parsons::test::source_path;
namespace fs = std::filesystem;

namespace {

// The text files to read, relative to the source tree: README.md, the top-level CMakeLists.txt,
// docs/*.md, and every source, build, script and text file of the source folders.
std::vector<std::string> checked_files() {
    std::vector<std::string> out = {"README.md", "CMakeLists.txt"};
    const std::string root = source_path("");
    for (const auto& entry : fs::directory_iterator(source_path("docs"))) {
        if (entry.is_regular_file() && entry.path().extension() == ".md") {
            out.push_back(entry.path().generic_string().substr(root.size()));
        }
    }
    static const std::set<std::string> kinds = {".cpp", ".hpp", ".h",     ".txt",  ".sh",
                                                ".md",  ".py",  ".cmake", ".json", ".csv"};
    for (const char* folder :
         {"cardreader", "relaylogic", "axes", "decks", "cli", "tests", "scripts"}) {
        for (const auto& entry : fs::recursive_directory_iterator(source_path(folder))) {
            if (entry.is_regular_file() && kinds.count(entry.path().extension().string()) == 1) {
                out.push_back(entry.path().generic_string().substr(root.size()));
            }
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The anchor GitHub gives a heading: lower case, spaces as hyphens, punctuation dropped. (The
// headings of docs/design-rules.md are plain ASCII; other bytes are dropped too.)
std::string anchor_of(const std::string& heading) {
    std::string out;
    for (const char ch : heading) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80 && std::isalnum(c) != 0) {
            out += static_cast<char>(std::tolower(c));
        } else if (c == ' ' || c == '-') {
            out += '-';
        } else if (c == '_') {
            out += '_';
        }
    }
    return out;
}

} // namespace

TEST_CASE("Docs: README, docs and sources point at nothing outside the repository, and every "
          "rule they cite has its heading in docs/design-rules.md",
          "[docs]") {
    const std::vector<std::string> files = checked_files();
    REQUIRE(files.size() > 100);
    REQUIRE(std::count(files.begin(), files.end(), "docs/design-rules.md") == 1);
    REQUIRE(std::count(files.begin(), files.end(), "tests/self_contained_docs_test.cpp") == 1);

    // The headings of docs/design-rules.md: every anchor, and the rules by number.
    std::set<std::string> anchors;
    std::set<int> rules;
    const std::regex heading(R"(^#+ +(.*\S) *$)");
    const std::regex rule_heading(R"(^## Rule (\d+): )");
    for (const std::string& line : lines_of(read_bytes(source_path("docs/design-rules.md")))) {
        std::smatch m;
        if (std::regex_match(line, m, heading)) {
            anchors.insert(anchor_of(m[1]));
        }
        if (std::regex_search(line, m, rule_heading)) {
            const int n = std::stoi(m[1]);
            INFO("docs/design-rules.md: " << line);
            CHECK(rules.count(n) == 0);
            rules.insert(n);
        }
    }
    // Rules 1 to 14, the numbering the code and the pages have always cited.
    CHECK(rules.size() == 14);
    for (int n = 1; n <= 14; ++n) {
        INFO("rule " << n);
        CHECK(rules.count(n) == 1);
    }
    CHECK_THAT(read_bytes(source_path("README.md")), Catch::Contains("docs/design-rules.md"));

    // What lies outside the repository, spelt in pieces so that this file does not name it.
    const std::vector<std::string> outside = {
        std::string("DESIGN") + ".md", std::string("..") + "/shared", std::string("seeds") + "/0"};
    // Citations: "design-rules.md rule 5", "design-rules.md rules 5, 6 and 12"; links such as
    // design-rules.md#the-sources; and, on the page itself, links such as "](#principles)".
    const std::regex cited_rules(R"(design-rules\.md,? rules? (\d+(?:(?:, | and )\d+)*))");
    const std::regex number(R"(\d+)");
    const std::regex linked(R"(design-rules\.md#([A-Za-z0-9_-]+))");
    const std::regex on_page(R"(\]\(#([A-Za-z0-9_-]+)\))");
    int citations = 0;
    for (const std::string& file : files) {
        const std::vector<std::string> lines = lines_of(read_bytes(source_path(file)));
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::string& line = lines[i];
            for (const std::string& needle : outside) {
                if (line.find(needle) != std::string::npos) {
                    FAIL_CHECK(file << ":" << (i + 1) << " names " << needle << ": " << line);
                }
            }
            const bool this_page = file == "docs/design-rules.md";
            if (line.find("design-rules.md") == std::string::npos && !this_page) {
                continue;
            }
            INFO(file << ":" << (i + 1) << ": " << line);
            for (std::sregex_iterator it(line.begin(), line.end(), cited_rules), end; it != end;
                 ++it) {
                const std::string list = (*it)[1];
                for (std::sregex_iterator n(list.begin(), list.end(), number); n != end; ++n) {
                    CHECK(rules.count(std::stoi(n->str())) == 1);
                    ++citations;
                }
            }
            for (std::sregex_iterator it(line.begin(), line.end(), linked), end; it != end; ++it) {
                CHECK(anchors.count((*it)[1].str()) == 1);
                ++citations;
            }
            if (this_page) {
                for (std::sregex_iterator it(line.begin(), line.end(), on_page), end; it != end;
                     ++it) {
                    CHECK(anchors.count((*it)[1].str()) == 1);
                }
            }
        }
    }
    // The rules are cited from the code and the pages, not only listed.
    CHECK(citations > 30);
}
