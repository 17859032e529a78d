// What a run tells the user (the command-line issue, item 5): the report names the version and
// its own layout, the profile actually applied and where every limit came from, and rounds
// its figures to what they resolve; a resume says which deck it goes on with; Ctrl-C lights
// what docs/stop-codes.md says.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "outputs/report/run_report.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace parsons;
using namespace parsons::test;
using nlohmann::json;

namespace {

json read_report_json(const std::filesystem::path& p) {
    return json::parse(read_bytes(p));
}

// The project's version, as the top-level CMakeLists.txt declares it.
std::string project_version() {
    const std::string cmake = read_bytes(source_path("CMakeLists.txt"));
    std::smatch m;
    REQUIRE(std::regex_search(cmake, m, std::regex(R"(project\(parsons VERSION ([0-9.]+))")));
    return m[1];
}

// True when v is a whole number of `step`s (to the last bits of a double).
bool on_grid(double v, double step) {
    const double n = v / step;
    return std::abs(n - std::round(n)) < 1e-6;
}

// The listing with one field of one row replaced: the row of card `card` for `axis`, field
// `index` counted from 0 (card, spindle, axis, motion, speed, slow1, slow2, stop, check, seq).
std::string with_field(const std::string& listing, int card, const std::string& axis,
                       std::size_t index, const std::string& value) {
    std::istringstream in(listing);
    std::string out;
    std::string line;
    bool found = false;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream row(line);
        for (std::string f; std::getline(row, f, ',');) {
            fields.push_back(f);
        }
        if (fields.size() > index && fields.at(0) == std::to_string(card) && fields.at(2) == axis) {
            fields.at(index) = value;
            found = true;
            line.clear();
            for (const auto& f : fields) {
                line += (line.empty() ? "" : ",") + f;
            }
        }
        out += line + "\n";
    }
    REQUIRE(found);
    return out;
}

json differences_by_key(const json& report) {
    json by_key = json::object();
    for (const auto& d : report["profile_applied"]["differs_from_named"]) {
        by_key[d["key"].get<std::string>()] = d;
    }
    return by_key;
}

} // namespace

TEST_CASE("Report: it names the parsons version, its schema version and the profile applied",
          "[cli][report]") {
    TempDir dir;
    const std::string sample = q(source_path("decks/samples/patent-example.csv"));
    REQUIRE(run_parsons("run " + sample + " -q --report " + q(dir.str("r.json"))).exit_code == 0);
    const json r = read_report_json(dir.path("r.json"));
    CHECK(r["parsons_version"] == project_version());
    CHECK(r["schema_version"] == 1);
    CHECK(r["profile"] == "parsons-1952");
    const json& p = r["profile_applied"];
    CHECK(p["name"] == "parsons-1952");
    CHECK(p["file"].is_null());
    CHECK(p["named_profile"] == "parsons-1952");
    CHECK(p["differs_from_named"] == json::array());
    CHECK(p["limits"]["table"]["movement_range"]["in"].is_null());
    CHECK(p["limits"]["table"]["movement_range"]["from"] == "profile parsons-1952");
    CHECK(p["limits"]["tilt"]["limit_switches"]["in"] == json::array({-0.5, 10.5}));
    CHECK(p["limits"]["tilt"]["limit_switches"]["from"] == "profile parsons-1952");

    // The built-in parsons-safe by name: nothing differs from it, and it is what applied.
    REQUIRE(run_parsons("run " + sample + " -q --profile parsons-safe --report " +
                        q(dir.str("safe.json")))
                .exit_code == 0);
    const json safe = read_report_json(dir.path("safe.json"));
    CHECK(safe["profile_applied"]["name"] == "parsons-safe");
    CHECK(safe["profile_applied"]["differs_from_named"] == json::array());
}

TEST_CASE("Report: a profile file is applied over the built-in profile it names, and every "
          "value that differs from that profile is listed with both values",
          "[cli][report]") {
    TempDir dir;
    const std::string sample = q(source_path("decks/samples/patent-example.csv"));
    // Named parsons-safe: its double-punch refusal stays on, though the file does not say so.
    write_bytes(dir.path("worn.json"),
                R"({"name": "parsons-safe", "delay_258_s": 0.2,
                    "axes": {"table": {"backlash_in": 0.002, "travel_max_in": 10.0}}})");
    const auto run = run_parsons("run " + sample + " -q --profile " + q(dir.str("worn.json")) +
                                 " --limit cross=0:3 --report " + q(dir.str("r.json")));
    REQUIRE(run.exit_code == 0);
    const json r = read_report_json(dir.path("r.json"));
    const json& p = r["profile_applied"];
    CHECK(p["name"] == "parsons-safe");
    CHECK(p["named_profile"] == "parsons-safe");
    CHECK(p["file"] == dir.str("worn.json"));
    const json by_key = differences_by_key(r);
    CHECK(by_key.size() == 4);
    CHECK(by_key["delay_258_s"]["value"] == 0.2);
    CHECK(by_key["delay_258_s"]["named_value"] == 0.15);
    CHECK(by_key["axes.table.backlash_in"]["value"] == 0.002);
    CHECK(by_key["axes.table.backlash_in"]["named_value"] == 0.0);
    CHECK(by_key["axes.table.travel_max_in"]["value"] == 10.0);
    CHECK(by_key["axes.cross.soft_limits_in"]["value"] == json::array({0.0, 3.0}));
    CHECK(by_key["axes.cross.soft_limits_in"]["named_value"].is_null());
    CHECK_FALSE(by_key.contains("refuse_double_punch")); // safe's own value, not a difference
    // Where each limit came from.
    CHECK(p["limits"]["cross"]["movement_range"]["from"] == "--limit cross=0:3");
    CHECK(p["limits"]["table"]["limit_switches"]["from"] == "profile file " + dir.str("worn.json"));
    CHECK(p["limits"]["cross"]["limit_switches"]["from"] == "profile parsons-safe");
}

TEST_CASE("Report: figures are rounded to what they resolve, a saved state keeps every bit",
          "[cli][report]") {
    TempDir dir;
    // A deck whose moves coast past their stops: real positions and times are not round. Card
    // 3's table check is one short, so the machine stops there (check_mismatch).
    write_bytes(dir.path("deck.csv"), with_field(long_listing(6), 3, "table", 8, "8.999"));
    REQUIRE(run_parsons("run " + q(dir.str("deck.csv")) + " -q --report " + q(dir.str("r.json")) +
                        " --save-state " + q(dir.str("s.json")))
                .exit_code == 3);
    const json r = read_report_json(dir.path("r.json"));
    CHECK(on_grid(r["machine_seconds"].get<double>(), 1e-6));
    int off_thousandth = 0;
    for (const auto& [name, a] : r["axes"].items()) {
        INFO(name);
        CHECK(on_grid(a["position"].get<double>(), 0.001));
        CHECK(on_grid(a["real_position"].get<double>(), 0.00001));
        CHECK(on_grid(a["position_error"].get<double>(), 0.00001));
        CHECK(on_grid(a["screw_turns_position"].get<double>(), 0.00001));
        off_thousandth += on_grid(a["real_position"].get<double>(), 0.001) ? 0 : 1;
    }
    CHECK(off_thousandth > 0); // real positions keep their coast: not rounded to the counters
    REQUIRE(r["cards"].size() == 3);
    for (const auto& c : r["cards"]) {
        CHECK(on_grid(c["start_seconds"].get<double>(), 1e-6));
        CHECK(on_grid(c["machine_seconds"].get<double>(), 1e-6));
    }
    // The saved state keeps the real positions to the last bit.
    const json s = read_report_json(dir.path("s.json"));
    int kept = 0;
    for (const auto& [name, a] : r["axes"].items()) {
        const double exact = s["stop"]["axes_at_rest"][name]["real_in"].get<double>();
        const double rounded = a["real_position"].get<double>();
        CHECK(std::abs(exact - rounded) <= 5e-6);
        kept += exact != rounded ? 1 : 0;
    }
    CHECK(kept > 0);
}

TEST_CASE("Resume: it names the deck the state was saved from when another is given, warns "
          "when the cards already machined changed, and says where each limit came from",
          "[cli][resume][report]") {
    TempDir dir;
    const std::string good = long_listing(6);
    // Card 3's table check is one short: the machine stops on card 3, cards 1 and 2 machined.
    write_bytes(dir.path("deck.csv"), with_field(good, 3, "table", 8, "8.999"));
    const std::string state_file = dir.str("state.json");
    const auto stopped = run_parsons("run " + q(dir.str("deck.csv")) +
                                     " -q --limit table=0:9.6 --save-state " + q(state_file));
    REQUIRE(stopped.exit_code == 3);
    const json state = read_report_json(dir.path("state.json"));
    REQUIRE(state["resume_card"] == 3);
    CHECK(state["cards_machined"]["cards"] == 2);
    CHECK(state["profile_applied"]["limits"]["table"]["movement_range"]["from"] ==
          "--limit table=0:9.6");
    write_bytes(dir.path("deck.csv"), good); // the deck corrected in place

    SECTION("the corrected deck, a new --limit: where each limit came from") {
        const auto resumed = run_parsons("run " + q(dir.str("deck.csv")) + " --resume " +
                                         q(state_file) + " --limit table=0:9.7");
        INFO(resumed.output);
        CHECK(resumed.exit_code == 0);
        CHECK_THAT(resumed.output,
                   Catch::Contains("table    movement range 0.000 .. 9.700 in (--limit "
                                   "table=0:9.7)"));
        CHECK_THAT(resumed.output,
                   Catch::Contains("cross    no movement range (saved state " + state_file +
                                   ", profile parsons-1952 in the stopped run); limit switches "
                                   "-0.500 .. 10.500 in (saved state " +
                                   state_file + ", profile parsons-1952 in the stopped run)"));
        CHECK(resumed.output.find("saved from another deck") == std::string::npos);
        CHECK(resumed.output.find("are not the cards") == std::string::npos);
    }
    SECTION("resumed without --limit: the stopped run's range, and that it came from --limit") {
        const auto resumed =
            run_parsons("run " + q(dir.str("deck.csv")) + " --resume " + q(state_file));
        INFO(resumed.output);
        CHECK(resumed.exit_code == 0);
        CHECK_THAT(resumed.output,
                   Catch::Contains("table    movement range 0.000 .. 9.600 in (saved state " +
                                   state_file + ", --limit table=0:9.6 in the stopped run)"));
    }
    SECTION("another deck, whose card 1 differs from the card the stopped run machined") {
        std::string other = good;
        for (const char* axis : {"table", "cross", "vertical", "swivel", "tilt"}) {
            other = with_field(other, 1, axis, 1, "0"); // spindle forward, not reverse
        }
        write_bytes(dir.path("other.csv"), other);
        const auto resumed =
            run_parsons("run " + q(dir.str("other.csv")) + " --resume " + q(state_file));
        INFO(resumed.output);
        CHECK_THAT(resumed.output,
                   Catch::Contains("(saved from another deck: " + dir.str("deck.csv") + ")"));
        CHECK_THAT(resumed.output, Catch::Contains("cards 1 to 2 of " + dir.str("other.csv") +
                                                   " are not the cards the stopped run machined"));
    }
    SECTION("a copy of the deck under another name: named, but no warning") {
        write_bytes(dir.path("copy.csv"), good);
        const auto resumed =
            run_parsons("run " + q(dir.str("copy.csv")) + " --resume " + q(state_file));
        CHECK(resumed.exit_code == 0);
        CHECK_THAT(resumed.output, Catch::Contains("saved from another deck"));
        CHECK(resumed.output.find("are not the cards") == std::string::npos);
    }
}

TEST_CASE("Ctrl-C: the operator opens master switch 204 by hand: no indicator 268, no lamp of "
          "the stop, as docs/stop-codes.md says",
          "[cli][signals]") {
    std::vector<cardreader::CardOrders> cards;
    std::array<int, 5> at{0, 0, 0, 0, 0};
    cards.push_back(idle_card(1, at));
    cards.front().axis(cardreader::Axis::table) = order(0, 985, 1, 785, 885, 1);
    std::vector<cardreader::Card> punched;
    for (const auto& o : cards) {
        punched.push_back(cardreader::encode(o, cardreader::fig8_layout()).card);
    }
    VectorDeck deck(punched);
    relaylogic::ControlCabinet cabinet(axes::default_profile(), cardreader::fig8_layout());
    Recorder recorder;
    cabinet.attach(&recorder);
    volatile std::sig_atomic_t pressed = 1;
    cabinet.watch_interrupt(&pressed);
    const relaylogic::RunResult r = cabinet.run(deck);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == relaylogic::StopReason::interrupted);
    CHECK(r.stop->lamps.empty());
    CHECK(recorder.value.at("cabinet.master_switch_204") == 0);
    CHECK(recorder.value.at("cabinet.indicator_268") == 0);
    CHECK(recorder.value.at("cabinet.electromagnet_265") == 0);
    // The docs say the same.
    const std::string doc = read_bytes(source_path("docs/stop-codes.md"));
    const auto row = doc.find("| `interrupted` |");
    REQUIRE(row != std::string::npos);
    const std::string line = doc.substr(row, doc.find('\n', row) - row);
    CHECK_THAT(line, Catch::Contains("none of the checks: the operator opened master switch 204 "
                                     "by hand"));
    CHECK_THAT(line, Catch::Contains("indicator 268 silent"));
}

namespace {

// Every key of a JSON document, at any depth; the axis names (keys of per-axis objects) are
// not field names.
void collect_report_keys(const json& j, std::set<std::string>& keys) {
    static const std::set<std::string> axes = {"table", "cross", "vertical", "swivel", "tilt"};
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) {
            if (axes.count(k) == 0) {
                keys.insert(k);
            }
            collect_report_keys(v, keys);
        }
    } else if (j.is_array()) {
        for (const auto& v : j) {
            collect_report_keys(v, keys);
        }
    }
}

} // namespace

TEST_CASE("Report: docs/report.md names every key a report carries", "[cli][report][docs]") {
    TempDir dir;
    const std::string sample = q(source_path("decks/samples/patent-example.csv"));
    std::set<std::string> keys;
    // Completed; stopped by a fault with a profile file and a limit; a template cut; a wing cut.
    REQUIRE(run_parsons("run " + sample + " -q --report " + q(dir.str("a.json"))).exit_code == 0);
    write_bytes(dir.path("p.json"),
                R"({"name": "worn", "axes": {"table": {"backlash_in": 0.001}}})");
    REQUIRE(run_parsons("run " + sample + " -q --profile " + q(dir.str("p.json")) +
                        " --limit table=0:9.5 --fault drop-impulse:table:120 --report " +
                        q(dir.str("b.json")))
                .exit_code == 3);
    REQUIRE(
        run_parsons("gen airfoil --naca 2412 --stations 12 -o " + q(dir.str("t.cbn"))).exit_code ==
        0);
    REQUIRE(run_parsons("run " + q(dir.str("t.cbn")) + " -q --cut " + q(dir.str("t.svg")) +
                        " --report " + q(dir.str("c.json")))
                .exit_code == 0);
    REQUIRE(run_parsons("gen airfoil --naca 0012 --job wing --chord 4 --span 5 --stations 6 -o " +
                        q(dir.str("w.cbn")))
                .exit_code == 0);
    REQUIRE(run_parsons("run " + q(dir.str("w.cbn")) + " -q --cut " + q(dir.str("w.svg")) +
                        " --report " + q(dir.str("d.json")))
                .exit_code == 0);
    // Press synchronisation (an addition): a sync card, a move, a loop, under parsons-extended.
    write_bytes(dir.path("press.csv"), "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n"
                                       "1,sync,position,30\n"
                                       "2,0,table,+,1,0.200,0.250,0.300,0.300,1\n"
                                       "2,0,cross,+,3,,,0.000,0.000,2\n"
                                       "2,0,vertical,+,3,,,0.000,0.000,3\n"
                                       "2,0,swivel,+,3,,,0.000,0.000,4\n"
                                       "2,0,tilt,+,3,,,0.000,0.000,5\n"
                                       "3,0,table,-,1,0.050,0.020,0.000,0.300,1\n"
                                       "3,0,cross,+,3,,,0.000,0.000,2\n"
                                       "3,0,vertical,+,3,,,0.000,0.000,3\n"
                                       "3,0,swivel,+,3,,,0.000,0.000,4\n"
                                       "3,0,tilt,+,3,,,0.000,0.000,5\n"
                                       "4,sync,loop,1,2\n");
    const auto pressed =
        run_parsons("run " + q(dir.str("press.csv")) + " -q --profile parsons-extended --report " +
                    q(dir.str("e.json")));
    INFO(pressed.output);
    REQUIRE(pressed.exit_code == 0);
    const auto press_report = read_report_json(dir.path("e.json"));
    CHECK(press_report["press"]["cycles"] == 3);
    CHECK(press_report["press"]["loop_backs"] == 2);
    CHECK(press_report["press"]["mean_cycle_seconds"].get<double>() ==
          Approx(30.0).margin(1.0 / 48));
    // The press-feeder job's proof adds its figures to the press block.
    REQUIRE(run_parsons("gen press-feeder --cycles 1 -o " + q(dir.str("f.csv"))).exit_code == 0);
    REQUIRE(run_parsons("run " + q(dir.str("f.csv")) + " -q --press-proof " +
                        q(dir.str("f.csv.job.json")) + " --report " + q(dir.str("f.json")))
                .exit_code == 0);
    for (const char* name : {"a.json", "b.json", "c.json", "d.json", "e.json", "f.json"}) {
        collect_report_keys(read_report_json(dir.path(name)), keys);
    }
    // The reports exercised what they were meant to.
    for (const char* expected :
         {"fixture_angle_deg", "max_scallop_in", "root", "lamps", "effect", "named_value",
          "movement_range", "loop_backs", "min_clearance_in"}) {
        CHECK(keys.count(expected) == 1);
    }
    const std::string doc = read_bytes(source_path("docs/report.md"));
    for (const std::string& key : keys) {
        INFO(key);
        CHECK(doc.find("`" + key + "`") != std::string::npos);
    }
}

TEST_CASE("Progress: a line on standard error for bench, run and gen on a terminal only, never "
          "in a pipe or under -q",
          "[cli][progress]") {
    TempDir dir;
    write_bytes(dir.path("deck.csv"), long_listing(6));
    const std::string bench = "bench --runs 1 --long-cards 4 --trace-cards 2 --short-cards 1000 "
                              "--memory-cards 1000 --press-cycles 10";
    // `script` gives the command a terminal (a pseudo-terminal) and copies what it printed.
    auto on_terminal = [](const std::string& args) {
        return run_shell("script -qec " + q(std::string("'") + PARSONS_EXE + "' " + args) +
                         " /dev/null");
    };
    const auto tty = on_terminal(bench);
    REQUIRE(tty.exit_code == 0);
    CHECK_THAT(tty.output, Catch::Contains("\r[#####"));
    CHECK_THAT(tty.output, Catch::Contains("fast-forward, short moves (4/13)"));
    CHECK_THAT(tty.output, Catch::Contains("press cycles (13/13)"));
    CHECK_THAT(tty.output, Catch::Contains("deck generation"));
    const auto piped = run_parsons(bench);
    REQUIRE(piped.exit_code == 0);
    CHECK(piped.output.find('\r') == std::string::npos);
    CHECK(piped.output.find("(4/13)") == std::string::npos);

    const auto run_tty = on_terminal("run " + q(dir.str("deck.csv")));
    REQUIRE(run_tty.exit_code == 0);
    CHECK_THAT(run_tty.output, Catch::Contains("card 1  machine time"));
    const auto run_quiet = on_terminal("run -q " + q(dir.str("deck.csv")));
    CHECK(run_quiet.output.find("machine time") == std::string::npos);
    const auto run_piped = run_parsons("run " + q(dir.str("deck.csv")));
    CHECK(run_piped.output.find('\r') == std::string::npos);

    const std::string gen = "gen airfoil --naca 2412 --stations 9997 -o " + q(dir.str("g.cbn"));
    const auto gen_tty = on_terminal(gen);
    REQUIRE(gen_tty.exit_code == 0);
    CHECK_THAT(gen_tty.output, Catch::Contains("naca 2412: computing the stations"));
    CHECK_THAT(gen_tty.output, Catch::Contains("punching card 1 of 9999"));
    const auto gen_piped = run_parsons(gen);
    CHECK(gen_piped.output.find("computing the stations") == std::string::npos);
}

TEST_CASE("Summary: an axis that ends half a thousandth or more from where its counters say is "
          "warned about with the cause the chain's figures give, and less is no warning",
          "[report][summary][mutation]") {
    // A cross slide whose commutators read 1.000 and whose part stands 1.00125: instrument
    // shaft 74's own error +0.0015 at the reading, the rest where it came to rest.
    auto summary_with = [](double error_in) {
        relaylogic::RunResult r;
        r.completed = true;
        auto& x = r.axes.at(1); // the cross slide
        x.commutator_in = 1.0;
        x.real_in = 1.0 + error_in;
        x.error_in = error_in;
        x.chain.at_in = 1.0;
        x.chain.instrument_in = error_in;
        return cli::summary_text(r, "d.cbn", "parsons-safe");
    };
    CHECK_THAT(summary_with(0.0005),
               Catch::Contains("cross ends +0.0005 in from where its counters say (instrument "
                               "shaft 74's own screw error +0.0005 in at 1.000 in "
                               "(instrument_error_in)"));
    CHECK_THAT(summary_with(-0.0005), Catch::Contains("cross ends -0.0005 in"));
    CHECK_THAT(summary_with(-0.0123), Catch::Contains("own screw error -0.0123 in"));
    CHECK_THAT(summary_with(0.00049), !Catch::Contains("warning"));
    CHECK_THAT(summary_with(-0.00049), !Catch::Contains("warning"));
    CHECK_THAT(summary_with(0.0), !Catch::Contains("warning"));
    // Nothing in the chain, nothing the counters did: a figure no mechanism gives is said to be
    // unaccounted for, never put on a cause.
    relaylogic::RunResult odd;
    odd.completed = true;
    odd.axes.at(1).real_in = 1.002;
    odd.axes.at(1).commutator_in = 1.002;
    odd.axes.at(1).error_in = 0.002;
    CHECK_THAT(cli::summary_text(odd, "d.cbn", "parsons-safe"),
               Catch::Contains("+0.0020 in between the commutators and the counters not "
                               "accounted for"));
}

TEST_CASE("Summary: the causes of a silent position error come from the measuring chain's own "
          "figures, largest first, each with its share",
          "[report][summary][measuring-chain]") {
    relaylogic::RunResult r;
    r.completed = true;
    auto& x = r.axes.at(0); // the table, counting screw turns
    x.chain.counts_screw_turns = true;
    x.chain.at_in = 2.389;
    x.chain.backlash_in = 0.004;
    x.chain.lead_in = 0.001;
    x.chain.slip_in = -0.00004; // under the last decimal printed: left out
    x.commutator_in = 2.385;
    x.real_in = 2.385 + 0.005 - 0.00004 + 0.00025;
    x.wrong_way = 3;
    x.error_in = x.real_in - 2.385 + 0.006; // the counters three impulses short of the reading
    const std::string s = cli::summary_text(r, "d.cbn", "parsons-1952");
    INFO(s);
    const auto backlash = s.find("backlash in nut 78 +0.0040 in");
    const auto wrong = s.find("3 impulses of coast counted in the other direction");
    const auto lead = s.find("lead error of lead screw 22 +0.0010 in at 2.389 in");
    REQUIRE(backlash != std::string::npos);
    REQUIRE(wrong != std::string::npos);
    REQUIRE(lead != std::string::npos);
    CHECK(wrong < backlash); // +0.0060 first, then +0.0040, then +0.0010
    CHECK(backlash < lead);
    CHECK_THAT(s, Catch::Contains("(reversing control 214 was already set for the next card): "
                                  "+0.0060 in"));
    CHECK_THAT(s, !Catch::Contains("slipped"));
    CHECK_THAT(s, !Catch::Contains("not accounted for"));
}
