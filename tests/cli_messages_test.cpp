// What the command line says where a user meets its edges (issue 53): a full disk on standard
// output, a device that takes no output, a profile or a saved state that is not one, a size too
// large to lay out, a spindle speed of 0, a successful demo's standard error, show's --help, and
// the README's map of the source. Each test is named after the rule it holds.
#include "cli/support/value_names.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

using parsons::test::kSample;
using parsons::test::make_device_node;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::whole_share;
using parsons::test::write_bytes;

namespace {

constexpr unsigned kMemoryMajor = 1; // Linux's memory devices: 3 null, 7 full
constexpr unsigned kFullMinor = 7;
constexpr unsigned kNullMinor = 3;

bool says(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

} // namespace

TEST_CASE("Messages: a full disk under --version and --help is 'No space left on device', exit 2",
          "[cli][messages][output]") {
    TempDir dir;
    const auto full = make_device_node(dir.path(""), "full", kMemoryMajor, kFullMinor);
    if (!full) {
        WARN("not run: mknod is not permitted here (not root, or no CAP_MKNOD): no full device "
             "of the test's own to write to, and the machine's /dev/full is not the test's");
        return;
    }
    for (const char* command :
         {"--version", "--help", "show --help", "gen airfoil --help", "demo --help"}) {
        INFO(command);
        const auto r = run_shell("PARSONS " + std::string(command) + " > " + q(full->string()));
        CHECK(r.exit_code == 2);
        CHECK(says(r.output,
                   "parsons: error: standard output: cannot write: No space left on device"));
        CHECK_FALSE(says(r.output, "Input/output error"));
    }
}

TEST_CASE("Messages: demo --out a device that takes nothing is exit 2, as run --report is, a null "
          "device takes the demo, and a successful demo says nothing on standard error",
          "[cli][messages][demo][output]") {
    TempDir dir;
    const auto full = make_device_node(dir.path(""), "full", kMemoryMajor, kFullMinor);
    const auto null = make_device_node(dir.path(""), "null", kMemoryMajor, kNullMinor);
    if (!full || !null) {
        WARN("not run: mknod is not permitted here (not root, or no CAP_MKNOD): no device of the "
             "test's own for --out");
        return;
    }
    const auto report =
        run_parsons("run " + q(source_path(kSample)) + " -q --report " + q(full->string()));
    CHECK(report.exit_code == 2);
    CHECK(says(report.output, "No space left on device"));
    // The whole demo runs before its first write fails: under the sanitizers (a share of the
    // cases, test_support.hpp) only the null device's run below, some 11 s there; the regular
    // build runs both.
    if (whole_share()) {
        const auto onto_full = run_parsons("demo --out " + q(full->string()));
        CHECK(onto_full.exit_code == 2);
        CHECK(says(onto_full.output, "parsons: error: " + full->string() + ": "));
        CHECK(says(onto_full.output, "No space left on device"));
    }
    // Into a null device: the story on standard output, nothing on standard error (its
    // intended collision and wrong pitch are told in the story, not as errors).
    const auto onto_null =
        run_shell("PARSONS demo --out " + q(null->string()) + " 2> " + q(dir.str("err.txt")));
    CHECK(onto_null.exit_code == 0);
    CHECK(says(onto_null.output, "COLLISION in cycle"));
    CHECK(says(onto_null.output, "holes flagged, as expected"));
    CHECK(says(onto_null.output, "sent its index page to " + null->string()));
    CHECK(read_bytes(dir.path("err.txt")).empty());
    CHECK(parsons::test::node_kind(*null) == "character device 1:3");
}

TEST_CASE("Messages: a --profile that is neither a file nor a built-in profile lists the built-in "
          "names",
          "[cli][messages]") {
    for (const char* command : {"run", "check", "show"}) {
        INFO(command);
        const auto r =
            run_parsons(std::string(command) + " " + q(source_path(kSample)) + " --profile nosuch");
        CHECK(r.exit_code == 2);
        CHECK(says(r.output, "parsons: error: nosuch: no such profile: neither a built-in profile "
                             "(parsons-1952, parsons-safe or parsons-extended) nor a file"));
    }
    // A file that exists but cannot be read is told as what it is, not as a missing name.
    TempDir dir;
    std::filesystem::create_directories(dir.path("folder.json"));
    const auto folder =
        run_parsons("run " + q(source_path(kSample)) + " --profile " + q(dir.str("folder.json")));
    CHECK(folder.exit_code == 2);
    CHECK_FALSE(says(folder.output, "no such profile"));
}

TEST_CASE("Messages: --resume of a file that is not a saved state says so, naming the file",
          "[cli][messages][resume]") {
    TempDir dir;
    const std::string sample = q(source_path(kSample));
    REQUIRE(run_parsons("run " + sample + " -q --report " + q(dir.str("report.json"))).exit_code ==
            0);
    const auto report = run_parsons("run " + sample + " --resume " + q(dir.str("report.json")));
    CHECK(report.exit_code == 2);
    CHECK(says(report.output, "parsons: error: " + dir.str("report.json") +
                                  ": not a saved state: it is a run report (--resume takes the "
                                  "file 'parsons run DECK --save-state FILE' wrote"));
    CHECK_FALSE(says(report.output, "profile must be"));
    write_bytes(dir.path("list.json"), "[1, 2]");
    const auto list = run_parsons("run " + sample + " --resume " + q(dir.str("list.json")));
    CHECK(list.exit_code == 2);
    CHECK(says(list.output, dir.str("list.json") + ": not a saved state (--resume takes"));
    write_bytes(dir.path("text.json"), "not json");
    const auto text = run_parsons("run " + sample + " --resume " + q(dir.str("text.json")));
    CHECK(says(text.output, dir.str("text.json") + ": not a saved state: not valid JSON"));
}

TEST_CASE("Messages: a wing too large to lay out, however large, says the counters' limit",
          "[cli][messages][gen][wing]") {
    TempDir dir;
    for (const char* span : {"1e307", "1e308", "1.7e308"}) {
        INFO(span);
        const auto r = run_parsons("gen airfoil --naca 2412 --job wing --span " +
                                   std::string(span) + " -o " + q(dir.str("w.csv")));
        CHECK(r.exit_code == 2);
        CHECK(says(r.output, "the counters leave: use a smaller wing"));
        CHECK_FALSE(says(r.output, "does not fit in 4 digit columns"));
        CHECK_FALSE(std::filesystem::exists(dir.path("w.csv")));
    }
}

TEST_CASE("Messages: gen tapping --rpm is 1 to 9999, whatever side it is out on (0 is not 'not "
          "given')",
          "[cli][messages][gen][tapping]") {
    TempDir dir;
    for (const char* rpm : {"0", "-5", "10000"}) {
        INFO(rpm);
        const auto r =
            run_parsons("gen tapping --rpm " + std::string(rpm) + " -o " + q(dir.str("t.csv")));
        CHECK(r.exit_code == 2);
        CHECK(says(r.output, "--rpm " + std::string(rpm) + ": give 1 to 9999 rev/min"));
        CHECK_FALSE(std::filesystem::exists(dir.path("t.csv")));
    }
    CHECK(run_parsons("gen tapping --rpm 1 -o " + q(dir.str("t.csv"))).exit_code == 0);
}

TEST_CASE("Messages: show --help says --profile is the profile the deck is sensed and run under",
          "[cli][messages]") {
    const auto r = run_parsons("show --help");
    CHECK(r.exit_code == 0);
    CHECK_FALSE(says(r.output, "coast estimate"));
    CHECK(says(r.output, "the deck run as under it"));
}

TEST_CASE("Completion: the bundled airfoils --dat offers are the files decks/airfoils holds",
          "[cli][manual]") {
    std::set<std::string> shipped;
    for (const auto& entry : std::filesystem::directory_iterator(source_path("decks/airfoils"))) {
        if (entry.path().extension() == ".dat") {
            shipped.insert(entry.path().stem().string());
        }
    }
    const std::set<std::string> offered(parsons::cli::kBundledAirfoils.begin(),
                                        parsons::cli::kBundledAirfoils.end());
    CHECK(offered == shipped);
    const auto choices = parsons::cli::value_choices("FILE.dat|AIRFOIL");
    CHECK(std::set<std::string>(choices.words.begin(), choices.words.end()) == shipped);
    CHECK(choices.extensions == std::vector<std::string>{"dat"});
}

TEST_CASE("README: 'Where things are' names every folder of the source that builds a library",
          "[docs-map]") {
    const std::string readme = read_bytes(source_path("README.md"));
    const auto at = readme.find("## Where things are");
    REQUIRE(at != std::string::npos);
    const std::string table = readme.substr(at, readme.find("\n## ", at + 1) - at);
    int folders = 0;
    for (const auto& entry : std::filesystem::directory_iterator(source_path(""))) {
        const std::string name = entry.path().filename().string();
        if (!entry.is_directory() || name.front() == '.' ||
            !std::filesystem::exists(entry.path() / "CMakeLists.txt")) {
            continue;
        }
        ++folders;
        INFO(name);
        CHECK(says(table, "| `" + name + "/` |"));
    }
    CHECK(folders >= 7); // cardreader, relaylogic, axes, decks, outputs, cli, web, examples, tests
}
