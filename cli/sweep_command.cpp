// parsons sweep: one deck family over a grid of generator options and profile values, each case
// generated and run by parsons itself (`parsons gen`, then `parsons run`) as child processes,
// as many at once as --jobs says; one CSV row a case, in the grid's order (docs/performance.md,
// "Sweeps"). The machine model is single-threaded; a sweep is parallel by deck.
//
// The keys are checked before any case runs: each must be an option of `gen FAMILY` (without
// its dashes) or profile.SECTION...KEY, a key the profile has; each value is parsed by gen's own
// command line, and each profile value applied to the profile and loaded as a run would load it.
// A key or value refused there is exit 2 naming it, and nothing runs. A combination that only
// its case refuses (two values each fine alone) is that case's row: status "refused", its
// message, and exit 2 once every case has run.
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/support/child_process.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/file_plan.hpp"
#include "cli/support/operator_stop.hpp"
#include "cli/support/progress_line.hpp"
#include "cli/support/sweep_grid.hpp"
#include "cli/support/sweep_keys.hpp"
#include "outputs/output_file.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sched.h>
#include <set>
#include <sstream>
#include <sys/wait.h>
#include <thread>

namespace parsons::cli {

namespace {

using cardreader::DeckError;
using nlohmann::json;
namespace fs = std::filesystem;

struct SweepOptions {
    std::string family;
    std::vector<std::string> sets;
    std::vector<std::string> varies;
    std::string cases_in;
    std::string cases_out;
    std::string output;
    int jobs = 0; // 0: one a core
    bool quiet = false;
};

// Where a sweep's cases go and what each child writes.
struct CaseFiles {
    std::string dir, deck, job, made_profile, profile, report, cut, out, err;
    explicit CaseFiles(const std::string& scratch, long number)
        : dir((fs::path(scratch) / fmt::format("case-{}", number)).string()),
          deck(dir + "/deck.cbn"), job(deck + ".job.json"), made_profile(deck + ".profile.json"),
          profile(dir + "/profile.json"), report(dir + "/report.json"), cut(dir + "/cut.svg"),
          out(dir + "/out.txt"), err(dir + "/err.txt") {}
};

// The arguments of the case's run: its deck, the report, and what its family proves.
std::vector<std::string> run_args(const std::string& family, const CaseFiles& f,
                                  const std::string& profile) {
    std::vector<std::string> args = {"run", f.deck, "--report", f.report, "-q"};
    if (family == "press-feeder" || family == "tapping") {
        args.insert(args.end(), {"--profile", f.made_profile,
                                 family == "tapping" ? "--thread-proof" : "--press-proof", f.job});
        return args;
    }
    if (!profile.empty()) {
        args.insert(args.end(), {"--profile", profile});
    }
    if (family == "airfoil" || family == "two-tool") {
        args.insert(args.end(), {"--cut", f.cut});
    }
    return args;
}

// The last words a child said on standard error, without "parsons: "; a line that ends in a
// colon with the first indented line after it ("thread proof: wrong pitch in 6 of 6 holes: hole
// 1 ...").
std::string last_words(const std::string& err_file) {
    std::ifstream in(err_file);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    std::string last;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (lines[i].empty() || lines[i].rfind("  ", 0) == 0) {
            continue;
        }
        last = lines[i];
        if (last.back() == ':' && i + 1 < lines.size() && lines[i + 1].rfind("  ", 0) == 0) {
            last += " " + lines[i + 1].substr(lines[i + 1].find_first_not_of(' '));
        }
    }
    for (const char* prefix : {"parsons: error: ", "parsons: "}) {
        if (last.rfind(prefix, 0) == 0) {
            return last.substr(std::string(prefix).size());
        }
    }
    return last;
}

struct CaseResult {
    int exit_code = 0;
    std::string status; // completed, stopped, proof failed, refused, failed
    std::string stop_reason, stop_card, cards_read, machine_seconds, gouge, leftover, message;
};

std::string number_text(const json& v) {
    return v.is_number() ? v.dump() : std::string();
}

// The largest of `key` over the cut proof (a wing's root and tip each have one).
std::string cut_figure(const json& cut, const char* key) {
    if (cut.contains(key)) {
        return number_text(cut.at(key));
    }
    double most = -1;
    for (const char* end : {"root", "tip"}) {
        if (cut.contains(end) && cut.at(end).contains(key) && cut.at(end).at(key).is_number()) {
            most = std::max(most, cut.at(end).at(key).get<double>());
        }
    }
    return most < 0 ? std::string() : json(most).dump();
}

CaseResult read_result(int exit_code, const CaseFiles& f) {
    CaseResult r;
    r.exit_code = exit_code;
    json report;
    if (exit_code == 0 || exit_code == 3) {
        std::ifstream in(f.report);
        report = json::parse(in, nullptr, false);
    }
    if (!report.is_object()) {
        r.status = exit_code == 2 ? "refused" : "failed";
        r.message = last_words(f.err);
        if (r.message.empty()) {
            r.message = fmt::format("parsons run ended with exit {}", exit_code);
        }
        return r;
    }
    r.cards_read = number_text(report.value("cards_read", json()));
    r.machine_seconds = number_text(report.value("machine_seconds", json()));
    const json stop = report.value("stop", json());
    if (stop.is_object()) {
        r.status = "stopped";
        r.stop_reason = stop.value("reason", "");
        r.stop_card = number_text(stop.value("card", json()));
        r.message = stop.value("message", "");
    } else {
        r.status = exit_code == 0 ? "completed" : "proof failed";
        r.message = exit_code == 0 ? std::string() : last_words(f.err);
    }
    const json cut = report.value("cut", json());
    if (cut.is_object()) {
        r.gouge = cut_figure(cut, "max_gouge_in");
        r.leftover = cut_figure(cut, "max_leftover_in");
    }
    return r;
}

// A case that gen (or the sweep, for its profile) refused: no run.
CaseResult refused(int exit_code, std::string message) {
    CaseResult r;
    r.exit_code = exit_code;
    r.status = exit_code == 2 ? "refused" : "failed";
    r.message = message.empty() ? fmt::format("parsons gen ended with exit {}", exit_code)
                                : std::move(message);
    return r;
}

std::string result_row(const SweepCase& c, const CaseResult& r) {
    std::string row = fmt::format("{},{}", c.number, csv_field(c.family));
    for (const std::string& v : c.values) {
        row += ',';
        row += csv_field(v);
    }
    for (const std::string& field :
         {std::to_string(r.exit_code), r.status, r.stop_reason, r.stop_card, r.cards_read,
          r.machine_seconds, r.gouge, r.leftover, r.message}) {
        row += ',';
        row += csv_field(field);
    }
    return row + "\n";
}

// The cores this process may run on (taskset, a container's cpuset), at least 1.
int cores_to_run_on() {
#ifndef __EMSCRIPTEN__ // the page has no affinity (and runs no sweep:
                       // cli/support/child_process.hpp)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof(set), &set) == 0 && CPU_COUNT(&set) > 0) {
        return CPU_COUNT(&set);
    }
#endif
    return static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
}

// One case on its way: which of its two children runs.
struct Running {
    std::size_t index = 0;
    bool generating = true;
    std::unique_ptr<CaseFiles> files;
    std::string run_profile;
    std::string refusal; // the case refused before any child ran
};

// Runs every case, `jobs` at a time; the results in the grid's order. An operator's signal
// stops the children (SIGTERM, each removes its own temporary files) and ends the sweep.
class Sweep {
public:
    Sweep(const SweepGrid& grid, std::vector<KeyUse> uses, const std::string& scratch, int jobs,
          bool quiet)
        : grid_(grid), uses_(std::move(uses)), scratch_(scratch), jobs_(jobs),
          results_(grid.cases.size()), progress_(!quiet) {}

    // nullopt when every case ran; else the exit code of the operator's stop.
    std::optional<ExitCode> run(const OperatorStop& stop) {
        std::size_t next = 0;
        std::map<pid_t, Running> running;
        while (next < grid_.cases.size() || !running.empty()) {
            while (stop.signal() == 0 && next < grid_.cases.size() &&
                   running.size() < static_cast<std::size_t>(jobs_)) {
                Running r = start_case(next++);
                if (!r.refusal.empty()) {
                    finish(r, refused(2, r.refusal));
                    continue;
                }
                const pid_t pid = start_parsons(gen_command(r), r.files->out, r.files->err);
                running.emplace(pid, std::move(r));
            }
            const ChildEnd end = stop.signal() == 0 ? wait_for_child() : ChildEnd{};
            if (stop.signal() != 0) {
                end_children(running, end);
                return stop.interrupted_exit();
            }
            const auto it = running.find(end.pid);
            if (it == running.end()) {
                continue; // interrupted by a signal that is no stop, or no child of ours
            }
            Running r = std::move(it->second);
            running.erase(it);
            if (r.generating && end.exit_code == 0) {
                r.generating = false;
                const auto args = run_args(grid_.cases[r.index].family, *r.files, r.run_profile);
                const pid_t pid = start_parsons(args, r.files->out, r.files->err);
                running.emplace(pid, std::move(r));
                continue;
            }
            finish(r, r.generating ? refused(end.exit_code, last_words(r.files->err))
                                   : read_result(end.exit_code, *r.files));
        }
        progress_.clear();
        return std::nullopt;
    }
    const std::vector<CaseResult>& results() const { return results_; }

private:
    void finish(const Running& r, CaseResult result) {
        results_[r.index] = std::move(result);
        std::error_code ec;
        fs::remove_all(r.files->dir, ec);
        ++done_;
        progress_.show(static_cast<double>(done_) / static_cast<double>(results_.size()),
                       fmt::format("case {} of {}", done_, results_.size()));
    }
    Running start_case(std::size_t index) {
        const SweepCase& c = grid_.cases[index];
        Running r;
        r.index = index;
        r.files = std::make_unique<CaseFiles>(scratch_, c.number);
        std::error_code ec;
        fs::create_directory(r.files->dir, ec);
        if (ec) {
            throw DeckError::in_file(r.files->dir,
                                     "cannot make the case's folder: " + ec.message());
        }
        CLI::App& family = *gen_.family(c.family);
        r.run_profile = base_profile(family, uses_, c.values);
        const bool profile_values = std::any_of(uses_.begin(), uses_.end(),
                                                [](const KeyUse& u) { return u.profile_value; });
        if (profile_values) {
            std::string text;
            try {
                text = case_profile(r.run_profile, uses_, c.values);
            } catch (const DeckError& e) {
                r.refusal = e.what(); // a profile key of another base profile than the first's
                return r;
            }
            write_file(r.files->profile, text);
            r.run_profile = r.files->profile;
        }
        return r;
    }
    std::vector<std::string> gen_command(const Running& r) const {
        std::vector<std::string> args = {"gen"};
        const auto more = gen_args(grid_.cases[r.index].family, uses_, grid_.cases[r.index].values);
        args.insert(args.end(), more.begin(), more.end());
        args.insert(args.end(), {"-o", r.files->deck});
        if (r.run_profile == r.files->profile) {
            args.insert(args.end(), {"--profile", r.files->profile});
        }
        return args;
    }
    static void end_children(std::map<pid_t, Running>& running, const ChildEnd& ended) {
        running.erase(ended.pid);
        for (const auto& [pid, r] : running) {
            ::kill(pid, SIGTERM);
        }
        for (const auto& [pid, r] : running) {
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
        }
    }

    const SweepGrid& grid_;
    std::vector<KeyUse> uses_;
    std::string scratch_;
    int jobs_;
    std::vector<CaseResult> results_;
    std::size_t done_ = 0;
    GenCommandLine gen_;
    ProgressLine progress_;
};

std::string results_csv(const SweepGrid& grid, const std::vector<CaseResult>& results) {
    std::string out = "case,family";
    for (const std::string& k : grid.keys) {
        out += ',';
        out += csv_field(k);
    }
    out += ",exit,status,stop_reason,stop_card,cards_read,machine_seconds,max_gouge_in,"
           "max_leftover_in,message\n";
    for (std::size_t i = 0; i < grid.cases.size(); ++i) {
        out += result_row(grid.cases[i], results[i]);
    }
    return out;
}

SweepGrid grid_asked(const SweepOptions& o) {
    if (!o.cases_in.empty()) {
        if (!o.family.empty() || !o.sets.empty() || !o.varies.empty()) {
            throw DeckError("sweep: --cases gives the family and every key's value; FAMILY, "
                            "--set and --vary go with the grid they would make, not with it");
        }
        return read_cases(o.cases_in);
    }
    if (o.family.empty()) {
        throw DeckError("sweep: a FAMILY (airfoil, two-tool, press-feeder, tapping, gcode) or "
                        "--cases FILE is required");
    }
    std::vector<SweepKey> keys;
    for (const std::string& s : o.sets) {
        keys.push_back(parse_set(s));
    }
    for (const std::string& s : o.varies) {
        keys.push_back(parse_vary(s));
    }
    return expand_grid(o.family, keys);
}

ExitCode run_sweep(const SweepOptions& o) {
    if (o.output.empty() && o.cases_out.empty()) {
        throw DeckError("sweep: -o RESULTS.csv (run the cases) or --cases-out CASES.csv (write "
                        "them only) is required");
    }
    FilePlan plan;
    plan.read("--cases", o.cases_in);
    plan.write("--cases-out", o.cases_out);
    plan.write("-o", o.output);
    plan.check();
    if (!o.output.empty() && !parsons_executable_registered()) {
        throw DeckError("sweep: runs parsons itself for each case, and this program is not the "
                        "parsons executable");
    }
    const SweepGrid grid = grid_asked(o);
    // From here a signal stops the sweep in order: its scratch folder is removed.
    OperatorStop stop;
    ScratchFolder scratch("parsons-sweep");
    GenCommandLine gen;
    std::vector<KeyUse> uses = check_grid(gen, grid, scratch.path());
    if (stop.signal() != 0) {
        say(stderr, "parsons: sweep: stopped by the operator; no results written\n");
        return stop.interrupted_exit();
    }
    if (!o.cases_out.empty()) {
        write_file(o.cases_out, grid_csv(grid));
    }
    if (o.output.empty()) {
        if (!o.quiet) {
            say(message_stream(),
                fmt::format("sweep: {} cases of gen {} written to {}\n", grid.cases.size(),
                            grid.cases.front().family, o.cases_out));
        }
        return ExitCode::ok;
    }
    const int jobs = o.jobs > 0 ? o.jobs : 2 * cores_to_run_on();
    const auto start = std::chrono::steady_clock::now();
    // Opened before any case runs, so that an output that cannot be written wastes no run.
    OutputFile results(o.output);
    Sweep sweep(grid, std::move(uses), scratch.path(), jobs, o.quiet);
    if (const auto interrupted = sweep.run(stop)) {
        say(stderr, "parsons: sweep: stopped by the operator; no results written\n");
        return *interrupted;
    }
    stop.restore();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    results.stream() << results_csv(grid, sweep.results());
    results.commit();
    std::map<std::string, std::size_t> count;
    const CaseResult* first_bad = nullptr;
    long first_bad_case = 0;
    for (std::size_t i = 0; i < grid.cases.size(); ++i) {
        const CaseResult& r = sweep.results()[i];
        ++count[r.status];
        if ((r.status == "refused" || r.status == "failed") && first_bad == nullptr) {
            first_bad = &r;
            first_bad_case = grid.cases[i].number;
        }
    }
    if (!o.quiet) {
        say(message_stream(),
            fmt::format("sweep: {} cases of gen {} in {:.2f} s on {} jobs: {} completed, {} "
                        "stopped, {} proof failed, {} refused, {} failed; results in {}\n",
                        grid.cases.size(), grid.cases.front().family, seconds, jobs,
                        count["completed"], count["stopped"], count["proof failed"],
                        count["refused"], count["failed"], o.output));
    }
    if (first_bad != nullptr) {
        say(stderr, fmt::format("parsons: error: sweep: {} of {} cases {} (the first, case {}: "
                                "{}); their rows say why\n",
                                count["refused"] + count["failed"], grid.cases.size(),
                                count["failed"] > 0 ? "failed or were refused" : "were refused",
                                first_bad_case, first_bad->message));
        return count["failed"] > 0 ? ExitCode::internal : ExitCode::bad_input;
    }
    return ExitCode::ok;
}

} // namespace

void add_sweep_command(CLI::App& app, Command& selected) {
    auto o = std::make_shared<SweepOptions>();
    CLI::App* cmd = app.add_subcommand(
        "sweep", "Generate and run one deck family over a grid of gen options and profile "
                 "values, on every core: one CSV row a case (stop, machine time, the cut's "
                 "gouge and leftover)");
    std::vector<std::string> families; // gen's generators, registered before sweep
    for (const CLI::App* sub : app.get_subcommand("gen")->get_subcommands({})) {
        families.push_back(sub->get_name());
    }
    cmd->add_option("FAMILY", o->family, "The generator: one of parsons gen's (not with --cases)")
        ->check(CLI::IsMember(families));
    cmd->add_option("--set", o->sets,
                    "KEY=VALUE for every case: a gen option without its dashes (chord=6, "
                    "naca=2412) or a profile value (profile.axes.table.acceleration_in_per_s2=0.3)")
        ->type_name("KEY=VALUE");
    cmd->add_option("--vary", o->varies,
                    "KEY=V1,V2,... or KEY=A:B:N (N values from A to B): the grid is every "
                    "combination, the first --vary varying slowest")
        ->type_name("KEY=VALUES");
    cmd->add_option("--cases", o->cases_in,
                    "Run the cases of this CSV (as --cases-out writes it; any of its rows) "
                    "instead of a grid")
        ->type_name("FILE.csv");
    cmd->add_option("--cases-out", o->cases_out,
                    "Write the grid's cases as CSV (to split and run anywhere); without -o, "
                    "nothing runs")
        ->type_name("FILE.csv");
    cmd->add_option("-o,--output", o->output,
                    "The results: one CSV row a case, in the grid's order")
        ->type_name("FILE.csv");
    cmd->add_option("--jobs", o->jobs,
                    "Cases at once (default: two a core this process may run on, so that a core "
                    "is busy while another case's processes start and end)")
        ->check(CLI::Range(1, 1024));
    cmd->add_flag("-q,--quiet", o->quiet, "No summary line and no progress line");
    cmd->footer(
        exit_codes_help({{ExitCode::ok, "every case ran (a machine stop is a case's result, "
                                        "in its row)"},
                         {ExitCode::interrupted, "stopped with Ctrl-C (no results written)"},
                         {ExitCode::terminated, "stopped by SIGTERM (no results written)"}}) +
        "A case that gen or run refused (a combination of values) is its row's status "
        "\"refused\", and the sweep ends with exit 2 after writing every row (1 if a case "
        "failed: a bug). docs/performance.md, Sweeps.\n\n"
        "Examples:\n"
        "  parsons sweep airfoil --set naca=2412 --vary cutter-radius=0.125,0.25 --vary "
        "scallop=0.001:0.004:4 -o results.csv\n"
        "  parsons sweep airfoil --set naca=2412 --vary profile.axes.table.backlash_in=0:0.004:5 "
        "-o backlash.csv\n"
        "  parsons sweep airfoil --vary chord=4:8:1000 --cases-out cases.csv   (then split it "
        "and run each part with --cases)");
    cmd->callback([&selected, o] { selected = [o] { return run_sweep(*o); }; });
}

} // namespace parsons::cli
