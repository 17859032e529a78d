// The one rule for numbers on the command line (cli/support/number_rule.hpp, docs/stop-codes.md):
// written in decimal and finite, or refused naming the option (exit 2). Held for every number
// option of every command, read from the command line itself, so a new option is held too.
#include "cli/command_line.hpp"
#include "cli/support/manual.hpp"
#include "cli/support/number_rule.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using parsons::cli::number_problem;
using parsons::cli::NumberKind;
using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::TempDir;

namespace {

struct NumberCommandLine {
    CLI::App app;
    parsons::cli::Command selected;
    NumberCommandLine() { parsons::cli::build_command_line(app, selected, "parsons test"); }
};

// The words of a command path ("gen airfoil"), then `more`.
std::vector<std::string> number_command_words(const std::string& path,
                                              const std::vector<std::string>& more) {
    std::vector<std::string> words;
    std::istringstream in(path);
    std::string w;
    while (in >> w) {
        words.push_back(w);
    }
    words.insert(words.end(), more.begin(), more.end());
    return words;
}

// Parses `parsons WORDS` on a fresh command line; the ValidationError's message, or "" when the
// parse got past every value (a required option missing is no concern here).
std::string validation_error(const std::vector<std::string>& words) {
    NumberCommandLine cl;
    std::vector<std::string> reversed(words.rbegin(), words.rend()); // CLI11 takes them reversed
    try {
        cl.app.parse(reversed);
    } catch (const CLI::ValidationError& e) {
        return e.what();
    } catch (const CLI::ParseError&) {
        return "";
    }
    return "";
}

bool number_option_type(const std::string& type) {
    const std::string base = type.substr(0, type.find(':'));
    return base == "INT" || base == "UINT" || base == "FLOAT";
}

} // namespace

TEST_CASE("Number rule: decimal and finite, or the reason it is not", "[cli][numbers]") {
    for (const char* good : {"6", "-0.5", "+2", "1.5e-3", "1E3", ".5", "5.", "0", "1e-400"}) {
        INFO(good);
        CHECK_FALSE(number_problem(good, NumberKind::real));
    }
    for (const char* good : {"3", "-5", "+7", "010", "2147483647", "-2147483648"}) {
        INFO(good);
        CHECK_FALSE(number_problem(good, NumberKind::whole));
    }
    struct Bad {
        const char* text;
        NumberKind kind;
        const char* says;
    };
    const std::vector<Bad> bad = {
        {"nan", NumberKind::real, "'nan' is not a number"},
        {"-NaN", NumberKind::real, "is not a number"},
        {"nan(0x1)", NumberKind::real, "is not a number"},
        {"inf", NumberKind::real, "'inf' is not finite"},
        {"-Infinity", NumberKind::real, "is not finite"},
        {"1e400", NumberKind::real, "'1e400' is too large"},
        {"-1e309", NumberKind::real, "is too large"},
        {"0x6", NumberKind::real, "'0x6' is not decimal"},
        {"-0X1p3", NumberKind::real, "is not decimal"},
        {"0x10", NumberKind::whole, "is not decimal"},
        {"0b101", NumberKind::whole, "is not decimal"},
        {"1.5", NumberKind::whole, "'1.5' is not a whole number"},
        {"1e3", NumberKind::whole, "is not a whole number"},
        {"2147483648", NumberKind::whole, "is too large"},
        {"-99999999999999999999", NumberKind::whole, "is too large"},
        {"", NumberKind::real, "an empty value"},
        {"6in", NumberKind::real, "'6in' is not a number"},
        {"1e", NumberKind::real, "is not a number"},
        {".", NumberKind::real, "is not a number"},
        {"- 5", NumberKind::whole, "is not a number"},
        {" 5", NumberKind::real, "is not a number"},
    };
    for (const Bad& b : bad) {
        INFO(b.text);
        const auto problem = number_problem(b.text, b.kind);
        REQUIRE(problem);
        CHECK(problem->find(b.says) != std::string::npos);
    }
}

TEST_CASE("Number rule: every number option of every command refuses NaN, infinities, overflow "
          "and hexadecimal, naming the option",
          "[cli][numbers]") {
    NumberCommandLine cl;
    int options = 0;
    for (const auto& [path, app] : parsons::cli::command_paths(cl.app)) {
        for (const CLI::Option* o : app->get_options({})) {
            if (o->get_positional() || o->get_items_expected_max() == 0 ||
                !number_option_type(o->get_type_name())) {
                continue;
            }
            ++options;
            const std::string name = o->get_name(false, true);
            for (const char* value : {"nan", "NaN", "inf", "-inf", "1e400", "0x6", "0x1p3"}) {
                INFO("parsons " << path << " " << name << " " << value);
                const std::string error =
                    validation_error(number_command_words(path, {name, value}));
                CHECK(error.find(name) != std::string::npos);
            }
        }
    }
    // The options of gen (airfoil, two-tool, gcode, press-feeder, tapping), run, bench: dozens.
    CHECK(options > 40);
}

TEST_CASE("Number rule: a number option takes decimal numbers as written, a whole number's "
          "leading zeros as decimal",
          "[cli][numbers]") {
    NumberCommandLine cl;
    // Reversed, as CLI11 takes a vector; -o is required and left out: the values are read first.
    CHECK_THROWS_AS(cl.app.parse(std::vector<std::string>{"010", "--rows", "tapping", "gen"}),
                    CLI::RequiredError);
    CLI::App* tapping = cl.app.get_subcommand("gen")->get_subcommand("tapping");
    CHECK(tapping->get_option("--rows")->as<int>() == 10); // not octal 8
    NumberCommandLine airfoil;
    CHECK_THROWS_AS(airfoil.app.parse(std::vector<std::string>{"1.5e-1", "--scallop", ".5",
                                                               "--chord", "airfoil", "gen"}),
                    CLI::RequiredError);
    CLI::App* gen = airfoil.app.get_subcommand("gen")->get_subcommand("airfoil");
    CHECK(gen->get_option("--chord")->as<double>() == 0.5);
    CHECK(gen->get_option("--scallop")->as<double>() == 0.15);
}

TEST_CASE("Number rule: gen gcode --work-zero nan,0,0.5 is refused naming --work-zero, and no "
          "deck is written",
          "[cli][numbers]") {
    TempDir dir;
    parsons::test::write_bytes(dir.path("p.ngc"), "G21\nG90\nG0 X0 Y0 Z5\nG1 Z-1\nG1 X10 Y5\n"
                                                  "G0 Z5\nM2\n");
    for (const char* zero : {"nan,0,0.5", "0,inf,0.5", "0,0,1e999", "0x1,0,0.5"}) {
        INFO(zero);
        const auto r = run_parsons("gen gcode " + q(dir.str("p.ngc")) + " -o " +
                                   q(dir.str("d.csv")) + " --work-zero " + zero);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("parsons: error: --work-zero: ") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir.path("d.csv")));
    }
}

TEST_CASE("Number rule: --limit's MIN and MAX keep the rule of every number option",
          "[cli][numbers]") {
    for (const char* limit : {"table=0x0:9", "table=0:nan", "table=-inf:9", "table=0:1e400"}) {
        INFO(limit);
        const auto r = run_parsons(
            "check " + q(parsons::test::source_path(parsons::test::kSample)) + " --limit " + limit);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find(std::string("--limit '") + limit + "': '") != std::string::npos);
    }
    const auto hex = run_parsons("check " + q(parsons::test::source_path(parsons::test::kSample)) +
                                 " --limit table=0x0:9");
    CHECK(hex.output.find("is not decimal") != std::string::npos);
}
