// docs/output-formats.md against what parsons really writes: the events stream (run --events),
// the path CSV (run --path), the cutter-centres CSV (gen airfoil --centres) and the job file
// (DECK.job.json). Each test runs the built executable on shipped inputs, collects every field,
// column, event kind, stop reason and signal the file holds, and requires each to be named in a
// table row of the page's section for that file: a writer that gains a field nobody documented
// fails here. A few values are checked too, so that the files are what the page says they are.
#include "tests/test_support.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/deck_io.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using parsons::test::kSample;
using parsons::test::lines_of;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::vector<std::string> split(const std::string& line, char sep) {
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream in(line);
    while (std::getline(in, cell, sep)) {
        cells.push_back(cell);
    }
    if (!line.empty() && line.back() == sep) {
        cells.emplace_back();
    }
    return cells;
}

// The section of docs/output-formats.md whose "## " heading holds `key`, up to the next "## ".
std::string doc_section(const std::string& key) {
    const std::string doc = read_bytes(source_path("docs/output-formats.md"));
    std::string out;
    bool inside = false;
    for (const std::string& line : lines_of(doc)) {
        if (line.rfind("## ", 0) == 0) {
            inside = line.find(key) != std::string::npos;
        }
        if (inside) {
            out += line + "\n";
        }
    }
    REQUIRE_FALSE(out.empty());
    return out;
}

// The table rows of a section, keyed by each `name` in backticks in the row's first cell
// (a row may name several: "| `table.motor_38`, `cross.motor_50` | ..."): name -> the row.
std::map<std::string, std::string> documented(const std::string& section) {
    std::map<std::string, std::string> rows;
    static const std::regex kName("`([^`]+)`");
    for (const std::string& line : lines_of(section)) {
        if (line.rfind("| ", 0) != 0) {
            continue;
        }
        const auto end = line.find(" |", 1);
        const std::string first = line.substr(2, end == std::string::npos ? 0 : end - 2);
        for (std::sregex_iterator it(first.begin(), first.end(), kName), last; it != last; ++it) {
            rows[(*it)[1].str()] = line;
        }
    }
    return rows;
}

// The n-th cell (0-based) of a table row.
std::string cell(const std::string& row, std::size_t n) {
    const auto cells = split(row, '|');
    return n + 1 < cells.size() ? cells[n + 1] : std::string();
}

void require_documented(const std::set<std::string>& names,
                        const std::map<std::string, std::string>& rows, const std::string& what) {
    for (const std::string& name : names) {
        INFO(what << " `" << name << "` is written but has no row in docs/output-formats.md");
        CHECK(rows.count(name) == 1);
    }
}

// Every key of a JSON object, nested objects as "outer.inner" (arrays are values).
void collect_doc_keys(const nlohmann::json& j, const std::string& prefix,
                      std::set<std::string>& out) {
    for (const auto& [key, value] : j.items()) {
        out.insert(prefix + key);
        if (value.is_object()) {
            collect_doc_keys(value, prefix + key + ".", out);
        }
    }
}

// A signal's family as the page names it: "table.absolute_storage_352.relay_7" ->
// "AXIS.absolute_storage_352.relay_D"; cabinet signals keep their scope.
std::string signal_family(const std::string& signal) {
    static const std::set<std::string> kAxes = {"table", "cross", "vertical", "swivel", "tilt"};
    std::string family = signal;
    const auto dot = family.find('.');
    if (dot != std::string::npos && kAxes.count(family.substr(0, dot)) == 1) {
        family = "AXIS" + family.substr(dot);
    }
    static const std::regex kRelay(R"(\.relay_[0-9]$)");
    return std::regex_replace(family, kRelay, ".relay_D");
}

// What one or more events streams hold.
struct EventsSeen {
    std::set<std::string> fields;               // keys of every line
    std::set<std::string> kinds;                // values of "event"
    std::set<std::string> reasons;              // values of "reason" on stop lines
    std::map<std::string, std::string> signals; // signal -> its numeral
    long lines = 0;

    void read(const std::string& text) {
        double last_t = -1;
        for (const std::string& line : lines_of(text)) {
            const auto j = nlohmann::json::parse(line);
            REQUIRE(j.is_object());
            ++lines;
            collect_doc_keys(j, "", fields);
            const double t = j.at("t").get<double>();
            CHECK(t >= last_t); // machine time never runs backwards
            last_t = t;
            if (j.contains("event")) {
                kinds.insert(j.at("event").get<std::string>());
                if (j.at("event") == "stop") {
                    reasons.insert(j.at("reason").get<std::string>());
                }
            } else {
                REQUIRE(j.contains("signal"));
                signals[j.at("signal").get<std::string>()] = j.at("numeral").get<std::string>();
            }
        }
    }
};

// Every signal the cabinet defines (the events stream shows only those that change).
class SignalNames : public parsons::relaylogic::MachineObserver {
public:
    void on_signal_defined(const parsons::relaylogic::SignalInfo& info,
                           std::uint32_t /*initial*/) override {
        signals[info.scope + "." + info.name] = info.numeral;
    }
    std::map<std::string, std::string> signals;
};

std::string sample_with(const std::string& from, const std::string& to) {
    std::string text = read_bytes(source_path(kSample));
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

} // namespace

TEST_CASE("Output formats: every field, event kind, stop reason and signal of run --events has a "
          "row in docs/output-formats.md",
          "[output-formats][events][docs][heavy]") {
    TempDir dir;
    EventsSeen seen;
    // The sample deck run through, then stopped by each check the machine has.
    const std::string sample = q(source_path(kSample));
    write_bytes(dir.path("stall.csv"), sample_with("1,0,vertical,+,3,,,1.250,1.250,34",
                                                   "1,0,vertical,+,3,,,1.250,1.250,2"));
    const std::vector<std::pair<std::string, int>> runs = {
        {sample, 0},
        {sample + " --fault stuck-relay:table:354:1", 3}, // check_mismatch
        {sample + " --fault feed-twice:2", 3},            // out_of_order_card
        {sample + " --fault drop-impulse:cross:120", 3},  // missed_impulse
        {sample + " --fault short-card:2", 3},            // bad_punch
        {sample + " --limit table=0:8", 3},               // soft_limit
        {q(dir.str("stall.csv")), 3},                     // sequence_stall
        // Condition cards (an addition): their three lines, and condition_not_met.
        {q(source_path("decks/samples/condition-cards.csv")) + " --profile parsons-extended", 0},
        {q(dir.str("not-met.csv")) + " --profile parsons-extended", 3},
        // Press synchronisation (an addition): a sync card (position and speed) and its motion
        // card, and the same deck with a processor 17 too impatient for the crank.
        {q(dir.str("press.csv")) + " --profile parsons-extended", 0},
        {q(dir.str("press.csv")) + " --profile " + q(dir.str("impatient.json")), 3},
    };
    // Card 1 waits for the crank at 30 deg and has the table follow it at 0.00150 in a pulse;
    // card 2 takes the table out 0.3 in. With sync_timeout_s 1 the crank (12 deg/s from top
    // dead centre) is still short of 30 deg when processor 17 gives up: sync_timeout.
    write_bytes(dir.path("press.csv"), "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n"
                                       "1,sync,position,30\n"
                                       "1,sync,speed,table,0.00150\n"
                                       "2,0,table,+,1,0.100,0.200,0.300,0.300,1\n"
                                       "2,0,cross,+,3,,,0.000,0.000,2\n"
                                       "2,0,vertical,+,3,,,0.000,0.000,3\n"
                                       "2,0,swivel,+,3,,,0.000,0.000,4\n"
                                       "2,0,tilt,+,3,,,0.000,0.000,5\n");
    write_bytes(dir.path("impatient.json"),
                R"({"base": "parsons-extended", "sync_timeout_s": 1.0})");
    {
        std::string deck = read_bytes(source_path("decks/samples/condition-cards.csv"));
        const std::string row = "1,if,7,table,+,5.000,lamp,3";
        REQUIRE(deck.find(row) != std::string::npos);
        deck.replace(deck.find(row), row.size(), "1,if,7,table,-,5.000,lamp,3");
        write_bytes(dir.path("not-met.csv"), deck);
    }
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::string events = dir.str("e" + std::to_string(i) + ".jsonl");
        const auto r = run_parsons("run " + runs[i].first + " -q --events " + q(events));
        INFO(runs[i].first << "\n" << r.output);
        REQUIRE(r.exit_code == runs[i].second);
        seen.read(read_bytes(events));
    }
    CHECK(seen.lines > 1000);
    CHECK(seen.kinds == std::set<std::string>{"card", "stop", "finish", "condition_met",
                                              "action_started", "action_acknowledged"});
    CHECK(seen.reasons == std::set<std::string>{
                              "check_mismatch", "out_of_order_card", "missed_impulse", "bad_punch",
                              "soft_limit", "sequence_stall", "condition_not_met", "sync_timeout"});
    // The press's signals are in the stream, those of every edge and those of the sync card.
    for (const char* name :
         {"press.crank_21.angle", "press.die_20.height", "press.detector_10.phase_a",
          "press.position_register_14", "press.speed_register_11.stored",
          "press.position_reader_60.hold", "press.sync_position_detector_61",
          "press.feed_speed_reader_62.table", "press.processor_63.table"}) {
        INFO(name);
        CHECK(seen.signals.count(name) == 1);
    }

    const std::string section = doc_section("--events");
    const auto rows = documented(section);
    require_documented(seen.fields, rows, "field");
    require_documented(seen.kinds, rows, "event kind");
    require_documented(seen.reasons, rows, "stop reason");
    // Every reason the machine can stop with, not only those these runs met.
    std::set<std::string> all_reasons;
    for (int i = 0; i < 256; ++i) {
        all_reasons.insert(std::string(parsons::relaylogic::stop_reason_name(
            static_cast<parsons::relaylogic::StopReason>(i))));
    }
    require_documented(all_reasons, rows, "stop reason");

    // Every signal: those the runs changed, and every one the cabinet defines. Each family's
    // row gives the patent numeral the lines carry.
    SignalNames defined;
    parsons::relaylogic::ControlCabinet cabinet(parsons::axes::default_profile(),
                                                parsons::cardreader::fig8_layout());
    cabinet.attach(&defined);
    // ... and the condition units' and the press's (parsons-extended).
    parsons::relaylogic::ControlCabinet extended(parsons::axes::extended_profile(),
                                                 parsons::cardreader::fig8_layout());
    extended.attach(&defined);
    CHECK(defined.signals.size() > 100);
    auto signals = defined.signals;
    for (const auto& [name, numeral] : seen.signals) {
        INFO(name);
        CHECK(defined.signals.count(name) == 1);
        signals[name] = numeral;
    }
    std::set<std::string> scopes;
    for (const auto& [name, numeral] : signals) {
        const std::string family = signal_family(name);
        scopes.insert(name.substr(0, name.find('.')));
        const auto row = rows.count(name) == 1 ? rows.find(name) : rows.find(family);
        INFO("signal `" << name << "` (family `" << family << "`)");
        if (row == rows.end()) {
            FAIL_CHECK("has no row in docs/output-formats.md");
        } else if (!numeral.empty()) {
            INFO("its row: " << row->second);
            CHECK_THAT(cell(row->second, 1), Catch::Matchers::Contains(numeral));
        }
    }
    require_documented(scopes, rows, "signal scope");
}

TEST_CASE("Output formats: the path CSV of run --path is one time column and one column per axis, "
          "each documented, times never decreasing, no row repeated",
          "[output-formats][path][docs]") {
    TempDir dir;
    const auto r = run_parsons("run " + q(source_path(kSample)) + " -q --path " +
                               q(dir.str("p.csv")) + " --report " + q(dir.str("r.json")));
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(read_bytes(dir.path("p.csv")));
    REQUIRE(lines.size() > 1000);
    const auto header = split(lines.front(), ',');
    CHECK(header == std::vector<std::string>{"t", "table", "cross", "vertical", "swivel", "tilt"});
    require_documented(std::set<std::string>(header.begin(), header.end()),
                       documented(doc_section("--path")), "column");

    double last_t = 0;
    std::vector<std::string> last;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        last = split(lines[i], ',');
        REQUIRE(last.size() == header.size());
        const double t = std::stod(last[0]);
        CHECK(t >= last_t);
        last_t = t;
        if (i > 1) {
            CHECK(lines[i] != lines[i - 1]); // no row repeats the one before
        }
    }
    // The last row is where the run left the part: the report's real positions.
    const auto report = nlohmann::json::parse(read_bytes(dir.path("r.json")));
    CHECK(last_t <= report["machine_seconds"].get<double>());
    for (std::size_t a = 1; a < header.size(); ++a) {
        INFO(header[a]);
        CHECK(std::stod(last[a]) ==
              Approx(report["axes"][header[a]]["real_position"].get<double>()).margin(1e-5));
    }
}

TEST_CASE("Output formats: the centres CSV of gen airfoil --centres, template and wing, each "
          "column documented",
          "[output-formats][centres][docs]") {
    TempDir dir;
    const auto rows = documented(doc_section("--centres"));

    const auto t = run_parsons("gen airfoil --naca 2412 --chord 6 --cutter-radius 0.25 "
                               "--stations 12 -o " +
                               q(dir.str("t.cbn")) + " --centres " + q(dir.str("t.csv")));
    REQUIRE(t.exit_code == 0);
    auto lines = lines_of(read_bytes(dir.path("t.csv")));
    const auto header = split(lines.front(), ',');
    CHECK(header == std::vector<std::string>{"x", "y", "cx", "cy"});
    require_documented(std::set<std::string>(header.begin(), header.end()), rows, "column");
    CHECK(t.output.find("stations         " + std::to_string(lines.size() - 1)) !=
          std::string::npos);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto v = split(lines[i], ',');
        REQUIRE(v.size() == 4);
        // The cutter centre stands one cutter radius from its work point, on the normal.
        const double dx = std::stod(v[2]) - std::stod(v[0]);
        const double dy = std::stod(v[3]) - std::stod(v[1]);
        CHECK(std::hypot(dx, dy) == Approx(0.25).margin(2e-6));
    }

    const auto w = run_parsons("gen airfoil --naca 0012 --job wing --chord 4 --span 5 --taper 0.6 "
                               "--sweep 10 --stations 6 -o " +
                               q(dir.str("w.cbn")) + " --centres " + q(dir.str("w.csv")));
    REQUIRE(w.exit_code == 0);
    lines = lines_of(read_bytes(dir.path("w.csv")));
    const auto wing_header = split(lines.front(), ',');
    CHECK(wing_header.size() == 9);
    require_documented(std::set<std::string>(wing_header.begin(), wing_header.end()), rows,
                       "column");
    double last_u = -1;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto v = split(lines[i], ',');
        REQUIRE(v.size() == wing_header.size());
        const double u = std::stod(v[0]);
        CHECK(u > last_u); // chord stations from the leading edge to the trailing edge
        CHECK(u <= 1.0);
        last_u = u;
        CHECK(std::stod(v[5]) > std::stod(v[2])); // the tip lies out along the span (y)
    }
}

TEST_CASE("Output formats: the job file gen airfoil writes beside the deck, template and wing, "
          "every key documented and the deck fingerprint that of the deck",
          "[output-formats][job][docs]") {
    TempDir dir;
    const auto rows = documented(doc_section("job.json"));
    std::set<std::string> keys;
    for (const std::string job : {"template", "wing"}) {
        INFO(job);
        const std::string deck = dir.str(job + ".cbn");
        const auto r = run_parsons("gen airfoil --naca 2412 --chord 4 --stations 8 --job " + job +
                                   " -o " + q(deck));
        REQUIRE(r.exit_code == 0);
        const auto j = nlohmann::json::parse(read_bytes(deck + ".job.json"));
        collect_doc_keys(j, "", keys);
        CHECK(j["job"] == job);
        CHECK(j["airfoil"] == "naca 2412");

        // The deck block: the cards gen reported, and the FNV-1a hash of the deck's columns.
        std::smatch cards;
        REQUIRE(std::regex_search(r.output, cards, std::regex(R"(cards +([0-9]+))")));
        CHECK(j["deck"]["cards"].get<long>() == std::stol(cards[1].str()));
        std::istringstream in(read_bytes(deck), std::ios::binary);
        parsons::cardreader::DeckOptions options;
        options.file_name = deck;
        auto source = parsons::cardreader::open_card_source(in, options);
        parsons::cardreader::DeckFingerprint fingerprint;
        while (auto card = source->next()) {
            fingerprint.add(*card);
        }
        CHECK(fingerprint.cards() == j["deck"]["cards"].get<long>());
        CHECK(j["deck"]["fingerprint"] == fingerprint.hex());
    }
    require_documented(keys, rows, "key");
}
