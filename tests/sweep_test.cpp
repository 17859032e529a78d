// parsons sweep (cli/sweep_command.cpp): each row is what `parsons gen` then `parsons run` of
// its case give by hand; the grid's order and values; --jobs changes nothing but the time; a
// case refused is its row and exit 2; keys and values refused before anything runs; a grid
// split with --cases-out and run in parts gives the whole; Ctrl-C leaves nothing.
#include "tests/test_support.hpp"

#include "cli/command_line.hpp"
#include "cli/support/sweep_grid.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::TempDir;

// A CSV line's fields (quoted fields as RFC 4180 writes them), for reading sweep's results.
std::vector<std::string> sweep_fields(const std::string& line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

// The results file as rows of column → value.
std::vector<std::map<std::string, std::string>> sweep_rows(const std::string& path) {
    const auto lines = parsons::test::lines_of(parsons::test::read_bytes(path));
    REQUIRE_FALSE(lines.empty());
    const auto header = sweep_fields(lines.front());
    std::vector<std::map<std::string, std::string>> rows;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto f = sweep_fields(lines[i]);
        REQUIRE(f.size() == header.size());
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < f.size(); ++k) {
            row[header[k]] = f[k];
        }
        rows.push_back(row);
    }
    return rows;
}

// `parsons gen` then `parsons run --report --cut` by hand: the report.
nlohmann::json by_hand(const TempDir& dir, const std::string& name, const std::string& gen,
                       const std::string& run_extra) {
    const std::string deck = dir.str(name + ".cbn");
    const auto g = run_parsons("gen airfoil " + gen + " -o " + q(deck));
    REQUIRE(g.exit_code == 0);
    const auto r = run_parsons("run " + q(deck) + " -q --report " + q(dir.str(name + ".json")) +
                               " --cut " + q(dir.str(name + ".svg")) + run_extra);
    INFO(r.output);
    REQUIRE((r.exit_code == 0 || r.exit_code == 3));
    return nlohmann::json::parse(parsons::test::read_bytes(dir.path(name + ".json")));
}

std::string number_of(const nlohmann::json& v) {
    return v.dump();
}

} // namespace

TEST_CASE("Sweep: each row is gen then run of its case by hand, in the grid's order (the first "
          "--vary slowest), and --jobs 1 and 2 write the same bytes",
          "[sweep][cli]") {
    TempDir dir;
    const std::string grid = "sweep airfoil --set naca=2412 --set stations=12 --vary "
                             "cutter-radius=0.125,0.25 --vary chord=4:6:3 -q -o ";
    const auto one = run_parsons(grid + q(dir.str("one.csv")) + " --jobs 1");
    INFO(one.output);
    REQUIRE(one.exit_code == 0);
    const auto two = run_parsons(grid + q(dir.str("two.csv")) + " --jobs 2");
    REQUIRE(two.exit_code == 0);
    CHECK(parsons::test::read_bytes(dir.path("one.csv")) ==
          parsons::test::read_bytes(dir.path("two.csv")));

    const auto rows = sweep_rows(dir.str("one.csv"));
    REQUIRE(rows.size() == 6);
    const std::vector<std::pair<std::string, std::string>> order = {{"0.125", "4"}, {"0.125", "5"},
                                                                    {"0.125", "6"}, {"0.25", "4"},
                                                                    {"0.25", "5"},  {"0.25", "6"}};
    for (std::size_t i = 0; i < rows.size(); ++i) {
        INFO("row " << i + 1);
        CHECK(rows[i].at("case") == std::to_string(i + 1));
        CHECK(rows[i].at("family") == "airfoil");
        CHECK(rows[i].at("naca") == "2412");
        CHECK(rows[i].at("stations") == "12");
        CHECK(rows[i].at("cutter-radius") == order[i].first);
        CHECK(rows[i].at("chord") == order[i].second);
        CHECK(rows[i].at("status") == "completed");
        CHECK(rows[i].at("exit") == "0");
    }
    // Case 5 (cutter 0.25, chord 5) by hand.
    const auto report =
        by_hand(dir, "case5", "--naca 2412 --stations 12 --cutter-radius 0.25 --chord 5", "");
    const auto& row = rows[4];
    CHECK(row.at("cards_read") == number_of(report.at("cards_read")));
    CHECK(row.at("machine_seconds") == number_of(report.at("machine_seconds")));
    CHECK(row.at("max_gouge_in") == number_of(report.at("cut").at("max_gouge_in")));
    CHECK(row.at("max_leftover_in") == number_of(report.at("cut").at("max_leftover_in")));
    CHECK(row.at("stop_reason").empty());
    // The cases differ: the grid's values reached the generator.
    CHECK(rows[3].at("machine_seconds") != rows[4].at("machine_seconds"));
    CHECK(rows[1].at("max_gouge_in") != rows[4].at("max_gouge_in"));
}

TEST_CASE("Sweep: a profile value reaches gen and run as a profile file would, a machine stop is "
          "its case's row (exit 0), and a wing's cut is the worse of root and tip",
          "[sweep][cli]") {
    TempDir dir;
    const auto r = run_parsons("sweep airfoil --set naca=2412 --set stations=12 --vary "
                               "profile.axes.table.speed_in_per_min.0=5.4,4,6 -q -o " +
                               q(dir.str("p.csv")));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto rows = sweep_rows(dir.str("p.csv"));
    REQUIRE(rows.size() == 3);
    // Speed 1 of the table at 4 in/min, by hand: the profile file of `parsons profile` with that
    // value, given to gen and run.
    auto profile = nlohmann::json::parse(run_parsons("profile").output);
    profile["axes"]["table"]["speed_in_per_min"][0] = 4;
    parsons::test::write_bytes(dir.path("slow-profile.json"), profile.dump());
    const std::string slow = " --profile " + q(dir.str("slow-profile.json"));
    const auto report = by_hand(dir, "slow", "--naca 2412 --stations 12" + slow, slow);
    CHECK(rows[1].at("status") == "completed");
    CHECK(rows[1].at("machine_seconds") == number_of(report.at("machine_seconds")));
    CHECK(rows[1].at("machine_seconds") != rows[0].at("machine_seconds"));
    // Speed 1 at 6 in/min overshoots the stop: the machine stops itself, and says so in the row.
    profile["axes"]["table"]["speed_in_per_min"][0] = 6;
    parsons::test::write_bytes(dir.path("fast-profile.json"), profile.dump());
    const std::string faster = " --profile " + q(dir.str("fast-profile.json"));
    const auto fast = by_hand(dir, "fast", "--naca 2412 --stations 12" + faster, faster);
    REQUIRE(fast.at("status") == "stopped");
    CHECK(rows[2].at("exit") == "3");
    CHECK(rows[2].at("status") == "stopped");
    CHECK(rows[2].at("stop_reason") == fast.at("stop").at("reason").get<std::string>());
    CHECK(rows[2].at("stop_card") == number_of(fast.at("stop").at("card")));
    CHECK(rows[2].at("message") == fast.at("stop").at("message").get<std::string>());

    // A wing job's cut proof has a root and a tip: the row takes the larger of each figure.
    const auto w = run_parsons("sweep airfoil --set naca=0012 --set job=wing --set chord=4 --set "
                               "stations=10 -q -o " +
                               q(dir.str("w.csv")));
    INFO(w.output);
    REQUIRE(w.exit_code == 0);
    const auto wing = by_hand(dir, "wing", "--naca 0012 --job wing --chord 4 --stations 10", "");
    const auto& cut = wing.at("cut");
    const auto wrow = sweep_rows(dir.str("w.csv")).at(0);
    for (const char* key : {"max_gouge_in", "max_leftover_in"}) {
        INFO(key);
        const double most =
            std::max(cut.at("root").at(key).get<double>(), cut.at("tip").at(key).get<double>());
        CHECK(std::stod(wrow.at(key)) == most);
    }
    CHECK(cut.at("root").at("max_leftover_in") != cut.at("tip").at("max_leftover_in"));
}

TEST_CASE("Sweep: a case gen refuses is its row, \"refused\" with gen's words, and the sweep "
          "ends with exit 2 after writing every row",
          "[sweep][cli]") {
    TempDir dir;
    const auto r = run_parsons("sweep tapping --vary rpm=100,5000 -o " + q(dir.str("t.csv")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::Contains("sweep: 1 of 2 cases were refused (the first, case 2: "
                                         "gen tapping: --rpm 5000"));
    const auto rows = sweep_rows(dir.str("t.csv"));
    REQUIRE(rows.size() == 2);
    CHECK(rows[0].at("status") == "completed");
    CHECK(rows[0].at("exit") == "0");
    CHECK_FALSE(rows[0].at("machine_seconds").empty());
    CHECK(rows[0].at("max_gouge_in").empty()); // a tapping job has no cut proof
    CHECK(rows[1].at("status") == "refused");
    CHECK(rows[1].at("exit") == "2");
    CHECK_THAT(rows[1].at("message"), Catch::StartsWith("gen tapping: --rpm 5000: spindle motor "
                                                        "27 turns at most"));

    // A proof that objects (threads cut to the job's pitch, judged against a tolerance far
    // under what the machine holds) is its case's result, exit 3 in the row, and the sweep's
    // exit 0.
    const auto p =
        run_parsons("sweep tapping --vary tolerance=5,0.01 -q -o " + q(dir.str("p.csv")));
    INFO(p.output);
    CHECK(p.exit_code == 0);
    const auto proofs = sweep_rows(dir.str("p.csv"));
    REQUIRE(proofs.size() == 2);
    CHECK(proofs[0].at("status") == "completed");
    CHECK(proofs[1].at("status") == "proof failed");
    CHECK(proofs[1].at("exit") == "3");
    CHECK(proofs[1].at("stop_reason").empty());
    CHECK(proofs[1].at("machine_seconds") == proofs[0].at("machine_seconds"));
    CHECK_THAT(proofs[1].at("message"), Catch::StartsWith("thread proof: wrong pitch in 6 of 6 "
                                                          "holes") &&
                                            Catch::Contains("hole 1"));
}

TEST_CASE("Sweep: keys and values are checked before any case runs: exit 2 naming the key, and "
          "no results file",
          "[sweep][cli][bad-input]") {
    TempDir dir;
    const std::string out = " -o " + q(dir.str("r.csv"));
    std::vector<std::pair<std::string, std::string>> refused = {
        {"sweep airfoil --set naca=2412 --vary frob=1,2",
         "sweep: gen airfoil has no option '--frob' (its keys: naca, dat,"},
        {"sweep airfoil --set naca=2412 --vary stations=12,x",
         "sweep: stations=x: --stations: 'x' is not a number"},
        {"sweep airfoil --set naca=2412 --set output=x.cbn", "the key 'output' is the sweep's own"},
        {"sweep airfoil --set naca=2412 --vary profile.axes.table.nope=1",
         "the profile parsons-1952 has no key 'axes.table.nope'"},
        {"sweep airfoil --set naca=2412 --vary profile.axes.table.backlash_in=0,0.2",
         "sweep: profile.axes.table.backlash_in=0.2: the profile refuses it: "
         "axes.table.backlash_in: must be a number at least 0 and at most 0.1, not 0.2"},
        {"sweep airfoil --set naca=2412 --vary profile.axes.table.backlash_in=0,x",
         "profile.axes.table.backlash_in=x: the profile's value is a number"},
        {"sweep airfoil --set naca=2412 --vary chord=4:8:1", "N must be a whole number from 2"},
        {"sweep airfoil --set naca=2412 --vary chord=4:8", "a range is A:B:N"},
        {"sweep airfoil --set naca=2412 --vary chord=4,,5", "an empty value in the list"},
        {"sweep airfoil --set naca=2412 --vary naca=0012", "the key 'naca' is given twice"},
        {"sweep mill --set naca=2412", "FAMILY: mill not in {airfoil,two-tool,press-feeder"},
        {"sweep --set naca=2412", "a FAMILY (airfoil, two-tool, press-feeder, tapping, gcode)"},
    };
    for (const auto& [args, says] : refused) {
        INFO(args);
        const auto r = run_parsons(args + out);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Catch::Contains(says));
        CHECK_FALSE(std::filesystem::exists(dir.path("r.csv")));
    }
    // An output that cannot be written is refused before any case runs.
    const auto nowhere = run_parsons("sweep airfoil --set naca=2412 --vary chord=4:8:200 -o " +
                                     q(dir.str("no/such/folder/r.csv")));
    CHECK(nowhere.exit_code == 2);
    CHECK_THAT(nowhere.output, Catch::Contains("no/such/folder/r.csv: cannot write"));
}

TEST_CASE("Sweep: --cases-out writes the grid without running it: its rows split in two and run "
          "with --cases give the whole sweep's rows",
          "[sweep][cli]") {
    TempDir dir;
    const auto w = run_parsons("sweep airfoil --set naca=2412 --set stations=10 --vary "
                               "chord=4:6:5 --cases-out " +
                               q(dir.str("cases.csv")));
    REQUIRE(w.exit_code == 0);
    CHECK_FALSE(std::filesystem::exists(dir.path("r.csv")));
    const auto lines = parsons::test::lines_of(parsons::test::read_bytes(dir.path("cases.csv")));
    REQUIRE(lines.size() == 6);
    CHECK(lines[0] == "case,family,naca,stations,chord");
    CHECK(lines[2] == "2,airfoil,2412,10,4.5");
    CHECK(lines[5] == "5,airfoil,2412,10,6");
    parsons::test::write_bytes(dir.path("a.csv"),
                               lines[0] + "\n" + lines[1] + "\n" + lines[2] + "\n");
    parsons::test::write_bytes(dir.path("b.csv"), lines[0] + "\n" + lines[3] + "\n" + lines[4] +
                                                      "\n" + lines[5] + "\n");
    for (const char* part : {"a", "b", "cases"}) {
        const auto r = run_parsons("sweep -q --cases " + q(dir.str(std::string(part) + ".csv")) +
                                   " -o " + q(dir.str(std::string(part) + ".out.csv")));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
    }
    const std::string a = parsons::test::read_bytes(dir.path("a.out.csv"));
    const std::string b = parsons::test::read_bytes(dir.path("b.out.csv"));
    CHECK(a + b.substr(b.find('\n') + 1) == parsons::test::read_bytes(dir.path("cases.out.csv")));

    // A cases file that is not one, or not one family, is refused naming the file and line.
    parsons::test::write_bytes(dir.path("bad.csv"),
                               "case,family,chord\n1,airfoil,4\n1,airfoil,5\n");
    const auto twice =
        run_parsons("sweep --cases " + q(dir.str("bad.csv")) + " -o " + q(dir.str("x.csv")));
    CHECK(twice.exit_code == 2);
    CHECK_THAT(twice.output, Catch::Contains("bad.csv:3: case 1 is there twice"));
    parsons::test::write_bytes(dir.path("mixed.csv"),
                               "case,family,naca\n1,airfoil,2412\n2,tapping,2412\n");
    const auto mixed =
        run_parsons("sweep --cases " + q(dir.str("mixed.csv")) + " -o " + q(dir.str("x.csv")));
    CHECK(mixed.exit_code == 2);
    CHECK_THAT(mixed.output, Catch::Contains("case 2 is of the family 'tapping' where case 1 is "
                                             "'airfoil' (a sweep is one family)"));
    parsons::test::write_bytes(dir.path("keys.csv"), "case,family,naca,naca\n1,airfoil,1,2\n");
    const auto keys =
        run_parsons("sweep --cases " + q(dir.str("keys.csv")) + " -o " + q(dir.str("x.csv")));
    CHECK(keys.exit_code == 2);
    CHECK_THAT(keys.output, Catch::Contains("keys.csv:1: the key 'naca' is there twice"));
    parsons::test::write_bytes(dir.path("short.csv"), "case,family,naca\n1,airfoil\n");
    const auto short_row =
        run_parsons("sweep --cases " + q(dir.str("short.csv")) + " -o " + q(dir.str("x.csv")));
    CHECK(short_row.exit_code == 2);
    CHECK_THAT(short_row.output, Catch::Contains("short.csv:2: 2 fields where the header has 3"));
    CHECK_FALSE(std::filesystem::exists(dir.path("x.csv")));
}

TEST_CASE("Sweep grid: A:B:N is N evenly spaced values with both ends, the first --vary varies "
          "slowest, and a value with a comma survives the cases file",
          "[sweep]") {
    using parsons::cli::parse_vary;
    CHECK(parse_vary("x=0.1:0.3:3").values == std::vector<std::string>{"0.1", "0.2", "0.3"});
    CHECK(parse_vary("x=4:8:5").values == std::vector<std::string>{"4", "5", "6", "7", "8"});
    CHECK(parse_vary("x=1:-1:3").values == std::vector<std::string>{"1", "0", "-1"});
    CHECK(parse_vary("x=a,b").values == std::vector<std::string>{"a", "b"});
    CHECK(parse_vary("x=0:1:1000").values.size() == 1000);
    CHECK_THROWS_WITH(parse_vary("x=0:1:2.5"), Catch::Contains("N must be a whole number"));
    CHECK_THROWS_WITH(parse_vary("=1,2"), Catch::Contains("not KEY=V1,V2"));

    const auto grid = parsons::cli::expand_grid(
        "airfoil", {parse_vary("a=1,2"), parse_vary("b=x,y,z"), parsons::cli::parse_set("c=q")});
    REQUIRE(grid.cases.size() == 6);
    CHECK(grid.cases[1].values == std::vector<std::string>{"1", "y", "q"});
    CHECK(grid.cases[3].values == std::vector<std::string>{"2", "x", "q"});
    CHECK(grid.cases[5].number == 6);

    TempDir dir;
    parsons::cli::SweepGrid odd = grid;
    odd.cases[0].values[2] = "1 2, \"3\"";
    parsons::test::write_bytes(dir.path("g.csv"), parsons::cli::grid_csv(odd));
    const auto back = parsons::cli::read_cases(dir.str("g.csv"));
    CHECK(back.keys == odd.keys);
    REQUIRE(back.cases.size() == 6);
    CHECK(back.cases[0].values == odd.cases[0].values);
    CHECK(back.cases[4].values == odd.cases[4].values);
}

TEST_CASE("Sweep: only the parsons executable starts children: the command line inside another "
          "program refuses a sweep (exit 2) and writes nothing",
          "[sweep][cli]") {
    TempDir dir;
    const std::string out = dir.str("r.csv");
    std::vector<std::string> args = {"parsons",   "sweep", "airfoil", "--set",
                                     "naca=2412", "-q",    "-o",      out};
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    const int code =
        parsons::cli::command_line_main(static_cast<int>(argv.size()), argv.data(), "test");
    CHECK(code == 2);
    CHECK_FALSE(std::filesystem::exists(out));
}

TEST_CASE("Sweep: Ctrl-C stops the children and the sweep (exit 130): no results file and no "
          "scratch folder left",
          "[sweep][cli]") {
    TempDir dir;
    std::filesystem::create_directory(dir.path("tmp"));
    const std::string command = "TMPDIR=" + q(dir.str("tmp")) +
                                " exec PARSONS sweep airfoil --set naca=2412 --vary "
                                "chord=4:8:2000 --jobs 2 -q -o " +
                                q(dir.str("r.csv"));
    // The sweep in the background, stopped once its first case is under way (its folder in
    // the scratch folder: a slow build, under a sanitizer, takes longer to get there).
    const std::string cases = q(dir.str("tmp")) + "/parsons-sweep-*/case-*";
    const auto r = parsons::test::run_shell(
        "( " + command + " ) & pid=$!; for i in $(seq 600); do ls -d " + cases +
        " >/dev/null 2>&1 && break; sleep 0.05; done; kill -INT $pid; wait $pid; echo exit=$?");
    INFO(r.output);
    CHECK_THAT(r.output, Catch::Contains("exit=130"));
    CHECK_THAT(r.output, Catch::Contains("sweep: stopped by the operator; no results written"));
    CHECK_FALSE(std::filesystem::exists(dir.path("r.csv")));
    CHECK(std::filesystem::is_empty(dir.path("tmp")));
}
