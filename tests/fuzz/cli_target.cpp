// The cli target: random command lines of the commands that write files (run, convert, punch,
// show, gen), each output option given a name from a small vocabulary: the files the command
// reads, spelled five ways (as given, with ./, through sub/.., a hard link, a symbolic link),
// new names, an existing file with a hard and a symbolic link to it, a dangling link, "-" and a
// null device. They run in a scratch folder of inputs made once. The null device is a node of
// the scratch folder's own (mknod 1, 3), never the machine's /dev/null: a writer gone wrong must
// not break the machine it runs on (issue 53); where mknod is not permitted (not root) the name
// is left out of the vocabulary. Whatever the command line:
//
//   - no input changes (bytes, inode, links), and no output writer's temporary file stays;
//   - the null device stays a character device, and nothing appears beside it;
//   - a command line whose outputs name one of its inputs, or one file twice (a generated deck's
//     job description included), is refused: exit 2;
//   - no command line is an internal error (exit 1), and none crashes or hangs.
//
// The names carry, by construction, which file they are (`Name::file`), so the target knows a
// clash without asking the code under test (docs/reliability.md, "Nothing lost").
#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/in_process.hpp"

#include "axes/profile_json.hpp"
#include "cli/command_line.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>
#include <vector>

namespace parsons::fuzz {
namespace {

namespace fs = std::filesystem;

// The files every template reads, made once in the scratch folder.
const std::vector<std::string> kInputs = {
    "g.cbn",      "g.cbn.job.json", "listing.csv",    "prof.json",          "ext.json",
    "state.json", "f.csv",          "f.csv.job.json", "f.csv.profile.json", "prog.ngc"};

// A name for an output: its text, which file it is ("" for a device, which may take any number
// of outputs), and which file the job description a generator writes beside it would be.
struct Name {
    std::string text;
    std::string file;
    std::string companion;
};

// One command and what it reads; `outputs` are its output options, the first `required` of them
// always given.
struct Template {
    std::vector<std::string> args; // {S} stands for the scratch folder
    std::vector<std::string> reads;
    std::vector<std::string> outputs;
    std::size_t required = 0;
    bool writes_job = false;          // a generator: -o's job description beside it
    std::vector<std::string> extras;  // flags an input may add, one byte each
    bool profile_file_option = false; // may add --profile {S}/prof.json (read)
};

const std::vector<Template>& templates() {
    static const std::vector<Template> all = {
        {{"run", "{S}/listing.csv"},
         {"listing.csv"},
         {"--report", "--trace", "--events", "--path", "--html", "--plot", "--save-state"},
         0,
         false,
         {"-q", "--impulse-level", "--limit", "table=0:0.3"},
         true},
        {{"run", "{S}/g.cbn"},
         {"g.cbn", "g.cbn.job.json"},
         {"--cut", "--report", "--plot", "--html"},
         1,
         false,
         {"-q"},
         false},
        {{"run", "{S}/listing.csv", "--resume", "{S}/state.json"},
         {"listing.csv", "state.json"},
         {"--save-state", "--report", "--events"},
         0,
         false,
         {"-q", "--limit", "table=0:9"},
         false},
        {{"run", "{S}/f.csv", "--press-proof", "{S}/f.csv.job.json"},
         {"f.csv", "f.csv.job.json", "f.csv.profile.json"},
         {"--report", "--plot"},
         0,
         false,
         {"-q"},
         false},
        {{"convert", "{S}/g.cbn", "--to", "bin"}, {"g.cbn"}, {"-o"}, 1, false, {}, false},
        {{"convert", "{S}/listing.csv", "--to", "gcode"},
         {"listing.csv"},
         {"-o"},
         1,
         false,
         {},
         true},
        {{"punch", "{S}/listing.csv", "--to", "cbn"},
         {"listing.csv"},
         {"-o"},
         1,
         false,
         {"--json"},
         false},
        {{"show", "{S}/g.cbn"}, {"g.cbn"}, {"--svg"}, 0, false, {"--json"}, true},
        {{"gen", "airfoil", "--naca", "0012", "--chord", "2", "--stations", "8"},
         {},
         {"-o", "--centres", "--job-out"},
         1,
         true,
         {"--json", "--to", "cbn"},
         true},
        {{"gen", "press-feeder", "--cycles", "1", "--profile", "{S}/ext.json"},
         {"ext.json"},
         {"-o", "--job-out"},
         1,
         true,
         {"--json", "--to", "cbn"},
         false},
        {{"gen", "gcode", "{S}/prog.ngc"}, {"prog.ngc"}, {"-o"}, 1, false, {"--to", "cbn"}, true},
    };
    return all;
}

// Runs a parsons command line in this process, its standard input, output and error on
// /dev/null; the exit code.
int parsons(std::vector<std::string> args) {
    const int null = ::open("/dev/null", O_RDWR);
    const int code = run_in_process(std::move(args), null, null, null);
    ::close(null);
    return code;
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The scratch folder: the inputs, a hard and a symbolic link to each, an existing output with
// its own links, a dangling link and a folder to spell sub/.. with. Made once a process; removed
// as the process ends.
struct Workshop {
    fs::path dir;
    std::map<std::string, std::string> protected_files; // name -> what it must stay
    bool has_null = false;                              // dir/null is a null device of our own

    Workshop() {
        std::string name = (fs::temp_directory_path() / "parsons-fuzz-cli-XXXXXX").string();
        if (::mkdtemp(name.data()) == nullptr) {
            throw Finding("cli: cannot make a scratch folder");
        }
        dir = name;
        try {
            const std::string s = dir.string();
            write_text(dir / "prof.json", axes::profile_to_json(axes::default_profile()));
            write_text(dir / "ext.json", axes::profile_to_json(axes::extended_profile()));
            write_text(dir / "prog.ngc", "G20\nG0 X1 Y1\nG1 X2 F10\nG1 Y1.5\nM2\n");
            const std::vector<std::vector<std::string>> setup = {
                {"gen", "airfoil", "--naca", "0012", "--chord", "2", "--stations", "8", "-o",
                 s + "/g.cbn"},
                {"convert", s + "/g.cbn", "--to", "listing", "-o", s + "/listing.csv"},
                {"gen", "press-feeder", "--cycles", "1", "-o", s + "/f.csv"}};
            for (const auto& line : setup) {
                if (parsons(line) != 0) {
                    throw Finding("cli: the scratch folder's inputs could not be made");
                }
            }
            if (parsons({"run", s + "/listing.csv", "-q", "--limit", "table=0:0.3", "--save-state",
                         s + "/state.json"}) != 3) {
                throw Finding("cli: the saved state could not be made");
            }
            fs::create_directories(dir / "sub");
            for (const std::string& f : kInputs) {
                fs::create_hard_link(dir / f, dir / ("hard-" + f));
                fs::create_symlink(f, dir / ("soft-" + f));
            }
            restore_outputs();
            // The null device of our own: made, and writable, or left out.
            const fs::path null = dir / "null";
            if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0) {
                const int fd = ::open(null.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
                has_null = fd >= 0;
                if (fd >= 0) {
                    ::close(fd);
                } else {
                    ::unlink(null.c_str()); // a nodev mount: of no use
                }
            }
            for (const auto& entry : fs::directory_iterator(dir)) {
                const std::string n = entry.path().filename().string();
                if (!entry.is_directory() && n.rfind("old", 0) != 0 &&
                    n.rfind("dangling", 0) != 0) {
                    protected_files[n] = describe(entry.path());
                }
            }
        } catch (...) {
            // A workshop that could not be made is removed too: no half folder stays in
            // the temporary folder (612 of them did, from one run whose set-up failed).
            std::error_code ec;
            fs::remove_all(dir, ec);
            throw;
        }
    }
    ~Workshop() {
        std::error_code ec;
        fs::remove_all(dir, ec); // made by mkdtemp: ours
    }

    // An existing output and its links, a dangling link to a new name.
    void restore_outputs() const {
        write_text(dir / "old.csv", "an earlier output\n");
        std::error_code ec;
        for (const char* link : {"old-hard.csv", "old-soft.csv", "dangling-soft.csv"}) {
            fs::remove(dir / link, ec);
        }
        fs::create_hard_link(dir / "old.csv", dir / "old-hard.csv");
        fs::create_symlink("old.csv", dir / "old-soft.csv");
        fs::create_symlink("new1.csv", dir / "dangling-soft.csv");
    }

    static std::string describe(const fs::path& p) {
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0) {
            return "missing";
        }
        if (S_ISLNK(st.st_mode)) {
            return "link -> " + fs::read_symlink(p).string();
        }
        return fmt::format("inode {} mode {:o} ", st.st_ino, st.st_mode) + read_text(p);
    }

    // After a command line: every input as it was, no temporary file; then everything the
    // command wrote is cleared away for the next.
    void check_and_clear(const std::string& line) const {
        for (const auto& [name, was] : protected_files) {
            if (describe(dir / name) != was) {
                throw Finding(fmt::format("cli: {} changed the input {}", line, name));
            }
        }
        std::vector<fs::path> written;
        for (const auto& entry : fs::recursive_directory_iterator(dir)) {
            const std::string n = entry.path().filename().string();
            if (n.find(".partial-") != std::string::npos) {
                throw Finding(fmt::format("cli: {} left the temporary file {}", line, n));
            }
            if (has_null && n.rfind("null.", 0) == 0) {
                throw Finding(fmt::format("cli: {} wrote {} beside the null device", line, n));
            }
            if (entry.path().parent_path() == dir && !protected_files.count(n) && n != "sub") {
                written.push_back(entry.path());
            }
        }
        std::error_code ec;
        for (const fs::path& p : written) {
            fs::remove_all(p, ec);
        }
        fs::remove_all(dir / "sub", ec);
        fs::create_directories(dir / "sub");
        restore_outputs();
    }
};

// Reads the fuzz input a byte at a time (0 once it is used up).
class ByteReader {
public:
    explicit ByteReader(Bytes input) : input_(input) {}
    std::uint8_t next() { return at_ < input_.size() ? input_[at_++] : 0; }

private:
    Bytes input_;
    std::size_t at_ = 0;
};

// The names an output of `t` may be given.
std::vector<Name> vocabulary(const Template& t, const std::vector<std::string>& reads,
                             const std::string& s, bool has_null) {
    std::vector<Name> names;
    for (const std::string& f : reads) {
        const std::string id = "input " + f;
        for (const std::string& spelled : {f, "./" + f, "sub/../" + f, "hard-" + f, "soft-" + f}) {
            names.push_back({s + "/" + spelled, id, "companion of " + spelled});
        }
    }
    const std::vector<Name> others = {
        {s + "/new1.csv", "new1.csv", "new1.csv.job.json"},
        {s + "/./new1.csv", "new1.csv", "new1.csv.job.json"},
        {s + "/dangling-soft.csv", "new1.csv", "dangling-soft.csv.job.json"},
        {s + "/new1.csv.job.json", "new1.csv.job.json", "new1.csv.job.json.job.json"},
        {s + "/new2.svg", "new2.svg", "new2.svg.job.json"},
        {s + "/new3.json", "new3.json", "new3.json.job.json"},
        {s + "/old.csv", "old.csv", "old.csv.job.json"},
        {s + "/old-hard.csv", "old.csv", "old-hard.csv.job.json"},
        {s + "/old-soft.csv", "old.csv", "old-soft.csv.job.json"},
        {"-", "standard output", ""}};
    names.insert(names.end(), others.begin(), others.end());
    if (has_null) {
        names.push_back({s + "/null", "", ""});
    }
    (void)t;
    return names;
}

} // namespace

void fuzz_cli(Bytes input) {
    static const Workshop workshop;
    const std::string s = workshop.dir.string();
    ByteReader bytes(input);
    const Template& t = templates()[bytes.next() % templates().size()];
    std::vector<std::string> args;
    for (const std::string& a : t.args) {
        args.push_back(a.rfind("{S}", 0) == 0 ? s + a.substr(3) : a);
    }
    std::vector<std::string> reads = t.reads;
    if (t.profile_file_option && bytes.next() % 2 == 1) {
        args.insert(args.end(), {"--profile", s + "/prof.json"});
        reads.push_back("prof.json");
    }
    for (std::size_t i = 0; i < t.extras.size(); ++i) {
        const bool with_value = i + 1 < t.extras.size() && t.extras[i + 1][0] != '-';
        if (bytes.next() % 2 == 1) {
            args.push_back(t.extras[i]);
            if (with_value) {
                args.push_back(t.extras[i + 1]);
            }
        }
        i += with_value ? 1 : 0;
    }
    // Each output: left out (not when required) or a name of the vocabulary.
    const std::vector<Name> names = vocabulary(t, reads, s, workshop.has_null);
    std::vector<std::pair<std::string, Name>> given;
    for (std::size_t i = 0; i < t.outputs.size(); ++i) {
        const std::uint8_t b = bytes.next();
        if (i >= t.required && b % 4 == 0) {
            continue;
        }
        const Name& n = names[(b / 4u + b) % names.size()];
        given.emplace_back(t.outputs[i], n);
        args.insert(args.end(), {t.outputs[i], n.text});
    }
    // What the command line asks for, by construction: which files its outputs are.
    std::set<std::string> read_ids;
    for (const std::string& f : reads) {
        read_ids.insert("input " + f);
    }
    std::vector<std::string> written_ids;
    bool job_out = false;
    for (const auto& [option, n] : given) {
        written_ids.push_back(n.file);
        job_out = job_out || option == "--job-out";
    }
    for (const auto& [option, n] : given) {
        if (t.writes_job && option == "-o" && !job_out && !n.companion.empty()) {
            written_ids.push_back(n.companion);
        }
    }
    bool clash = false;
    for (std::size_t i = 0; i < written_ids.size(); ++i) {
        const std::string& id = written_ids[i];
        if (id.empty()) {
            continue;
        }
        clash = clash || read_ids.count(id) > 0;
        for (std::size_t j = i + 1; j < written_ids.size(); ++j) {
            clash = clash || written_ids[j] == id;
        }
    }
    std::string line = "parsons";
    for (const std::string& a : args) {
        line += " " + a;
    }
    const int code = parsons(args);
    workshop.check_and_clear(line);
    if (code == 1) {
        throw Finding(fmt::format("cli: {}: an internal error (exit 1)", line));
    }
    if (clash && code != 2) {
        throw Finding(fmt::format("cli: {}: an output is an input or another output, and the "
                                  "command went on (exit {})",
                                  line, code));
    }
}

} // namespace parsons::fuzz
