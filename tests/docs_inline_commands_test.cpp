// Inline commands of the docs (`parsons run DECK --trace T.vcd` in a sentence): the commands they
// name exist and each option is in that command's --help (docs/testing.md, "The docs are tested
// too").
#include "tests/docs_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <sstream>

using namespace parsons::test;
namespace fs = std::filesystem;

namespace {

// The command path and options of an inline command (`parsons run DECK --trace T.vcd`): the
// words after `parsons` that name commands, then every word that begins with '-' (to its '=').
struct InlineCommand {
    std::string path;
    std::vector<std::string> options;
};

std::vector<InlineCommand> inline_commands(const std::string& markdown,
                                           const std::set<std::string>& command_words) {
    std::vector<InlineCommand> out;
    static const std::regex span(R"(`(?:build/cli/)?parsons ([^`]+)`)");
    for (std::sregex_iterator it(markdown.begin(), markdown.end(), span), end; it != end; ++it) {
        InlineCommand c;
        std::istringstream words((*it)[1].str());
        bool in_path = true;
        for (std::string w; words >> w;) {
            if (w == "|" || w == "&&" || w == ";" || w.front() == '>' || w.rfind("2>", 0) == 0) {
                break; // another program's words from here
            }
            if (in_path && command_words.count(w) == 1) {
                c.path += (c.path.empty() ? "" : " ") + w;
                continue;
            }
            in_path = false;
            const bool number = w.size() > 1 && std::isdigit(static_cast<unsigned char>(w[1]));
            if (w.size() > 1 && w.front() == '-' && !number && w.find('|') == std::string::npos) {
                c.options.push_back(w.substr(0, w.find('=')));
            }
        }
        out.push_back(c);
    }
    return out;
}

} // namespace

TEST_CASE("Docs: every inline command of every page names commands and options parsons has",
          "[docs][cli]") {
    // The commands, from the program's own --help.
    std::set<std::string> words;
    for (const std::string& c : subcommands(run_parsons("--help").output)) {
        words.insert(c);
        for (const std::string& s : subcommands(run_parsons(c + " --help").output)) {
            words.insert(s);
        }
    }
    REQUIRE(words.count("airfoil") == 1);
    std::map<std::string, std::string> helps;
    int checked = 0;
    std::vector<fs::path> pages = {source_path("README.md")};
    for (const auto& entry : fs::directory_iterator(source_path("docs"))) {
        if (entry.path().extension() == ".md") {
            pages.push_back(entry.path());
        }
    }
    for (const fs::path& page : pages) {
        for (const InlineCommand& c : inline_commands(read_bytes(page), words)) {
            if (helps.count(c.path) == 0) {
                helps[c.path] = run_parsons(c.path + " --help").output;
            }
            const std::string& help = helps[c.path];
            for (const std::string& o : c.options) {
                INFO(page.filename().string() << ": `parsons " << c.path << " ... " << o
                                              << "`: no such option in its --help");
                const std::regex listed("(^|[ ,])" + o + "([ ,=]|$)", std::regex::multiline);
                CHECK(std::regex_search(help, listed));
                ++checked;
            }
        }
    }
    CHECK(checked > 80);
}
