// Exit codes that mean what the docs say (issue 17, item 2): every command's --help lists the
// codes it can return, each command really returns each of them, CLI11's own messages are
// worded as ours with exit 2, and `check` exits 3 exactly when the machine will stop.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using parsons::test::idle_rest;
using parsons::test::kHeader;
using parsons::test::long_listing;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

const std::string kSampleDeck =
    std::string(PARSONS_SOURCE_DIR) + "/decks/samples/patent-example.csv";

// The codes listed under "Exit codes:" in a help text.
std::set<int> listed_codes(const std::string& help) {
    std::set<int> codes;
    std::istringstream in(help.substr(help.find("Exit codes:")));
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line) && !line.empty()) {
        codes.insert(std::stoi(line));
    }
    return codes;
}

// The table of docs/stop-codes.md, "Exit codes of every command": each command's codes, as
// the rows' last cell names it ("all", or "run, convert (to G-code), check").
std::map<std::string, std::set<int>> documented_codes(const std::vector<std::string>& commands) {
    std::map<std::string, std::set<int>> out;
    const std::string page = read_bytes(source_path("docs/stop-codes.md"));
    const auto from = page.find("## Exit codes of every command");
    REQUIRE(from != std::string::npos);
    std::istringstream in(page.substr(from));
    std::string line;
    int rows = 0;
    while (std::getline(in, line)) {
        if (line.rfind("| ", 0) != 0 || line.rfind("| code", 0) == 0) {
            if (rows > 0 && line.empty()) {
                break;
            }
            continue;
        }
        ++rows;
        std::vector<std::string> cells;
        std::size_t at = 1;
        for (auto bar = line.find(" | ", at); bar != std::string::npos;
             at = bar + 3, bar = line.find(" | ", at)) {
            cells.push_back(line.substr(at, bar - at));
        }
        cells.push_back(line.substr(at, line.rfind(" |") - at));
        REQUIRE(cells.size() == 3);
        std::set<int> codes;
        std::istringstream numbers(cells.front());
        for (std::string n; std::getline(numbers, n, ',');) {
            codes.insert(std::stoi(n));
        }
        const std::string who = cells.back();
        for (const std::string& c : commands) {
            const std::string top = c.substr(0, c.find(' ')); // gen airfoil: gen's row
            const bool named = who.rfind("all", 0) == 0 ||
                               (" " + who + ",").find(" " + top + ",") != std::string::npos ||
                               (" " + who + ",").find(" " + top + " (") != std::string::npos;
            if (named) {
                out[c].insert(codes.begin(), codes.end());
            }
        }
    }
    CHECK(rows >= 6);
    return out;
}

} // namespace

TEST_CASE("Exit codes: every command's --help lists exactly the codes docs/stop-codes.md's table "
          "gives it, 2, 141 and 1 included",
          "[cli][exit-codes]") {
    const std::vector<std::string> commands = {"run",     "check",   "demo", "show",
                                               "punch",   "convert", "gen",  "gen airfoil",
                                               "profile", "bench",   "sweep"};
    const auto expected = documented_codes(commands);
    // The table as it reads today, so a row that loses a command is seen here too.
    CHECK(expected.at("run") == std::set<int>{0, 1, 2, 3, 130, 141, 143});
    CHECK(expected.at("demo") == std::set<int>{0, 1, 2, 130, 141, 143});
    CHECK(expected.at("show") == std::set<int>{0, 1, 2, 141});
    CHECK(expected.at("sweep") == std::set<int>{0, 1, 2, 130, 141, 143});
    REQUIRE(expected.size() == commands.size());
    for (const auto& [command, codes] : expected) {
        const auto help = run_parsons(command + " --help");
        INFO(command << ":\n" << help.output);
        CHECK(help.exit_code == 0);
        REQUIRE(help.output.find("Exit codes:") != std::string::npos);
        CHECK(listed_codes(help.output) == codes);
        CHECK(help.output.find("  1    internal error: a bug in parsons") != std::string::npos);
    }
}

TEST_CASE("Exit codes: CLI11's own messages are worded as ours, name the help to read, and "
          "exit 2",
          "[cli][exit-codes]") {
    const std::map<std::string, std::string> cases = {
        {"run", "DECK is required (see 'parsons run --help')"},
        {"run deck.cbn --no-such-option",
         "The following argument was not expected: --no-such-option (see 'parsons run --help')"},
        {"gen airfoil --naca 2412 --stations many -o x.cbn",
         "--stations: 'many' is not a number: give a whole number such as 3 (see 'parsons gen "
         "airfoil --help')"},
        {"check a.cbn b.cbn", "(see 'parsons check --help')"},
        {"bench --runs 0", "(see 'parsons bench --help')"},
        {"", "A subcommand is required (see 'parsons --help')"}};
    for (const auto& [args, message] : cases) {
        const auto r = run_parsons(args);
        INFO("parsons " << args << ":\n" << r.output);
        CHECK(r.exit_code == 2);
        CHECK(r.output.rfind("parsons: error: ", 0) == 0);
        CHECK(r.output.find(message) != std::string::npos);
    }
}

TEST_CASE("Exit codes: each command returns 0 when it did its work and 2 on input it cannot "
          "read",
          "[cli][exit-codes]") {
    TempDir dir;
    const std::string missing = q(dir.str("missing.cbn"));
    const std::string deck = q(dir.str("deck.cbn"));
    REQUIRE(run_parsons("punch " + q(kSampleDeck) + " -o " + deck).exit_code == 0);
    const std::map<std::string, std::string> ok = {
        {"run", "run -q " + deck},
        {"check", "check " + deck},
        {"show", "show " + deck},
        {"convert", "convert " + deck + " -o " + q(dir.str("deck.bin"))},
        {"gen airfoil", "gen airfoil --naca 0012 --stations 20 -o " + q(dir.str("g.cbn"))},
        {"profile", "profile"},
        {"demo", "demo --out " + q(dir.str("demo"))},
        {"bench", "bench --runs 1 --long-cards 2 --trace-cards 2 --short-cards 10 --memory-cards "
                  "100 --press-cycles 2 --json"}};
    for (const auto& [command, args] : ok) {
        const auto r = run_parsons(args);
        INFO(args << ":\n" << r.output);
        CHECK(r.exit_code == 0);
    }
    const std::map<std::string, std::string> bad = {
        {"run", "run " + missing},
        {"check", "check " + missing},
        {"show", "show " + missing},
        {"punch", "punch " + missing + " -o " + q(dir.str("p.cbn"))},
        {"convert", "convert " + missing + " -o " + q(dir.str("c.bin"))},
        {"gen airfoil", "gen airfoil --dat " + missing + " -o " + q(dir.str("g2.cbn"))},
        {"profile", "profile --profile " + missing},
        {"demo", "demo --out " + q(dir.str("deck.cbn") + "/demo")}, // under a file: no folder
        {"bench", "bench --runs 1000"}};
    for (const auto& [command, args] : bad) {
        const auto r = run_parsons(args);
        INFO(args << ":\n" << r.output);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("parsons: error: ") != std::string::npos);
    }
}

TEST_CASE("Exit codes: a file name longer than the system allows, as deck, profile, job or "
          "output, is refused with exit 2 naming it, never an internal error",
          "[cli][exit-codes]") {
    // Found by the argv fuzz target: std::filesystem's throwing checks ended in exit 1.
    TempDir dir;
    const std::string too_long(5000, 'a');
    const std::string deck = q(dir.str("deck.cbn"));
    REQUIRE(run_parsons("punch " + q(kSampleDeck) + " -o " + deck).exit_code == 0);
    for (const std::string& args :
         {"run " + too_long, "show " + too_long, "check " + too_long,
          "run " + deck + " --profile " + too_long,
          "run " + q(dir.str("")) + " --profile " + too_long,
          "run " + deck + " --cut " + q(dir.str("cut.svg")) + " --job " + too_long,
          "run " + deck + " --vcd " + too_long, "punch " + too_long + " -o " + q(dir.str("p.cbn")),
          "demo --out " + q(dir.str(too_long))}) {
        const auto r = run_parsons(args);
        INFO(args.substr(0, 120) << ":\n" << r.output.substr(0, 400));
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("parsons: error: ") != std::string::npos);
        CHECK(r.output.find(too_long.substr(0, 255)) != std::string::npos);
        CHECK(r.output.find("internal error") == std::string::npos);
    }
}

TEST_CASE("Exit codes: run returns 3 on a machine stop, 130 on Ctrl-C and 143 on SIGTERM",
          "[cli][exit-codes][signals]") {
    TempDir dir;
    write_bytes(dir.path("wrong.csv"),
                std::string(kHeader) + "1,0,table,+,3,,,0.100,0.110,1\n" + idle_rest(1));
    const auto stopped = run_parsons("run -q " + q(dir.str("wrong.csv")));
    CHECK(stopped.exit_code == 3);
    CHECK(stopped.output.find("check_mismatch") != std::string::npos);

    write_bytes(dir.path("long.csv"), long_listing(4000));
    const std::string deck = q(dir.str("long.cbn"));
    // The trace goes to a null device of the test's own (never the machine's /dev/null), or,
    // where mknod is not permitted, to a file of its own.
    const std::string trace = q(parsons::test::make_device_node(dir.path(""), "null", 1, 3)
                                    .value_or(dir.path("trace.vcd"))
                                    .string());
    REQUIRE(run_parsons("punch " + q(dir.str("long.csv")) + " -o " + deck).exit_code == 0);
    // About three seconds of work at the impulse level with a trace (400 cards ran through in
    // 0.3 s on a fast machine): the signal comes first.
    for (const auto& [signal, code] : std::map<std::string, int>{{"INT", 130}, {"TERM", 143}}) {
        const auto r = run_shell("timeout --preserve-status -s " + signal + " 0.3 PARSONS run " +
                                 deck + " --impulse-level --trace " + trace + " -q");
        INFO("SIG" << signal << ":\n" << r.output);
        CHECK(r.exit_code == code);
        CHECK(r.output.find("the operator stopped the run") != std::string::npos);
    }
}

TEST_CASE("Exit codes: demo returns 130 on Ctrl-C and 143 on SIGTERM, even while it waits "
          "for the reader of a FIFO, and leaves no half file",
          "[cli][exit-codes][signals]") {
    for (const auto& [signal, code] : std::map<std::string, int>{{"INT", 130}, {"TERM", 143}}) {
        TempDir dir;
        const std::string out = dir.str("out");
        // The trace of the demo's first run, the sample deck's, is a FIFO that nobody reads
        // (a live viewer not started yet): the run waits in open() for a reader. The operator gives
        // up: the signal ends the wait. The demo starts with both signals ignored (as a background
        // job's Ctrl-C is), so a signal that comes while it still generates its deck is lost, on a
        // slow machine (the sanitizer build) too; the operator presses again every 0.1 s until the
        // run takes it, which it does only where it waits. (A loop, not a bare wait, so that a demo
        // that ignores the signal fails the test instead of hanging it.)
        const auto r = run_shell(
            "mkdir -p " + q(out + "/sample-deck") + " && mkfifo " +
            q(out + "/sample-deck/trace.vcd") + " && { trap '' INT TERM; PARSONS demo --out " +
            q(out) + " > " + q(dir.str("log.txt")) +
            " 2>&1 & pid=$!; trap - INT TERM; i=0; while kill -0 $pid " +
            "2>/dev/null && [ $i -lt 300 ]; do kill -" + signal +
            " $pid 2>/dev/null; sleep 0.1; i=$((i+1)); done; kill -9 $pid 2>/dev/null; wait " +
            "$pid; echo status $?; }");
        const std::string log = parsons::test::read_bytes(dir.path("log.txt"));
        INFO("SIG" << signal << ":\n" << r.output << log);
        CHECK(r.output.find(fmt::format("status {}", code)) != std::string::npos);
        CHECK(log.find("parsons: interrupted while opening the outputs, before any card") !=
              std::string::npos);
        CHECK(std::filesystem::is_fifo(dir.path("out/sample-deck/trace.vcd")));
        CHECK_FALSE(std::filesystem::exists(dir.path("out/sample-deck/report.json")));
        CHECK_FALSE(std::filesystem::exists(dir.path("out/airfoil-template")));
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir.path("out"))) {
            CHECK(entry.path().filename().string().find(".partial-") == std::string::npos);
        }
    }
}

TEST_CASE("Exit codes: check exits 3 exactly when the machine will stop on the deck, and 0 "
          "with only what it observed",
          "[cli][exit-codes][check]") {
    TempDir dir;
    struct Case {
        const char* name;
        std::string listing;
        int code;
        const char* says;
    };
    const std::vector<Case> cases = {
        {"good", std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" + idle_rest(1), 0, ""},
        {"wrong check", std::string(kHeader) + "1,0,table,+,3,,,0.100,0.110,1\n" + idle_rest(1), 3,
         "the machine stops at card 1 (number 0001), table: check_mismatch"},
        {"card number",
         std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" + idle_rest(1) +
             "3,0,table,+,3,,,0.200,0.100,1\n" + idle_rest(3),
         3,
         "the machine stops at card 2 (number 0003): out_of_order_card: card 2 (number 0003): card "
         "number 0003 follows 0001"},
        {"stall",
         std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n1,0,cross,+,3,,,0.200,0.200,1\n"
                                "1,0,vertical,+,3,,,0.000,0.000,3\n1,0,swivel,+,3,,,0.000,0.000,4\n"
                                "1,0,tilt,+,3,,,0.000,0.000,5\n",
         3, "the machine stops at card 1 (number 0001): sequence_stall"},
        {"slow-downs a thousandth apart",
         std::string(kHeader) + "1,0,table,+,1,8.983,8.984,8.985,8.985,1\n" + idle_rest(1) +
             "2,0,table,+,3,,,9.085,0.100,1\n" + idle_rest(2),
         3, "the machine stops at card 1 (number 0001), table: limit_switch"},
        {"a stop met on speed 2: observed, and the deck runs through",
         std::string(kHeader) + "1,0,table,+,2,,,0.300,0.300,1\n" + idle_rest(1), 0,
         "observed: table: it met its stop 0.300 on speed 2: relay 256 only stepped 236 on to "
         "speed 3"},
    };
    for (const Case& c : cases) {
        const std::string file = dir.str(std::string(c.name) + ".csv");
        write_bytes(file, c.listing);
        const auto check = run_parsons("check " + q(file));
        const auto run = run_parsons("run -q " + q(file));
        INFO(c.name << ":\n" << check.output << "\nrun:\n" << run.output);
        CHECK(check.exit_code == c.code);
        CHECK(check.output.find(c.says) != std::string::npos);
        // The machine agrees with the check.
        CHECK(run.exit_code == c.code);
    }
}

TEST_CASE("Save state: a stopped run says where the state is and prints the command that "
          "resumes it, which works once the deck is corrected",
          "[cli][resume]") {
    TempDir dir;
    const std::string deck = dir.str("deck.csv");
    const std::string good = std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" +
                             idle_rest(1) + "2,0,table,+,3,,,0.300,0.200,1\n" + idle_rest(2);
    std::string wrong = good;
    wrong.replace(wrong.find("0.300,0.200"), 11, "0.300,0.250"); // card 2's check
    write_bytes(deck, wrong);
    const std::string state = dir.str("saved state.json"); // a name the shell must quote
    const auto stopped = run_parsons("run -q " + q(deck) + " --save-state " + q(state));
    INFO(stopped.output);
    REQUIRE(stopped.exit_code == 3);
    const std::string intro = "correct the deck, then resume with:\n  ";
    const auto at = stopped.output.find(intro);
    REQUIRE(at != std::string::npos);
    CHECK(stopped.output.find("the machine state is saved in " + state) != std::string::npos);
    std::string command = stopped.output.substr(at + intro.size());
    command = command.substr(0, command.find('\n'));
    REQUIRE(command.rfind("parsons run ", 0) == 0);
    // Typed as printed, on the corrected deck, the run goes on from card 2 and completes.
    write_bytes(deck, good);
    const auto resumed = run_shell("PARSONS" + command.substr(std::string("parsons").size()));
    INFO(command << "\n" << resumed.output);
    CHECK(resumed.exit_code == 0);
    // A run that completes has nothing to resume: no such line.
    const auto done = run_parsons("run -q " + q(deck) + " --save-state " + q(dir.str("s2.json")));
    CHECK(done.exit_code == 0);
    CHECK(done.output.find("resume with") == std::string::npos);
}
