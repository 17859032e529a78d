// The spindle lanes of run --plot (outputs/plots/plot_spindle.hpp,
// outputs/plots/plot_spindle_lanes.hpp; spindle synchronisation is an addition after EP 0360190,
// Mitsubishi): a run that reads tap cards draws motor 27, tool 16, interface 33, memory 12a, the
// synchronous control's feed and depth, bus 35's handshake and PC 130's relays under the panels, on
// their time axis, and what they draw is what the machine did — the speeds the cards ordered, the
// ratio changing once the transfer is done, the handshake's lines in the seed's order (Fig. 4). A
// run without a tap card draws exactly the chart it drew before the lanes, byte for byte (and a run
// under parsons-1952 draws tests/golden/plot-1952.svg: tests/press_plot_test.cpp).
#include "tests/machine_support.hpp"

#include "outputs/plots/plot_spindle_lanes.hpp"
#include "outputs/plots/plot_svg.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>
#include <vector>

using namespace parsons;
using cardreader::CardKind;
using cardreader::CardOrders;
using cli::PlotSvgRecorder;
using cli::SpindleTrace;
using parsons::test::idle_card;
using parsons::test::run_orders;
using Line = SpindleTrace::Line;
using Interval = std::pair<double, double>;
using parsons::test::count;

namespace {

const std::array<int, 5> kOrigin = {0, 0, 0, 0, 0};

axes::MachineProfile spindle_profile(axes::RatioSource source = axes::RatioSource::transferred) {
    axes::MachineProfile p = axes::extended_profile();
    p.press_sync = false; // the spindle's lanes alone
    p.spindle.ratio_source = source;
    return p;
}

CardOrders plot_tap_card(int number, int tool, int depth, int pitch, int rpm) {
    CardOrders c;
    c.kind = CardKind::tap;
    c.number = number;
    c.tap.tool = tool;
    c.tap.axis = cardreader::Axis::vertical;
    c.tap.motion = cardreader::Motion::forward;
    c.tap.depth = static_cast<cardreader::Thousandths>(depth);
    c.tap.pitch = pitch;
    c.tap.rpm = rpm;
    return c;
}

// Card 2 taps 0.300 in with tool 1 (on the spindle from the start: ratio 1/4, a 0.05 in tap)
// at 240 rev/min; card 3 calls tool 2 (ratio 1/3, a 0.0625 in tap): PC 130 exchanges the head
// and the ratio reaches 12a (transferred, or selected if stored) before it taps 0.400 in at
// 180 rev/min. Both tools turn 60 rev/min.
const std::vector<CardOrders> kTwoTaps = {
    idle_card(1, kOrigin), plot_tap_card(2, 1, 300, 5000, 240), plot_tap_card(3, 2, 400, 6250, 180),
    idle_card(4, kOrigin)};

struct PlottedTaps {
    relaylogic::RunResult result;
    PlotSvgRecorder plot;
};

void run_plotted(const std::vector<CardOrders>& cards, const axes::MachineProfile& profile,
                 PlottedTaps& out, const std::vector<relaylogic::Fault>& faults = {}) {
    out.result = run_orders(cards, profile, &out.plot, faults);
}

const PlottedTaps& two_taps() {
    static const PlottedTaps* run = [] {
        auto* r = new PlottedTaps;
        run_plotted(kTwoTaps, spindle_profile(), *r);
        return r;
    }();
    return *run;
}

// The largest value of a series within [t0, t1].
double max_between(const std::vector<SpindleTrace::Point>& s, double t0, double t1) {
    double hi = 0;
    for (const auto& p : s) {
        if (p.t >= t0 && p.t <= t1) {
            hi = std::max(hi, p.x);
        }
    }
    return hi;
}

// The time-weighted mean of a step series over [t0, t1].
double mean_between(const std::vector<SpindleTrace::Point>& s, double t0, double t1) {
    double sum = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const double a = std::max(t0, s[i].t);
        const double b = std::min(t1, i + 1 < s.size() ? s[i + 1].t : t1);
        if (b > a) {
            sum += s[i].x * (b - a);
        }
    }
    return sum / (t1 - t0);
}

// The first interval of a line or relay that begins at or after t.
std::optional<Interval> first_from(const std::vector<Interval>& on, double t) {
    for (const Interval& i : on) {
        if (i.first >= t) {
            return i;
        }
    }
    return std::nullopt;
}

// The start times in the titles of the SVG's bars of a class, row by row in document order:
// data attribute value -> the starts of its bars.
std::vector<std::pair<std::string, double>>
bar_starts(const std::string& svg, const std::string& cls, const std::string& data) {
    std::vector<std::pair<std::string, double>> out;
    const std::regex bar("<rect class=\"" + cls + "\" " + data +
                         "=\"([a-z0-9_]+)\"[^>]*><title>[^<]*, ([0-9.]+) s to ([0-9.]+) s</title>");
    for (std::sregex_iterator it(svg.begin(), svg.end(), bar), last; it != last; ++it) {
        out.emplace_back((*it)[1].str(), std::stod((*it)[2].str()));
    }
    return out;
}

} // namespace

TEST_CASE("Spindle plot: motor 27 and tool 16 reach the speeds the tap cards order, and "
          "interface 33 counts the edges encoder 32 gives at them",
          "[spindle_plot]") {
    const PlottedTaps& run = two_taps();
    INFO((run.result.stop ? run.result.stop->message : std::string("completed")));
    REQUIRE(run.result.completed);
    REQUIRE(run.result.tapping);
    REQUIRE(run.result.tapping->holes.size() == 2);
    const SpindleTrace& spindle = run.plot.spindle();
    REQUIRE(spindle.present());
    REQUIRE(spindle.taps().size() == 2);

    const auto motor = spindle.series(SpindleTrace::Series::motor_27_rpm);
    const auto tool = spindle.series(SpindleTrace::Series::tool_16_rpm);
    const auto edges = spindle.series(SpindleTrace::Series::interface_33_edges);
    REQUIRE(motor.front().t == 0);
    CHECK(motor.front().x == 0);
    const std::vector<int> ordered = {240, 180};
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& h = run.result.tapping->holes[k];
        INFO("hole " << k + 1 << ": " << h.start_s << " .. " << h.end_s << " s");
        // The commanded speed, reached (to the sample) before the reversal at the depth.
        CHECK(max_between(motor, h.start_s, h.reverse_s) == Approx(ordered[k]).margin(1));
        CHECK(max_between(tool, h.start_s, h.reverse_s) == Approx(60).margin(1));
        // 24 edges a revolution, a sample of 0.05 s: 4.8 edges at 240 rev/min, 3.6 at 180.
        const double per_sample = ordered[k] * 24.0 / 60.0 * 0.05;
        CHECK(max_between(edges, h.start_s, h.reverse_s) == Approx(std::ceil(per_sample)));
        // Standing still before the card and after it.
        CHECK(SpindleTrace::value_at(motor, h.start_s - 0.01) == 0);
        CHECK(SpindleTrace::value_at(motor, h.end_s + 0.01) == 0);
    }
    CHECK(motor.back().t == Approx(run.result.machine_seconds)); // held to the end
}

TEST_CASE("Spindle plot: memory 12a's lane changes to the new head's ratio once the transfer is "
          "done, after the exchange mark, and the feed and depth follow each tap",
          "[spindle_plot]") {
    const PlottedTaps& run = two_taps();
    REQUIRE(run.result.completed);
    const SpindleTrace& spindle = run.plot.spindle();
    const double t_end = run.result.machine_seconds;
    const auto& holes = run.result.tapping->holes;

    // One exchange, to tool 2, between the two holes.
    const auto exchanges = spindle.exchanges();
    REQUIRE(exchanges.size() == 1);
    CHECK(exchanges[0].tool == 2);
    CHECK(exchanges[0].t > holes[0].end_s);
    CHECK(exchanges[0].t < holes[1].start_s);

    // The ratio: 1/4 from the start, 1/3 once the NC stored the transfer (S16), which is the
    // scan PC 130 answers tool ready — after the exchange, before the tap.
    const auto& ratio = spindle.steps(SpindleTrace::Steps::ratio_12a);
    REQUIRE(ratio.size() == 2);
    CHECK(ratio[0].t == 0);
    CHECK(ratio[0].x == Approx(0.25));
    CHECK(ratio[1].x == Approx(1.0 / 3.0).margin(1e-6));
    const auto received = first_from(spindle.line_on(Line::nc_received, t_end), exchanges[0].t);
    const auto ready = first_from(spindle.line_on(Line::tool_ready, t_end), exchanges[0].t);
    REQUIRE(received);
    REQUIRE(ready);
    CHECK(ratio[1].t > exchanges[0].t);
    CHECK(ratio[1].t > received->first);
    CHECK(ratio[1].t == Approx(ready->first));
    CHECK(ratio[1].t <= holes[1].start_s);
    // The ratio on the data lines was the new head's.
    CHECK(SpindleTrace::value_at(spindle.data_ratio(), received->first) ==
          Approx(1.0 / 3.0).margin(1e-6));

    // The feed: 60 tool rev/min times the pitch, 3 in/min and 3.75 in/min; the depth called
    // reaches about each hole's depth and comes back.
    const auto feed = spindle.series(SpindleTrace::Series::feed_in_per_min);
    const auto depth = spindle.series(SpindleTrace::Series::depth_called_in);
    const std::vector<double> feeds = {3.0, 3.75};
    const std::vector<double> depths = {0.300, 0.400};
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& h = holes[k];
        INFO("hole " << k + 1);
        // (Each sample's command follows the edges of that sample, 4 or 5 at 240 rev/min, and
        // the position correction: the mean over the cut once the motor is up to speed.)
        CHECK(mean_between(feed, h.start_s + 2, h.reverse_s) == Approx(feeds[k]).epsilon(0.05));
        CHECK(max_between(depth, h.start_s, h.end_s) == Approx(depths[k]).margin(0.01));
        CHECK(SpindleTrace::value_at(depth, h.end_s + 0.01) < 0.01);
    }
    // The phases: a tool call, in, out, ... for each tap.
    const auto& phase = spindle.steps(SpindleTrace::Steps::phase);
    CHECK(std::count_if(phase.begin(), phase.end(), [](const auto& p) { return p.x == 2; }) == 2);
    CHECK(std::count_if(phase.begin(), phase.end(), [](const auto& p) { return p.x == 3; }) == 2);
}

TEST_CASE("Spindle plot: bus 35's handshake and PC 130's relays come in the seed's order for a "
          "head exchange (Fig. 4), in the record and in the bars drawn",
          "[spindle_plot]") {
    const PlottedTaps& run = two_taps();
    REQUIRE(run.result.completed);
    const SpindleTrace& spindle = run.plot.spindle();
    const double t_end = run.result.machine_seconds;
    const double card_3 = spindle.taps().at(1).t;

    // Tool call, transfer request (S4), NC ready (S13), data valid (S6), NC received (S15),
    // tool ready: each begins a scan or more after the one before.
    std::vector<double> starts;
    for (Line l : {Line::tool_call, Line::transfer_request, Line::nc_ready, Line::data_valid,
                   Line::nc_received, Line::tool_ready}) {
        const auto on = first_from(spindle.line_on(l, t_end), card_3);
        INFO("bus line " << static_cast<int>(l));
        REQUIRE(on);
        starts.push_back(on->first);
    }
    for (std::size_t i = 1; i < starts.size(); ++i) {
        CHECK(starts[i] > starts[i - 1]);
    }
    // The exchange (CR2) took the profile's head_change_s before the request.
    const double exchange_s = axes::extended_profile().spindle.head_change_s;
    CHECK(starts[1] - starts[0] > exchange_s);
    // The tool call stands while the card runs; the request and the data drop at tool ready.
    CHECK(first_from(spindle.line_on(Line::tool_call, t_end), card_3)->second >
          run.result.tapping->holes[1].reverse_s);
    CHECK(first_from(spindle.line_on(Line::transfer_request, t_end), card_3)->second ==
          Approx(starts[5]));
    // PC 130's ladder: CR1 ... CR8 pick one after the other.
    std::vector<double> relays;
    for (std::size_t r = 0; r < SpindleTrace::kRelays; ++r) {
        const auto on = first_from(spindle.relay_on(r, t_end), card_3);
        INFO("CR" << r + 1);
        REQUIRE(on);
        relays.push_back(on->first);
    }
    for (std::size_t i = 1; i < relays.size(); ++i) {
        CHECK(relays[i] > relays[i - 1]);
    }
    // Card 2 called the head already on: no exchange, no transfer (CR1, CR4, CR8 only).
    const double card_2 = spindle.taps().at(0).t;
    CHECK(first_from(spindle.relay_on(1, t_end), card_2)->first > card_3);
    CHECK(first_from(spindle.line_on(Line::transfer_request, t_end), card_2)->first > card_3);

    // Drawn: the bus lane's rows in the seed's order, the last bar of each row card 3's, with
    // its times in its title.
    const std::string svg = run.plot.svg();
    const auto bars = bar_starts(svg, "bus35-bar", "data-line");
    const std::vector<std::string> rows = {"tool_call",  "transfer_request", "nc_ready",
                                           "data_valid", "nc_received",      "tool_ready"};
    std::vector<double> drawn;
    std::size_t row = 0;
    for (const auto& [line, t] : bars) {
        while (row < rows.size() && line != rows[row]) {
            ++row;
        }
        REQUIRE(row < rows.size()); // each row's bars together, in the rows' order
        if (drawn.size() == row + 1) {
            drawn.back() = t;
        } else {
            drawn.push_back(t);
        }
    }
    REQUIRE(drawn.size() == rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        CHECK(drawn[i] == Approx(starts[i]).margin(0.0006));
    }
    CHECK(count(svg, "<rect class=\"pc130-bar\" data-relay=\"cr7_transfer\"") == 1);
    CHECK(svg.find("bus 35: PC 130's ratio on the data lines (S6): 0.333333") != std::string::npos);
}

TEST_CASE("Spindle plot: the chart of a run with tap cards has its lanes under the panels in "
          "order, each in the legend, and one time axis under them all",
          "[spindle_plot]") {
    const PlottedTaps& run = two_taps();
    const std::string svg = run.plot.svg();
    const std::vector<std::string> lanes = {
        "motor_27",         "tool_16",      "interface_33", "memory_12a",
        "synchronous_feed", "depth_called", "bus_35",       "pc_130"};
    std::size_t last = 0;
    for (const std::string& lane : lanes) {
        INFO(lane);
        const auto at = svg.find("<g class=\"spindle-lane\" data-lane=\"" + lane + "\"");
        REQUIRE(at != std::string::npos);
        CHECK(at > svg.rfind("<g class=\"panel\""));
        CHECK(at > last);
        last = at;
    }
    CHECK(count(svg, "<g class=\"spindle-lane\"") == lanes.size());
    CHECK(count(svg, "<clipPath id=\"spindle-clip-") == lanes.size());
    CHECK(count(svg, "class=\"spindle-legend\"") == 13);
    CHECK(count(svg, "<text class=\"ratio-label\"") == 2); // 0.2500, then 0.3333
    CHECK(count(svg, "class=\"exchange-marker\"") == 1);
    CHECK(count(svg, "<path class=\"motor_27\"") == 1);
    CHECK(count(svg, "<path class=\"ratio-12a\"") == 1);
    CHECK(svg.find("press-lane") == std::string::npos); // no press in this profile
    CHECK(count(svg, ">machine time (s)</text>") == 1);
    CHECK(svg.find(">machine time (s)</text>") > last);
    std::smatch m;
    REQUIRE(std::regex_search(svg, m, std::regex(R"re(height="([0-9]+)")re")));
    const double height = std::stod(m[1].str());
    std::smatch label;
    REQUIRE(std::regex_search(svg, label,
                              std::regex(R"re(y="([0-9.]+)"[^>]*>machine time \(s\)</text>)re")));
    CHECK(std::stod(label[1].str()) < height);
    CHECK(std::stod(label[1].str()) > height - 40);
}

TEST_CASE("Spindle plot: with a press beside the machine the spindle's lanes come under the "
          "press's, and both legends are drawn",
          "[spindle_plot]") {
    axes::MachineProfile profile = spindle_profile();
    profile.press_sync = true;
    PlottedTaps run;
    run_plotted({idle_card(1, kOrigin), plot_tap_card(2, 1, 200, 5000, 240), idle_card(3, kOrigin)},
                profile, run);
    INFO((run.result.stop ? run.result.stop->message : std::string("completed")));
    REQUIRE(run.result.completed);
    const std::string svg = run.plot.svg();
    const auto press = svg.rfind("<g class=\"press-lane\"");
    const auto spindle = svg.find("<g class=\"spindle-lane\"");
    REQUIRE(press != std::string::npos);
    REQUIRE(spindle != std::string::npos);
    CHECK(spindle > press);
    CHECK(svg.rfind("class=\"press-legend\"") < svg.find("class=\"spindle-legend\""));
    // The two groups' clip paths do not overlap: the spindle's first starts below the press's
    // last (press-clip-4: no processor 63 lane, no drive followed the press).
    std::smatch p;
    std::smatch s;
    REQUIRE(
        std::regex_search(svg, p,
                          std::regex(R"re(<clipPath id="press-clip-4"><rect x="[0-9.]+" )re"
                                     R"re(y="([0-9.]+)" width="[0-9.]+" height="([0-9.]+)")re")));
    CHECK(svg.find("press-clip-5") == std::string::npos);
    REQUIRE(std::regex_search(
        svg, s,
        std::regex(R"re(<clipPath id="spindle-clip-0"><rect x="[0-9.]+" y="([0-9.]+)")re")));
    CHECK(std::stod(s[1].str()) > std::stod(p[1].str()) + std::stod(p[2].str()));
}

TEST_CASE("Spindle plot: with the ratios stored per tool no transfer is drawn, and with the "
          "stale-ratio fault the head is exchanged while memory 12a's ratio stays",
          "[spindle_plot]") {
    SECTION("stored (Figs. 5-7)") {
        PlottedTaps run;
        run_plotted(kTwoTaps, spindle_profile(axes::RatioSource::stored), run);
        REQUIRE(run.result.completed);
        const SpindleTrace& spindle = run.plot.spindle();
        const double t_end = run.result.machine_seconds;
        CHECK(spindle.line_on(Line::transfer_request, t_end).empty());
        CHECK(spindle.line_on(Line::data_valid, t_end).empty());
        CHECK(spindle.relay_on(6, t_end).empty()); // CR7
        REQUIRE(spindle.exchanges().size() == 1);
        const auto& ratio = spindle.steps(SpindleTrace::Steps::ratio_12a);
        REQUIRE(ratio.size() == 2);
        CHECK(ratio[1].x == Approx(1.0 / 3.0).margin(1e-6));
        CHECK(ratio[1].t >= spindle.exchanges()[0].t);
        CHECK(count(run.plot.svg(), "class=\"bus35-bar\" data-line=\"transfer_request\"") == 0);
    }
    SECTION("stale-ratio:1") {
        PlottedTaps run;
        run_plotted(kTwoTaps, spindle_profile(), run, {relaylogic::parse_fault("stale-ratio:1")});
        INFO((run.result.stop ? run.result.stop->message : std::string("completed")));
        const SpindleTrace& spindle = run.plot.spindle();
        REQUIRE(spindle.exchanges().size() == 1);
        CHECK(spindle.exchanges()[0].tool == 2);
        const auto& ratio = spindle.steps(SpindleTrace::Steps::ratio_12a);
        REQUIRE(ratio.size() == 1); // 1/4 all along: the NC computes with the old ratio
        CHECK(ratio[0].x == Approx(0.25));
        CHECK(spindle.line_on(Line::transfer_request, run.result.machine_seconds).empty());
    }
}

TEST_CASE("Spindle plot: the speeds kept for the lanes stay within the reduction's bound however "
          "many samples a run takes",
          "[spindle_plot]") {
    SpindleTrace spindle;
    relaylogic::SignalInfo info;
    info.id = 0;
    info.scope = "spindle";
    info.name = "motor_27.rpm";
    const auto slot = spindle.define(info, 0);
    REQUIRE(slot);
    info.name = "encoder_32.phase_a"; // an edge signal: not kept
    CHECK_FALSE(spindle.define(info, 0));
    info.scope = "press";
    info.name = "motor_27.rpm";
    CHECK_FALSE(spindle.define(info, 0));
    CHECK_FALSE(spindle.present()); // no tap card read yet
    // Ten hours of samples at 20 a second, a speed that rises and falls.
    const long n = 10L * 3600 * 20;
    for (long i = 1; i <= n; ++i) {
        spindle.change(*slot, static_cast<double>(i) * 0.05,
                       static_cast<std::uint32_t>(120 + 120 * std::sin(i * 0.001)));
    }
    spindle.finish(static_cast<double>(n) * 0.05 + 1);
    const auto motor = spindle.series(SpindleTrace::Series::motor_27_rpm);
    CHECK(motor.size() <= 4 * SpindleTrace::Reduced::kMaxBuckets);
    CHECK(motor.size() > 1000);
    CHECK(max_between(motor, 0, 1e9) == 239); // the sine's top, cut to a whole rev/min
    CHECK(motor.back().t == Approx(static_cast<double>(n) * 0.05 + 1));
    CardOrders card;
    card.kind = CardKind::tap;
    spindle.card(1, card);
    CHECK(spindle.present());
}

TEST_CASE("Spindle plot: a run with spindle synchronisation but no tap card draws no spindle "
          "lane, byte for byte the chart of the same run without it",
          "[spindle_plot]") {
    const std::vector<CardOrders> deck = {idle_card(1, kOrigin), idle_card(2, kOrigin)};
    for (bool press : {false, true}) {
        INFO("press " << press);
        axes::MachineProfile with = spindle_profile();
        with.press_sync = press;
        axes::MachineProfile without = with;
        without.spindle_sync = false;
        PlottedTaps a;
        PlottedTaps b;
        run_plotted(deck, with, a);
        run_plotted(deck, without, b);
        REQUIRE(a.result.completed);
        CHECK_FALSE(a.plot.spindle().present());
        const std::string svg = a.plot.svg();
        CHECK(svg.find("spindle-") == std::string::npos);
        CHECK(svg == b.plot.svg());
    }
}
