// Never lose a file (issue 27; docs/reliability.md, "Nothing lost"; cli/support/file_plan.hpp): an
// output is never an input and never another output, by file identity; companion files follow
// their deck's kind; a null device discards every output, as root and as a user, and stays a
// device with nothing beside it; a reader that goes away ends a command quietly (exit 141); and
// an interrupted command leaves nothing half-done under a real name.
//
// A test never writes what is not its own (issue 53): the device outputs are a null device of the
// test's own, made with mknod in its scratch folder (make_device_node), never the machine's
// /dev/null, which a writer gone wrong would replace or crowd as root. Where mknod is not
// permitted (not root, no CAP_MKNOD) those tests say so and are skipped; each checks that the
// real /dev/null is as it was.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::whole_share;
using parsons::test::write_bytes;
namespace fs = std::filesystem;

using parsons::test::make_device_node;
using parsons::test::node_kind;
using parsons::test::running_as_root;

namespace {

// Everything in a folder, recursively: each entry's kind and, for a file its bytes, for a link
// its target. Two snapshots equal: nothing was written, made, removed or renamed.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> all;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string name = fs::relative(entry.path(), dir).string();
        if (entry.is_symlink()) {
            all[name] = "link -> " + fs::read_symlink(entry.path()).string();
        } else if (entry.is_regular_file()) {
            struct stat st {};
            REQUIRE(stat(entry.path().c_str(), &st) == 0);
            all[name] = fmt::format("file (inode {}) ", st.st_ino) + read_bytes(entry.path());
        } else {
            all[name] = entry.is_directory() ? "folder" : node_kind(entry.path());
        }
    }
    return all;
}

// The names in a folder, recursively, that the output writer gives its temporary files (of the
// process `pid`, or of any).
std::vector<std::string> temporaries(const fs::path& dir, pid_t pid = 0) {
    const std::string mark = pid == 0 ? ".partial-" : fmt::format(".partial-{}", pid);
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (entry.path().filename().string().find(mark) != std::string::npos) {
            found.push_back(entry.path().string());
        }
    }
    return found;
}

// The machine's own /dev/null and the names a writer gone wrong would make beside it: what a test
// must leave as it found (it only looks: it never opens them).
std::string real_null_device() {
    return node_kind("/dev/null") + ", beside it: " + node_kind("/dev/null.job.json") + ", " +
           node_kind("/dev/null.profile.json") + ", " + node_kind("/dev/null.gtkw");
}

// A scratch folder with one of every input a command reads: the sample deck and its listing, a
// profile file of each kind, a generated template with its job description, a saved state, the
// press-feeder and tapping jobs with their profiles, a G-code program and an airfoil file.
struct Workshop {
    TempDir dir;
    std::string cd;

    Workshop() : cd("cd " + q(dir.str("")) + " && ") {
        write_bytes(dir.path("listing.csv"),
                    read_bytes(source_path("decks/samples/patent-example.csv")));
        write_bytes(dir.path("prog.ngc"), read_bytes(source_path("tests/gcode/plate-mm.ngc")));
        write_bytes(dir.path("clarky.dat"), read_bytes(source_path("decks/airfoils/clarky.dat")));
        for (const char* setup :
             {"punch listing.csv -o deck.cbn", "profile > prof.json",
              "profile --profile parsons-extended > ext.json",
              "gen airfoil --naca 0012 --chord 2 --stations 12 -o g.cbn",
              "gen press-feeder --cycles 1 -o f.csv", "gen tapping -o plate.csv"}) {
            INFO(setup);
            REQUIRE(sh(std::string("PARSONS ") + setup).exit_code == 0);
        }
        REQUIRE(sh("PARSONS run deck.cbn -q --limit table=0:2 --save-state state.json").exit_code ==
                3);
    }
    parsons::test::ProcessResult sh(const std::string& line) const { return run_shell(cd + line); }
};

// One command and the files it reads and writes. `command` holds {OUT} where the outputs go;
// every output option is given its own fresh name unless a case says otherwise.
struct Command {
    std::string command;
    std::vector<std::pair<std::string, std::string>> inputs; // option as the message names it,
                                                             // and the file
    std::vector<std::string> outputs;                        // output options
};

std::vector<Command> commands() {
    const std::vector<std::string> run_outputs = {"--report", "--trace", "--events",    "--path",
                                                  "--html",   "--plot",  "--save-state"};
    return {
        {"run deck.cbn --profile prof.json -q",
         {{"DECK", "deck.cbn"}, {"--profile", "prof.json"}},
         run_outputs},
        {"run g.cbn -q",
         {{"DECK", "g.cbn"}, {"the job description beside DECK", "g.cbn.job.json"}},
         {"--cut", "--report"}},
        {"run deck.cbn -q --resume state.json",
         {{"DECK", "deck.cbn"}, {"--resume", "state.json"}},
         {"--save-state", "--report"}},
        {"run f.csv -q --press-proof f.csv.job.json",
         {{"DECK", "f.csv"},
          {"--press-proof", "f.csv.job.json"},
          {"the profile of --press-proof", "f.csv.profile.json"}},
         {"--report", "--plot"}},
        {"run plate.csv -q --thread-proof plate.csv.job.json",
         {{"DECK", "plate.csv"},
          {"--thread-proof", "plate.csv.job.json"},
          {"the profile of --thread-proof", "plate.csv.profile.json"}},
         {"--report", "--events"}},
        {"convert deck.cbn --to bin", {{"DECK", "deck.cbn"}}, {"-o"}},
        {"convert listing.csv --to listing", {{"DECK", "listing.csv"}}, {"-o"}},
        {"convert deck.cbn --to gcode --profile prof.json",
         {{"DECK", "deck.cbn"}, {"--profile", "prof.json"}},
         {"-o"}},
        {"punch listing.csv --to cbn", {{"LISTING", "listing.csv"}}, {"-o"}},
        {"show deck.cbn --profile prof.json",
         {{"DECK", "deck.cbn"}, {"--profile", "prof.json"}},
         {"--svg"}},
        {"gen airfoil --dat clarky.dat --stations 10 --profile prof.json",
         {{"--dat", "clarky.dat"}, {"--profile", "prof.json"}},
         {"-o", "--centres", "--job-out"}},
        {"gen two-tool --dat clarky.dat --stations 10 --profile ext.json",
         {{"--dat", "clarky.dat"}, {"--profile", "ext.json"}},
         {"-o", "--job-out"}},
        {"gen press-feeder --cycles 1 --profile ext.json",
         {{"--profile", "ext.json"}},
         {"-o", "--job-out"}},
        {"gen tapping --profile ext.json", {{"--profile", "ext.json"}}, {"-o", "--job-out"}},
        {"gen gcode prog.ngc --profile prof.json",
         {{"PROGRAM", "prog.ngc"}, {"--profile", "prof.json"}},
         {"-o"}},
    };
}

// The command line with `given` (option -> value) and a fresh name for every other output.
std::string command_line(const Command& c, const std::map<std::string, std::string>& given) {
    std::string line = "PARSONS " + c.command;
    int fresh = 0;
    for (const std::string& option : c.outputs) {
        const auto it = given.find(option);
        // A deck's format comes from its name: fresh names say .csv, which every command takes.
        line += " " + option + " " +
                (it != given.end() ? it->second : fmt::format("fresh-{}.csv", ++fresh));
    }
    return line;
}

// Four ways to name one file: as given, with ./, a hard link to it, a symbolic link to it.
std::vector<std::string> spellings(const Workshop& w, const std::string& file) {
    const std::string hard = "hard-" + file;
    const std::string soft = "soft-" + file;
    if (!fs::exists(w.dir.path(hard))) {
        fs::create_hard_link(w.dir.path(file), w.dir.path(hard));
        fs::create_symlink(file, w.dir.path(soft));
    }
    return {file, "./" + file, hard, soft};
}

void check_refused(const Workshop& w, const std::string& line,
                   const std::vector<std::string>& named) {
    INFO(line);
    const auto before = snapshot(w.dir.path(""));
    const auto r = w.sh(line);
    INFO(r.output);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Catch::StartsWith("parsons: error: "));
    CHECK_THAT(r.output, Catch::Contains("nothing was written"));
    for (const std::string& n : named) {
        CHECK_THAT(r.output, Catch::Contains(n));
    }
    CHECK(snapshot(w.dir.path("")) == before);
}

} // namespace

TEST_CASE("Never lose a file: every output option of every command pointed at every input, in "
          "four spellings, is exit 2 naming both and leaves every file as it was",
          "[never-lose][cli]") {
    Workshop w;
    for (const Command& c : commands()) {
        for (const std::string& out : c.outputs) {
            for (const auto& [in_option, file] : c.inputs) {
                for (const std::string& name : spellings(w, file)) {
                    check_refused(w, command_line(c, {{out, name}}), {out, in_option, name});
                }
            }
        }
    }
}

TEST_CASE("Never lose a file: two outputs of one command that are one file, however spelled, are "
          "exit 2 naming both, and nothing is written",
          "[never-lose][cli]") {
    Workshop w;
    write_bytes(w.dir.path("taken.csv"), "an output of an earlier run\n");
    fs::create_hard_link(w.dir.path("taken.csv"), w.dir.path("hard-taken.csv"));
    fs::create_symlink("taken.csv", w.dir.path("soft-taken.csv"));
    fs::create_symlink("not-yet.csv", w.dir.path("dangling.csv"));
    // (the first output's name, the second's): a new name twice, with ./, an existing file and a
    // hard link to it, a symbolic link to it, and a dangling link to the new name.
    const std::vector<std::pair<std::string, std::string>> pairs = {
        {"new.csv", "new.csv"},
        {"new.csv", "./new.csv"},
        {"taken.csv", "hard-taken.csv"},
        {"taken.csv", "soft-taken.csv"},
        {"not-yet.csv", "dangling.csv"}};
    for (const Command& c : commands()) {
        for (std::size_t a = 0; a < c.outputs.size(); ++a) {
            for (std::size_t b = a + 1; b < c.outputs.size(); ++b) {
                for (const auto& [first, second] : pairs) {
                    check_refused(w,
                                  command_line(c, {{c.outputs[a], first}, {c.outputs[b], second}}),
                                  {c.outputs[a], c.outputs[b]});
                }
            }
        }
    }
}

TEST_CASE("Never lose a file: the files a command writes on its own beside another are outputs "
          "too",
          "[never-lose][cli]") {
    Workshop w;
    fs::copy_file(w.dir.path("plate.csv.profile.json"), w.dir.path("kept.profile.json"));
    // gen airfoil -o g.cbn --centres g.cbn.job.json: the centres would replace the job file.
    check_refused(w,
                  "PARSONS gen airfoil --naca 2412 --stations 10 -o n.cbn --centres n.cbn.job.json",
                  {"the job description beside -o", "--centres", "n.cbn.job.json"});
    // ... or name the job of the deck it reads.
    check_refused(w, "PARSONS run g.cbn --cut cut.svg --report g.cbn.job.json",
                  {"--report", "the job description beside DECK"});
    // A press or tapping job's profile, beside its job description, against the profile read.
    check_refused(w, "PARSONS gen press-feeder --cycles 1 --profile f.csv.profile.json -o f.csv",
                  {"the profile beside the job description", "--profile", "f.csv.profile.json"});
    check_refused(w,
                  "PARSONS gen tapping --profile kept.profile.json -o x.csv --job-out "
                  "kept.job.json",
                  {"the profile beside the job description", "--profile", "kept.profile.json"});
    // show --svg FOLDER: no picture it would write may be the deck it reads.
    fs::create_directories(w.dir.path("cards"));
    fs::copy_file(w.dir.path("deck.cbn"), w.dir.path("cards/card-0002.svg"));
    check_refused(w, "PARSONS show cards/card-0002.svg --format cbn --svg cards",
                  {"--svg", "DECK", "card-0002.svg"});
    fs::create_hard_link(w.dir.path("cards/card-0002.svg"), w.dir.path("deck-link.cbn"));
    check_refused(w, "PARSONS show deck-link.cbn --svg cards", {"--svg", "DECK", "deck-link.cbn"});
    // A file of another name in the folder is not show's: it runs.
    const auto other = w.sh("PARSONS show deck.cbn --svg . > /dev/null");
    CHECK(other.exit_code == 0);
    CHECK(fs::exists(w.dir.path("card-0004.svg")));
}

TEST_CASE("Never lose a file: two outputs on standard output are refused before either is "
          "written",
          "[never-lose][cli]") {
    Workshop w;
    for (const char* line : {"run deck.cbn --report - --trace -",
                             "run deck.cbn --trace - --events -", "run deck.cbn --path - --html -",
                             "gen airfoil --naca 2412 --stations 10 -o - --to cbn --centres -"}) {
        INFO(line);
        const auto r = w.sh(std::string("PARSONS ") + line + " 2>/dev/null");
        CHECK(r.exit_code == 2);
        CHECK(r.output.empty()); // not a byte of either on standard output
        const auto said = w.sh(std::string("PARSONS ") + line + " >/dev/null");
        CHECK_THAT(said.output, Catch::Contains("only one output can go to standard output"));
    }
}

TEST_CASE("Never lose a file: a deck that goes to a device, a FIFO or standard output has no job "
          "description beside it, unless --job-out names one",
          "[never-lose][cli][heavy]") {
    Workshop w;
    const std::string real = real_null_device();
    const auto null = make_device_node(w.dir.path(""), "null", 1, 3);
    if (!null) {
        WARN("skipped: mknod is not permitted here (not root, or no CAP_MKNOD), and the test "
             "writes no device but its own");
        return;
    }
    REQUIRE(mkfifo(w.dir.path("pipe").c_str(), 0600) == 0);
    for (const char* gen : {"gen airfoil --naca 2412 --stations 10", "gen two-tool --naca 2412",
                            "gen press-feeder --cycles 1", "gen tapping"}) {
        INFO(gen);
        const auto before = snapshot(w.dir.path(""));
        CHECK(w.sh(std::string("PARSONS ") + gen + " --to cbn -o - > /dev/null").exit_code == 0);
        const auto r = w.sh(std::string("PARSONS ") + gen + " --to cbn -o null");
        CHECK(r.exit_code == 0);
        CHECK_THAT(r.output, Catch::Contains("no job description"));
        CHECK_THAT(r.output, Catch::Contains("--job-out FILE"));
        const auto fifo = w.sh("{ cat pipe > /dev/null & PARSONS " + std::string(gen) +
                               " --to cbn -o pipe; rc=$?; wait; exit $rc; }");
        CHECK(fifo.exit_code == 0);
        // Nothing beside -, the device or the FIFO, and the device still the device.
        CHECK(snapshot(w.dir.path("")) == before);
        CHECK(node_kind(*null) == "character device 1:3");
        // --job-out: where the job (and a press or tapping job's profile) goes.
        const auto kept = w.sh(std::string("PARSONS ") + gen + " --to cbn -o null --json " +
                               "--job-out kept.job.json");
        INFO(kept.output);
        REQUIRE(kept.exit_code == 0);
        const auto doc = nlohmann::json::parse(kept.output);
        CHECK(doc["job_file"] == "kept.job.json");
        CHECK(fs::exists(w.dir.path("kept.job.json")));
        if (doc.contains("profile_file")) {
            CHECK(doc["profile_file"] == "kept.profile.json");
            CHECK(fs::exists(w.dir.path("kept.profile.json")));
        }
        fs::remove(w.dir.path("kept.job.json"));
        fs::remove(w.dir.path("kept.profile.json"));
    }
    // A deck to a file keeps its job beside it, and --json says where; none beside a device.
    const auto file = w.sh("PARSONS gen airfoil --naca 2412 --stations 10 -o a.cbn --json");
    CHECK(nlohmann::json::parse(file.output)["job_file"] == "a.cbn.job.json");
    const auto device =
        w.sh("PARSONS gen airfoil --naca 2412 --stations 10 -o null --to cbn --json");
    CHECK(nlohmann::json::parse(device.output)["job_file"].is_null());
    CHECK(real_null_device() == real); // the machine's /dev/null: not named, not touched
}

namespace {

// Every output of every command at `n`, a null device of the test's own in the workshop; `as`
// runs the line as another user (or "").
void discard_everything(const Workshop& w, const std::string& n, const std::string& as,
                        bool with_demo = true) {
    std::vector<std::pair<std::string, int>> lines = {
        {"run deck.cbn --limit table=0:2 --report " + n + " --trace " + n + " --events " + n +
             " --path " + n + " --html " + n + " --plot " + n + " --save-state " + n,
         3},
        {"run g.cbn --cut " + n + " --report " + n, 0},
        {"convert deck.cbn -o " + n, 0}, // no --to: nothing reads what a null device takes
        {"convert deck.cbn --to gcode -o " + n, 0},
        {"punch listing.csv -o " + n, 0},
        {"show deck.cbn --svg " + n, 0},
        {"gen airfoil --naca 2412 --stations 10 --to cbn -o " + n + " --centres " + n +
             " --job-out " + n,
         0},
        {"gen two-tool --naca 2412 -o " + n, 0},
        {"gen press-feeder --cycles 1 --to cbn -o " + n + " --job-out " + n, 0},
        {"gen tapping --to cbn -o " + n, 0},
        {"gen gcode prog.ngc -o " + n, 0},
    };
    if (with_demo) {
        lines.emplace_back("demo --out " + n, 0);
    }
    for (const auto& [line, code] : lines) {
        INFO((as.empty() ? "" : as + " ") + line);
        const auto before = snapshot(w.dir.path(""));
        const auto r = w.sh(as + " PARSONS " + line + " > /dev/null");
        INFO(r.output);
        CHECK(r.exit_code == code);
        // The device is still the device (in the snapshot: "character device 1:3"), and
        // nothing appeared beside it (null.job.json, null.profile.json) or anywhere else.
        CHECK(snapshot(w.dir.path("")) == before);
    }
}

} // namespace

TEST_CASE("Never lose a file: a null device discards every output of every command, as root and "
          "as a user, stays a device, and nothing appears beside it",
          "[never-lose][cli][heavy]") {
    Workshop w;
    const std::string real = real_null_device();
    const auto null = make_device_node(w.dir.path(""), "null", 1, 3);
    if (!null) {
        WARN("skipped: mknod is not permitted here (not root, or no CAP_MKNOD), and the test "
             "writes no device but its own");
        return;
    }
    REQUIRE(node_kind(*null) == "character device 1:3");
    discard_everything(w, "null", "");
    if (running_as_root()) {
        // The same as the user nobody, in a folder it may read but not write.
        fs::permissions(w.dir.path(""), fs::perms::owner_all | fs::perms::group_read |
                                            fs::perms::group_exec | fs::perms::others_read |
                                            fs::perms::others_exec);
        for (const auto& entry : fs::recursive_directory_iterator(w.dir.path(""))) {
            fs::permissions(entry.path(), fs::perms::others_read, fs::perm_options::add);
        }
        // Under the sanitizers (a share of the cases, test_support.hpp) the user's pass leaves
        // out the demo, some 11 s there: root's pass ran all of it under them, and the regular
        // build runs the user's demo too.
        discard_everything(w, "null", "setpriv --reuid=65534 --regid=65534 --clear-groups",
                           whole_share());
    }
    CHECK(node_kind(*null) == "character device 1:3");
    CHECK(real_null_device() == real); // the machine's /dev/null: not named, not touched
}

namespace {

struct Ended {
    bool exited = false;
    int code = -1;   // the exit status, when exited
    int signal = 0;  // the signal that ended it, when not
    std::string err; // what it wrote to standard error (when only standard output was the pipe)
};

// In a child just forked: parsons ARGS (words split at spaces) in `dir`, SIGPIPE, SIGINT and
// SIGTERM at their defaults, as a shell starts a program. Never returns.
[[noreturn]] void exec_parsons(const fs::path& dir, const std::string& args) {
    for (int signal : {SIGPIPE, SIGINT, SIGTERM}) {
        std::signal(signal, SIG_DFL);
    }
    if (chdir(dir.c_str()) != 0) {
        _exit(120);
    }
    std::vector<std::string> words;
    std::istringstream in(args);
    for (std::string word; in >> word;) {
        words.push_back(word);
    }
    std::vector<char*> argv{const_cast<char*>(PARSONS_EXE)};
    for (std::string& w : words) {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    execv(PARSONS_EXE, argv.data());
    _exit(121);
}

// How a child ended, from waitpid's status.
Ended ended(int status) {
    Ended e;
    e.exited = WIFEXITED(status);
    e.code = e.exited ? WEXITSTATUS(status) : -1;
    e.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return e;
}

// Which of the standard streams go into the closed pipe.
enum class Into { standard_output, both, standard_error };

// Runs parsons ARGS in `dir` with standard output, standard error or both the writing end of a
// pipe whose reader has already gone (the other to a file), and SIGPIPE at its default, as a
// shell starts `parsons ARGS | head` after head has read enough.
Ended into_a_closed_pipe(const fs::path& dir, const std::string& args, Into into) {
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    ::close(fds[0]); // the reader is gone before parsons writes a byte
    const fs::path other = dir / "other-stream.txt";
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        const int file = ::open(other.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(into == Into::standard_error ? file : fds[1], STDOUT_FILENO);
        dup2(into == Into::standard_output ? file : fds[1], STDERR_FILENO);
        exec_parsons(dir, args);
    }
    ::close(fds[1]);
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    Ended e = ended(status);
    if (into == Into::standard_output) {
        e.err = read_bytes(other);
    }
    fs::remove(other);
    return e;
}

} // namespace

TEST_CASE("Never lose a file: a reader that goes away ends every command quietly with exit 141, "
          "standard error on the same pipe or not, and leaves no temporary file",
          "[never-lose][cli][pipe][heavy]") {
    Workshop w;
    for (const char* args :
         {"run deck.cbn",
          "run deck.cbn -q --trace -",
          "run deck.cbn -q --report - --trace t.vcd",
          "run deck.cbn -q --events - --report r.json",
          "run deck.cbn --limit table=0:2",
          "run deck.cbn --help",
          "show deck.cbn",
          "show deck.cbn --json",
          "check deck.cbn",
          "check deck.cbn --json",
          "convert deck.cbn --to listing -o -",
          "convert deck.cbn --to gcode -o -",
          "convert deck.cbn --to bin -o d.bin",
          "punch listing.csv --to cbn -o -",
          "punch listing.csv -o p.cbn",
          "profile",
          "profile --profile ext.json",
          "gen airfoil --naca 2412 --stations 10 -o a.cbn",
          "gen airfoil --naca 2412 --stations 10 --to cbn -o - --centres c.csv",
          "gen two-tool --naca 2412 -o t.cbn",
          "gen press-feeder --cycles 1 -o p.csv",
          "gen tapping -o tp.csv --json",
          "gen gcode prog.ngc -o gc.cbn",
          "demo --out demo",
          "bench --runs 1 --long-cards 2 --trace-cards 2 --short-cards 10 --memory-cards 100 "
          "--press-cycles 2",
          "bench --runs 101", // ends at its first line, never measures for nobody
          "--help",
          "--version"}) {
        for (Into into : {Into::standard_output, Into::both}) {
            INFO(args << (into == Into::both ? " 2>&1" : ""));
            const Ended e = into_a_closed_pipe(w.dir.path(""), args, into);
            INFO("stderr: " << e.err);
            CHECK(e.exited); // not SIGABRT, not SIGPIPE midway
            CHECK(e.signal == 0);
            CHECK(e.code == 141);
            // Nothing about the pipe, even on a standard error that is alive (what the command
            // says of its own work, such as a machine stop, may stand there).
            CHECK(e.err.find("pipe") == std::string::npos);
            CHECK(e.err.find("error") == std::string::npos);
            CHECK(temporaries(w.dir.path("")).empty());
            if (std::string_view(args).starts_with("demo")) {
                // It ends where it first finds its reader gone, after its first line and
                // before it runs any deck: no report, no folder of a system.
                CHECK_FALSE(fs::exists(w.dir.path("demo/sample-deck")));
                CHECK_FALSE(fs::exists(w.dir.path("demo/airfoil-template/report.json")));
            }
        }
    }
}

TEST_CASE("Never lose a file: a standard error whose reader went away ends the command quietly, "
          "exit 141, and leaves no temporary file",
          "[never-lose][cli][pipe]") {
    Workshop w;
    // Each says something on standard error: a machine stop, a summary beside a deck on
    // standard output, a warning, a usage error.
    for (const char* args :
         {"run deck.cbn -q --limit table=0:2", "run deck.cbn -q --report - --plot t.png",
          "gen airfoil --naca 2412 --stations 10 --to cbn -o -", "convert deck.cbn --to bin -o -",
          "run missing.cbn", "show deck.cbn --no-such-option"}) {
        INFO(args);
        const Ended e = into_a_closed_pipe(w.dir.path(""), args, Into::standard_error);
        CHECK(e.exited);
        CHECK(e.signal == 0);
        CHECK(e.code == 141);
        CHECK(temporaries(w.dir.path("")).empty());
    }
}

TEST_CASE("Never lose a file: a named FIFO whose reader goes away ends the run at once, exit 141, "
          "the FIFO named on standard error, and the run's other outputs not written",
          "[never-lose][cli][pipe]") {
    Workshop w;
    REQUIRE(mkfifo(w.dir.path("f").c_str(), 0600) == 0);
    const auto r = w.sh("{ head -c 10 f >/dev/null & PARSONS run deck.cbn -q --trace f --report "
                        "r.json; echo \"exit=$?\"; exec 3<>f; exec 3>&-; wait; }");
    CHECK_THAT(r.output, Catch::Contains("exit=141"));
    CHECK_THAT(r.output, Catch::Contains("parsons: f: the reader went away (broken pipe)"));
    CHECK_FALSE(fs::exists(w.dir.path("r.json"))); // a run stopped for nobody writes no report
    CHECK(temporaries(w.dir.path("")).empty());
}

namespace {

// Starts parsons ARGS in `dir`, waits until the output writer's temporary file appears, stops it
// there, sends `signal` and lets it go on; how it ended. A command that finished before its
// temporary file was seen (a fast or quiet machine between two looks) wrote `output` whole: it
// is removed and the command started again, up to 20 times.
Ended interrupted_while_writing(const fs::path& dir, const std::string& args, int signal,
                                const std::string& output) {
    bool seen = false;
    int status = 0;
    for (int attempt = 0; attempt < 20 && !seen; ++attempt) {
        const pid_t pid = fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            const int null = ::open("/dev/null", O_WRONLY);
            dup2(null, STDOUT_FILENO);
            dup2(null, STDERR_FILENO);
            exec_parsons(dir, args);
        }
        bool done = false;
        for (int i = 0; i < 200000 && !seen && !done; ++i) {
            done = waitpid(pid, &status, WNOHANG) == pid;
            seen = !done && !temporaries(dir, pid).empty();
            if (seen) {
                kill(pid, SIGSTOP);
                seen = !temporaries(dir, pid).empty(); // still writing when stopped
                kill(pid, signal);
                kill(pid, SIGCONT);
                REQUIRE(waitpid(pid, &status, 0) == pid);
                done = true;
            } else if (!done) {
                std::this_thread::sleep_for(std::chrono::microseconds(200));
            }
        }
        if (!seen) {
            if (!done) {
                kill(pid, SIGKILL);
                waitpid(pid, &status, 0);
            }
            std::error_code ec;
            fs::remove(dir / output, ec); // the test's own output, written whole
        }
    }
    REQUIRE(seen);
    return ended(status);
}

} // namespace

TEST_CASE("Never lose a file: a conversion stopped by Ctrl-C or SIGTERM while it writes leaves "
          "neither its output nor its temporary file",
          "[never-lose][cli][signals]") {
    Workshop w;
    // A deck long enough that writing it takes a while: the most cards a deck holds.
    write_bytes(w.dir.path("long.csv"), parsons::test::long_listing(9999));
    REQUIRE(w.sh("PARSONS punch long.csv -o long.cbn").exit_code == 0);
    for (int signal : {SIGINT, SIGTERM}) {
        INFO("signal " << signal);
        const Ended e = interrupted_while_writing(
            w.dir.path(""), "convert long.cbn --to bin -o long.bin", signal, "long.bin");
        CHECK(e.signal == signal); // ended by the signal, as any Unix program, after cleaning up
        CHECK_FALSE(fs::exists(w.dir.path("long.bin")));
        CHECK(temporaries(w.dir.path("")).empty());
    }
}

TEST_CASE("Never lose a file: a conversion to G-code stopped by Ctrl-C says it is incomplete and "
          "does not end in M2",
          "[never-lose][cli][signals][gcode]") {
    Workshop w;
    write_bytes(w.dir.path("long.csv"), parsons::test::long_listing(400));
    const Ended e = interrupted_while_writing(w.dir.path(""), "convert long.csv -o long.ngc",
                                              SIGINT, "long.ngc");
    CHECK(e.exited);
    CHECK(e.code == 130);
    const auto lines = parsons::test::lines_of(read_bytes(w.dir.path("long.ngc")));
    REQUIRE_FALSE(lines.empty());
    CHECK_THAT(lines.back(), Catch::Contains("INCOMPLETE"));
    for (const std::string& line : lines) {
        CHECK(line != "M2");
        CHECK(line != "M30");
    }
    CHECK(temporaries(w.dir.path("")).empty());
}
