// The argv target: command lines of every command, built from the same definitions that make
// the shell completion (cli::command_words over the command line of cli/command_line.hpp: each
// command's flags, its options with the type name of their values, its positionals), each value
// a hostile one for its type: NaN, infinities, -0, 1e308, hex, huge and negative integers, empty
// and very long words, bytes that are not UTF-8, files that are folders, empty or missing, "-"
// (standard input, an empty file of its own). Whatever the command line:
//
//   - it ends with exit 0, 2 or 3: never 1 (an internal error), never a signal;
//   - a number option (CLI11 type FLOAT, INT, ...) given NaN or an infinity is refused, exit 2,
//     whatever else the line holds (unless --help or --version ends it first);
//   - within kMostSeconds and kMostMegabytes (libFuzzer's -timeout and -rss_limit_mb also hold a
//     hang or a runaway to account);
//   - it writes nowhere but its own scratch folder: the command runs with its working folder
//     there, every file name it is given is relative to it, and its standard input, output and
//     error are files in it (never a device). The folder is made afresh for every command line.
//
// bench and demo are parsed, not run: bench measures itself by starting /proc/self/exe (here the
// fuzzer or the test program), demo runs every job for minutes. Their options still meet every
// hostile value: a value CLI11 refuses is exit 2, one it takes would run.
#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/in_process.hpp"

#include "axes/profile_json.hpp"
#include "cli/command_line.hpp"
#include "cli/support/manual.hpp"
#include "cli/support/value_names.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace parsons::fuzz {
// Named, not anonymous: the unity build compiles this file with cli_target.cpp.
namespace argv_target {

namespace fs = std::filesystem;

constexpr double kMostSeconds = 10; // scripts/fuzz.sh gives libFuzzer -timeout=10
constexpr long kMostMegabytes = 2048;

// The commands parsed but not run (above).
bool parse_only(const std::string& path) {
    return path == "bench" || path == "demo";
}

// The words of a '|'-separated list.
std::vector<std::string> split(std::string_view list) {
    std::vector<std::string> out;
    for (std::size_t from = 0;;) {
        const auto bar = list.find('|', from);
        out.emplace_back(list.substr(from, bar == std::string_view::npos ? bar : bar - from));
        if (bar == std::string_view::npos) {
            return out;
        }
        from = bar + 1;
    }
}

// Numbers as a user, a script or an attacker might type them (single, and as the lists some
// options take, "table,cross,vertical").
const std::vector<std::string> kHostileNumbers =
    split("nan|NaN|-nan|inf|-inf|infinity|-0|0|1e308|-1e308|1e309|1e-320|0x10|0X1p3|010|"
          "99999999999999999999999|-99999999999999999999999|4294967296|2147483648|-1|-5|1.|.5|"
          "+3| 4|5 |1e|1,5|1_000|12abc||-|--|\xd9\xa3|nan,0,0.5|inf,0,0|1,2|1,2,3,4|1e308,1,1|"
          "-0,-0,-0|,,");
const std::vector<std::string> kGoodNumbers = split("1|2|3|0.5|0.25|0.01|10|4|1,1,0.5|2,1,0");

// Words that are no number: empty, long, not UTF-8, control bytes, option-like.
std::vector<std::string> hostile_words() {
    std::vector<std::string> words =
        split("|\xff\xfe\xfd|\xc3(|\x1b[31mred\x1b[0m|a\tb\nc|--help|-|table=nan:1|table=0:0.3|"
              "tilt=-inf:inf|cross=1:0|x=1:2|table=|=|:|slip:table:1:5|slip:table:nan:1|"
              "stuck:table:2:3|stuck:tilt:99999999999:0|nosuch:1|parsons-safe|parsons-extended|"
              "nosuch|0012|23012|9999|NACA 2412");
    words.push_back(std::string(5000, 'a'));
    return words;
}

// Files of the scratch folder, by what they are; every name is relative to it.
const std::vector<std::string> kGoodFiles = split("g.cbn|listing.csv|prog.ngc|prof.json|ext.json|"
                                                  "state.json|naca.dat|text.txt");
const std::vector<std::string> kHostileFiles =
    split("empty.csv|empty.cbn|empty.json|empty.ngc|folder|folder.csv|folder.json|missing.csv|"
          "missing.json|missing.cbn|no/such/dir/x.csv|\xff\xfe.csv|sub/../g.cbn|-|"
          "g.cbn.job.json|garbage.bin|folder/|.|..x|out.csv");

// A number no option takes: NaN or an infinity, alone or in a list.
bool names_non_finite(const std::string& value) {
    for (const char* word : {"nan", "NaN", "inf", "infinity", "1e309"}) {
        if (value.find(word) != std::string::npos) {
            return true;
        }
    }
    return false;
}

bool is_number_type(const std::string& type_name) {
    for (const char* t : {"FLOAT", "INT", "UINT", "NUMBER"}) {
        if (type_name.rfind(t, 0) == 0) {
            return true;
        }
    }
    return false;
}

// The value of an option or positional of this type name, chosen by the byte b: three bytes in
// four a plausible one (an input of its kind, a new file, a word it offers, a small number), the
// fourth a hostile one. An input (a positional) is plausible only as a file that exists.
std::string value_for(const std::string& type_name, std::uint8_t b, bool input = false) {
    const cli::ValueChoices v = cli::value_choices(type_name);
    const bool files = !v.extensions.empty() || v.any_file || v.folders;
    std::vector<std::string> pool;
    if (b % 4 != 3) {
        pool = v.words;
        for (const std::string& e : v.extensions) {
            for (const std::string& f : kGoodFiles) {
                if (f.size() > e.size() && f.compare(f.size() - e.size(), e.size(), e) == 0) {
                    pool.push_back(f);
                }
            }
            if (!input) {
                pool.push_back("new." + e);
            }
        }
        if (v.any_file) {
            pool.insert(pool.end(), {"g.cbn", "new.txt"});
        }
        if (v.folders) {
            pool.insert(pool.end(), {"newdir", "folder"});
        }
        if (pool.empty() && files) {
            pool.push_back("new." + v.extensions.front());
        }
        if (pool.empty()) {
            pool = is_number_type(type_name) ? kGoodNumbers : hostile_words();
        }
    } else {
        pool = files ? kHostileFiles : kHostileNumbers;
        const auto words = hostile_words();
        pool.insert(pool.end(), words.begin(), words.end());
    }
    return pool[(b / 4u) % pool.size()];
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

// The scratch folder's inputs, made once a process (in `pristine`), copied afresh into `work`
// for every command line.
struct Scratch {
    fs::path root;
    fs::path pristine;
    fs::path work;
    fs::path io; // standard input, output and error

    Scratch() {
        std::string name = (fs::temp_directory_path() / "parsons-fuzz-argv-XXXXXX").string();
        if (::mkdtemp(name.data()) == nullptr) {
            throw Finding("argv: cannot make a scratch folder");
        }
        root = name;
        pristine = root / "pristine";
        work = root / "work";
        io = root / "io";
        fs::create_directories(pristine);
        fs::create_directories(io);
        const fs::path& d = pristine;
        write_file(d / "prof.json", axes::profile_to_json(axes::default_profile()));
        write_file(d / "ext.json", axes::profile_to_json(axes::extended_profile()));
        write_file(d / "prog.ngc", "G20\nG0 X1 Y1\nG1 X2 F10\nG1 Y1.5\nM2\n");
        write_file(d / "naca.dat", "NACA 0012\n1 0\n0.5 0.06\n0 0\n0.5 -0.06\n1 0\n");
        for (const char* e : {"empty.csv", "empty.cbn", "empty.json", "empty.ngc"}) {
            write_file(d / e, "");
        }
        write_file(d / "text.txt", "not a deck\n");
        write_file(d / "garbage.bin", std::string("\x00\xff\x1b\x80garbage", 11));
        write_file(d / "\xff\xfe.csv", "not UTF-8 in its name\n");
        for (const char* f : {"folder", "folder.csv", "folder.json", "sub"}) {
            fs::create_directories(d / f);
        }
        const std::string s = d.string();
        const std::vector<std::vector<std::string>> setup = {
            {"gen", "airfoil", "--naca", "0012", "--chord", "2", "--stations", "8", "-o",
             s + "/g.cbn"},
            {"convert", s + "/g.cbn", "--to", "listing", "-o", s + "/listing.csv"}};
        for (const auto& line : setup) {
            if (run_in(line, false) != 0) {
                throw Finding("argv: the scratch folder's inputs could not be made");
            }
        }
        if (run_in({"run", s + "/listing.csv", "-q", "--limit", "table=0:0.3", "--save-state",
                    s + "/state.json"},
                   false) != 3) {
            throw Finding("argv: the saved state could not be made");
        }
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(root, ec); // made by mkdtemp: ours
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    // A fresh copy of the inputs in `work`.
    void refresh() const {
        std::error_code ec;
        fs::remove_all(work, ec);
        fs::copy(pristine, work, fs::copy_options::recursive);
    }

    // Runs a parsons command line in this process, in `work` (when `in_work`), its standard
    // input an empty file and its output and error files of io/; the exit code.
    int run_in(std::vector<std::string> args, bool in_work) const {
        const fs::path was = fs::current_path();
        if (in_work) {
            fs::current_path(work);
        }
        write_file(io / "stdin", "");
        const int in = ::open((io / "stdin").c_str(), O_RDONLY);
        const int out = ::open((io / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = ::open((io / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int code = run_in_process(std::move(args), in, out, err);
        for (int fd : {in, out, err}) {
            ::close(fd);
        }
        fs::current_path(was);
        return code;
    }
};

// Parses the command line as parsons would, without running the command: 0 (taken, or --help),
// 2 (refused by the command line).
int parse_in(std::vector<std::string> args) {
    CLI::App app;
    cli::Command selected;
    cli::build_command_line(app, selected, "parsons (fuzz)");
    std::reverse(args.begin(), args.end()); // CLI11 takes a vector in reverse
    try {
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        return e.get_exit_code() == 0 ? 0 : 2;
    }
    return 0;
}

const std::vector<cli::CommandWords>& commands() {
    static const std::vector<cli::CommandWords> all = [] {
        CLI::App app;
        cli::Command selected;
        cli::build_command_line(app, selected, "parsons (fuzz)");
        return cli::command_words(app);
    }();
    return all;
}

// The command line as a shell would take it back: each word quoted, bytes not printable escaped.
std::string shown(const std::vector<std::string>& args) {
    std::string line = "parsons";
    for (const std::string& a : args) {
        std::string word;
        for (const unsigned char c : a) {
            word += c < 0x20 || c >= 0x7f ? fmt::format("\\x{:02x}", c)
                    : c == '\''           ? std::string("'\\''")
                                          : std::string(1, static_cast<char>(c));
        }
        line += a.size() > 200 ? fmt::format(" '{}...'({} bytes)", word.substr(0, 20), a.size())
                               : " '" + word + "'";
    }
    return line;
}

class ByteReader {
public:
    explicit ByteReader(Bytes input) : input_(input) {}
    bool more() const { return at_ < input_.size(); }
    std::uint8_t next() { return at_ < input_.size() ? input_[at_++] : 0; }

private:
    Bytes input_;
    std::size_t at_ = 0;
};

// The input's bytes in hex.
std::string hex(Bytes input) {
    std::string out;
    for (const std::uint8_t b : input) {
        out += fmt::format("{:02x}", b);
    }
    return out;
}

long peak_megabytes() {
    rusage use{};
    getrusage(RUSAGE_SELF, &use);
    return use.ru_maxrss / 1024;
}

} // namespace argv_target

std::vector<std::string> argv_command_line(Bytes input, std::string* non_finite) {
    argv_target::ByteReader bytes(input);
    const auto& all = argv_target::commands();
    const cli::CommandWords& c = all[bytes.next() % all.size()];
    std::vector<std::string> args;
    std::istringstream words(c.path);
    for (std::string w; words >> w;) {
        args.push_back(w);
    }
    // The positionals first (each may be left out), then options while bytes last: a byte picks
    // a flag or a valued option, the next its value.
    for (const std::string& type : c.positionals) {
        const std::uint8_t b = bytes.next();
        if (b % 8 != 7) {
            args.push_back(argv_target::value_for(type, static_cast<std::uint8_t>(b / 8), true));
        }
    }
    const std::size_t choices = c.flags.size() + c.valued.size();
    const int options = bytes.next() % 6;
    for (int n = 0; bytes.more() && n < options && choices > 0; ++n) {
        const std::uint8_t b = bytes.next();
        const std::size_t pick = b % choices;
        if (pick < c.flags.size()) {
            const std::string& flag = c.flags[pick];
            // --help and --version end the line before anything is run: one time in eight
            if ((flag == "-h" || flag == "--help" || flag == "--version") && b / choices % 8 != 0) {
                continue;
            }
            args.push_back(flag);
        } else {
            const auto& [name, type] = c.valued[pick - c.flags.size()];
            args.push_back(name);
            args.push_back(argv_target::value_for(type, bytes.next()));
            if (non_finite != nullptr && argv_target::is_number_type(type) &&
                argv_target::names_non_finite(args.back())) {
                *non_finite = name;
            }
        }
    }
    return args;
}

void fuzz_argv(Bytes input) {
    static const argv_target::Scratch scratch;
    std::string non_finite; // a number option given NaN or an infinity
    const std::vector<std::string> args = argv_command_line(input, &non_finite);
    // The line as a shell takes it, and the input that makes it (to keep as a file).
    const std::string line =
        argv_target::shown(args) + " (input hex " + argv_target::hex(input) + ")";
    const bool help = std::any_of(args.begin(), args.end(), [](const std::string& a) {
        return a == "-h" || a == "--help" || a == "--version";
    });
    scratch.refresh();
    const auto start = std::chrono::steady_clock::now();
    const bool parsed_only = !args.empty() && argv_target::parse_only(args.front());
    const int code = parsed_only ? argv_target::parse_in(args) : scratch.run_in(args, true);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (std::getenv("PARSONS_ARGV_VERBOSE") != nullptr) { // each line, its exit and time
        std::fprintf(stderr, "exit %d %.2fs %s\n", code, seconds, line.c_str());
    }
    if (code != 0 && code != 2 && code != 3) {
        std::ifstream err(scratch.io / "stderr");
        std::string said;
        std::getline(err, said);
        throw Finding(fmt::format("argv: {}: exit {} ({})", line, code, said));
    }
    // Every number option refuses NaN and the infinities (issue 53): whatever else the line
    // holds, it cannot be taken.
    if (!non_finite.empty() && !help && code != 2) {
        throw Finding(fmt::format("argv: {}: {} took a value that is no finite number (exit {})",
                                  line, non_finite, code));
    }
    if (seconds > argv_target::kMostSeconds) {
        throw Finding(fmt::format("argv: {}: took {:.1f} s", line, seconds));
    }
    if (argv_target::peak_megabytes() > argv_target::kMostMegabytes) {
        throw Finding(
            fmt::format("argv: {}: the process passed {} MB", line, argv_target::kMostMegabytes));
    }
}

} // namespace parsons::fuzz
