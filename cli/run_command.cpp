// parsons run DECK: feed the deck through the emulated control cabinet and the five axes.
//
// Exit 0: the deck completed. Exit 3: the machine stopped itself (a check fired: a correct
// emulation). Exit 2: the deck or a flag could not be read. Every output file is written
// whole or not at all.
#include "cli/commands.hpp"
#include "cli/run_outputs.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/data_files.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/deck_prediction.hpp"
#include "cli/support/file_plan.hpp"
#include "cli/support/job_files.hpp"
#include "cli/support/operator_stop.hpp"
#include "cli/support/progress_line.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output.hpp"
#include "outputs/output_file.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "outputs/report/run_report.hpp"

#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"
#include "decks/job_file.hpp"
#include "decks/press_feeder_job.hpp"
#include "decks/tapping_job.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <unistd.h>
#include <utility>

namespace parsons::cli {
namespace {

using cardreader::DeckError;

// The job description a run reads: --job, or the one beside the deck for --cut (which needs it)
// and --html (which draws its design when there is one); "" for none.
std::string job_file_read(const RunRequest& f) {
    if (!f.job.empty()) {
        return f.cut.empty() && f.html.empty() && f.timeline == nullptr ? "" : f.job;
    }
    const std::string beside = f.input + ".job.json";
    if (!f.cut.empty()) {
        return beside;
    }
    // The replay page draws the cut of a job that has one; the job file of a press feeder or
    // a tapping plate beside the deck is for its proof (--press-proof, --thread-proof).
    std::error_code ec; // a name the system cannot look up is no job file beside the deck
    if ((!f.html.empty() || f.timeline != nullptr) && f.input != "-" &&
        std::filesystem::is_regular_file(beside, ec)) {
        const std::string text = read_text_file(beside);
        return decks::is_press_job(text) || decks::is_tapping_job(text) ? "" : beside;
    }
    return "";
}

// Every file the run reads and writes, compared before anything is written
// (cli/support/file_plan.hpp): the files named on the command line.
FilePlan run_plan(const RunRequest& f) {
    FilePlan plan;
    plan.read("DECK", f.input);
    plan.read("--profile", AppliedProfile::file_read(f.profile));
    plan.read("--resume", f.resume);
    plan.read("--press-proof", f.press_proof);
    plan.read("--thread-proof", f.thread_proof);
    plan.read(f.job.empty() ? "the job description beside DECK" : "--job", job_file_read(f));
    plan.write("--report", f.report);
    plan.write("--trace", f.trace);
    plan.write("the GTKWave save file beside --trace", gtkwave_save_file_for(f.trace));
    plan.write("--events", f.events);
    plan.write("--path", f.path);
    plan.write("-o", f.gcode); // convert DECK -o path.ngc
    plan.write("--html", f.html);
    plan.write("--plot", f.plot);
    plan.write("--cut", f.cut);
    plan.write("--save-state", f.save_state);
    return plan;
}

// A progress line on stderr, only when stderr is a terminal: how far through the deck file.
class ProgressBar : public relaylogic::MachineObserver {
public:
    ProgressBar(InputDeck& deck, bool wanted) : deck_(deck), line_(wanted) {}
    bool shown() const { return line_.shown(); }
    void on_card(double t, std::int64_t index, const cardreader::CardOrders& /*orders*/) override {
        line_.show(deck_.fraction_read(), fmt::format("card {}  machine time {:.1f} s", index, t));
    }
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
    void on_finish(double /*t*/) override { line_.clear(); }

private:
    InputDeck& deck_;
    ProgressLine line_;
};

// A saved state is the JSON object marked "parsons_state" (docs/reliability.md); any other file
// (a run report, a profile) is refused as what it is not, before a key of it is read.
nlohmann::json read_state(const std::string& file) {
    const std::string text = read_text_file(file, "cannot open the saved state");
    nlohmann::json state;
    try {
        state = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw DeckError::in_file(
            file, fmt::format("not a saved state: not valid JSON at byte {}", e.byte));
    }
    if (!state.is_object() || !state.contains("parsons_state")) {
        const bool report = state.is_object() && state.contains("schema_version") &&
                            state.contains("stop") && state.contains("cards");
        throw DeckError::in_file(
            file, fmt::format("not a saved state{} (--resume takes the file 'parsons run DECK "
                              "--save-state FILE' wrote, marked \"parsons_state\")",
                              report ? ": it is a run report" : ""));
    }
    return state;
}

} // namespace

// An output named for another format than the one written: said, not silently mislabelled.
void warn_format(const std::string& path, const std::string& option, const char* format,
                 std::initializer_list<const char*> extensions, const char* advice) {
    if (path.empty() || path == "-") {
        return;
    }
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const char* known : extensions) {
        if (ext == known) {
            fmt::print(stderr,
                       "parsons: warning: {} writes {}: {} will hold {}, whatever its "
                       "name says ({})\n",
                       option, format, path, format, advice);
            return;
        }
    }
}

// A word for the shell, quoted only where it needs to be.
static std::string shell_word(const std::string& word) {
    const bool plain =
        !word.empty() &&
        word.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghij"
                               "klmnopqrstuvwxyz0123456789_./-=:+") == std::string::npos;
    if (plain) {
        return word;
    }
    std::string quoted = "'";
    for (char c : word) {
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return quoted + "'";
}

// After a stop with --save-state: that the state was written, and the command that resumes
// from it once the deck is corrected (the state carries the profile and the faults).
static void say_how_to_resume(const RunRequest& f) {
    if (f.save_state.empty() || f.save_state == "-" || f.input == "-") {
        return;
    }
    std::string command =
        "parsons run " + shell_word(f.input) + " --resume " + shell_word(f.save_state);
    if (!f.deck.format.empty() && f.deck.format != "auto") {
        command += " --format " + shell_word(f.deck.format);
    }
    if (f.deck.code != "029") {
        command += " --code " + shell_word(f.deck.code);
    }
    if (f.deck.layout != "fig8") {
        command += " --layout " + shell_word(f.deck.layout);
    }
    fmt::print(stderr,
               "parsons: the machine state is saved in {}; correct the deck, then resume with:\n"
               "  {}\n",
               f.save_state, command);
}

// Before a resumed run: which deck the state was saved from when it is not this one, a warning
// when the cards the stopped run had machined are not the same cards now, and where each
// limit comes from.
static void say_what_resumes(const nlohmann::json& state, const AppliedProfile& applied,
                             const RunRequest& f) {
    const std::string saved_deck = state.contains("deck") && state.at("deck").is_string()
                                       ? state.at("deck").get<std::string>()
                                       : std::string();
    if (!f.quiet || (!saved_deck.empty() && saved_deck != f.input)) {
        fmt::print(stderr, "parsons: resuming {} from {}{}\n", f.input, f.resume,
                   saved_deck.empty() || saved_deck == f.input
                       ? std::string()
                       : fmt::format(" (saved from another deck: {})", saved_deck));
    }
    const nlohmann::json machined = state.value("cards_machined", nlohmann::json());
    if (machined.is_object() && f.input != "-") {
        const std::int64_t cards = machined.value("cards", std::int64_t{0});
        const std::string was = machined.value("fingerprint", std::string());
        const auto now = fingerprint_deck(f.input, f.deck, cards);
        if (now.cards() == cards && now.hex() != was) {
            fmt::print(stderr,
                       "parsons: warning: cards 1 to {} of {} are not the cards the stopped run "
                       "machined (fingerprint {}, saved {}): the part was cut by the old ones\n",
                       cards, f.input, now.hex(), was);
        }
    }
    if (!f.quiet) {
        for (const std::string& line : applied.limit_lines()) {
            fmt::print(stderr, "  {}\n", line);
        }
    }
}

namespace {

// Pictures and traces named for another format than the one written: said.
void warn_formats(const RunRequest& f) {
    for (const auto& [path, option] : {std::pair{f.plot, "--plot"}, std::pair{f.cut, "--cut"}}) {
        warn_format(path, option, "SVG", {".png", ".jpg", ".jpeg", ".gif", ".pdf", ".eps", ".ps"},
                    "name it .svg; rsvg-convert or any browser turns SVG into PNG or PDF");
    }
    warn_format(f.trace, "--trace", "VCD", {".fst", ".ghw", ".lxt", ".lxt2", ".vzt", ".fsdb"},
                "name it .vcd; GTKWave's vcd2fst turns it into FST");
}

// Flags that cannot go together, or a tolerance out of range: refused before anything is read.
void refuse_flag_combinations(const RunRequest& f) {
    if (!f.resume.empty() && !f.press_proof.empty()) {
        throw DeckError("--press-proof with --resume: the proof follows the press from the start "
                        "of the job, so it proves whole runs only (run the deck from its first "
                        "card)");
    }
    if (!f.resume.empty() && !f.thread_proof.empty()) {
        throw DeckError("--thread-proof with --resume: the proof judges each hole from the tap's "
                        "first turn and the job's from its first card, so it proves whole runs "
                        "only (run the deck from its first card)");
    }
    if (!f.job.empty() && f.cut.empty() && f.html.empty() && f.timeline == nullptr) {
        throw DeckError("--job: the job description is read only for --cut (and the design "
                        "--html draws); give --cut FILE.svg or --html FILE.html with it, or "
                        "leave --job out");
    }
    if (f.thread_tolerance_percent && f.thread_proof.empty()) {
        throw DeckError("--thread-tolerance: give it with --thread-proof JOB (the tolerance of "
                        "the thread proof)");
    }
    if (f.thread_tolerance_percent &&
        !(*f.thread_tolerance_percent > 0 && *f.thread_tolerance_percent < 100)) {
        throw DeckError(fmt::format("--thread-tolerance {}: give a percentage of the pitch, more "
                                    "than 0 and less than 100",
                                    *f.thread_tolerance_percent));
    }
}

// What a run reads before the machine starts: the saved state it resumes, the profile and faults
// it applies, and the job descriptions its cut, page and proofs are judged against.
struct RunInputs {
    nlohmann::json state;
    std::vector<std::string> fault_specs;
    AppliedProfile applied;
    std::optional<decks::PressFeederJob> press_job;
    std::optional<decks::TappingJob> tapping_job;
    std::optional<decks::JobDescription> job; // for --cut, and --html's design
};

// A resumed run takes the profile and the faults the state was saved with (its --limit
// widens or narrows the movement range, as an operator would before going on).
void read_profile_and_faults(const RunRequest& f, RunInputs& in) {
    in.fault_specs = f.faults;
    if (f.resume.empty()) {
        in.applied = AppliedProfile::load(f.profile);
        return;
    }
    if (!f.profile.empty() || !f.faults.empty()) {
        throw DeckError("--resume: the saved state carries its machine profile and faults; "
                        "give --limit to change the movement range, not --profile or --fault");
    }
    in.state = read_state(f.resume);
    try {
        in.applied = AppliedProfile::from_state(in.state, f.resume);
        in.fault_specs = axes::read<std::vector<std::string>>(in.state, "faults");
    } catch (const std::exception& e) {
        throw DeckError::in_file(f.resume, e.what());
    }
}

// The proofs' jobs (--press-proof, --thread-proof); with no --profile, a run takes the profile
// written beside the job. Then the files the jobs name: their profiles, and the airfoil a
// template job is cut against.
void read_jobs(const RunRequest& f, FilePlan& plan, RunInputs& in) {
    if (!f.press_proof.empty()) {
        in.press_job = read_press_job(f.press_proof);
        if (f.profile.empty() && f.resume.empty() && !in.press_job->profile_file.empty()) {
            in.applied = AppliedProfile::load(in.press_job->profile_file);
        }
    }
    if (!f.thread_proof.empty()) {
        in.tapping_job = read_tapping_job(f.thread_proof);
        if (f.profile.empty() && f.resume.empty() && !in.press_job &&
            !in.tapping_job->profile_file.empty()) {
            in.applied = AppliedProfile::load(in.tapping_job->profile_file);
        }
    }
    if (in.press_job && in.applied.file() == in.press_job->profile_file) {
        plan.read("the profile of --press-proof", in.press_job->profile_file);
    }
    if (in.tapping_job && in.applied.file() == in.tapping_job->profile_file) {
        plan.read("the profile of --thread-proof", in.tapping_job->profile_file);
    }
    const std::string job_file = job_file_read(f);
    if (!job_file.empty()) {
        in.job = read_job(job_file, f.input, f.deck);
        plan.read("the airfoil file of the job", airfoil_file_read(in.job->airfoil));
    }
}

// The cabinet before its first card: the faults injected, the state resumed, and what the run
// needs kept (the resume point for --save-state, the card times for --report).
void prepare_cabinet(relaylogic::ControlCabinet& cabinet, const RunRequest& f,
                     const std::vector<relaylogic::Fault>& faults, const nlohmann::json& state) {
    for (const auto& fault : faults) {
        cabinet.add_fault(fault);
    }
    if (!f.resume.empty()) {
        try {
            cabinet.resume(axes::member(state, "resume"));
        } catch (const std::exception& e) {
            throw DeckError::in_file(f.resume, std::string("not a machine state parsons can "
                                                           "resume: ") +
                                                   e.what());
        }
    }
    cabinet.keep_resume_point(!f.save_state.empty());
    cabinet.set_pace(f.impulse_level ? relaylogic::Pace::impulse_level
                                     : relaylogic::Pace::fast_forward);
    cabinet.record_card_times(!f.report.empty());
}

// Every output the run asks for, made in the table's order (cli/run_outputs.hpp). An output
// that opens its file when made is where an operator's signal can end the wait for a FIFO's
// reader: the run then ends before any card (nullopt, and `code` says how).
std::optional<std::vector<std::unique_ptr<Output>>>
make_outputs(RunSetup& setup, const OperatorStop& operator_stop, ExitCode& code) {
    std::vector<std::unique_ptr<Output>> made;
    for (const RunOutputOption& option : run_output_options()) {
        if (!option.wanted(setup.request)) {
            continue;
        }
        try {
            made.push_back(option.make(setup));
        } catch (const DeckError& e) {
            if (!option.opens_when_made || operator_stop.signal() == 0) {
                throw;
            }
            fmt::print(stderr,
                       "parsons: interrupted while opening the outputs, before any card: {}\n",
                       e.what());
            code = operator_stop.interrupted_exit();
            return std::nullopt;
        }
    }
    return made;
}

// The run is over: a trace whose reader went away stopped the machine, and the run ends there,
// quietly, leaving no other output of a run nobody asked to stop. Else every output is
// finished in the table's order, and the summary printed with what the outputs added.
void finish_outputs(const std::vector<std::unique_ptr<Output>>& outputs,
                    const relaylogic::RunResult& result, const AppliedProfile& applied,
                    const RunRequest& f) {
    for (const auto& output : outputs) {
        if (const std::string gone = output->gone(); !gone.empty()) {
            throw BrokenPipe(gone);
        }
    }
    nlohmann::json report = report_json(result, applied.profile(), applied.describe(), f.input);
    std::string summary;
    RunEnd end{result, report, summary};
    for (const auto& output : outputs) {
        output->finish(end);
    }
    if (!f.quiet) {
        fmt::print(message_stream(), "{}{}", summary_text(result, f.input, applied.profile().name),
                   summary);
    }
}

// The exit code: a stop (the operator's or the machine's), else the first proof that objects.
ExitCode verdict(const relaylogic::RunResult& result,
                 const std::vector<std::unique_ptr<Output>>& outputs,
                 const OperatorStop& operator_stop, const RunRequest& f) {
    if (result.stop && result.stop->reason == relaylogic::StopReason::interrupted) {
        fmt::print(stderr, "parsons: interrupted: {}\n", result.stop->message);
        say_how_to_resume(f);
        return operator_stop.interrupted_exit();
    }
    if (result.stop) {
        if (!f.finding_expected) {
            fmt::print(stderr, "parsons: machine stop: {}: {}\n",
                       relaylogic::stop_reason_name(result.stop->reason), result.stop->message);
            say_how_to_resume(f);
        }
        return ExitCode::machine_stop;
    }
    for (const auto& output : outputs) {
        if (const std::string objection = output->objection(); !objection.empty()) {
            if (!f.finding_expected) {
                fmt::print(stderr, "{}", objection);
            }
            return ExitCode::machine_stop;
        }
    }
    return ExitCode::ok;
}

} // namespace

ExitCode run_deck(const RunRequest& f, relaylogic::RunResult* out) {
    if (f.phases != nullptr) {
        f.phases->start(relaylogic::Phase::setup);
    }
    FilePlan plan = run_plan(f);
    plan.check(); // before anything is read at length or written
    warn_formats(f);
    refuse_flag_combinations(f);
    RunInputs in;
    read_profile_and_faults(f, in);
    read_jobs(f, plan, in);
    plan.check();
    in.applied.apply_limits(f.limits);
    axes::MachineProfile& profile = in.applied.profile();
    const std::vector<relaylogic::Fault> faults = parse_faults(in.fault_specs);
    InputDeck deck(f.input, f.deck);
    apply_feed(profile, f.feed, deck.options());
    {
        // Condition cards (an addition), before any motion: the deck read through once.
        const relaylogic::InPhase reading(f.phases, relaylogic::Phase::read_decode);
        refuse_condition_errors(deck, profile);
    }
    if (!f.resume.empty()) {
        say_what_resumes(in.state, in.applied, f);
    }
    relaylogic::ControlCabinet cabinet(profile, *deck.options().layout);
    prepare_cabinet(cabinet, f, faults, in.state);

    // Ctrl-C and SIGTERM stop the machine at its next event; the outputs are then written
    // whole, as after any stop. Caught from here on: opening a FIFO waits for its reader, and
    // a signal then ends the wait (and the run, before any card) instead of killing parsons.
    OperatorStop operator_stop;
    RunSetup setup{f,
                   in.applied,
                   in.fault_specs,
                   in.job ? &*in.job : nullptr,
                   in.press_job,
                   in.tapping_job,
                   cabinet};
    ExitCode code = ExitCode::ok;
    const auto outputs = make_outputs(setup, operator_stop, code);
    if (!outputs) {
        return code;
    }
    relaylogic::ObserverFanOut observers;
    for (const auto& output : *outputs) {
        if (relaylogic::MachineObserver* observer = output->observer()) {
            observers.add(observer);
        }
    }
    ProgressBar progress(deck, !f.quiet);
    if (progress.shown()) {
        observers.add(&progress);
    }
    if (!observers.empty()) {
        cabinet.attach(observers.attachable());
    }

    cabinet.watch_interrupt(operator_stop.flag());
    cabinet.time_phases(f.phases);
    const relaylogic::RunResult result = cabinet.run(deck.cards());
    operator_stop.restore();
    if (out != nullptr) {
        *out = result;
    }
    finish_outputs(*outputs, result, in.applied, f);
    code = verdict(result, *outputs, operator_stop, f);
    if (f.phases != nullptr) {
        f.phases->stop();
    }
    return code;
}

void add_run_command(CLI::App& app, Command& selected, RunTimeline* timeline) {
    auto flags = std::make_shared<RunRequest>();
    flags->timeline = timeline;
    CLI::App* cmd = app.add_subcommand(
        "run", "Run a deck through the emulated control cabinet and five lead-screw axes");
    cmd->add_option("DECK", flags->input, "The deck to run")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--report", flags->report, "Write the run report as JSON")
        ->type_name(file_value({"json"}));
    cmd->add_option("--trace", flags->trace,
                    "Write every relay, switch and lamp and the axes' real positions as a VCD "
                    "trace, and beside it a GTKWave save file (T.gtkw for T.vcd: gtkwave T.gtkw)")
        ->type_name(file_value({"vcd"}));
    cmd->add_option("--events", flags->events, "Write one JSON object per signal change")
        ->type_name(file_value({"jsonl"}));
    cmd->add_option("--html", flags->html,
                    "Write the run as one self-contained HTML page that replays it: the cabinet's "
                    "relays, counters and lamps and the cutter's path, on machine time (opens "
                    "from disk, no server)")
        ->type_name(file_value({"html"}));
    cmd->add_option("--path", flags->path, "Write machine time and the five real positions, CSV")
        ->type_name(file_value({"csv"}));
    cmd->add_option("--plot", flags->plot, "Draw positions and speed positions against time, SVG")
        ->type_name(file_value({"svg"}));
    cmd->add_option("--cut", flags->cut,
                    "Sweep the cutter along the path the axes really took and draw the cut "
                    "against the design, SVG (generated decks)")
        ->type_name(file_value({"svg"}));
    cmd->add_option("--job", flags->job,
                    "The job description for --cut and --html's design (default DECK.job.json); "
                    "refused without one of them")
        ->type_name(file_value({"json"}));
    cmd->add_option("--press-proof", flags->press_proof,
                    "Prove a press-feeder job (gen press-feeder's DECK.job.json): the feeder never "
                    "inside the die zone while the die is below its safe height; a collision is "
                    "exit 3")
        ->type_name(file_value({"json"}));
    cmd->add_option("--thread-proof", flags->thread_proof,
                    "Prove a tapping job (gen tapping's DECK.job.json): the pitch each hole was "
                    "cut with against its tap's; a hole beyond the tolerance is exit 3")
        ->type_name(file_value({"json"}));
    cmd->add_option("--thread-tolerance", flags->thread_tolerance_percent,
                    "The thread proof's tolerance, percent of the tap's pitch (default: the "
                    "job's, 5)");
    cmd->add_option("--fault", flags->faults,
                    "Inject a fault (repeatable; docs/faults.md): drop-impulse:AXIS:N, "
                    "stuck-relay:AXIS:BANK:DIGIT, dead-relay:AXIS:BANK:DIGIT, "
                    "skip-step:AXIS:SWITCH:N, feed-twice:N, swap-cards:N, short-card:N, "
                    "slip:AXIS:N:M, stale-ratio:N, transfer-hang:N")
        ->type_name("FAULT");
    cmd->add_option("--profile", flags->profile, "Machine profile JSON (see 'parsons profile')")
        ->type_name(std::string(kProfileValue));
    cmd->add_option("--feed", flags->feed,
                    "cards (separate cards, a feed gap each) or ribbon (Fig. 9: cards end to end, "
                    "no gap); a tape deck always feeds as a ribbon")
        ->check(CLI::IsMember({"cards", "ribbon"}));
    cmd->add_option("--limit", flags->limits,
                    "Soft limits of the job, AXIS=MIN:MAX inches (e.g. table=0:9.5): the machine "
                    "stops with soft_limit before the part passes one")
        ->type_name("AXIS=MIN:MAX");
    cmd->add_flag("-q,--quiet", flags->quiet, "No summary and no progress bar");
    cmd->add_option("--save-state", flags->save_state,
                    "On a stop (or Ctrl-C), write the machine state as JSON: where it stopped, "
                    "and the machine as the stopped card was fed, to --resume from")
        ->type_name(file_value({"json"}));
    cmd->add_option("--resume", flags->resume,
                    "Resume from a saved state: the deck (corrected) is read again from the "
                    "card the machine stopped on")
        ->type_name(file_value({"json"}));
    cmd->add_flag("--impulse-level", flags->impulse_level,
                  "Take every commutator impulse one by one (the reference) instead of "
                  "fast-forwarding between comparer equalities; the result is the same");
    add_input_flags(*cmd, flags->deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck completed"},
                                 {ExitCode::machine_stop,
                                  "the machine stopped itself (a check fired; docs/stop-codes.md), "
                                  "or --press-proof found a collision, or --thread-proof a wrong "
                                  "pitch"},
                                 {ExitCode::interrupted, "stopped by the operator with Ctrl-C"},
                                 {ExitCode::terminated, "stopped by SIGTERM"}}) +
                "Examples:\n"
                "  parsons run decks/samples/patent-example.csv --report report.json\n"
                "  parsons run decks/samples/patent-example.csv --trace run.vcd --plot run.svg\n"
                "  parsons run decks/samples/patent-example.csv --fault drop-impulse:table:120   "
                "(a missed impulse "
                "stops it: exit 3)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_deck(*flags); }; });
}

} // namespace parsons::cli
