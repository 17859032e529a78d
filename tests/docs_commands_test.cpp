// Docs that match the binary (the command-line issue, item 6): every example of every
// command's --help, and every command of the README and the tutorial, run as written in a
// scratch folder (with `decks/` of the source tree and `build/cli/parsons` beside them); the
// exit codes they document, the figures the tutorial quotes and its pictures must be what the
// binary gives today.
//
// PARSONS_UPDATE_DOCS=1 (scripts/docs.sh) rewrites the quoted figures and copies the pictures
// into docs/images/ instead of comparing them.
#include "tests/docs_figures.hpp"
#include "tests/docs_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

using namespace parsons::test;
namespace fs = std::filesystem;

namespace {

bool updating() {
    const char* v = std::getenv("PARSONS_UPDATE_DOCS");
    return v != nullptr && std::string(v) == "1";
}

std::string join_lines(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) {
        out += l + "\n";
    }
    return out;
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t");
    const auto b = s.find_last_not_of(" \t");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// Runs of spaces and newlines as one space.
std::string squeeze(const std::string& s) {
    std::string out;
    for (char c : s) {
        const bool space = c == ' ' || c == '\n' || c == '\t';
        if (space && (out.empty() || out.back() == ' ')) {
            continue;
        }
        out += space ? ' ' : c;
    }
    return trim(out);
}

// `text` holds `pattern`, where "…" in the pattern stands for any run of characters.
bool matches_with_ellipsis(const std::string& text, const std::string& pattern) {
    const std::string ellipsis = "…";
    std::size_t at = 0;
    std::size_t from = 0;
    while (true) {
        const auto next = pattern.find(ellipsis, from);
        const std::string piece = trim(pattern.substr(from, next - from));
        if (!piece.empty()) {
            const auto found = text.find(piece, at);
            if (found == std::string::npos) {
                return false;
            }
            at = found + piece.size();
        }
        if (next == std::string::npos) {
            return true;
        }
        from = next + ellipsis.size();
    }
}

// A scratch folder laid out as the source tree is for a reader of the docs: decks/ (the
// shipped samples and airfoils), build/cli/parsons, and parsons on the PATH.
class Scratch {
public:
    Scratch() {
        fs::create_directories(dir_.path("build/cli"));
        fs::create_directories(dir_.path("bin"));
        fs::create_symlink(PARSONS_EXE, dir_.path("build/cli/parsons"));
        fs::create_symlink(PARSONS_EXE, dir_.path("bin/parsons"));
        fs::create_directory_symlink(source_path("decks"), dir_.path("decks"));
    }
    ProcessResult run(const std::string& command) const {
        return run_shell("cd " + q(dir_.str(".")) + " && PATH=" + q(dir_.str("bin")) +
                         ":\"$PATH\" && " + command);
    }
    fs::path path(const std::string& relative) const { return dir_.path(relative); }

private:
    TempDir dir_;
};

// "exit N" in a command's comment: the code it is documented to return (0 when none).
int documented_exit(const std::string& comment) {
    std::smatch m;
    if (std::regex_search(comment, m, std::regex(R"(exit (\d+))"))) {
        return std::stoi(m[1]);
    }
    return 0;
}

struct Example {
    std::string command;
    std::string comment;
    std::vector<std::string> expected; // output the doc quotes right under the command
};

// The commands of a Markdown page's indented code blocks: lines that begin with
// `build/cli/parsons`, `parsons` (on the PATH), `mkdir` or `awk`, with or without a `$ ` prompt
// (continued over lines ending in a backslash), with their trailing `# comment`; the lines under a
// command in the same block are output it must print.
std::vector<Example> page_commands(const std::string& markdown) {
    std::vector<Example> out;
    bool in_block = false;
    std::string pending;
    for (const std::string& raw : lines_of(markdown)) {
        const bool indented = raw.rfind("    ", 0) == 0;
        if (!indented) {
            in_block = false;
            continue;
        }
        // "$ COMMAND": a terminal session, indented.
        const std::string line = raw.rfind("    $ ", 0) == 0 ? raw.substr(6) : raw.substr(4);
        if (!pending.empty()) {
            pending += " " + trim(line);
        } else if (line.rfind("build/cli/parsons ", 0) == 0 || line.rfind("parsons ", 0) == 0 ||
                   line.rfind("mkdir ", 0) == 0 || line.rfind("awk ", 0) == 0) {
            pending = line;
            in_block = true;
        } else if (in_block && !out.empty()) {
            out.back().expected.push_back(line);
            continue;
        } else {
            continue;
        }
        if (!pending.empty() && pending.back() == '\\') {
            pending.pop_back();
            continue;
        }
        Example e;
        const auto hash = pending.find("  #");
        e.command = trim(pending.substr(0, hash));
        e.comment = hash == std::string::npos ? "" : pending.substr(hash);
        out.push_back(e);
        pending.clear();
    }
    return out;
}

void check_quoted_output(const Example& e, const ProcessResult& r) {
    if (e.expected.empty()) {
        return;
    }
    std::string quoted;
    for (const auto& l : e.expected) {
        quoted += l + " ";
    }
    INFO("quoted: " << quoted << "\nprinted: " << r.output);
    CHECK(matches_with_ellipsis(squeeze(r.output), squeeze(quoted)));
}

// A fenced block quotes lines of the last command's output: each quoted line stands for the
// printed line that begins with the same 16 characters (its label), and must equal it.
void check_fenced(std::vector<std::string>& lines, std::size_t open, std::size_t close,
                  const std::string& printed, bool& changed) {
    const auto out_lines = lines_of(printed);
    for (std::size_t i = open + 1; i < close; ++i) {
        std::string& quoted = lines.at(i);
        const std::string label = quoted.substr(0, std::min<std::size_t>(16, quoted.size()));
        const auto found = std::find_if(out_lines.begin(), out_lines.end(),
                                        [&](const auto& l) { return l.rfind(label, 0) == 0; });
        INFO("quoted line: " << quoted << "\nprinted:\n" << printed);
        REQUIRE(found != out_lines.end());
        if (updating()) {
            changed = changed || quoted != *found;
            quoted = *found;
        } else {
            CHECK(quoted == *found);
        }
    }
}

// Pictures: an image whose line is preceded by `<!-- drawn by the commands above: FILE -->`
// must be the file those commands drew (in the scratch folder), byte for byte.
void check_pictures(const std::vector<std::string>& lines, const fs::path& page,
                    const Scratch& scratch, int& compared) {
    static const std::regex from(R"(<!-- drawn by the commands above: (\S+) -->)");
    static const std::regex image(R"(!\[[^\]]*\]\(([^)]+)\))");
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
        std::smatch f;
        std::smatch img;
        if (!std::regex_search(lines.at(i), f, from) ||
            !std::regex_search(lines.at(i + 1), img, image)) {
            continue;
        }
        const fs::path drawn = scratch.path(f[1]);
        const fs::path shipped = page.parent_path() / std::string(img[1]);
        INFO(shipped.string() << " from " << drawn.string());
        REQUIRE(fs::exists(drawn));
        ++compared;
        if (updating()) {
            fs::copy_file(drawn, shipped, fs::copy_options::overwrite_existing);
        } else {
            CHECK(read_bytes(drawn) == read_bytes(shipped));
        }
    }
}

// A block the docs test does not run says why on the line before it (blank lines between
// allowed): `<!-- not run: REASON -->`. The reason, or nothing when the block has no marker.
std::optional<std::string> not_run_reason(const std::vector<std::string>& lines,
                                          std::size_t block) {
    static const std::regex marker(R"(^<!-- not run: (.+) -->$)");
    for (std::size_t i = block; i-- > 0;) {
        if (trim(lines.at(i)).empty()) {
            continue;
        }
        std::smatch m;
        if (std::regex_match(lines.at(i), m, marker)) {
            return std::string(m[1]);
        }
        return std::nullopt;
    }
    return std::nullopt;
}

// A line of a code block that is a command the docs test cannot run in its scratch folder (a
// build script, another program): such a block must carry a not-run marker.
bool foreign_command(const std::string& line) {
    static const std::regex foreign(
        R"(^(scripts/|cmake |cpack |sudo |apt |gtkwave |ctest |node |npm |chromium |valgrind |jq |PARSONS_\w+=|build/tests/|build-\w+/|man |source |xvfb-run |git ))");
    return std::regex_search(line, foreign) || line.find("| jq") != std::string::npos;
}

struct PageRun {
    int commands = 0;
    int figures = 0;
    std::vector<std::string> not_run; // "page:line: reason"
};

// A fenced block right under a block of commands (nothing but blank lines between) quotes
// their output.
bool right_after(const std::vector<std::string>& lines, std::size_t commands_end,
                 std::size_t fence) {
    if (commands_end == 0 || commands_end > fence) {
        return false;
    }
    for (std::size_t i = commands_end; i < fence; ++i) {
        if (!trim(lines.at(i)).empty()) {
            return false;
        }
    }
    return true;
}

// A terminal session in a fenced block: each `$ COMMAND` line runs (its `# comment` may give the
// exit code), and the lines under it, up to the next `$`, are what it prints ("..." alone on a
// line standing for any lines).
void run_session(const std::vector<std::string>& block, const std::string& relative,
                 const Scratch& scratch, PageRun& run, std::string& last_output) {
    std::vector<Example> session;
    for (const std::string& l : block) {
        if (l.rfind("$ ", 0) == 0) {
            Example e;
            const std::string line = l.substr(2);
            const auto hash = line.find("  #");
            e.command = trim(line.substr(0, hash));
            e.comment = hash == std::string::npos ? "" : line.substr(hash);
            session.push_back(e);
        } else if (!session.empty()) {
            session.back().expected.push_back(trim(l) == "..." ? "…" : l);
        }
    }
    for (const Example& e : session) {
        INFO(relative << ": $ " << e.command);
        CHECK_FALSE(foreign_command(e.command));
        const ProcessResult r = scratch.run(e.command);
        INFO(r.output);
        CHECK(r.exit_code == documented_exit(e.comment));
        check_quoted_output(e, r);
        last_output = r.output;
        ++run.commands;
    }
}

// Runs a page's commands in order in one scratch folder, checks their exit codes and the
// output they quote, then the fenced blocks (against the output of the command before them,
// where `fenced_are_output`: README and the tutorial) and the pictures. A block marked not to be
// run is counted in `run.not_run`; an unmarked block with a command the test cannot run fails.
void run_page(const std::string& relative, Scratch& scratch, int& pictures, PageRun& run,
              bool fenced_are_output = true) {
    const fs::path page = source_path(relative);
    std::vector<std::string> lines = lines_of(read_bytes(page));
    std::string last_output;
    bool changed = false;
    std::size_t commands_end = 0; // the line after the last block of commands run
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines.at(i);
        if (line.rfind("```", 0) == 0) {
            const auto close = std::find_if(lines.begin() + static_cast<long>(i) + 1, lines.end(),
                                            [](const auto& l) { return l.rfind("```", 0) == 0; });
            REQUIRE(close != lines.end());
            const auto c = static_cast<std::size_t>(close - lines.begin());
            const std::vector<std::string> block(lines.begin() + static_cast<long>(i) + 1, close);
            const bool session = std::any_of(block.begin(), block.end(),
                                             [](const auto& l) { return l.rfind("$ ", 0) == 0; });
            if (session) {
                if (const auto reason = not_run_reason(lines, i)) {
                    run.not_run.push_back(relative + ":" + std::to_string(i + 1) + ": " + *reason);
                } else {
                    run_session(block, relative, scratch, run, last_output);
                }
            } else if ((fenced_are_output || right_after(lines, commands_end, i)) &&
                       !last_output.empty()) {
                check_fenced(lines, i, c, last_output, changed);
            }
            i = c;
            continue;
        }
        // An indented block: collect it whole, then run its commands.
        if (line.rfind("    ", 0) == 0) {
            std::size_t end = i;
            while (end < lines.size() && lines.at(end).rfind("    ", 0) == 0) {
                ++end;
            }
            std::vector<std::string> block(lines.begin() + static_cast<long>(i),
                                           lines.begin() + static_cast<long>(end));
            const auto reason = not_run_reason(lines, i);
            if (reason) {
                run.not_run.push_back(relative + ":" + std::to_string(i + 1) + ": " + *reason);
                i = end - 1;
                continue;
            }
            for (const std::string& b : block) {
                INFO(relative << ":" << i + 1 << ": a command the docs test cannot run: mark the "
                              << "block <!-- not run: REASON --> or make it runnable");
                CHECK_FALSE(foreign_command(trim(b)));
            }
            commands_end = end;
            for (const Example& e : page_commands(join_lines(block))) {
                const ProcessResult r = scratch.run(e.command);
                INFO(relative << ": " << e.command << "\n" << r.output);
                CHECK(r.exit_code ==
                      (e.expected.empty() || e.expected.front().rfind("parsons: error:", 0) != 0
                           ? documented_exit(e.comment)
                           : 2));
                check_quoted_output(e, r);
                last_output = r.output;
                ++run.commands;
            }
            i = end - 1;
        }
    }
    check_pictures(lines, page, scratch, pictures);
    check_figures(
        lines, relative, [&](const std::string& c) { return scratch.run(c); }, scratch.path("."),
        updating(), changed, run.figures);
    if (updating() && changed) {
        std::ofstream(page, std::ios::binary) << join_lines(lines);
    }
}

std::vector<std::string> help_examples(const std::string& help) {
    std::vector<std::string> out;
    bool in_examples = false;
    for (const std::string& line : lines_of(help)) {
        if (line.rfind("Example", 0) == 0) {
            in_examples = true;
            continue;
        }
        if (in_examples && line.rfind("  parsons ", 0) == 0) {
            out.push_back(trim(line));
        } else if (in_examples && trim(line).empty()) {
            in_examples = false;
        }
    }
    return out;
}

} // namespace

TEST_CASE("Docs: every example of every command's --help runs as written against shipped "
          "files, with the exit code its comment gives",
          "[docs][cli][heavy]") {
    // Every command, and the commands under one (gen airfoil), as `parsons --help` lists them.
    std::vector<std::string> commands;
    for (const std::string& c : subcommands(run_parsons("--help").output)) {
        const auto sub = subcommands(run_parsons(c + " --help").output);
        if (sub.empty()) {
            commands.push_back(c);
        }
        for (const std::string& s : sub) {
            commands.push_back(c + " " + s);
        }
    }
    REQUIRE(commands.size() >= 9);
    int examples = 0;
    for (const std::string& c : commands) {
        // A fresh folder for each command: its examples need nothing but the shipped files and
        // what an example before them in the same --help wrote.
        Scratch scratch;
        const auto help = run_parsons(c + " --help");
        REQUIRE(help.exit_code == 0);
        const auto lines = help_examples(help.output);
        INFO(c);
        CHECK_FALSE(lines.empty()); // every command shows one
        for (const std::string& line : lines) {
            // "parsons ARGS   (a comment)": the comment may give the exit code.
            const auto comment = line.find("   (");
            const std::string command = trim(line.substr(0, comment));
            const int expected =
                comment == std::string::npos ? 0 : documented_exit(line.substr(comment));
            const ProcessResult r = scratch.run(command);
            INFO(command << "\n" << r.output);
            CHECK(r.exit_code == expected);
            ++examples;
        }
    }
    CHECK(examples >= 15);
}

TEST_CASE("Docs: every command of the README and the tutorial runs as written, and the "
          "figures and pictures they quote are what the binary gives",
          "[docs][cli][heavy]") {
    int pictures = 0;
    {
        Scratch scratch;
        PageRun run;
        run_page("README.md", scratch, pictures, run);
        CHECK(run.commands > 20);
    }
    {
        Scratch scratch;
        PageRun run;
        run_page("docs/tutorial.md", scratch, pictures, run);
        CHECK(run.commands > 5);
        // The prose figures of step 2: cards and minutes of machine time.
        const std::string tutorial = read_bytes(source_path("docs/tutorial.md"));
        std::smatch m;
        REQUIRE(std::regex_search(tutorial, m,
                                  std::regex(R"((\d+) cards and about (\w+) minutes of 1952)")));
        const auto report =
            nlohmann::json::parse(read_bytes(scratch.path("out/tutorial/report.json")));
        static const std::vector<std::string> words = {"zero", "one",    "two",   "three", "four",
                                                       "five", "six",    "seven", "eight", "nine",
                                                       "ten",  "eleven", "twelve"};
        const auto minutes =
            static_cast<std::size_t>(std::lround(report["machine_seconds"].get<double>() / 60));
        REQUIRE(minutes < words.size());
        const std::string cards = std::to_string(report["cards_read"].get<long>());
        if (updating()) {
            const std::string figures =
                cards + " cards and about " + words.at(minutes) + " minutes of 1952";
            std::ofstream(source_path("docs/tutorial.md"), std::ios::binary)
                << m.prefix().str() << figures << m.suffix().str();
        } else {
            CHECK(cards == std::string(m[1]));
            CHECK(words.at(minutes) == std::string(m[2]));
        }
    }
    CHECK(pictures >= 5);
}

TEST_CASE("Docs: every command of every page under docs/ runs as written, with the exit code and "
          "output it documents, or its block says why not",
          "[docs][cli][heavy]") {
    PageRun run;
    int pictures = 0;
    int pages = 0;
    for (const auto& entry : fs::directory_iterator(source_path("docs"))) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".md" || name == "tutorial.md") {
            continue; // the tutorial: the test above, with its figures
        }
        ++pages;
        Scratch scratch; // a fresh folder a page: a page's commands build on each other only
        run_page("docs/" + name, scratch, pictures, run, false);
    }
    CHECK(pages >= 24);
    CHECK(run.commands >= 15);
    CHECK(run.figures >= 5);
    // What is not run, and why, for the log.
    std::string skipped;
    for (const std::string& s : run.not_run) {
        skipped += "  " + s + "\n";
    }
    WARN(run.commands << " commands run and " << run.figures << " figures checked on " << pages
                      << " pages; " << run.not_run.size() << " blocks not run:\n"
                      << skipped);
}

namespace {

// The cells of a Markdown table row (`| a | b |`), trimmed. A code span may not hold `|`.
std::vector<std::string> table_cells(const std::string& row) {
    std::vector<std::string> cells;
    std::size_t from = 1;
    while (from < row.size()) {
        const auto bar = row.find('|', from);
        if (bar == std::string::npos) {
            break;
        }
        cells.push_back(trim(row.substr(from, bar - from)));
        from = bar + 1;
    }
    return cells;
}

// The first code span of a cell, or "" when it has none.
std::string first_code_span(const std::string& cell) {
    const auto open = cell.find('`');
    if (open == std::string::npos) {
        return "";
    }
    const auto close = cell.find('`', open + 1);
    return close == std::string::npos ? "" : cell.substr(open + 1, close - open - 1);
}

struct ClaimRow {
    std::string section;
    int claim = 0;
    std::string command;  // empty: the emulator does not show the claim
    std::string look_for; // the whole cell
    std::string test;     // the whole cell
};

std::vector<ClaimRow> claim_rows(const std::string& markdown) {
    std::vector<ClaimRow> rows;
    std::string section;
    for (const std::string& line : lines_of(markdown)) {
        if (line.rfind("## ", 0) == 0) {
            section = line.substr(3);
            continue;
        }
        if (line.rfind("| ", 0) != 0 || line.rfind("| claim |", 0) == 0 ||
            line.rfind("|---", 0) == 0) {
            continue;
        }
        const auto cells = table_cells(line);
        REQUIRE(cells.size() == 5);
        ClaimRow r;
        r.section = section;
        r.claim = std::stoi(cells.at(0));
        r.command = cells.at(2) == "—" ? "" : first_code_span(cells.at(2));
        r.look_for = cells.at(3);
        r.test = cells.at(4);
        rows.push_back(r);
    }
    return rows;
}

} // namespace

TEST_CASE("Docs: the claims table lists every claim of the five seed patents, runs every command "
          "in it and finds what each row says to look for, and names tests that exist",
          "[docs][cli][claims]") {
    const std::vector<ClaimRow> rows = claim_rows(read_bytes(source_path("docs/claims.md")));
    // Each patent's claims, numbered 1 to N in order: US 2,820,187 has 23 ("23 Claims"),
    // EP 0640901 six, EP 0436887 nine, EP 0360190 three, EP 0636958 sixteen.
    const std::vector<std::pair<std::string, int>> patents = {{"US 2,820,187", 23},
                                                              {"EP 0640901", 6},
                                                              {"EP 0436887", 9},
                                                              {"EP 0360190", 3},
                                                              {"EP 0636958", 16}};
    std::size_t at = 0;
    for (const auto& [patent, claims] : patents) {
        for (int n = 1; n <= claims; ++n, ++at) {
            INFO(patent << " claim " << n);
            REQUIRE(at < rows.size());
            CHECK(rows.at(at).section.rfind(patent, 0) == 0);
            CHECK(rows.at(at).claim == n);
        }
    }
    CHECK(at == rows.size());
    Scratch scratch;
    int shown = 0;
    for (const ClaimRow& row : rows) {
        INFO(row.section << ", claim " << row.claim);
        // The test cell: `tests/FILE.cpp` "part of a TEST_CASE name", or a dash.
        std::smatch m;
        if (row.test != "—") {
            REQUIRE(std::regex_search(row.test, m, std::regex(R"re(`(tests/[^`]+)` "([^"]+)")re")));
            const std::string file = read_bytes(source_path(m[1]));
            CHECK(file.find(std::string(m[2])) != std::string::npos);
        }
        if (row.command.empty()) {
            CHECK(row.look_for.size() > 40); // the sentence on why the emulator does not show it
            continue;
        }
        const bool runs_parsons = row.command.rfind("build/cli/parsons ", 0) == 0 ||
                                  row.command.rfind("mkdir -p out/claims && ", 0) == 0 ||
                                  row.command.rfind("printf ", 0) == 0;
        REQUIRE(runs_parsons);
        const std::string literal = first_code_span(row.look_for);
        REQUIRE_FALSE(literal.empty());
        const ProcessResult r = scratch.run(row.command);
        INFO(row.command << "\n" << r.output.substr(0, 4000));
        CHECK(r.exit_code == documented_exit(row.look_for));
        CHECK(r.output.find(literal) != std::string::npos);
        ++shown;
    }
    CHECK(shown >= 40);
}
