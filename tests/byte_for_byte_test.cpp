// Behaviour unchanged, byte for byte: the guard of a move that must change no output (the house,
// docs/testing.md "Byte for byte").
//
// The test runs, through the parsons executable as a user would, the sample decks, the demo and
// every deck it writes, G-code programs and the wing job through their generators, a stopped run
// saved and resumed, the seed decks of the readers' fuzz targets, and 100 random decks from the
// machine fuzz target's recipe, each at both paces (fast-forward and --impulse-level) and with
// every output the run can write (summary, report, VCD trace, events, path, plot, replay page,
// cut, press and thread proofs, saved state). It records each output's size and FNV-1a hash with
// the wall-clock date of the VCD masked, and compares them with tests/golden/byte-for-byte.txt,
// written by the main the move started from. A difference names the output; to look at it, run
// the test again with PARSONS_BYTE_FOR_BYTE_DIR=DIR (the outputs stay there) against each commit.
//
// When a change of an output is meant, PARSONS_UPDATE_GOLDEN=1 rewrites the manifest: review
// which lines changed and why, and commit it with the change. Not built under the sanitizers
// (tests/CMakeLists.txt).
#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/test_support.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_io.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;
namespace fs = std::filesystem;

namespace {

constexpr int kRandomDecks = 100;

std::uint64_t fnv1a(const std::string& bytes) {
    std::uint64_t h = 14695981039346656037ULL;
    for (unsigned char c : bytes) {
        h = (h ^ c) * 1099511628211ULL;
    }
    return h;
}

struct Entry {
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    bool operator==(const Entry&) const = default;
};
using Manifest = std::map<std::string, Entry>;

class Outputs {
public:
    // keep: leave every output in the work folder (else the large ones go once recorded).
    Outputs(fs::path work, bool keep) : work_(std::move(work)), keep_(keep) {}

    const fs::path& work() const { return work_; }
    const Manifest& manifest() const { return manifest_; }

    // Runs `parsons ARGS` in the work folder; its standard output, standard error and exit code
    // are outputs too, named after `name`.
    // With `good`, every command run from here on has a deck and flags that are right: it does
    // its work (exit 0) or the machine stops (exit 3). An exit 2 there would have the manifest
    // keep an error message instead of the outputs, as it once kept for the demo's press-feeder
    // and tapping runs (their job files taken for the replay page's) and for the G-code decks
    // (a --job-out that gen gcode does not have), so it fails the test, whatever the manifest
    // says. The random decks and the readers' bad seeds are refused on purpose.
    void expect_good_input(bool good) { good_ = good; }

    void run(const std::string& name, const std::string& args) {
        const std::string out = name + ".stdout";
        const std::string err = name + ".stderr";
        const auto r =
            run_shell("cd " + q(work_.string()) + " && unset SOURCE_DATE_EPOCH && PARSONS " + args +
                      " >" + q(out) + " 2>" + q(err));
        if (good_) {
            INFO(args << "\n" << read_bytes(work_ / err));
            CHECK((r.exit_code == 0 || r.exit_code == 3));
        }
        record(name + ".exit", std::to_string(r.exit_code) + "\n");
        record_file(out);
        record_file(err);
    }

    void record(const std::string& name, const std::string& bytes) {
        manifest_[name] = Entry{bytes.size(), fnv1a(bytes)};
    }
    void record_file(const std::string& relative) {
        const fs::path p = work_ / relative;
        record(relative, read_bytes(p)); // every byte: no output holds the wall clock
    }
    // Every file under a folder of the work folder, in name order.
    void record_folder(const std::string& relative) {
        std::vector<std::string> files;
        for (const auto& e : fs::recursive_directory_iterator(work_ / relative)) {
            if (e.is_regular_file()) {
                files.push_back(fs::relative(e.path(), work_).generic_string());
            }
        }
        std::sort(files.begin(), files.end());
        for (const auto& f : files) {
            record_file(f);
        }
    }
    // A run with every output the deck allows, in folder `name` (one per pace).
    void run_all_outputs(const std::string& name, const std::string& deck, const std::string& extra,
                         bool html = true) {
        for (const bool impulse : {false, true}) {
            const std::string dir = name + (impulse ? "/impulse-level" : "/fast-forward");
            fs::create_directories(work_ / dir);
            std::string args = "run " + q(deck) + " " + extra + (impulse ? " --impulse-level" : "");
            for (const auto& [option, file] :
                 std::vector<std::pair<std::string, std::string>>{{"--report", "report.json"},
                                                                  {"--trace", "trace.vcd"},
                                                                  {"--events", "events.jsonl"},
                                                                  {"--path", "path.csv"},
                                                                  {"--plot", "plot.svg"},
                                                                  {"--save-state", "state.json"}}) {
                args += " " + option + " " + q(dir + "/" + file);
            }
            if (html) {
                args += " --html " + q(dir + "/replay.html");
            }
            run(dir + "/run", args);
            record_folder(dir);
            if (!keep_) {
                for (const char* large : {"trace.vcd", "events.jsonl", "path.csv", "replay.html"}) {
                    fs::remove(work_ / dir / large);
                }
            }
        }
    }

private:
    fs::path work_;
    bool keep_;
    bool good_ = false;
    Manifest manifest_;
};

Manifest read_manifest(const std::string& text) {
    Manifest m;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line.front() == '#') {
            continue;
        }
        std::istringstream fields(line);
        std::string name;
        std::string hash;
        Entry e;
        fields >> e.size >> hash >> name;
        e.hash = std::stoull(hash, nullptr, 16);
        m[name] = e;
    }
    return m;
}

std::string manifest_text(const Manifest& m) {
    std::string text =
        "# Every output of tests/byte_for_byte_test.cpp: size, FNV-1a 64 hash, name.\n"
        "# Written by PARSONS_UPDATE_GOLDEN=1 (docs/testing.md, \"Byte for byte\").\n";
    for (const auto& [name, e] : m) {
        text += fmt::format("{} {:016x} {}\n", e.size, e.hash, name);
    }
    return text;
}

// The decks of the machine fuzz target's recipe: random bytes, a deck a programmer might have
// punched (and its profile), as .cbn and JSON in the work folder; returns the run's options.
std::string random_deck(Outputs& o, int i, std::mt19937& rng) {
    std::vector<std::uint8_t> bytes(std::uniform_int_distribution<std::size_t>(8, 160)(rng));
    for (auto& b : bytes) {
        b = static_cast<std::uint8_t>(std::uniform_int_distribution<int>(0, 255)(rng));
    }
    parsons::axes::MachineProfile profile = parsons::axes::default_profile();
    std::vector<parsons::relaylogic::Fault> faults;
    const auto cards = parsons::fuzz::machine_deck(bytes, profile, &faults);
    const std::string name = fmt::format("random/{:03}", i);
    fs::create_directories(o.work() / "random");
    write_bytes(o.work() / (name + ".cbn"),
                parsons::test::deck_bytes(cards, parsons::cardreader::DeckFormat::cbn));
    write_bytes(o.work() / (name + ".profile.json"), parsons::axes::profile_to_json(profile));
    o.record_file(name + ".cbn");
    std::string args = "--profile " + q(name + ".profile.json");
    for (const auto& f : faults) {
        args += " --fault " + q(f.spec);
    }
    return args;
}

} // namespace

TEST_CASE("Byte for byte: the sample decks, the demo, the generators' decks, a saved and resumed "
          "run, the readers' seed decks and 100 random decks give every output exactly as the "
          "manifest records",
          "[byte-for-byte][cli][heavy]") {
    const char* keep = std::getenv("PARSONS_BYTE_FOR_BYTE_DIR");
    const TempDir temp;
    const fs::path work = keep != nullptr ? fs::path(keep) : temp.path("work");
    REQUIRE((!fs::exists(work) || fs::is_empty(work))); // a kept folder starts empty
    fs::create_directories(work / "samples");
    Outputs o(work, keep != nullptr);
    o.expect_good_input(true); // until the readers' seeds and the random decks

    // The sample decks, each under the profile the README runs it with.
    for (const auto& [deck, profile] : std::vector<std::pair<std::string, std::string>>{
             {"patent-example.csv", ""},
             {"condition-cards.csv", "--profile parsons-extended"},
             {"press-sync.csv", "--profile parsons-extended"},
             {"press-reset.csv", "--profile parsons-extended"},
             {"contour.csv", "--profile parsons-extended"}}) {
        fs::copy_file(source_path("decks/samples/" + deck), work / "samples" / deck);
        o.run_all_outputs("samples/" + fs::path(deck).stem().string(), "samples/" + deck, profile);
    }
    // A stop saved and resumed: a dropped impulse, then the deck again from the saved state.
    o.run_all_outputs("samples/dropped", "samples/patent-example.csv",
                      "--fault drop-impulse:table:120");
    o.run("samples/resumed", "run samples/patent-example.csv --resume " +
                                 q("samples/dropped/fast-forward/state.json") +
                                 " --report samples/resumed.json");
    o.record_file("samples/resumed.json");

    // The demo: every file it writes, then each of its decks with every output.
    o.run("demo", "demo --out demo");
    o.record_folder("demo");
    o.run_all_outputs("runs/naca2412", "demo/airfoil-template/naca2412.cbn",
                      "--cut runs/naca2412.cut.svg");
    o.record_file("runs/naca2412.cut.svg");
    for (const std::string variant : {"boundary", "tripped"}) {
        const std::string deck = "demo/two-tools/two-tool-" + variant + ".csv";
        o.run_all_outputs("runs/two-tool-" + variant, deck,
                          "--profile parsons-extended --cut runs/two-tool-" + variant + ".svg");
        o.record_file("runs/two-tool-" + variant + ".svg");
    }
    for (const std::string deck : {"press-feeder", "press-feeder-speed-only"}) {
        const std::string d = "demo/press-feeder/" + deck + ".csv";
        o.run_all_outputs("runs/" + deck, d,
                          "--profile " + q(d + ".slowing.json") + " --press-proof " +
                              q(d + ".job.json"));
    }
    for (const std::string deck : {"tapping-transferred", "tapping-stored"}) {
        const std::string d = "demo/tapping/" + deck + ".csv";
        o.run_all_outputs("runs/" + deck, d, "--thread-proof " + q(d + ".job.json"));
    }
    o.run_all_outputs("runs/tapping-stale-ratio", "demo/tapping/tapping-transferred.csv",
                      "--thread-proof demo/tapping/tapping-transferred.csv.job.json --fault "
                      "stale-ratio:1");

    // The generators: G-code programs and the tapered wing, deck and job file, then run.
    fs::create_directories(work / "gen");
    for (const auto& [name, program] : std::vector<std::pair<std::string, std::string>>{
             {"bracket", "decks/samples/bracket.ngc"}, {"plate-mm", "tests/gcode/plate-mm.ngc"}}) {
        fs::copy_file(source_path(program), work / "gen" / (name + ".ngc"));
        o.run("gen/" + name + ".gen", "gen gcode gen/" + name + ".ngc -o gen/" + name + ".cbn");
        o.record_file("gen/" + name + ".cbn");
        o.run_all_outputs("gen/" + name, "gen/" + name + ".cbn", "", false);
    }
    o.run("gen/wing.gen", "gen airfoil --naca 2412 --job wing --stations 8 -o gen/wing.cbn");
    o.record_file("gen/wing.cbn");
    o.record_file("gen/wing.cbn.job.json");
    o.run_all_outputs("gen/wing", "gen/wing.cbn", "--cut gen/wing.cut.svg", false);
    o.record_file("gen/wing.cut.svg");

    // The readers' seed decks (good and bad): the summary or the error, and the report.
    o.expect_good_input(false);
    fs::create_directories(work / "seeds");
    for (const std::string target : {"cbn", "bin", "text", "listing", "tape", "five"}) {
        std::vector<fs::path> seeds;
        for (const auto& e : fs::directory_iterator(source_path("tests/fuzz/corpus/" + target))) {
            seeds.push_back(e.path());
        }
        std::sort(seeds.begin(), seeds.end());
        for (const auto& seed : seeds) {
            const std::string name = "seeds/" + target + "-" + seed.filename().string();
            fs::copy_file(seed, work / name);
            o.run(name, "run " + q(name) + " --format " + target + " --report " +
                            q(name + ".report.json"));
            if (fs::exists(work / (name + ".report.json"))) {
                o.record_file(name + ".report.json");
            }
        }
    }

    // 100 random decks from the machine fuzz target's recipe.
    std::mt19937 rng(28);
    for (int i = 0; i < kRandomDecks; ++i) {
        const std::string args = random_deck(o, i, rng);
        o.run_all_outputs(fmt::format("random/{:03}", i), fmt::format("random/{:03}.cbn", i), args,
                          i < 10);
    }

    const std::string manifest_file = source_path("tests/golden/byte-for-byte.txt");
    if (std::getenv("PARSONS_UPDATE_GOLDEN") != nullptr) {
        write_bytes(manifest_file, manifest_text(o.manifest()));
        WARN("rewrote " << manifest_file << " (" << o.manifest().size() << " outputs)");
        return;
    }
    const Manifest expected = read_manifest(read_bytes(manifest_file));
    std::vector<std::string> differ;
    for (const auto& [name, e] : o.manifest()) {
        const auto it = expected.find(name);
        if (it == expected.end()) {
            differ.push_back(name + ": not in the manifest");
        } else if (!(it->second == e)) {
            differ.push_back(fmt::format("{}: {} bytes, hash {:016x}; the manifest has {} bytes, "
                                         "hash {:016x}",
                                         name, e.size, e.hash, it->second.size, it->second.hash));
        }
    }
    for (const auto& [name, e] : expected) {
        if (o.manifest().count(name) == 0) {
            differ.push_back(name + ": in the manifest, not written");
        }
    }
    std::string listed;
    for (std::size_t i = 0; i < std::min<std::size_t>(differ.size(), 40); ++i) {
        listed += "\n  " + differ[i];
    }
    INFO(differ.size() << " of " << o.manifest().size() << " outputs differ:" << listed);
    CHECK(differ.empty());
    CHECK(o.manifest().size() > 2000U);
}

TEST_CASE("Reproducible: two runs of one deck write the same bytes in every output, the trace "
          "too, and only SOURCE_DATE_EPOCH dates the trace",
          "[reproducible][cli]") {
    const parsons::test::TempDir dir;
    const std::string gen = "PARSONS gen airfoil --naca 0012 --chord 2 --stations 12 -o wing.csv "
                            "--centres centres.csv";
    const std::string run = "PARSONS run wing.csv --report report.json --trace trace.vcd --events "
                            "events.jsonl --path path.csv --plot plot.svg --html replay.html --cut "
                            "cut.svg >run.out";
    for (const char* folder : {"a", "b"}) {
        fs::create_directories(dir.path(folder));
        const auto r = run_shell("cd " + q(dir.str(folder)) + " && unset SOURCE_DATE_EPOCH && " +
                                 gen + " >gen.out && " + run);
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
    }
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir.path("a"))) {
        names.push_back(e.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    CHECK(names.size() >= 11); // the deck, its job file, the centres, seven outputs, the stdouts
    for (const std::string& name : names) {
        INFO(name);
        REQUIRE(fs::exists(dir.path("b/" + name)));
        CHECK(read_bytes(dir.path("a/" + name)) == read_bytes(dir.path("b/" + name)));
    }
    const std::string trace = read_bytes(dir.path("a/trace.vcd"));
    CHECK(trace.find("$date") == std::string::npos);
    CHECK(trace.rfind("$version parsons $end\n", 0) == 0);
    // SOURCE_DATE_EPOCH (reproducible-builds.org): the trace's $date is that instant, UTC.
    auto dated = [&](const std::string& epoch) {
        const auto r = run_shell("cd " + q(dir.str("a")) + " && SOURCE_DATE_EPOCH=" + epoch +
                                 " PARSONS run wing.csv -q --trace dated.vcd");
        REQUIRE(r.exit_code == 0);
        return read_bytes(dir.path("a/dated.vcd"));
    };
    CHECK(dated("86399").rfind("$date\n    1970-01-01 23:59:59 UTC\n$end\n$version parsons $end\n",
                               0) == 0);
    CHECK(dated("1795651200").rfind("$date\n    2026-11-26 00:00:00 UTC\n$end\n", 0) == 0);
    // Not a count of seconds: no date, as without it.
    CHECK(dated("yesterday") == trace);
    CHECK(dated("''") == trace);
}
