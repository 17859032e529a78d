// The trace outputs of `parsons run` (outputs/traces/trace_outputs.hpp,
// outputs/plots/plot_svg.hpp), driven by real runs of small decks through the control cabinet: the
// VCD must declare every relay and switch of the cabinet once and replay to the counters' final
// positions, the JSON lines must parse, the path must end where the part is, and the plot must show
// every axis's stop.
#include "outputs/plots/plot_svg.hpp"
#include "outputs/traces/trace_outputs.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/control_cabinet.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <sys/wait.h>

using namespace parsons;
using cardreader::Axis;
using cardreader::CardOrders;
using cli::PlotSvgRecorder;
using parsons::test::count;
using parsons::test::lines_of;

namespace {

// A deck held in memory, each card read once.
class MemoryDeck : public cardreader::CardSource {
public:
    explicit MemoryDeck(const std::vector<CardOrders>& deck) {
        for (const CardOrders& o : deck) {
            auto encoded = cardreader::encode(o, cardreader::fig8_layout());
            REQUIRE(encoded);
            cards_.push_back(encoded.card);
        }
    }
    std::optional<cardreader::Card> next() override {
        if (next_ < cards_.size()) {
            return cards_[next_++];
        }
        return std::nullopt;
    }

private:
    std::vector<cardreader::Card> cards_;
    std::size_t next_ = 0;
};

// One card: every axis forward at speed 3 to its own stop (check = stop, from zero), one
// axis per sequence position: table 1, cross 2, vertical 3, swivel 4, tilt 5.
CardOrders one_axis_per_step() {
    CardOrders o;
    o.number = 1;
    o.spindle = cardreader::Spindle::forward;
    const std::array<cardreader::Thousandths, 5> stops = {53, 47, 50, 61, 38};
    for (Axis a : cardreader::kAxes) {
        const std::size_t k = cardreader::axis_index(a);
        auto& ax = o.axis(a);
        ax.motion = cardreader::Motion::forward;
        ax.start_speed = 3;
        ax.stop = stops.at(k);
        ax.check = stops.at(k);
        ax.sequence = static_cast<cardreader::SequencePattern>(1u << k);
    }
    return o;
}

struct Recorded {
    std::vector<relaylogic::SignalInfo> signals;
    relaylogic::RunResult result;
    std::string vcd, events, path;
    PlotSvgRecorder plot;
};

Recorded run_deck(const std::vector<CardOrders>& deck) {
    Recorded rec;
    std::ostringstream vcd_out, events_out, path_out;
    {
        cli::VcdWriter vcd(vcd_out, "test date");
        cli::EventsJsonlWriter events(events_out);
        cli::PathCsvWriter path(path_out);
        relaylogic::ObserverFanOut fan;
        fan.add(&vcd);
        fan.add(&events);
        fan.add(&path);
        fan.add(&rec.plot);
        relaylogic::ControlCabinet cab(axes::default_profile(), cardreader::fig8_layout());
        cab.attach(&fan);
        MemoryDeck source(deck);
        rec.result = cab.run(source);
        rec.signals = cab.tracer().signals();
    }
    rec.vcd = vcd_out.str();
    rec.events = events_out.str();
    rec.path = path_out.str();
    return rec;
}

const Recorded& simple_run() {
    static const Recorded rec = run_deck({one_axis_per_step()});
    return rec;
}

// A small VCD reader: declarations, then value changes, checking as it goes.
struct VcdVar {
    std::string name; // "table.absolute_counter_110"
    int width = 1;
    bool real = false; // an axis's position_in (tests/gtkwave_test.cpp reads its values)
};

struct ParsedVcd {
    std::map<std::string, VcdVar> vars; // by identifier code
    std::vector<std::string> names;     // in declaration order
    std::vector<std::string> problems;
    std::map<std::string, std::string> value; // last value by code ("0101")
    std::set<std::string> dumped;             // codes given an initial value
    std::vector<long long> times;
    std::size_t changes = 0; // of the signals (wires), after $dumpvars
    std::size_t real_changes = 0;
    std::string timescale;

    long long value_of(const std::string& name) const {
        for (const auto& [code, var] : vars) {
            if (var.name == name) {
                return std::stoll(value.at(code), nullptr, 2);
            }
        }
        return -1;
    }
};

ParsedVcd parse_vcd(const std::string& text) {
    ParsedVcd vcd;
    const auto end_of_definitions = text.find("$enddefinitions $end");
    REQUIRE(end_of_definitions != std::string::npos);
    std::istringstream header(text.substr(0, end_of_definitions));
    std::vector<std::string> scopes;
    std::string token;
    while (header >> token) {
        if (token == "$scope") {
            std::string kind, name, end;
            header >> kind >> name >> end;
            scopes.push_back(name);
        } else if (token == "$upscope") {
            header >> token;
            scopes.pop_back();
        } else if (token == "$var") {
            std::string kind, code, ref, end;
            int width = 0;
            header >> kind >> width >> code >> ref >> end;
            if (end != "$end") {
                header >> end; // the bit range
            }
            std::string full;
            for (const auto& s : scopes) {
                full += s + ".";
            }
            full += ref;
            if (vcd.vars.count(code) != 0) {
                vcd.problems.push_back("identifier used twice: " + code);
            }
            vcd.vars[code] = VcdVar{full, width, kind == "real"};
            vcd.names.push_back(full);
        } else if (token == "$timescale") {
            while (header >> token && token != "$end") {
                vcd.timescale += (vcd.timescale.empty() ? "" : " ") + token;
            }
        } else if (token.front() == '$') {
            while (header >> token && token != "$end") {
            }
        }
    }
    bool in_dumpvars = false;
    for (const std::string& line :
         lines_of(text.substr(end_of_definitions + std::string("$enddefinitions $end").size()))) {
        if (line.empty() || line.rfind("$comment", 0) == 0) {
            continue;
        }
        if (line == "$dumpvars") {
            in_dumpvars = true;
            continue;
        }
        if (line == "$end") {
            in_dumpvars = false;
            continue;
        }
        if (line[0] == '#') {
            vcd.times.push_back(std::stoll(line.substr(1)));
            continue;
        }
        std::string bits;
        std::string code;
        if (line[0] == 'r') {
            const auto space = line.find(' ');
            code = line.substr(space + 1);
            auto var = vcd.vars.find(code);
            if (var == vcd.vars.end() || !var->second.real) {
                vcd.problems.push_back("a real value of a variable not declared real: " + line);
                continue;
            }
            vcd.value[code] = line.substr(1, space - 1);
            if (in_dumpvars) {
                vcd.dumped.insert(code);
            } else {
                ++vcd.real_changes;
            }
            continue;
        }
        if (line[0] == 'b') {
            const auto space = line.find(' ');
            bits = line.substr(1, space - 1);
            code = line.substr(space + 1);
        } else {
            bits = line.substr(0, 1);
            code = line.substr(1);
        }
        auto var = vcd.vars.find(code);
        if (var == vcd.vars.end()) {
            vcd.problems.push_back("change of an undeclared identifier: " + line);
            continue;
        }
        if (var->second.real || static_cast<int>(bits.size()) != var->second.width) {
            vcd.problems.push_back("value of the wrong width: " + line);
        }
        vcd.value[code] = bits;
        if (in_dumpvars) {
            vcd.dumped.insert(code);
        } else {
            ++vcd.changes;
        }
    }
    return vcd;
}

int digit(double inches, int place) { // place 0 = thousandths .. 3 = inches
    const long v = std::lround(inches * 1000);
    return static_cast<int>(v / static_cast<long>(std::pow(10, place)) % 10);
}

int exit_status(int rc) {
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

} // namespace

TEST_CASE("VCD: identifier codes are printable ASCII 33-126, compact and all distinct",
          "[trace][vcd]") {
    CHECK(cli::vcd_identifier_code(0) == "!");
    CHECK(cli::vcd_identifier_code(93) == "~");
    CHECK(cli::vcd_identifier_code(94).size() == 2);
    CHECK(cli::vcd_identifier_code(94 + 94 * 94 - 1).size() == 2);
    CHECK(cli::vcd_identifier_code(94 + 94 * 94).size() == 3);
    std::set<std::string> seen;
    for (std::size_t n = 0; n < 20000; ++n) {
        const std::string code = cli::vcd_identifier_code(n);
        for (char c : code) {
            REQUIRE(c >= 33);
            REQUIRE(c <= 126);
        }
        REQUIRE(seen.insert(code).second);
    }
    CHECK(cli::vcd_reference_name("absolute_storage_352.relay_7") ==
          "absolute_storage_352_relay_7");
    CHECK(cli::vcd_reference_name("a b$c") == "a_b_c");
}

TEST_CASE("VCD: the header declares every signal of the cabinet once, one scope per axis and one "
          "for the cabinet",
          "[trace][vcd]") {
    const Recorded& rec = simple_run();
    const ParsedVcd vcd = parse_vcd(rec.vcd);
    CHECK(vcd.problems.empty());
    CHECK(rec.vcd.rfind("$date\n    test date\n$end\n$version parsons $end\n", 0) == 0);
    CHECK(vcd.timescale == "1 us");
    REQUIRE_FALSE(rec.signals.empty());
    CHECK(vcd.names.size() == rec.signals.size() + 5); // and the five positions
    std::multiset<std::string> declared(vcd.names.begin(), vcd.names.end());
    for (const auto& s : rec.signals) {
        INFO(s.scope << "." << s.name);
        CHECK(declared.count(s.scope + "." + cli::vcd_reference_name(s.name)) == 1);
    }
    // Widths as the tracer defined them, and an initial value for every one.
    for (const auto& [code, var] : vcd.vars) {
        CHECK(vcd.dumped.count(code) == 1);
    }
    CHECK(vcd.vars.size() == vcd.dumped.size());
    CHECK(declared.count("table.absolute_counter_110") == 1);
    CHECK(declared.count("cabinet.stepping_shaft_280") == 1);
    CHECK(declared.count("tilt.absolute_storage_352_relay_7") == 1);
    const std::vector<std::string> scope_order = {"table",  "cross", "vertical",
                                                  "swivel", "tilt",  "cabinet"};
    std::size_t at = 0;
    for (const auto& scope : scope_order) {
        const auto found = rec.vcd.find("$scope module " + scope + " $end", at);
        INFO(scope);
        REQUIRE(found != std::string::npos);
        at = found;
    }
}

TEST_CASE("VCD: every change names a declared signal, time only moves forward, and the counters "
          "104-110 replay to where the run left them",
          "[trace][vcd]") {
    const Recorded& rec = simple_run();
    REQUIRE(rec.result.completed);
    const ParsedVcd vcd = parse_vcd(rec.vcd);
    CHECK(vcd.problems.empty());
    REQUIRE(vcd.times.size() > 10);
    CHECK(vcd.times.front() == 0);
    for (std::size_t i = 1; i < vcd.times.size(); ++i) {
        REQUIRE(vcd.times[i] > vcd.times[i - 1]);
    }
    CHECK(vcd.times.back() == std::llround(rec.result.machine_seconds * 1e6));
    CHECK(vcd.changes > 100);
    CHECK(vcd.value_of("table.absolute_counter_110") == digit(rec.result.axes[0].counter_in, 0));
    CHECK(vcd.value_of("table.absolute_counter_110") == 3); // stop 0.053
    const std::array<const char*, 4> numerals = {"110", "108", "106", "104"};
    for (Axis a : cardreader::kAxes) {
        const std::size_t k = cardreader::axis_index(a);
        for (int place = 0; place < 4; ++place) {
            const std::string name = std::string(cardreader::axis_name(a)) + ".absolute_counter_" +
                                     numerals.at(static_cast<std::size_t>(place));
            INFO(name);
            CHECK(vcd.value_of(name) == digit(rec.result.axes.at(k).counter_in, place));
        }
    }
    CHECK(vcd.value_of("cabinet.master_switch_204") == 1);
    CHECK(rec.vcd.find("$comment card 1 read, number 1 $end") != std::string::npos);
}

TEST_CASE("VCD: changes in the same microsecond share one timestamp, wide values are written "
          "bit for bit",
          "[trace][vcd]") {
    std::ostringstream out;
    {
        cli::VcdWriter vcd(out, "d");
        relaylogic::SignalInfo relay{0, "table", "absolute_storage_352.relay_7", "relay", "352", 1};
        relaylogic::SignalInfo sw{1, "cabinet", "stepping_shaft_280", "shaft", "280", 3};
        vcd.on_signal_defined(relay, 0);
        vcd.on_signal_defined(sw, 1);
        vcd.on_start();
        vcd.on_signal(0.0000004, 0, 0, 1); // rounds to #0: no new timestamp
        vcd.on_signal(1.5, 1, 1, 2);
        vcd.on_signal(1.5000002, 0, 1, 0); // the same microsecond
        vcd.on_signal(2.25, 1, 2, 5);
        vcd.on_finish(3.0);
    }
    const std::string text = out.str();
    const std::string body = text.substr(text.find("$enddefinitions $end"));
    CHECK(body == "$enddefinitions $end\n#0\n$dumpvars\n0!\nb001 \"\n"
                  "r0.000 #\nr0.000 $\nr0.000 %\nr0.000 &\nr0.000 '\n$end\n"
                  "1!\n#1500000\nb010 \"\n0!\n#2250000\nb101 \"\n#3000000\n");
    CHECK(text.find("$var wire 1 ! absolute_storage_352_relay_7 $end") != std::string::npos);
    CHECK(text.find("$var wire 3 \" stepping_shaft_280 [2:0] $end") != std::string::npos);
}

TEST_CASE("VCD: GTKWave's vcd2fst converts the trace of a run, and fst2vcd gives back every signal",
          "[trace][vcd][gtkwave]") {
    const Recorded& rec = simple_run();
    test::TempDir dir;
    test::write_bytes(dir.path("run.vcd"), rec.vcd);
    INFO("vcd2fst comes with Debian's gtkwave package (scripts/install-deps.sh installs it)");
    REQUIRE(exit_status(std::system("command -v vcd2fst >/dev/null 2>&1")) == 0);
    const std::string q = "'";
    const int rc = std::system(("vcd2fst " + q + dir.str("run.vcd") + q + " " + q +
                                dir.str("run.fst") + q + " >" + q + dir.str("log") + q + " 2>&1")
                                   .c_str());
    INFO(test::read_bytes(dir.path("log")));
    REQUIRE(exit_status(rc) == 0);
    REQUIRE(std::filesystem::exists(dir.path("run.fst")));
    CHECK(std::filesystem::file_size(dir.path("run.fst")) > 0);
    REQUIRE(exit_status(std::system(("fst2vcd " + q + dir.str("run.fst") + q + " >" + q +
                                     dir.str("back.vcd") + q + " 2>/dev/null")
                                        .c_str())) == 0);
    const std::string back = test::read_bytes(dir.path("back.vcd"));
    CHECK(count(back, "$var ") == rec.signals.size() + 5); // the signals and the positions
    CHECK(count(back, "$var real 64 ") == 5);
    CHECK(back.find("absolute_counter_110") != std::string::npos);
}

TEST_CASE("Events: every line is a JSON object, motor 38 switching on, the card and the finish "
          "are there, one line per signal change",
          "[trace][events]") {
    const Recorded& rec = simple_run();
    const auto lines = lines_of(rec.events);
    REQUIRE(lines.size() > 100);
    std::size_t signal_lines = 0;
    bool motor_on = false;
    bool card = false;
    double last_t = 0;
    for (const std::string& line : lines) {
        INFO(line);
        const auto j = nlohmann::json::parse(line);
        REQUIRE(j.is_object());
        REQUIRE(j.at("t").is_number());
        CHECK(j.at("t").get<double>() >= last_t);
        last_t = j.at("t").get<double>();
        if (j.contains("signal")) {
            ++signal_lines;
            CHECK(j.at("old") != j.at("new"));
            CHECK(j.at("component").is_string());
            CHECK(j.at("numeral").is_string());
            if (j.at("signal") == "table.motor_38" && j.at("old") == 0 && j.at("new") == 1) {
                motor_on = true;
                CHECK(j.at("numeral") == "38");
            }
        } else if (j.at("event") == "card") {
            card = true;
            CHECK(j.at("index") == 1);
            CHECK(j.at("number") == 1);
        }
    }
    CHECK(motor_on);
    CHECK(card);
    CHECK(nlohmann::json::parse(lines.back()).at("event") == "finish");
    CHECK(signal_lines == parse_vcd(rec.vcd).changes);
    CHECK(rec.events.find("\"signal\":\"table.absolute_storage_356.relay_3\"") !=
          std::string::npos);
}

TEST_CASE("Events: a check mismatch is one stop line naming reason, card, axis, message and lamps",
          "[trace][events]") {
    CardOrders o = one_axis_per_step();
    o.axis(Axis::table).check = 40; // the increment counter reaches the check first
    const Recorded rec = run_deck({o});
    REQUIRE(rec.result.stop);
    std::vector<nlohmann::json> stops;
    for (const std::string& line : lines_of(rec.events)) {
        auto j = nlohmann::json::parse(line);
        if (j.value("event", "") == "stop") {
            stops.push_back(j);
        }
    }
    REQUIRE(stops.size() == 1);
    const auto& s = stops.front();
    CHECK(s.at("reason") == "check_mismatch");
    CHECK(s.at("card") == 1);
    CHECK(s.at("axis") == "table");
    CHECK(s.at("message") == rec.result.stop->message);
    CHECK(s.at("lamps").size() == rec.result.stop->lamps.size());
    CHECK(s.at("t").get<double>() > 0);
    CHECK(parse_vcd(rec.vcd).value_of("cabinet.master_switch_204") == 0);
    CHECK(rec.vcd.find("$comment machine stop: check_mismatch: ") != std::string::npos);
    CHECK(rec.plot.svg().find("stop: check_mismatch") != std::string::npos);
}

TEST_CASE("Events: names and messages are escaped JSON strings", "[trace][events]") {
    std::ostringstream out;
    {
        cli::EventsJsonlWriter events(out);
        events.on_signal_defined({0, "table", "odd\"name", "back\\slash\nnewline", "352", 1}, 0);
        events.on_signal(1.25, 0, 0, 1);
        relaylogic::StopInfo stop;
        stop.message = "quote \" and tab \t";
        stop.card_number = -1;
        events.on_stop(2, stop);
        events.on_finish(2);
    }
    const auto lines = lines_of(out.str());
    REQUIRE(lines.size() == 3);
    const auto change = nlohmann::json::parse(lines[0]);
    CHECK(change.at("signal") == "table.odd\"name");
    CHECK(change.at("component") == "back\\slash\nnewline");
    CHECK(change.at("t") == 1.25);
    const auto stop = nlohmann::json::parse(lines[1]);
    CHECK(stop.at("message") == "quote \" and tab \t");
    CHECK(stop.at("axis").is_null());
    CHECK(stop.at("card_number").is_null());
    CHECK(lines[0].rfind("{\"t\":1.250000,\"component\":", 0) == 0);
}

TEST_CASE("Path CSV: a header, one row per motion report, and the last row where the run left "
          "each part",
          "[trace][path]") {
    const Recorded& rec = simple_run();
    const auto lines = lines_of(rec.path);
    REQUIRE(lines.size() > 2);
    CHECK(lines.front() == "t,table,cross,vertical,swivel,tilt");
    double last_t = -1;
    std::array<double, 5> last{};
    for (std::size_t i = 1; i < lines.size(); ++i) {
        std::istringstream row(lines[i]);
        std::string field;
        std::vector<std::string> fields;
        while (std::getline(row, field, ',')) {
            fields.push_back(field);
        }
        REQUIRE(fields.size() == 6);
        REQUIRE(fields[0].size() - fields[0].find('.') == 7); // 6 decimals
        REQUIRE(fields[1].size() - fields[1].find('.') == 6); // 5 decimals
        const double t = std::stod(fields[0]);
        CHECK(t >= last_t);
        last_t = t;
        for (std::size_t k = 0; k < 5; ++k) {
            last.at(k) = std::stod(fields[k + 1]);
        }
    }
    for (std::size_t k = 0; k < 5; ++k) {
        CHECK(std::fabs(last.at(k) - rec.result.axes.at(k).real_in) <= 1e-5);
    }
    CHECK(std::fabs(last[0] - 0.053) < 0.001);
}

TEST_CASE("Plot: five panels sharing one time axis, a stop marker for every axis",
          "[trace][plot]") {
    const Recorded& rec = simple_run();
    const std::string svg = rec.plot.svg();
    CHECK(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
    CHECK(svg.find("</svg>") != std::string::npos);
    CHECK(count(svg, "<g class=\"panel\"") == 5);
    CHECK(count(svg, "machine time (s)") == 1);
    for (Axis a : cardreader::kAxes) {
        const std::string name(cardreader::axis_name(a));
        INFO(name);
        CHECK(count(svg, "class=\"stop-marker\" data-axis=\"" + name + "\"") >= 1);
        CHECK(rec.plot.stop_times(a).size() == 1);
        CHECK(rec.plot.slow_down_times(a).empty()); // start speed 3: no slow-downs
        const auto path = rec.plot.path(a);
        REQUIRE_FALSE(path.empty());
        CHECK(std::fabs(path.back().x - rec.result.axes.at(cardreader::axis_index(a)).real_in) <
              1e-9);
    }
    CHECK(svg.find("card 1") != std::string::npos);
    CHECK(svg.find("speed 1") != std::string::npos);
    CHECK(svg.find(">off<") != std::string::npos);
}

TEST_CASE("Plot: a speed-1 card with slow-downs 0.750 and 0.850 marks two slow-downs and the stop "
          "at 0.950 (Fig. 10, speed switch 236)",
          "[trace][plot]") {
    CardOrders o = one_axis_per_step();
    auto& table = o.axis(Axis::table);
    table.start_speed = 1;
    table.slow_down = {cardreader::Thousandths{750}, cardreader::Thousandths{850}};
    table.stop = 950;
    table.check = 950;
    const Recorded rec = run_deck({o});
    REQUIRE(rec.result.completed);
    const auto& slow = rec.plot.slow_down_times(Axis::table);
    REQUIRE(slow.size() == 2);
    REQUIRE(rec.plot.stop_times(Axis::table).size() == 1);
    CHECK(slow[0] < slow[1]);
    CHECK(slow[1] < rec.plot.stop_times(Axis::table).front());
    // The speed switch went 0 -> 1 (card), 1 -> 2, 2 -> 3 (slow-downs), 3 -> 0 (stop).
    std::vector<int> positions;
    for (const auto& p : rec.plot.speed_steps(Axis::table)) {
        positions.push_back(static_cast<int>(p.x));
    }
    CHECK(positions == std::vector<int>{0, 1, 2, 3, 0});
    const std::string svg = rec.plot.svg();
    CHECK(count(svg, "class=\"slowdown-marker\" data-axis=\"table\"") == 2);
    CHECK(count(svg, "class=\"slowdown-marker\" data-axis=\"cross\"") == 0);
}

TEST_CASE("Plot: a long run keeps at most 4 points a bucket, and the extremes of the path",
          "[trace][plot]") {
    PlotSvgRecorder plot;
    // A saw tooth: 200,000 reports over 2,000 s, the table swinging 0 .. 1 in every 10 s.
    plot.on_start();
    double peak = 0;
    for (int i = 1; i <= 200000; ++i) {
        const double t = i * 0.01;
        const double x = std::fmod(t, 10.0) / 10.0;
        peak = std::max(peak, x);
        plot.on_motion(t, {x, 0, 0, 0, 0});
    }
    plot.on_finish(2000.5);
    const auto path = plot.path(Axis::table);
    CHECK(path.size() <= 4 * PlotSvgRecorder::kMaxBuckets);
    CHECK(path.size() > 400);
    double highest = 0;
    for (const auto& p : path) {
        highest = std::max(highest, p.x);
    }
    CHECK(highest == peak);
    CHECK(path.front().t == 0);
    CHECK(path.back().t == 2000.5);
    for (std::size_t i = 1; i < path.size(); ++i) {
        REQUIRE(path[i].t >= path[i - 1].t);
    }
    CHECK(count(plot.svg(), "<g class=\"panel\"") == 5);
}

TEST_CASE("Patent map: every numeral a trace signal carries is listed in docs/patent-map.md, on a "
          "row that names the file it lives in",
          "[docs][trace]") {
    // The numerals the map lists: every whole number in the first cell of a table row, kept
    // only where the row names a source file.
    std::ifstream map(std::string(PARSONS_SOURCE_DIR) + "/docs/patent-map.md");
    REQUIRE(map);
    const std::regex row(R"(^\|([^|]*)\|.*\|\s*$)");
    const std::regex source_file(R"(`[a-z_0-9/]+\.(hpp|cpp)`)");
    const std::regex number(R"(\d+)");
    const std::regex range("(\\d+)\\s*(?:–|-)\\s*(\\d+)");
    std::set<std::string> listed;
    std::string line;
    while (std::getline(map, line)) {
        std::smatch m;
        if (!std::regex_match(line, m, row) || !std::regex_search(line, source_file)) {
            continue;
        }
        const std::string first = m[1];
        for (std::sregex_iterator it(first.begin(), first.end(), number), end; it != end; ++it) {
            listed.insert(it->str());
        }
        // A range ("226–234", "292–304") lists every numeral in it.
        for (std::sregex_iterator it(first.begin(), first.end(), range), end; it != end; ++it) {
            for (int n = std::stoi((*it)[1]); n <= std::stoi((*it)[2]); ++n) {
                listed.insert(std::to_string(n));
            }
        }
    }
    REQUIRE(listed.size() > 50);
    for (const bool separate : {false, true}) {
        auto profile = axes::default_profile();
        profile.separate_registers = separate;
        const relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
        for (const auto& s : cabinet.tracer().signals()) {
            for (std::sregex_iterator it(s.numeral.begin(), s.numeral.end(), number), end;
                 it != end; ++it) {
                INFO(s.scope << "." << s.name << " carries numeral " << s.numeral);
                CHECK(listed.count(it->str()) == 1);
            }
        }
    }
}

TEST_CASE("Patent map: numerals 28, 114 to 120 and 136 are on rows of US 2,820,187's own "
          "sections that name their files, and 268 is there as circuit and as indicator",
          "[docs][trace]") {
    std::ifstream map(std::string(PARSONS_SOURCE_DIR) + "/docs/patent-map.md");
    REQUIRE(map);
    const std::regex row(R"(^\|([^|]*)\|([^|]*)\|.*\|\s*$)");
    const std::regex source_file(R"(`[a-z_0-9/]+\.(hpp|cpp)`)");
    const std::regex number(R"(\d+)");
    const std::regex range("(\\d+)\\s*(?:–|-)\\s*(\\d+)");
    std::set<int> listed;
    std::string parts_268;
    std::string section;
    std::string line;
    while (std::getline(map, line)) {
        if (line.rfind("## ", 0) == 0) {
            section = line;
            continue;
        }
        // The patent's own sections: not EP 0640901, 0436887, 0360190, nor the additions.
        const bool us = section.find("EP 0") == std::string::npos &&
                        section.find("additions") == std::string::npos;
        std::smatch m;
        if (!us || !std::regex_match(line, m, row) || !std::regex_search(line, source_file)) {
            continue;
        }
        const std::string first = m[1];
        std::set<int> here;
        for (std::sregex_iterator it(first.begin(), first.end(), number), end; it != end; ++it) {
            here.insert(std::stoi(it->str()));
        }
        for (std::sregex_iterator it(first.begin(), first.end(), range), end; it != end; ++it) {
            for (int n = std::stoi((*it)[1]); n <= std::stoi((*it)[2]); ++n) {
                here.insert(n);
            }
        }
        listed.insert(here.begin(), here.end());
        if (here.count(268) == 1) {
            parts_268 += m[1].str() + m[2].str() + "\n";
        }
    }
    for (int n : {28, 114, 116, 118, 120, 136, 268}) {
        INFO("numeral " << n);
        CHECK(listed.count(n) == 1);
    }
    // The patent gives 268 to circuit 268 (contact 238 and comparers 122', 122'' to balancing
    // circuit 266 and channel 274) and to the indicator of circuit 262-264.
    INFO(parts_268);
    CHECK_THAT(parts_268, Catch::Contains("circuit 268") && Catch::Contains("indicator"));
}
