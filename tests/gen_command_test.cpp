// parsons gen airfoil, run --cut and demo as a user types them.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

TEST_CASE("Gen: a NACA 2412 template deck, its centres and its job, run --cut proves it",
          "[gen][cli]") {
    TempDir dir;
    auto gen = run_parsons("gen airfoil --naca 2412 --chord 6 --cutter-radius 0.25 --scallop 0.002 "
                           "-o " +
                           q(dir.str("n.cbn")) + " --centres " + q(dir.str("c.csv")));
    REQUIRE(gen.exit_code == 0);
    CHECK(gen.output.find("naca 2412 template, chord 6.000 in") != std::string::npos);
    const std::string centres = read_bytes(dir.path("c.csv"));
    // At the leading edge the normal runs along the camber line, slope 2m/p = 0.1:
    // the centre is 0.25 in back along it, (-0.25 cos 5.71 deg, -0.25 sin 5.71 deg).
    CHECK(centres.rfind("x,y,cx,cy\n0.000000,0.000000,-0.248759,-0.024876\n", 0) == 0);
    CHECK(std::filesystem::exists(dir.path("n.cbn.job.json")));
    auto run = run_parsons("run " + q(dir.str("n.cbn")) + " --cut " + q(dir.str("cut.svg")) +
                           " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 0);
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(report["status"] == "completed");
    CHECK(report["cut"]["max_gouge_in"].get<double>() < 0.003);
    CHECK(report["cut"]["max_leftover_in"].get<double>() < 0.003);
    CHECK(read_bytes(dir.path("cut.svg")).find("</svg>") != std::string::npos);
}

TEST_CASE("Gen: a tapered wing deck runs and both sections are proved", "[gen][cli][wing]") {
    TempDir dir;
    auto gen = run_parsons("gen airfoil --naca 2412 --job wing --chord 4 --span 4 --taper 0.7 "
                           "--sweep 5 --stations 30 -o " +
                           q(dir.str("w.csv")));
    REQUIRE(gen.exit_code == 0);
    CHECK(gen.output.find("cards            60 (set the section, then plunge and traverse)") !=
          std::string::npos);
    auto run = run_parsons("run " + q(dir.str("w.csv")) + " --cut " + q(dir.str("cut.svg")) +
                           " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 0);
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(report["cut"]["root"]["max_gouge_in"].get<double>() < 0.002);
    CHECK(report["cut"]["tip"]["max_gouge_in"].get<double>() < 0.002);
    const std::string svg = read_bytes(dir.path("cut.svg"));
    CHECK(svg.find("root section (span 0)") != std::string::npos);
    CHECK(svg.find("tip section (span 4.000 in)") != std::string::npos);
}

TEST_CASE("Gen: bad requests exit 2 and say why", "[gen][cli][bad-input]") {
    TempDir dir;
    const std::string out = " -o " + q(dir.str("x.cbn"));
    auto both = run_parsons("gen airfoil --naca 2412 --dat foo.dat" + out);
    CHECK(both.exit_code == 2);
    CHECK(both.output.find("give exactly one of --naca DIGITS or --dat FILE") != std::string::npos);
    auto digits = run_parsons("gen airfoil --naca 24a2" + out);
    CHECK(digits.exit_code == 2);
    CHECK(digits.output.find("parsons: error: gen airfoil:") != std::string::npos);
    write_bytes(dir.path("bad.dat"), "MY FOIL\n1.0 0.0\n0.5 oops\n");
    auto dat = run_parsons("gen airfoil --dat " + q(dir.str("bad.dat")) + out);
    CHECK(dat.exit_code == 2);
    CHECK(dat.output.find(dir.str("bad.dat") + ":3:") != std::string::npos);
    auto hollow = run_parsons("gen airfoil --naca 2412 --female --cutter-radius 0.25" + out);
    CHECK(hollow.exit_code == 2);
    CHECK(hollow.output.find("cannot reach into the surface") != std::string::npos);
    auto wing = run_parsons("gen airfoil --naca 2412 --job wing --surface lower" + out);
    CHECK(wing.exit_code == 2);
    CHECK(wing.output.find("the wing job cuts the upper surface") != std::string::npos);
    auto swept = run_parsons("gen airfoil --naca 2412 --job wing --chord 4 --span 5 --taper 0.5 "
                             "--sweep 15" +
                             out);
    CHECK(swept.exit_code == 2);
    CHECK(swept.output.find("the fixture must swivel 15.00 deg, which puts its screw at 10.359 "
                            "in, outside the counters' 0.000 .. 9.999 in") != std::string::npos);
    auto huge = run_parsons("gen airfoil --naca 2412 --chord 12" + out);
    CHECK(huge.exit_code == 2);
    CHECK(huge.output.find("use a shorter chord") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn")));
    auto nojob = run_parsons("run " + q(source_path("decks/samples/patent-example.csv")) +
                             " --cut " + q(dir.str("c.svg")));
    CHECK(nojob.exit_code == 2);
    CHECK(nojob.output.find("cannot open the job description") != std::string::npos);
}

TEST_CASE("Demo: the default job writes its deck, cards, report, trace, plot and cut",
          "[gen][cli][demo]") {
    TempDir dir;
    auto demo = run_parsons("demo --out " + q(dir.str("demo")));
    CHECK(demo.exit_code == 0);
    CHECK(demo.output.find("status         completed") != std::string::npos);
    CHECK(demo.output.find("cut            deepest gouge") != std::string::npos);
    // Where to find every claim shown at work (issue 30, item 4), and that the page is there.
    CHECK(demo.output.find("docs/claims.md") != std::string::npos);
    CHECK(std::filesystem::exists(source_path("docs/claims.md")));
    for (const char* f :
         {"airfoil-template/naca2412.cbn", "airfoil-template/naca2412.cbn.job.json",
          "airfoil-template/cards/card-0001.svg", "airfoil-template/report.json",
          "airfoil-template/trace.vcd", "airfoil-template/plot.svg", "airfoil-template/cut.svg",
          "airfoil-template/centres.csv", "airfoil-template/replay.html",
          "sample-deck/patent-example.cbn", "sample-deck/cards/card-0004.svg",
          "sample-deck/report.json", "sample-deck/replay.html", "two-tools/two-tool-tripped.csv",
          "press-feeder/press-feeder-speed-only.csv.plot.svg",
          "tapping/tapping-stale-ratio.report.json", "index.html"}) {
        INFO(f);
        CHECK(std::filesystem::exists(dir.path("demo/" + std::string(f))));
    }
}

namespace {

// Every href and src of the index, in the order they come.
std::vector<std::string> index_targets(const std::string& html) {
    std::vector<std::string> targets;
    static const std::regex target(R"re((?:href|src)="([^"#][^"]*)")re");
    for (auto it = std::sregex_iterator(html.begin(), html.end(), target);
         it != std::sregex_iterator(); ++it) {
        targets.push_back((*it)[1].str());
    }
    return targets;
}

} // namespace

TEST_CASE("Demo: one story in order, a folder a system, and an index.html whose every link and "
          "picture is a file the demo wrote",
          "[cli][demo]") {
    TempDir dir;
    const auto demo = run_parsons("demo --out " + q(dir.str("demo")));
    REQUIRE(demo.exit_code == 0);
    // The story: the five parts in order, the two failures shown on purpose announced before
    // they happen, and at the end what to open.
    std::size_t at = 0;
    for (const char* part : {"1. The 1952 machine", "2. What it was made for", "3. Two tools",
                             "4. A feeder", "falls behind and collides", "COLLISION", "5. Tapping",
                             "on purpose", "3 of 6 holes flagged", "Open "}) {
        INFO(part);
        const std::size_t found = demo.output.find(part, at);
        REQUIRE(found != std::string::npos);
        at = found;
    }
    CHECK(demo.output.find(dir.str("demo") + "/index.html") != std::string::npos);

    const std::string html = read_bytes(dir.path("demo/index.html"));
    const std::vector<std::string> targets = index_targets(html);
    CHECK(targets.size() > 30);
    for (const std::string& t : targets) {
        INFO(t);
        CHECK(t.find("..") == std::string::npos); // relative, inside the demo's folder
        CHECK(t.front() != '/');
        CHECK(std::filesystem::is_regular_file(dir.path("demo/" + t)));
    }
    for (const char* folder :
         {"sample-deck", "airfoil-template", "two-tools", "press-feeder", "tapping"}) {
        INFO(folder);
        CHECK(html.find(std::string("<section id=\"") + folder + "\">") != std::string::npos);
        CHECK(std::find_if(targets.begin(), targets.end(), [&](const std::string& t) {
                  return t.starts_with(std::string(folder) + "/") && t.ends_with(".svg");
              }) != targets.end()); // a picture each
    }
    // The figures in the page are the runs' own.
    const auto report =
        nlohmann::json::parse(read_bytes(dir.path("demo/airfoil-template/report.json")));
    const double seconds = report.at("machine_seconds").get<double>();
    CHECK(html.find(fmt::format("{} min {:.1f} s", static_cast<long>(seconds / 60),
                                seconds - 60.0 * static_cast<long>(seconds / 60))) !=
          std::string::npos);
}

TEST_CASE("Demo: without the shipped data it says the sample deck was not run, and runs the rest",
          "[cli][demo]") {
    TempDir dir;
    std::filesystem::create_directories(dir.path("empty"));
    // run_shell takes every PARSONS for the program: the variable's name is split in quotes.
    const auto demo = run_shell("env 'PARS''ONS_DATA_DIR='" + q(dir.str("empty")) +
                                " PARSONS demo --out " + q(dir.str("demo")));
    CHECK(demo.exit_code == 0);
    CHECK(demo.output.find("1. the patent's example deck: not run, the shipped sample decks were "
                           "not found") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("demo/sample-deck")));
    const std::string html = read_bytes(dir.path("demo/index.html"));
    CHECK(html.find("sample-deck/") == std::string::npos);
    CHECK(html.find("airfoil-template/replay.html") != std::string::npos);
}

TEST_CASE("Gen: a scallop of zero or less is refused, not taken as 'use --stations'",
          "[gen][cli][bad-input]") {
    TempDir dir;
    for (const char* bad : {"0", "-0.002", "nan"}) {
        INFO(bad);
        auto r = run_parsons(std::string("gen airfoil --naca 2412 --scallop ") + bad + " -o " +
                             q(dir.str("n.cbn")));
        CHECK(r.exit_code == 2);
        // NaN is no number at all: the one rule for every number option says so first.
        CHECK(r.output.find(std::string(bad) == "nan"
                                ? "--scallop: 'nan' is not a number"
                                : "must be a positive number of inches") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir.path("n.cbn")));
    }
}

TEST_CASE("Gen: a scallop finer than the finest stations is refused with the smallest possible, "
          "and that smallest one is accepted",
          "[gen][cli][bad-input][heavy]") {
    TempDir dir;
    for (const char* job : {"template", "wing"}) {
        INFO(job);
        const std::string gen = std::string("gen airfoil --naca 2412 --job ") + job + " -o " +
                                q(dir.str("n.cbn")) + " --scallop ";
        std::filesystem::remove(dir.path("n.cbn"));
        auto r = run_parsons(gen + "0.00001");
        REQUIRE(r.exit_code == 2);
        CHECK_FALSE(std::filesystem::exists(dir.path("n.cbn")));
        const std::string marker = "the smallest possible is ";
        const auto at = r.output.find(marker);
        REQUIRE(at != std::string::npos);
        const double smallest = std::stod(r.output.substr(at + marker.size()));
        CHECK(smallest > 0.00001);
        auto ok = run_parsons(gen + fmt::format("{:.5f}", smallest));
        INFO(ok.output);
        CHECK(ok.exit_code == 0);
        // And the deck made for it keeps its promise.
        const auto planned = ok.output.find("largest scallop  ");
        REQUIRE(planned != std::string::npos);
        CHECK(std::stod(ok.output.substr(planned + 17)) <= smallest + 1e-9);
    }
}

TEST_CASE("Gen: a huge number is said in engineering form, not hundreds of digits",
          "[gen][cli][bad-input]") {
    TempDir dir;
    auto r = run_parsons("gen airfoil --naca 2412 --chord 1e300 -o " + q(dir.str("n.cbn")));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("the cutter path spans 1.000e300 x 79.200e297 in") != std::string::npos);
    CHECK(r.output.size() < 300);
}

TEST_CASE("Gen: sizes past what a deck or the machine can hold are refused before any work, "
          "naming the option and the limit, and no deck is written",
          "[gen][cli][bad-input][limits]") {
    TempDir dir;
    const std::string out = " -o " + q(dir.str("x.cbn"));
    const std::string cards_limit = "more than the 9,999 a deck can number (card numbers are four "
                                    "digits, columns 77-80)";
    struct Case {
        const char* options;
        std::string says;
    };
    for (const Case& c : {
             // 10,000,002 cards: once 5.5 GB of memory and a 1.6 GB deck.
             Case{"--stations 10000000", "--stations 10000000: the deck would need at least "
                                         "10,000,002 cards (3 to approach the first of "
                                         "10,000,000 stations, then one to each of the others), " +
                                             cards_limit},
             // Once minutes of computing.
             Case{"--job wing --stations 100000",
                  "--stations 100000: the deck would need 200,000 cards (2 a station), " +
                      cards_limit},
             Case{"--chord 1e-300", "--chord 1e-300: a chord under 0.100 in is no shape to the "
                                    "machine, which moves in impulses of 0.001 in: give at least "
                                    "0.100 in"},
             Case{"--cutter-radius 1e-300", "--cutter-radius 1e-300: a cutter radius under 0.001 "
                                            "in is less than one impulse"},
             Case{"--job wing --span 1e-300", "--span 1e-300: a span under 0.100 in"},
         }) {
        INFO(c.options);
        auto r = run_parsons(std::string("gen airfoil --naca 2412 ") + c.options + out);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Catch::Matchers::Contains("parsons: error: gen airfoil: " + c.says));
        CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn")));
        CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn.job.json")));
    }
}

TEST_CASE("Gen gcode: a program of exactly 9,999 cards is punched, one move more is refused at "
          "its line and no deck is written",
          "[gen][cli][gcode][limits]") {
    TempDir dir;
    // Short moves along X, back and forth: one card each (one axis, no corner approach under
    // 0.1 in), from the reference zero, which is the work zero.
    std::string program = "G20 G90\n";
    for (int i = 0; i < 9999; ++i) {
        program += i % 2 == 0 ? "G1 X0.05\n" : "G1 X0.1\n";
    }
    write_bytes(dir.path("most.ngc"), program);
    write_bytes(dir.path("over.ngc"), program + "G1 X0.1\n");
    auto most = run_parsons("gen gcode " + q(dir.str("most.ngc")) + " -o " + q(dir.str("m.cbn")));
    CHECK(most.exit_code == 0);
    CHECK_THAT(most.output, Catch::Matchers::Contains("9999 moves in a straight line, 0 arcs), "
                                                      "9999 cards"));
    auto over = run_parsons("gen gcode " + q(dir.str("over.ngc")) + " -o " + q(dir.str("o.cbn")));
    CHECK(over.exit_code == 2);
    CHECK_THAT(over.output,
               Catch::Matchers::Contains("over.ngc:10001: more than 9,999 cards at a tolerance of "
                                         "0.005 in, the most a deck can number (card numbers are "
                                         "four digits, columns 77-80)"));
    CHECK_FALSE(std::filesystem::exists(dir.path("o.cbn")));
}
