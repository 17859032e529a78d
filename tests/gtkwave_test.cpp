// GTKWave as its users use it (issue 32, item 8; docs/output-formats.md, "VCD trace" and "GTKWave
// save file"): the five axes' real positions as `real` variables in the VCD, written to the
// thousandth only when they change, at the trace's own instants; and the save file
// (outputs/traces/gtkwave_save.hpp) beside the trace, naming it, one group per scope holding
// exactly the variables the VCD declares there, the positions as analogue waves. Both are the
// same bytes from run to run, and a trace that is not a file of ours has no save file.
#include "cli/support/file_plan.hpp"
#include "outputs/traces/gtkwave_save.hpp"
#include "outputs/traces/trace_outputs.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <sys/stat.h>

using namespace parsons;
using parsons::test::lines_of;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
namespace fs = std::filesystem;

namespace {

// A VCD read for what these tests need: the variables by scope, and every real value written
// (code -> (time in us, value)).
struct GtkwVcd {
    struct Var {
        std::string scope, reference, kind, code;
        int width = 0;
    };
    std::vector<Var> vars; // in declaration order
    std::map<std::string, std::vector<std::pair<long long, double>>> reals;
    std::map<std::string, std::vector<std::string>> real_texts; // as written, "8.985"
    std::set<long long> times;

    const Var& var(const std::string& scope, const std::string& reference) const {
        for (const Var& v : vars) {
            if (v.scope == scope && v.reference == reference) {
                return v;
            }
        }
        FAIL("no variable " << scope << "." << reference);
        return vars.front();
    }
};

GtkwVcd read_gtkw_vcd(const std::string& text) {
    GtkwVcd vcd;
    const std::string end_marker = "$enddefinitions $end";
    const auto end = text.find(end_marker);
    REQUIRE(end != std::string::npos);
    std::istringstream header(text.substr(0, end));
    std::string token;
    std::string scope;
    while (header >> token) {
        if (token == "$scope") {
            std::string kind, name, close;
            header >> kind >> name >> close;
            scope = name;
        } else if (token == "$var") {
            GtkwVcd::Var v;
            std::string close;
            header >> v.kind >> v.width >> v.code >> v.reference >> close;
            if (close != "$end") {
                header >> close; // the bit range
            }
            v.scope = scope;
            vcd.vars.push_back(v);
        }
    }
    long long now = -1;
    for (const std::string& line : lines_of(text.substr(end + end_marker.size()))) {
        if (!line.empty() && line[0] == '#') {
            now = std::stoll(line.substr(1));
            vcd.times.insert(now);
        } else if (!line.empty() && line[0] == 'r') {
            const auto space = line.find(' ');
            REQUIRE(space != std::string::npos);
            const std::string value = line.substr(1, space - 1);
            vcd.reals[line.substr(space + 1)].emplace_back(now, std::stod(value));
            vcd.real_texts[line.substr(space + 1)].push_back(value);
        }
    }
    return vcd;
}

// The path CSV: rows of (time in us, five positions).
std::vector<std::pair<long long, std::array<double, 5>>> read_path(const std::string& text) {
    std::vector<std::pair<long long, std::array<double, 5>>> rows;
    const auto lines = lines_of(text);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        std::istringstream row(lines[i]);
        std::string field;
        std::getline(row, field, ',');
        const long long t = std::llround(std::stod(field) * 1e6);
        std::array<double, 5> x{};
        for (double& v : x) {
            std::getline(row, field, ',');
            v = std::stod(field);
        }
        rows.emplace_back(t, x);
    }
    return rows;
}

// The groups of a save file: each group's name and its signal lines, with the flags each
// line was under ("@48020" ...), in order.
struct SaveGroup {
    std::string name;
    std::vector<std::pair<std::string, std::string>> lines; // (flags, line)
};

std::vector<SaveGroup> read_groups(const std::string& save) {
    std::vector<SaveGroup> groups;
    std::string flags;
    bool open = false;
    for (const std::string& line : lines_of(save)) {
        if (line.rfind('@', 0) == 0) {
            flags = line;
            continue;
        }
        if (flags == "@800200" && line.rfind('-', 0) == 0) {
            REQUIRE_FALSE(open);
            groups.push_back({line.substr(1), {}});
            open = true;
        } else if (flags == "@1000200" && line.rfind('-', 0) == 0) {
            REQUIRE(open);
            CHECK(line.substr(1) == groups.back().name); // closes the group it opened
            open = false;
        } else if (open) {
            groups.back().lines.emplace_back(flags, line);
        }
    }
    CHECK_FALSE(open);
    return groups;
}

std::string quoted_value(const std::string& save, const std::string& key) {
    for (const std::string& line : lines_of(save)) {
        if (line.rfind(key + " ", 0) == 0) {
            return line.substr(key.size() + 1);
        }
    }
    return "";
}

// The sample deck keypunched into a scratch folder, and a run of it.
struct SampleRun {
    TempDir dir;
    SampleRun() {
        const auto r = run_shell("cd " + q(dir.str("")) + " && PARSONS punch " +
                                 q(source_path(test::kSample)) + " -o deck.cbn");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
    }
    test::ProcessResult run(const std::string& args) const {
        return run_shell("cd " + q(dir.str("")) + " && PARSONS run deck.cbn -q " + args);
    }
};

const SampleRun& sample_run() {
    static const SampleRun* run = [] {
        auto* s = new SampleRun; // NOLINT: kept for the whole test program
        fs::create_directories(s->dir.path("out"));
        const auto r = s->run("--trace out/trace.vcd --path out/path.csv");
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        return s;
    }();
    return *run;
}

} // namespace

TEST_CASE("VCD positions: each axis scope declares position_in as a 64-bit real, the first of "
          "its scope, with codes after every signal's",
          "[trace][vcd][gtkwave]") {
    const GtkwVcd vcd = read_gtkw_vcd(read_bytes(sample_run().dir.path("out/trace.vcd")));
    std::vector<std::string> scopes_with_reals;
    std::set<std::string> wire_codes;
    for (const auto& v : vcd.vars) {
        if (v.kind == "real") {
            scopes_with_reals.push_back(v.scope);
            CHECK(v.reference == "position_in");
            CHECK(v.width == 64);
        } else {
            CHECK(v.kind == "wire");
            wire_codes.insert(v.code);
        }
    }
    CHECK(scopes_with_reals ==
          std::vector<std::string>{"table", "cross", "vertical", "swivel", "tilt"});
    // First in its scope, and its code comes after every wire's (the signals keep the codes a
    // trace without positions gave them).
    const std::size_t wires = wire_codes.size();
    for (std::size_t k = 0; k < 5; ++k) {
        const auto& v = vcd.var(scopes_with_reals[k], "position_in");
        CHECK(v.code == cli::vcd_identifier_code(wires + k));
        const auto at = std::find_if(vcd.vars.begin(), vcd.vars.end(),
                                     [&](const auto& x) { return x.scope == v.scope; });
        CHECK(at->reference == "position_in");
    }
}

TEST_CASE("VCD positions: the values are the path's positions to the thousandth at the path's "
          "instants, three decimals, each written only when it changes",
          "[trace][vcd][gtkwave]") {
    const SampleRun& s = sample_run();
    const GtkwVcd vcd = read_gtkw_vcd(read_bytes(s.dir.path("out/trace.vcd")));
    const auto path = read_path(read_bytes(s.dir.path("out/path.csv")));
    REQUIRE(path.size() > 1000);
    std::set<long long> row_times;
    for (const auto& row : path) {
        row_times.insert(row.first);
    }
    static const std::array<const char*, 5> axes = {"table", "cross", "vertical", "swivel", "tilt"};
    std::size_t written = 0;
    for (std::size_t k = 0; k < 5; ++k) {
        INFO(axes.at(k));
        const std::string code = vcd.var(axes.at(k), "position_in").code;
        const auto& values = vcd.reals.at(code);
        const auto& texts = vcd.real_texts.at(code);
        REQUIRE_FALSE(values.empty());
        CHECK(values.front().first == 0); // $dumpvars: where the axis stood at the start
        CHECK(values.front().second == 0.0);
        for (std::size_t i = 0; i < values.size(); ++i) {
            REQUIRE(texts[i].size() - texts[i].find('.') == 4); // three decimals
            if (i > 0) {
                REQUIRE(values[i].second != values[i - 1].second); // only on change
                REQUIRE(values[i].first >= values[i - 1].first);
                REQUIRE(vcd.times.count(values[i].first) == 1);
                REQUIRE(row_times.count(values[i].first) == 1); // at an instant of the path
            }
        }
        written += values.size() - 1;
        // At every row of the path, the value in force is the row's position to the thousandth
        // (the path has five decimals, rounded: half a thousandth and a hair).
        std::size_t at = 0;
        double value = values.front().second;
        for (const auto& [t, x] : path) {
            while (at + 1 < values.size() && values[at + 1].first <= t) {
                value = values[++at].second;
            }
            REQUIRE(std::fabs(value - x.at(k)) <= 0.0005 + 0.000006);
        }
    }
    // The figure docs/output-formats.md gives for the sample deck.
    CHECK(written == 31705);
}

TEST_CASE("VCD positions: the rule by hand, to the thousandth, rounding half away from zero, "
          "sharing the instant of the signals written with it",
          "[trace][vcd][gtkwave]") {
    std::ostringstream out;
    {
        cli::VcdWriter vcd(out, "d", {0.0, 1.25, -2.0, 0.0004, 0.0});
        vcd.on_signal_defined({0, "table", "motor_38", "motor", "38", 1}, 0);
        vcd.on_start();
        vcd.on_motion(0.5, {0.0004, 1.25, -2.0, 0.0004, 0.0}); // nothing changes to 0.001
        vcd.on_signal(1.0, 0, 0, 1);
        vcd.on_motion(1.0, {0.0005, 1.2504, -2.0006, 0.0004, 0.0});  // table and vertical
        vcd.on_motion(1.5, {0.0014, 1.2496, -2.0014, -0.0004, 0.0}); // nothing
        vcd.on_motion(2.0, {0.0016, 1.2496, -1.9996, -0.0025, 0.0}); // table, vertical, swivel
        vcd.on_finish(3.0);
    }
    const std::string text = out.str();
    const std::string body = text.substr(text.find("$enddefinitions $end"));
    // Codes: the signal "!", then the positions table '"', cross '#', vertical '$', swivel '%',
    // tilt '&'.
    CHECK(body == "$enddefinitions $end\n#0\n$dumpvars\n0!\n"
                  "r0.000 \"\nr1.250 #\nr-2.000 $\nr0.000 %\nr0.000 &\n$end\n"
                  "#1000000\n1!\nr0.001 \"\nr-2.001 $\n"
                  "#2000000\nr0.002 \"\nr-2.000 $\nr-0.003 %\n#3000000\n");
    CHECK(text.find("$scope module table $end\n$var real 64 \" position_in $end\n"
                    "$var wire 1 ! motor_38 $end\n") != std::string::npos);
    CHECK(text.find("$scope module tilt $end\n$var real 64 & position_in $end\n$upscope") !=
          std::string::npos);
}

TEST_CASE("GTKWave save file: beside the trace, naming it and itself by name alone, one group "
          "per scope holding exactly the variables the VCD declares there",
          "[trace][gtkwave]") {
    const SampleRun& s = sample_run();
    REQUIRE(fs::exists(s.dir.path("out/trace.gtkw")));
    const std::string save = read_bytes(s.dir.path("out/trace.gtkw"));
    const GtkwVcd vcd = read_gtkw_vcd(read_bytes(s.dir.path("out/trace.vcd")));
    CHECK(quoted_value(save, "[dumpfile]") == "\"trace.vcd\"");
    CHECK(quoted_value(save, "[savefile]") == "\"trace.gtkw\"");
    const auto groups = read_groups(save);
    std::vector<std::string> scopes;
    for (const auto& v : vcd.vars) {
        if (scopes.empty() || scopes.back() != v.scope) {
            scopes.push_back(v.scope);
        }
    }
    REQUIRE(groups.size() == scopes.size());
    CHECK(scopes.size() == 6); // five axes and the cabinet (no attachments in the 1952 profile)
    std::size_t signals = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        INFO(groups[g].name);
        CHECK(groups[g].name == scopes[g]);
        std::vector<std::string> expected;
        for (const auto& v : vcd.vars) {
            if (v.scope == scopes[g]) {
                expected.push_back(v.scope + "." + v.reference +
                                   (v.width > 1 && v.kind == "wire"
                                        ? fmt::format("[{}:0]", v.width - 1)
                                        : std::string()));
            }
        }
        std::vector<std::string> listed;
        for (std::size_t i = 0; i < groups[g].lines.size(); ++i) {
            const auto& [flags, line] = groups[g].lines[i];
            if (line == "-") {
                CHECK(flags == "@20000"); // the stretch under a position
                continue;
            }
            listed.push_back(line);
            const bool position =
                line.size() > 12 && line.substr(line.size() - 12) == ".position_in";
            const bool wide = line.back() == ']';
            CHECK(flags == (position ? "@48020" : wide ? "@24" : "@28"));
            if (position) { // taller: three stretch lines under it
                REQUIRE(i + 3 < groups[g].lines.size());
                for (std::size_t j = 1; j <= 3; ++j) {
                    CHECK(groups[g].lines[i + j] ==
                          std::make_pair(std::string("@20000"), std::string("-")));
                }
            }
        }
        CHECK(listed == expected);
        signals += listed.size();
    }
    CHECK(signals == vcd.vars.size());
    // The flags, as GTKWave's analyzer.h numbers them: real | analog step | right-justify.
    CHECK(cli::gtkwave_flag::kPosition == 0x48020);
    CHECK(cli::gtkwave_flag::kWire == 0x28);
    CHECK(cli::gtkwave_flag::kSwitch == 0x24);
    CHECK(cli::gtkwave_flag::kBegin == 0x800200);
    CHECK(cli::gtkwave_flag::kEnd == 0x1000200);
}

TEST_CASE("GTKWave save file: two runs, in two folders, write the same trace and save file byte "
          "for byte",
          "[trace][gtkwave]") {
    const SampleRun& first = sample_run();
    SampleRun second;
    fs::create_directories(second.dir.path("elsewhere/deeper"));
    const auto r = second.run("--trace elsewhere/deeper/trace.vcd");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(read_bytes(second.dir.path("elsewhere/deeper/trace.vcd")) ==
          read_bytes(first.dir.path("out/trace.vcd")));
    CHECK(read_bytes(second.dir.path("elsewhere/deeper/trace.gtkw")) ==
          read_bytes(first.dir.path("out/trace.gtkw")));
}

TEST_CASE("GTKWave save file: its name is the trace's with .gtkw for its extension, and a trace "
          "that is not a file of ours has none",
          "[trace][gtkwave]") {
    TempDir dir;
    CHECK(cli::gtkwave_save_file_for("out.vcd") == "out.gtkw");
    CHECK(cli::gtkwave_save_file_for("dir/run.1.vcd") == "dir/run.1.gtkw");
    CHECK(cli::gtkwave_save_file_for("trace") == "trace.gtkw");
    CHECK(cli::gtkwave_save_file_for("x.gtkw").empty()); // would be the trace itself
    CHECK(cli::gtkwave_save_file_for("-").empty());
    CHECK(cli::gtkwave_save_file_for("/dev/null").empty());
    CHECK(cli::gtkwave_save_file_for("a\nb.vcd").empty());
    REQUIRE(mkfifo(dir.str("pipe.vcd").c_str(), 0600) == 0);
    CHECK(cli::gtkwave_save_file_for(dir.str("pipe.vcd")).empty());
    // A save file's name that is not a file of ours: none either.
    REQUIRE(mkfifo(dir.str("f.gtkw").c_str(), 0600) == 0);
    CHECK(cli::gtkwave_save_file_for(dir.str("f.vcd")).empty());
    fs::create_directories(dir.path("d.gtkw"));
    CHECK(cli::gtkwave_save_file_for(dir.str("d.vcd")).empty());
    test::write_bytes(dir.path("kept.gtkw"), "an earlier save file\n");
    CHECK(cli::gtkwave_save_file_for(dir.str("kept.vcd")) == dir.str("kept.gtkw"));
}

TEST_CASE("GTKWave save file: a trace on standard output, /dev/null or a FIFO writes none and "
          "leaves nothing behind, and a refused or failed run writes neither file",
          "[trace][gtkwave][never-lose]") {
    SampleRun s;
    REQUIRE(mkfifo(s.dir.path("pipe").c_str(), 0600) == 0);
    auto names = [&s] {
        std::set<std::string> all;
        for (const auto& e : fs::directory_iterator(s.dir.path(""))) {
            all.insert(e.path().filename().string());
        }
        return all;
    };
    const std::set<std::string> before = names();
    const auto to_stdout = s.run("--trace - > got.vcd");
    CHECK(to_stdout.exit_code == 0);
    CHECK(read_bytes(s.dir.path("got.vcd")).rfind("$version parsons $end", 0) == 0);
    fs::remove(s.dir.path("got.vcd"));
    // A null device of the test's own (never the machine's /dev/null, issue 53).
    if (const auto null = test::make_device_node(s.dir.path(""), "null", 1, 3)) {
        CHECK(s.run("--trace null").exit_code == 0);
        CHECK(test::node_kind(*null) == "character device 1:3");
        fs::remove(*null); // the names before and after are compared below
    } else {
        WARN("the character device case skipped: mknod is not permitted here");
    }
    const auto fifo = run_shell("cd " + q(s.dir.str("")) +
                                " && { cat pipe > got.vcd & PARSONS run deck.cbn -q --trace pipe; "
                                "rc=$?; wait; exit $rc; }");
    INFO(fifo.output);
    CHECK(fifo.exit_code == 0);
    CHECK(read_bytes(s.dir.path("got.vcd")).find("position_in") != std::string::npos);
    fs::remove(s.dir.path("got.vcd"));
    CHECK(names() == before); // no pipe.gtkw, no -.gtkw, no temporary file
    // Refused before the run: neither file.
    const auto refused = s.run("--trace t.vcd --limit table=nonsense");
    CHECK(refused.exit_code == 2);
    CHECK(names() == before);
    // The save file is an output too: it may not be another output, nor the deck.
    const auto clash = s.run("--trace t.vcd --report t.gtkw");
    INFO(clash.output);
    CHECK(clash.exit_code == 2);
    CHECK_THAT(clash.output, Catch::Contains("the GTKWave save file beside --trace"));
    CHECK_THAT(clash.output, Catch::Contains("--report"));
    fs::copy_file(s.dir.path("deck.cbn"), s.dir.path("d.gtkw"));
    const auto deck = run_shell("cd " + q(s.dir.str("")) +
                                " && PARSONS run d.gtkw --format cbn -q --trace d.vcd");
    INFO(deck.output);
    CHECK(deck.exit_code == 2);
    CHECK(read_bytes(s.dir.path("d.gtkw")) == read_bytes(s.dir.path("deck.cbn")));
    fs::remove(s.dir.path("d.gtkw"));
    CHECK(names() == before);
}

TEST_CASE("GTKWave save file: GTKWave itself opens it from another folder, finds the trace beside "
          "it and shows the groups, the analogue positions and every signal",
          "[trace][gtkwave]") {
    INFO("gtkwave and xvfb-run (Debian's gtkwave and xvfb; scripts/install-deps.sh installs them)");
    REQUIRE(run_shell("command -v gtkwave && command -v xvfb-run").exit_code == 0);
    const SampleRun& s = sample_run();
    TempDir elsewhere;
    test::write_bytes(elsewhere.path("probe.tcl"),
                      "set f [open \"probe.out\" w]\n"
                      "puts $f \"dump [gtkwave::getDumpFileName]\"\n"
                      "set n [gtkwave::getTotalNumTraces]\n"
                      "for {set i 0} {$i < $n} {incr i} {\n"
                      "  puts $f \"[gtkwave::getTraceFlagsFromIndex $i] "
                      "[gtkwave::getTraceNameFromIndex $i]\"\n"
                      "}\n"
                      "close $f\n"
                      "gtkwave::/File/Quit\n");
    const auto r = run_shell("cd " + q(elsewhere.str("")) +
                             " && timeout 120 xvfb-run -a gtkwave -S probe.tcl " +
                             q(s.dir.str("out/trace.gtkw")) + " > gtkwave.log 2>&1");
    INFO(read_bytes(elsewhere.path("gtkwave.log")));
    REQUIRE(r.exit_code == 0);
    const auto lines = lines_of(read_bytes(elsewhere.path("probe.out")));
    REQUIRE_FALSE(lines.empty());
    CHECK(lines.front() == "dump " + fs::canonical(s.dir.path("out/trace.vcd")).string());
    const GtkwVcd vcd = read_gtkw_vcd(read_bytes(s.dir.path("out/trace.vcd")));
    std::size_t positions = 0;
    std::size_t named = 0;
    std::size_t group_begins = 0;
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const auto space = lines[i].find(' ');
        const unsigned long flags = std::stoul(lines[i].substr(0, space));
        const std::string name = lines[i].substr(space + 1);
        if ((flags & cli::gtkwave_flag::kGroupBegin) != 0) {
            ++group_begins;
        } else if (name == "position_in") {
            ++positions;
            CHECK(flags == cli::gtkwave_flag::kPosition);
        }
        if ((flags & (cli::gtkwave_flag::kBlank | cli::gtkwave_flag::kAnalogBlankStretch)) == 0) {
            ++named;
        }
    }
    CHECK(group_begins == 6);
    CHECK(positions == 5);
    CHECK(named == vcd.vars.size()); // GTKWave found every signal the save file names
}

TEST_CASE("GTKWave save file: docs/gtkwave/sample.gtkw is the save file the sample deck's run "
          "writes beside out/sample/trace.vcd, byte for byte",
          "[docs][gtkwave]") {
    const std::string written = read_bytes(sample_run().dir.path("out/trace.gtkw"));
    const std::string shipped = source_path("docs/gtkwave/sample.gtkw");
    const char* update = std::getenv("PARSONS_UPDATE_DOCS");
    if (update != nullptr && std::string(update) == "1") {
        test::write_bytes(shipped, written);
    }
    CHECK(read_bytes(shipped) == written);
}
