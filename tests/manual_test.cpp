// The manual pages and the shell completion (cli/support/manual.hpp): written from the command line
// itself, every option of every command is in its page and in both completion scripts, the
// pages are clean roff, the bash script completes as a user would see it, and the files the
// build wrote are the ones the command line gives now.
#include "cli/command_line.hpp"
#include "cli/support/manual.hpp"
#include "cli/support/value_names.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>

using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_shell;

namespace {

struct CommandLine {
    CLI::App app;
    parsons::cli::Command selected;
    explicit CommandLine(const std::string& version = "parsons test") {
        parsons::cli::build_command_line(app, selected, version);
    }
};

std::string roff_name(const std::string& name) {
    std::string out;
    for (const char c : name) {
        out += c == '-' ? std::string("\\-") : std::string(1, c);
    }
    return out;
}

// The one line of a completion script's case for a command path ("/gen/airfoil").
std::string case_line(const std::string& script, const std::string& slashed) {
    const std::string key = "        \"" + slashed + "\")";
    const auto at = script.find(key);
    if (at == std::string::npos) {
        return {};
    }
    return script.substr(at, script.find('\n', at) - at);
}

std::string slashed(const std::string& path) {
    std::string s;
    std::string word;
    for (const char c : path + " ") {
        if (c == ' ') {
            if (!word.empty()) {
                s += "/" + word;
            }
            word.clear();
        } else {
            word += c;
        }
    }
    return s;
}

} // namespace

TEST_CASE("Manual: every option of every command is in the command's man page and in the bash "
          "and zsh completion",
          "[cli][manual]") {
    CommandLine cl;
    const auto pages = parsons::cli::man_pages(cl.app, "parsons test");
    std::map<std::string, std::string> by_name;
    for (const auto& p : pages) {
        by_name[p.name] = p.text;
    }
    const std::string bash = parsons::cli::bash_completion(cl.app);
    const std::string zsh = parsons::cli::zsh_completion(cl.app);
    const auto paths = parsons::cli::command_paths(cl.app);
    REQUIRE(paths.size() == pages.size());
    // The commands the program has, and the nested ones, are all there.
    for (const char* path : {"", "run", "show", "gen", "gen airfoil", "gen tapping", "demo"}) {
        bool found = false;
        for (const auto& p : paths) {
            found = found || p.first == path;
        }
        CHECK(found);
    }
    int options = 0;
    int hidden = 0;
    for (const auto& [path, app] : paths) {
        INFO("command: parsons " << path);
        std::string name = path;
        for (char& c : name) {
            c = c == ' ' ? '-' : c;
        }
        name = path.empty() ? "parsons" : "parsons-" + name;
        REQUIRE(by_name.count(name) == 1);
        const std::string& page = by_name[name];
        const std::string b = case_line(bash, slashed(path));
        const std::string z = case_line(zsh, slashed(path));
        REQUIRE_FALSE(b.empty());
        REQUIRE_FALSE(z.empty());
        for (const CLI::Option* o :
             app->get_options([](const CLI::Option* x) { return !x->get_positional(); })) {
            for (const std::string& n : parsons::cli::option_names(*o)) {
                INFO("option " << n);
                if (o->get_group().empty()) { // internal (bench's --child-*): nowhere a user looks
                    ++hidden;
                    CHECK(page.find(roff_name(n)) == std::string::npos);
                    CHECK(bash.find(n) == std::string::npos);
                    CHECK(zsh.find(n) == std::string::npos);
                    continue;
                }
                ++options;
                CHECK(page.find("\\fB" + roff_name(n) + "\\fR") != std::string::npos);
                CHECK(page.find(roff_name(o->get_description().substr(0, 20))) !=
                      std::string::npos);
                CHECK((b.find(" " + n + " ") != std::string::npos ||
                       b.find("\"" + n + " ") != std::string::npos ||
                       b.find(" " + n + "\"") != std::string::npos ||
                       b.find("\"" + n + "\"") != std::string::npos));
                CHECK(z.find("'" + n + ":") != std::string::npos);
            }
        }
        for (const CLI::App* s : app->get_subcommands([](const CLI::App*) { return true; })) {
            INFO("subcommand " << s->get_name());
            CHECK(page.find(".B " + roff_name(s->get_name()) + "\n") != std::string::npos);
            CHECK(z.find("'" + s->get_name() + ":") != std::string::npos);
        }
        // The exit codes and examples of its --help, as sections of the page.
        if (app->get_footer().find("Exit codes:") != std::string::npos) {
            CHECK(page.find(".SH EXIT STATUS\n") != std::string::npos);
        }
        if (app->get_footer().find("Examples:") != std::string::npos) {
            CHECK(page.find(".SH EXAMPLES\n") != std::string::npos);
        }
    }
    CHECK(options > 100); // every command's, not a few
    CHECK(hidden >= 5);   // bench's five --child-* options were looked for
    // An option added to a command shows up in all three at once.
    CommandLine more;
    auto* run = more.app.get_subcommand("run");
    std::string extra;
    run->add_option("--brand-new-option", extra, "An option added for this test");
    const auto more_pages = parsons::cli::man_pages(more.app, "parsons test");
    bool in_page = false;
    for (const auto& p : more_pages) {
        in_page = in_page || (p.name == "parsons-run" &&
                              p.text.find("\\-\\-brand\\-new\\-option") != std::string::npos);
    }
    CHECK(in_page);
    CHECK(case_line(parsons::cli::bash_completion(more.app), "/run").find("--brand-new-option") !=
          std::string::npos);
    CHECK(case_line(parsons::cli::zsh_completion(more.app), "/run").find("'--brand-new-option:") !=
          std::string::npos);
}

TEST_CASE("Manual: the build's man pages and completion scripts are the command line's as it is "
          "now, and the pages are clean roff",
          "[cli][manual]") {
    const std::string dir = std::string(PARSONS_BINARY_DIR);
    const std::string top = read_bytes(dir + "/man/man1/parsons.1");
    // The version on the build's pages: ".TH PARSONS 1 "" "parsons 0.1.0 (...)" ..."
    const auto v0 = top.find("\"\" \"") + 4;
    std::string version = top.substr(v0, top.find('"', v0) - v0);
    std::string unescaped;
    for (std::size_t i = 0; i < version.size(); ++i) {
        if (version.compare(i, 2, "\\-") == 0) {
            unescaped += '-';
            ++i;
        } else {
            unescaped += version[i];
        }
    }
    CHECK(unescaped.rfind(std::string("parsons ") + PARSONS_PROJECT_VERSION, 0) == 0);
    CommandLine cl(unescaped);
    for (const auto& p : parsons::cli::man_pages(cl.app, unescaped)) {
        INFO(p.name);
        CHECK(read_bytes(dir + "/man/man1/" + p.name + ".1") == p.text);
    }
    CHECK(read_bytes(dir + "/completion/parsons.bash") == parsons::cli::bash_completion(cl.app));
    CHECK(read_bytes(dir + "/completion/_parsons") == parsons::cli::zsh_completion(cl.app));
    // groff reads every page without a warning (-ww: all of them).
    if (run_shell("command -v groff >/dev/null").exit_code == 0) {
        const auto r = run_shell("for f in " + q(dir) +
                                 "/man/man1/*.1; do groff -man -ww -z \"$f\" || exit 1; done 2>&1");
        INFO(r.output);
        CHECK(r.exit_code == 0);
        CHECK(r.output.empty());
    }
    // The zsh script parses, where zsh is at hand (scripts/install-deps.sh installs it).
    if (run_shell("command -v zsh >/dev/null").exit_code == 0) {
        const auto r = run_shell("zsh -n " + q(dir + "/completion/_parsons") + " 2>&1");
        INFO(r.output);
        CHECK(r.exit_code == 0);
    }
}

TEST_CASE("Manual: every value an option or argument takes says what it is, for --help and the "
          "completion",
          "[cli][manual]") {
    CommandLine cl;
    // The values typed, not chosen: a number, or these free texts. A new option whose value is
    // plain TEXT fails here until its type name says what it is (cli/support/value_names.hpp).
    const std::vector<std::string> typed = {"AXIS=MIN:MAX", "FAULT", "KEY=VALUE", "KEY=VALUES"};
    const std::map<std::string, std::string> free_text = {{"gen airfoil --naca", "TEXT"},
                                                          {"gen two-tool --naca", "TEXT"},
                                                          {"gen tapping --tools", "TEXT"}};
    int valued = 0;
    for (const auto& [path, app] : parsons::cli::command_paths(cl.app)) {
        for (const CLI::Option* o : app->get_options({})) {
            if (o->get_items_expected_max() == 0 || o->get_group().empty() ||
                o->get_name() == "--help") {
                continue;
            }
            const std::string name = o->get_positional() ? o->get_name() : o->get_name(false, true);
            const std::string type = o->get_type_name();
            INFO("parsons " << path << " " << name << ": " << type);
            ++valued;
            const bool number = type.rfind("INT", 0) == 0 || type.rfind("FLOAT", 0) == 0 ||
                                type.rfind("UINT", 0) == 0 || type.rfind("NUMBER", 0) == 0;
            const bool is_typed = std::find(typed.begin(), typed.end(), type) != typed.end();
            const auto free = free_text.find(path + " " + name);
            const bool is_free = free != free_text.end() && free->second == type;
            CHECK((number || is_typed || is_free || !parsons::cli::value_choices(type).empty()));
        }
    }
    CHECK(valued > 60);
    // The type names read back as their values: a deck is every extension the reader knows.
    const auto deck = parsons::cli::value_choices("DECK");
    for (const char* e :
         {"cbn", "bin", "txt", "crd", "card", "cards", "csv", "lst", "tape", "ptp", "five"}) {
        CHECK(std::find(deck.extensions.begin(), deck.extensions.end(), e) !=
              deck.extensions.end());
    }
    CHECK(deck.words.empty());
    const auto set = parsons::cli::value_choices("TEXT:{cards,ribbon}");
    CHECK(set.words == std::vector<std::string>{"cards", "ribbon"});
    CHECK(set.extensions.empty());
    const auto gcode = parsons::cli::value_choices("DECK|FILE.ngc|.nc|.gcode");
    CHECK(std::find(gcode.extensions.begin(), gcode.extensions.end(), "nc") !=
          gcode.extensions.end());
    CHECK(std::find(gcode.extensions.begin(), gcode.extensions.end(), "cbn") !=
          gcode.extensions.end());
    const auto profile = parsons::cli::value_choices("PROFILE");
    CHECK(profile.words ==
          std::vector<std::string>{"parsons-1952", "parsons-safe", "parsons-extended"});
    CHECK(profile.extensions == std::vector<std::string>{"json"});
    CHECK(parsons::cli::value_choices("DIR").folders);
    CHECK(parsons::cli::value_choices("FLOAT").empty());
    CHECK(parsons::cli::value_choices("INT:INT in [1 - 101]").empty());
    CHECK(parsons::cli::value_choices("AXIS=MIN:MAX").empty());
}

namespace {

// What the bash completion offers for COMP_WORDS=(words) with the cursor on word `cword`, in
// `dir`: COMPREPLY sorted, each word in brackets.
std::string bash_offers(const std::string& dir, const std::string& words, int cword) {
    const std::string script = std::string(PARSONS_BINARY_DIR) + "/completion/parsons.bash";
    const auto r = run_shell("cd " + q(dir) + " && bash -c " +
                             q("source " + q(script) + "; COMP_WORDS=(" + words +
                               "); COMP_CWORD=" + std::to_string(cword) +
                               "; _parsons; printf \"%s\\n\" \"${COMPREPLY[@]}\"") +
                             " 2>&1");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    auto offered = parsons::test::lines_of(r.output);
    std::sort(offered.begin(), offered.end());
    std::string out;
    for (const std::string& w : offered) {
        out += w.empty() ? "" : "[" + w + "]";
    }
    return out;
}

// A folder with one file of each kind the completion tells apart.
void fill_completion_folder(const parsons::test::TempDir& dir) {
    for (const char* f :
         {"a.cbn", "b.json", "c.txt", "d.vcd", "e.csv", "with space.cbn", "F.CBN", "g.ngc"}) {
        parsons::test::write_bytes(dir.path(f), "x");
    }
    std::filesystem::create_directories(dir.path("sub"));
}

} // namespace

TEST_CASE("Manual: the bash completion offers each value as its type says, after flags and in "
          "--option=value",
          "[cli][manual]") {
    const parsons::test::TempDir tmp;
    fill_completion_folder(tmp);
    const std::string dir = tmp.str("");
    auto complete = [&](const std::string& words, int cword) {
        return bash_offers(dir, words, cword);
    };
    const std::string decks = "[F.CBN][a.cbn][c.txt][e.csv][sub][with space.cbn]";
    // After an on/off flag, and after --json, the deck argument is next.
    CHECK(complete("parsons run -q \"\"", 3) == decks);
    CHECK(complete("parsons check --json \"\"", 3) == decks);
    CHECK(complete("parsons run --impulse-level -q \"\"", 4) == decks);
    // An option's value: its kind of file (and folders), a set of words, or nothing to offer.
    CHECK(complete("parsons run a.cbn --report \"\"", 4) == "[b.json][sub]");
    CHECK(complete("parsons run a.cbn --report = \"\"", 5) == "[b.json][sub]");
    CHECK(complete("parsons run a.cbn --report =", 4) == "[b.json][sub]");
    CHECK(complete("parsons run a.cbn --trace \"\"", 4) == "[d.vcd][sub]");
    CHECK(complete("parsons run a.cbn --feed \"\"", 4) == "[cards][ribbon]");
    CHECK(complete("parsons run a.cbn --format t", 4) == "[tape][text]");
    CHECK(complete("parsons punch e.csv --code \"\"", 4) == "[026][029]");
    CHECK(complete("parsons run a.cbn --profile \"\"", 4) ==
          "[b.json][parsons-1952][parsons-extended][parsons-safe][sub]");
    CHECK(complete("parsons gen airfoil --chord \"\"", 4).empty());
    // --dat: a .dat file, or a bundled airfoil by name.
    CHECK(complete("parsons gen airfoil --dat \"\"", 4) ==
          "[clarky][e387][n63412][naca0012][naca2412][naca63412_lednicer][sub]");
    CHECK(complete("parsons gen two-tool --dat n", 4) == "[n63412][naca0012][naca2412]"
                                                         "[naca63412_lednicer]");
    CHECK(complete("parsons run a.cbn --limit \"\"", 4).empty());
    CHECK(complete("parsons demo --out \"\"", 3) == "[sub]");
    CHECK(complete("parsons punch \"\"", 2) == "[e.csv][sub]");
    CHECK(complete("parsons convert a.cbn -o \"\"", 4) ==
          "[F.CBN][a.cbn][c.txt][e.csv][g.ngc][sub][with space.cbn]");
    CHECK(complete("parsons gen gcode \"\"", 3) == "[g.ngc][sub]");
    CHECK(complete("parsons gen tapping --ratio-source \"\"", 4) == "[stored][transferred]");
    // Internal options are offered nowhere.
    CHECK(complete("parsons bench --chi", 2).empty());
}

TEST_CASE("Manual: the zsh completion offers each value as its type says", "[cli][manual]") {
    if (run_shell("command -v zsh >/dev/null").exit_code != 0) {
        WARN("zsh is not installed (scripts/install-deps.sh installs it): not run");
        return;
    }
    const std::string script = std::string(PARSONS_BINARY_DIR) + "/completion/_parsons";
    // The completion system's functions as stubs that print how they were called.
    const std::string stubs =
        "compadd() { print -r -- \"compadd $*\"; }; _files() { print -r -- \"_files $*\"; }; "
        "_describe() { print -r -- \"_describe $1 $2 ${(P)4}\"; }; "
        "_message() { print -r -- \"_message $*\"; }; compset() { PREFIX=${PREFIX#*=}; }; ";
    auto complete = [&](const std::string& words, int current, const std::string& prefix) {
        const auto r =
            run_shell("zsh -c " +
                      q(stubs + "words=(" + words + "); CURRENT=" + std::to_string(current) +
                        "; PREFIX=" + q(prefix) + "; source " + q(script)) +
                      " 2>&1");
        INFO(r.output);
        CHECK(r.exit_code == 0);
        return r.output;
    };
    const std::string decks =
        "_files -g *.(#i)(cbn|bin|txt|crd|card|cards|csv|lst|tape|ptp|five)\n";
    CHECK(complete("parsons run -q \"\"", 4, "") == decks);
    CHECK(complete("parsons check --json \"\"", 4, "") == decks);
    CHECK(complete("parsons run a.cbn --report \"\"", 5, "") == "_files -g *.(#i)(json)\n");
    CHECK(complete("parsons run a.cbn --report=", 4, "--report=") == "_files -g *.(#i)(json)\n");
    CHECK(complete("parsons run a.cbn --feed \"\"", 5, "") == "compadd -- cards ribbon\n");
    CHECK(complete("parsons run a.cbn --profile \"\"", 5, "") ==
          "compadd -- parsons-1952 parsons-safe parsons-extended\n_files -g *.(#i)(json)\n");
    CHECK(complete("parsons gen airfoil --chord \"\"", 5, "") == "_message FLOAT\n");
    CHECK(complete("parsons demo --out \"\"", 4, "") == "_files -/\n");
    const std::string bench = complete("parsons bench --", 3, "--");
    CHECK(bench.find("--runs:") != std::string::npos);
    CHECK(bench.find("--child") == std::string::npos);
}

TEST_CASE("Manual: the bash completion offers commands, subcommands and options as typed",
          "[cli][manual]") {
    const parsons::test::TempDir tmp;
    auto complete = [&](const std::string& words, int cword) {
        return bash_offers(tmp.str(""), words, cword);
    };
    const std::string commands = complete("parsons \"\"", 1);
    CHECK(commands.find("[run]") != std::string::npos);
    CHECK(commands.find("tapping") == std::string::npos); // gen's, not here
    CHECK(complete("parsons gen ta", 2) == "[tapping]");
    CHECK(complete("parsons run deck.cbn --thr", 3) == "[--thread-proof][--thread-tolerance]");
    CHECK(complete("parsons gen tapping --rat", 3) == "[--ratio-source]");
    CHECK(complete("parsons --ver", 1) == "[--version]");
}
