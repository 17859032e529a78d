// The press lanes of run --plot (outputs/plots/plot_press.hpp, outputs/plots/plot_press_lanes.hpp;
// press synchronisation is an addition after EP 0436887, Mitsubishi): a run under parsons-extended
// with sync cards draws crank 21, die 20, registers 14 and 11, reader 60's holds and processor 63's
// speeds under the panels, on their time axis, and what it draws is the press's own motion —
// checked against a second, deliberately plain model of the default press (12 degrees a second
// from top dead centre, 4 pulses a degree, a slider crank with a 4 in stroke and an 8 in rod).
// A run without a press draws exactly the chart it drew before the lanes, byte for byte.
#include "tests/test_support.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/deck_io.hpp"
#include "outputs/plots/plot_press_lanes.hpp"
#include "outputs/plots/plot_svg.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace parsons;
using cli::PlotSvgRecorder;
using cli::PressTrace;
using parsons::test::count;
using parsons::test::kHeader;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

// Card 1: wait for the crank at 30 deg and follow it at 0.00150 in a pulse; card 2 takes the
// table out 1.5 in. Card 3: wait for 190 deg; card 4 brings the table back. Card 5 goes back to
// card 1 once: two cycles of the job.
const std::string kPressDeck = std::string(kHeader) +
                               "1,sync,position,30\n"
                               "1,sync,speed,table,0.00150\n"
                               "2,0,table,+,1,1.300,1.400,1.500,1.500,1\n" +
                               test::idle_rest(2) +
                               "3,sync,position,190\n"
                               "4,0,table,-,1,0.200,0.100,0.000,1.500,1\n" +
                               test::idle_rest(4) + "5,sync,loop,1,1\n";

struct PlottedRun {
    relaylogic::RunResult result;
    PlotSvgRecorder plot;
};

void run_listing(const std::string& listing, const axes::MachineProfile& profile, PlottedRun& out) {
    std::istringstream in(listing);
    cardreader::DeckOptions options;
    options.format = cardreader::DeckFormat::listing;
    options.file_name = "press.csv";
    auto source = cardreader::open_card_source(in, options);
    relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
    cabinet.attach(&out.plot);
    out.result = cabinet.run(*source);
}

const PlottedRun& press_run() {
    static const PlottedRun* run = [] {
        auto* r = new PlottedRun;
        run_listing(kPressDeck, axes::extended_profile(), *r);
        return r;
    }();
    return *run;
}

// The plain model: the default press from top dead centre at t = 0.
constexpr double kDegPerS = 12.0; // 2 strokes a minute
double crank_deg(double t) {
    return std::fmod(kDegPerS * t, 360.0);
}
double die_in(double a_deg) {
    const double a = a_deg * M_PI / 180;
    const double r = 2.0;
    const double l = 8.0;
    return r * std::cos(a) + std::sqrt(l * l - r * r * std::sin(a) * std::sin(a)) - (l - r);
}
// How far apart two angles are, round the circle.
double apart_deg(double a, double b) {
    const double d = std::fmod(std::fabs(a - b), 360.0);
    return std::min(d, 360.0 - d);
}

// The points of the first <path> of a class in the SVG: "M x,y L x,y ...".
std::vector<std::pair<double, double>> path_points(const std::string& svg, const std::string& cls) {
    const auto at = svg.find("<path class=\"" + cls + "\"");
    REQUIRE(at != std::string::npos);
    const auto d = svg.find(" d=\"", at);
    const auto end = svg.find('"', d + 4);
    const std::string text = svg.substr(d + 4, end - d - 4);
    std::vector<std::pair<double, double>> points;
    static const std::regex kPoint(R"([ML](-?[0-9.]+),(-?[0-9.]+))");
    for (std::sregex_iterator it(text.begin(), text.end(), kPoint), last; it != last; ++it) {
        points.emplace_back(std::stod((*it)[1].str()), std::stod((*it)[2].str()));
    }
    return points;
}

} // namespace

TEST_CASE("Press plot: crank 21's values on the chart are the press's, and its sawtooth falls "
          "back exactly where the crank passes top dead centre (Fig. 2A)",
          "[press_plot]") {
    const PlottedRun& run = press_run();
    INFO((run.result.stop ? run.result.stop->message : std::string("completed")));
    REQUIRE(run.result.completed);
    const PressTrace& press = run.plot.press();
    REQUIRE(press.present());
    const double t_end = run.result.machine_seconds;
    REQUIRE(t_end > 100); // the job waits for the crank: more than three revolutions

    const auto crank = press.series(PressTrace::Series::crank_21_deg);
    REQUIRE(crank.size() > 100);
    CHECK(crank.front().t > 0); // from the first detector edge on (plot_press.hpp)
    for (std::size_t i = 0; i + 1 < crank.size(); ++i) { // the last: held to the finish
        INFO("t " << crank[i].t << " s, crank " << crank[i].x << " deg");
        CHECK(crank[i].x >= 0);
        CHECK(crank[i].x < 360);
        CHECK(apart_deg(crank[i].x, crank_deg(crank[i].t)) <= 0.05 + 1e-9);
    }
    // A top dead centre every 30 s, where the 1440th edge of the revolution falls.
    const auto& tdc = press.top_dead_centres();
    REQUIRE(tdc.size() == static_cast<std::size_t>(std::floor(t_end / 30)));
    for (std::size_t k = 0; k < tdc.size(); ++k) {
        CHECK(tdc[k] == Approx(30.0 * static_cast<double>(k + 1)).margin(1e-6));
    }

    // Drawn: the crank's path falls by most of its lane once a revolution, at that time.
    const std::string svg = run.plot.svg();
    const auto drawn = path_points(svg, "crank");
    std::vector<double> falls;
    for (std::size_t i = 1; i < drawn.size(); ++i) {
        if (drawn[i].second - drawn[i - 1].second > 40) { // y grows downwards: 360 -> 0
            falls.push_back(drawn[i].first);
            CHECK(drawn[i].first - drawn[i - 1].first < 1.0); // straight down, not a slope
        }
    }
    REQUIRE(falls.size() == tdc.size());
    const double px_per_s = (cli::plot::kRight - cli::plot::kLeft) / t_end;
    for (std::size_t k = 0; k < tdc.size(); ++k) {
        CHECK(falls[k] == Approx(cli::plot::kLeft + tdc[k] * px_per_s).margin(0.6));
    }
    // Thinned for drawing, yet a rising ramp still climbs pixel by pixel.
    CHECK(drawn.size() < crank.size());
    for (std::size_t i = 1; i < drawn.size(); ++i) {
        if (drawn[i].second <= drawn[i - 1].second) { // rising
            CHECK(drawn[i - 1].second - drawn[i].second < 2.0);
        }
    }
}

TEST_CASE(
    "Press plot: die 20, register 14 and register 11 follow the crank, and reader 60 holds each "
    "card until detector 61 finds the crank on R",
    "[press_plot]") {
    const PlottedRun& run = press_run();
    REQUIRE(run.result.completed);
    const PressTrace& press = run.plot.press();

    REQUIRE(run.result.press);
    CHECK(press.series(PressTrace::Series::crank_21_deg).back().x ==
          Approx(run.result.press->crank_angle_deg).margin(0.05));
    CHECK(press.series(PressTrace::Series::register_14_pulses).back().x ==
          run.result.press->position_register);

    const auto die = press.series(PressTrace::Series::die_20_in);
    REQUIRE(die.size() > 100);
    for (std::size_t i = 0; i + 1 < die.size(); ++i) {
        INFO("t " << die[i].t);
        CHECK(die[i].x == Approx(die_in(crank_deg(die[i].t))).margin(0.0006));
    }
    const auto reg14 = press.series(PressTrace::Series::register_14_pulses);
    for (std::size_t i = 0; i + 1 < reg14.size(); ++i) {
        INFO("t " << reg14[i].t);
        CHECK(reg14[i].x < 1440); // setter 15 presets it at 360 deg (device 16)
        CHECK(apart_deg(reg14[i].x / 4, crank_deg(reg14[i].t)) <= 0.25 + 1e-9);
    }
    // 48 pulses a second, read by register 11 from its pulses' times: exactly 48 once two
    // pulses have been timed (the press turns steadily), 0 before.
    const auto reg11 = press.series(PressTrace::Series::register_11_speed);
    REQUIRE(reg11.size() >= 2);
    CHECK(reg11.front().x == 0);
    for (std::size_t i = 1; i < reg11.size(); ++i) {
        CHECK(reg11[i].x == Approx(48.0).margin(0.005));
    }

    // Four position syncs (two cards, two cycles), each held until 61 conducted at R.
    const auto holds = press.holds(run.result.machine_seconds);
    const auto& releases = press.releases();
    REQUIRE(holds.size() == 4);
    REQUIRE(releases.size() == 4);
    const std::vector<int> angles = {30, 190, 30, 190};
    const auto crank = press.series(PressTrace::Series::crank_21_deg);
    for (std::size_t k = 0; k < holds.size(); ++k) {
        INFO("hold " << k << ": " << holds[k].first << " .. " << holds[k].second << " s");
        CHECK(holds[k].first < releases[k]);
        CHECK(holds[k].second == Approx(releases[k]).margin(0.1)); // a relay's time after 61
        CHECK(apart_deg(crank_deg(releases[k]), angles[k]) <= 0.25);
    }
    CHECK(apart_deg(crank_deg(releases[0]), 30) <= 0.25);
    CHECK(press.sync_cards().size() == 6); // cards 1, 3, 5, and again after the loop-back
    // Processor 63 drove the table at 0.00150 in x 48 pulses/s = 4.32 in/min, its position
    // loop catching up the drive's start up to the drive's 5.4 in/min; no other axis.
    CHECK(press.any_speed_63());
    double fastest = 0;
    int at_f = 0;
    for (const auto& p : press.speed_63(cardreader::Axis::table)) {
        fastest = std::max(fastest, p.x);
        at_f += std::abs(p.x - 4.32) < 0.0005 ? 1 : 0;
    }
    CHECK(fastest <= 5.4 + 1e-9);
    CHECK(at_f >= 2); // back on F x 48 pulses a second once caught up
    for (auto a : {cardreader::Axis::cross, cardreader::Axis::vertical, cardreader::Axis::swivel,
                   cardreader::Axis::tilt}) {
        for (const auto& p : press.speed_63(a)) {
            CHECK(p.x == 0);
        }
    }
}

TEST_CASE("Press plot: the chart of a run with a press has one lane per press part under the "
          "panels, each in the legend, and one time axis under them all",
          "[press_plot]") {
    const PlottedRun& run = press_run();
    const std::string svg = run.plot.svg();
    const std::vector<std::string> lanes = {
        "crank_21",           "die_20",      "position_register_14", "speed_register_11",
        "position_reader_60", "processor_63"};
    std::size_t last = 0;
    for (const std::string& lane : lanes) {
        INFO(lane);
        const auto at = svg.find("<g class=\"press-lane\" data-lane=\"" + lane + "\"");
        REQUIRE(at != std::string::npos);
        CHECK(at > svg.rfind("<g class=\"panel\"")); // under the five panels, in this order
        CHECK(at > last);
        last = at;
    }
    CHECK(count(svg, "<g class=\"press-lane\"") == lanes.size());
    CHECK(count(svg, "class=\"press-legend\"") == 7); // six lanes and detector 61's mark
    CHECK(count(svg, "class=\"hold-bar\"") == 4);
    CHECK(count(svg, "class=\"release-marker\"") == 4);
    CHECK(count(svg, "<path class=\"speed-63 speed-63-table\"") == 1);
    // One time axis: its label comes once, after the last lane.
    CHECK(count(svg, ">machine time (s)</text>") == 1);
    CHECK(svg.find(">machine time (s)</text>") > last);
    // The page is tall enough for the lanes: the time axis label inside it.
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, std::regex(R"re(height="([0-9]+)")re")));
    const double height = std::stod(m[1].str());
    std::smatch label;
    REQUIRE(std::regex_search(svg, label,
                              std::regex(R"re(y="([0-9.]+)"[^>]*>machine time \(s\)</text>)re")));
    CHECK(std::stod(label[1].str()) < height);
    CHECK(std::stod(label[1].str()) > height - 40);
}

TEST_CASE("Press plot: thinning for drawing keeps a point a pixel or more from the last one kept "
          "and the point before it, so a step stays where it was",
          "[press_plot]") {
    using Points = std::vector<std::pair<double, double>>;
    // A slow ramp of 0.25 px a point: one point in four survives, with its predecessor.
    Points ramp;
    for (int i = 0; i <= 40; ++i) {
        ramp.emplace_back(i, 100 - 0.25 * i);
    }
    const Points thin = cli::thin_to_pixels(ramp);
    CHECK(thin.front() == ramp.front());
    CHECK(thin.back() == ramp.back());
    CHECK(thin.size() < 25);
    for (std::size_t i = 1; i < thin.size(); ++i) {
        CHECK(thin[i - 1].second - thin[i].second <= 1.0 + 1e-9);
    }
    // A flat run then a jump at x = 30: the flat end (29, 50) is kept, the jump is vertical.
    Points step;
    for (int i = 0; i < 30; ++i) {
        step.emplace_back(i, 50);
    }
    for (int i = 30; i < 40; ++i) {
        step.emplace_back(i, 10);
    }
    const Points s = cli::thin_to_pixels(step);
    CHECK(s == Points{{0, 50}, {29, 50}, {30, 10}, {38, 10}, {39, 10}});
}

TEST_CASE("Press plot: a run under parsons-1952 has no press lanes, and its chart is byte for "
          "byte the chart drawn before there were any (tests/golden/plot-1952.svg)",
          "[press_plot]") {
    TempDir dir;
    // Two cards: the table out at speed 1 with two slow-downs, the cross a little at speed 3,
    // and both back.
    write_bytes(dir.path("deck.csv"), std::string(kHeader) +
                                          "1,1,table,+,1,0.100,0.200,0.300,0.300,1\n"
                                          "1,1,cross,+,3,,,0.050,0.050,2\n"
                                          "1,1,vertical,+,3,,,0.000,0.000,3\n"
                                          "1,1,swivel,+,3,,,0.000,0.000,4\n"
                                          "1,1,tilt,+,3,,,0.000,0.000,5\n"
                                          "2,0,table,-,2,0.100,,0.000,0.300,1\n"
                                          "2,0,cross,-,3,,,0.000,0.050,2\n"
                                          "2,0,vertical,+,3,,,0.000,0.000,3\n"
                                          "2,0,swivel,+,3,,,0.000,0.000,4\n"
                                          "2,0,tilt,+,3,,,0.000,0.000,5\n");
    const auto r = run_shell("cd " + q(dir.str("")) +
                             " && PARSONS run deck.csv -q --profile parsons-1952 --plot p.svg");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::string svg = read_bytes(dir.path("p.svg"));
    CHECK(svg.find("press") == std::string::npos);
    // The golden file was drawn by the plot before the press lanes (commit 7aa2782) from this
    // deck. A change to the 1952 cabinet's timing also changes it: then look at both charts.
    CHECK(svg == read_bytes(source_path("tests/golden/plot-1952.svg")));
}

TEST_CASE("Press plot: a run under parsons-extended without a sync card still shows its press, "
          "turning, and holds nothing",
          "[press_plot]") {
    PlottedRun run;
    run_listing(std::string(kHeader) + "1,0,table,+,3,,,0.050,0.050,1\n" + test::idle_rest(1),
                axes::extended_profile(), run);
    REQUIRE(run.result.completed);
    const PressTrace& press = run.plot.press();
    REQUIRE(press.present());
    CHECK(press.holds(run.result.machine_seconds).empty());
    CHECK(press.releases().empty());
    CHECK_FALSE(press.any_speed_63());
    const std::string svg = run.plot.svg();
    CHECK(count(svg, "<g class=\"press-lane\"") == 5); // no processor 63 lane
    CHECK(count(svg, "class=\"press-legend\"") == 6);
    const auto crank = press.series(PressTrace::Series::crank_21_deg);
    REQUIRE(!crank.empty());
    REQUIRE(run.result.press);
    // Where the run left the crank: the report's angle at the last edge taken.
    CHECK(crank.back().x == Approx(run.result.press->crank_angle_deg).margin(0.05));
    CHECK(crank.back().x > 0);
}
