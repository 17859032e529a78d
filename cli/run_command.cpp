// parsons run DECK: feed the deck through the emulated control cabinet and the five axes.
//
// Exit 0: the deck completed. Exit 3: the machine stopped itself (a check fired: a correct
// emulation). Exit 2: the deck or a flag could not be read. Every output file is written
// whole or not at all.
#include "cli/applied_profile.hpp"
#include "cli/commands.hpp"
#include "cli/data_files.hpp"
#include "cli/deck_files.hpp"
#include "cli/file_plan.hpp"
#include "cli/progress_line.hpp"
#include "outputs/output_file.hpp"
#include "outputs/plots/plot_svg.hpp"
#include "outputs/proofs/cutter_paths.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "outputs/proofs/two_tool_proof.hpp"
#include "outputs/replay/replay_page.hpp"
#include "outputs/replay/run_timeline.hpp"
#include "outputs/report/run_report.hpp"
#include "outputs/traces/gcode_path.hpp"
#include "outputs/traces/trace_outputs.hpp"

#include "axes/profile_json.hpp"
#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"
#include "decks/cut_proof.hpp"
#include "decks/cut_svg.hpp"
#include "decks/job_file.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <memory>
#include <optional>
#include <sstream>
#include <unistd.h>
#include <utility>

namespace parsons::cli {
namespace {

using cardreader::DeckError;

// A trace written to a file while the machine runs; the file takes its name only when
// complete (OutputFile), so a failed run leaves none.
template <typename Writer>
class TraceFile {
public:
    template <typename... Args>
    void open(const std::string& path, relaylogic::ObserverFanOut& observers, Args&&... args) {
        if (path.empty()) {
            return;
        }
        file_ = std::make_unique<OutputFile>(path);
        writer_ = std::make_unique<Writer>(file_->stream(), std::forward<Args>(args)...);
        observers.add(writer_.get());
    }
    void commit() {
        if (file_) {
            writer_.reset(); // flushes what is buffered
            file_->commit();
        }
    }
    // Its reader went away (a closed pipe): the output it names, else empty.
    std::string gone() const { return file_ && file_->reader_gone() ? file_->name() : ""; }

private:
    std::unique_ptr<OutputFile> file_;
    std::unique_ptr<Writer> writer_;
};

// The job description of a generated deck; refused when it was written for another deck.
decks::JobDescription read_job(const std::string& file, const std::string& deck_path,
                               const DeckFlags& deck_flags) {
    const std::string text =
        read_text_file(file, "cannot open the job description (written by 'parsons gen airfoil' "
                             "beside the deck; or give --job FILE)");
    decks::JobDescription job;
    try {
        job = decks::job_from_json(text);
    } catch (const decks::JobError& e) {
        throw DeckError::in_file(file, e.what());
    }
    if (!job.deck_fingerprint.empty() && deck_path != "-") {
        const cardreader::DeckFingerprint fingerprint = fingerprint_deck(deck_path, deck_flags);
        if (fingerprint.hex() != job.deck_fingerprint) {
            throw DeckError::in_file(
                file, fmt::format("this job description was written for another deck ({} cards, "
                                  "fingerprint {}), not {} ({} cards, fingerprint {}): give the "
                                  "job the deck was generated with (--job FILE)",
                                  job.deck_cards, job.deck_fingerprint, deck_path,
                                  fingerprint.cards(), fingerprint.hex()));
        }
    }
    return job;
}

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
    if ((!f.html.empty() || f.timeline != nullptr) && f.input != "-" &&
        std::filesystem::is_regular_file(beside)) {
        return beside;
    }
    return "";
}

// Every file the run reads and writes, compared before anything is written (cli/file_plan.hpp):
// the files named on the command line.
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
    plan.write("--events", f.events);
    plan.write("--path", f.path);
    plan.write("-o", f.gcode); // convert DECK -o path.ngc
    plan.write("--html", f.html);
    plan.write("--plot", f.plot);
    plan.write("--cut", f.cut);
    plan.write("--save-state", f.save_state);
    return plan;
}

// The replay's design (--html, the page): for an airfoil template job (its job file beside the
// deck, or --job), the section the cut grows against in the table and cross-slide frame.
void add_design(RunTimeline& timeline, const RunRequest& f) {
    const std::string file = job_file_read(f);
    if (file.empty()) {
        return;
    }
    const decks::JobDescription job = read_job(file, f.input, f.deck);
    if (job.kind != decks::JobKind::template_2d || !job.passes.empty()) {
        return; // a wing or two-tool job: the replay shows the path alone
    }
    const auto airfoil = decks::open_airfoil(job);
    const auto samples = decks::design_samples(*airfoil, job.options, job.work_zero_in, 400);
    nlohmann::json points = nlohmann::json::array();
    for (const Eigen::Vector2d& p : samples.points) {
        points.push_back({p.x(), p.y()});
    }
    timeline.set_design({{"airfoil", job.airfoil},
                         {"cutter_radius_in", job.options.cutter_radius_in},
                         {"points", std::move(points)}});
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

// Keeps the tracer's values current (a saved state writes them) and nothing else: the cabinet
// may still fast-forward.
class KeepsValues : public relaylogic::MachineObserver {
public:
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
};

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_operator_signal(int signal) {
    g_signal = signal;
}

// SIGINT and SIGTERM, caught for the length of a run.
class OperatorStop {
public:
    OperatorStop() {
        g_signal = 0;
        give_up_on_signal(&g_signal);
        stop_on_broken_pipe(&g_signal);
        struct sigaction action {};
        action.sa_handler = on_operator_signal;
        sigemptyset(&action.sa_mask);
        sigaction(SIGINT, &action, &old_int_);
        sigaction(SIGTERM, &action, &old_term_);
    }
    ~OperatorStop() { restore(); }
    OperatorStop(const OperatorStop&) = delete;
    OperatorStop& operator=(const OperatorStop&) = delete;
    const volatile std::sig_atomic_t* flag() const { return &g_signal; }
    int signal() const { return g_signal; }
    void restore() {
        if (!restored_) {
            give_up_on_signal(nullptr);
            stop_on_broken_pipe(nullptr);
            sigaction(SIGINT, &old_int_, nullptr);
            sigaction(SIGTERM, &old_term_, nullptr);
            restored_ = true;
        }
    }

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
    bool restored_ = false;
};

nlohmann::json read_state(const std::string& file) {
    const std::string text = read_text_file(file, "cannot open the saved state");
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw DeckError::in_file(file, fmt::format("not valid JSON at byte {}", e.byte));
    }
}

// The saved state: where the machine stopped and why (for the operator), and the machine as
// the card it stopped on was fed (for --resume): the profile and faults it ran with too.
nlohmann::json state_json(const relaylogic::RunResult& r, const nlohmann::json& resume_point,
                          const AppliedProfile& profile, const std::vector<std::string>& faults,
                          const RunRequest& f) {
    nlohmann::json stopped = nlohmann::json::object();
    for (cardreader::Axis a : cardreader::kAxes) {
        const auto& x = r.axes.at(cardreader::axis_index(a));
        stopped[std::string(cardreader::axis_name(a))] = {{"counter_in", x.counter_in},
                                                          {"real_in", x.real_in}};
    }
    const auto& s = *r.stop;
    const std::int64_t resume_card = axes::read<std::int64_t>(resume_point, "cards_read") + 1;
    // The cards the stopped run had machined, so that a resume can tell when they changed.
    nlohmann::json machined = nullptr;
    if (f.input != "-") {
        const auto fingerprint = fingerprint_deck(f.input, f.deck, resume_card - 1);
        machined = {{"cards", fingerprint.cards()}, {"fingerprint", fingerprint.hex()}};
    }
    return nlohmann::json{
        {"parsons_state", 1},
        {"parsons_version", PARSONS_VERSION},
        {"deck", f.input},
        {"cards_machined", machined},
        {"stop",
         {{"reason", relaylogic::stop_reason_name(s.reason)},
          {"card", s.card},
          {"message", s.message},
          {"machine_seconds", r.machine_seconds},
          {"axes_at_rest", stopped}}},
        {"resume_card", resume_card},
        {"profile", nlohmann::json::parse(axes::profile_to_json(profile.profile()))},
        {"profile_applied", profile.describe()},
        {"faults", faults},
        {"resume", resume_point}};
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

ExitCode run_deck(const RunRequest& f, relaylogic::RunResult* out) {
    FilePlan plan = run_plan(f);
    plan.check(); // before anything is read at length or written
    for (const auto& [path, option] : {std::pair{f.plot, "--plot"}, std::pair{f.cut, "--cut"}}) {
        warn_format(path, option, "SVG", {".png", ".jpg", ".jpeg", ".gif", ".pdf", ".eps", ".ps"},
                    "name it .svg; rsvg-convert or any browser turns SVG into PNG or PDF");
    }
    warn_format(f.trace, "--trace", "VCD", {".fst", ".ghw", ".lxt", ".lxt2", ".vzt", ".fsdb"},
                "name it .vcd; GTKWave's vcd2fst turns it into FST");
    // A resumed run takes the profile and the faults the state was saved with (its --limit
    // widens or narrows the movement range, as an operator would before going on).
    nlohmann::json state;
    std::vector<std::string> fault_specs = f.faults;
    AppliedProfile applied;
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
    if (!f.resume.empty()) {
        if (!f.profile.empty() || !f.faults.empty()) {
            throw DeckError("--resume: the saved state carries its machine profile and faults; "
                            "give --limit to change the movement range, not --profile or --fault");
        }
        state = read_state(f.resume);
        try {
            applied = AppliedProfile::from_state(state, f.resume);
            fault_specs = axes::read<std::vector<std::string>>(state, "faults");
        } catch (const std::exception& e) {
            throw DeckError::in_file(f.resume, e.what());
        }
    } else {
        applied = AppliedProfile::load(f.profile);
    }
    // --press-proof: the job's geometry; with no --profile, the profile written beside it.
    std::optional<decks::PressFeederJob> press_job;
    if (!f.press_proof.empty()) {
        press_job = read_press_job(f.press_proof);
        if (f.profile.empty() && f.resume.empty() && !press_job->profile_file.empty()) {
            applied = AppliedProfile::load(press_job->profile_file);
        }
    }
    // --thread-proof: the job's holes; with no --profile, the profile written beside it.
    std::optional<decks::TappingJob> tapping_job;
    if (!f.thread_proof.empty()) {
        tapping_job = read_tapping_job(f.thread_proof);
        if (f.profile.empty() && f.resume.empty() && !press_job &&
            !tapping_job->profile_file.empty()) {
            applied = AppliedProfile::load(tapping_job->profile_file);
        }
    }
    // The files the jobs name: their profiles, and the airfoil a template job is cut against.
    if (press_job && applied.file() == press_job->profile_file) {
        plan.read("the profile of --press-proof", press_job->profile_file);
    }
    if (tapping_job && applied.file() == tapping_job->profile_file) {
        plan.read("the profile of --thread-proof", tapping_job->profile_file);
    }
    decks::JobDescription job;
    const std::string job_file = job_file_read(f); // for --cut, and --html's design
    if (!job_file.empty()) {
        job = read_job(job_file, f.input, f.deck);
        plan.read("the airfoil file of the job", airfoil_file_read(job.airfoil));
    }
    plan.check();
    applied.apply_limits(f.limits);
    axes::MachineProfile& profile = applied.profile();
    std::vector<relaylogic::Fault> faults;
    for (const auto& spec : fault_specs) {
        try {
            faults.push_back(relaylogic::parse_fault(spec));
        } catch (const relaylogic::FaultSpecError& e) {
            throw DeckError(e.what());
        }
    }
    InputDeck deck(f.input, f.deck);
    apply_feed(profile, f.feed, deck.options());
    refuse_condition_errors(deck, profile); // condition cards (an addition): before any motion
    if (!f.resume.empty()) {
        say_what_resumes(state, applied, f);
    }
    relaylogic::ControlCabinet cabinet(profile, *deck.options().layout);
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

    // Ctrl-C and SIGTERM stop the machine at its next event; the outputs are then written
    // whole, as after any stop. Caught from here on: opening a FIFO waits for its reader, and
    // a signal then ends the wait (and the run, before any card) instead of killing parsons.
    OperatorStop operator_stop;
    relaylogic::ObserverFanOut observers;
    TraceFile<VcdWriter> vcd;
    TraceFile<EventsJsonlWriter> events;
    TraceFile<PathCsvWriter> path;
    TraceFile<GcodePathWriter> gcode;
    try {
        vcd.open(f.trace, observers);
        events.open(f.events, observers);
        path.open(f.path, observers);
        gcode.open(f.gcode, observers, f.input == "-" ? std::string("standard input") : f.input);
    } catch (const DeckError& e) {
        if (operator_stop.signal() == 0) {
            throw;
        }
        fmt::print(stderr, "parsons: interrupted while opening the outputs, before any card: {}\n",
                   e.what());
        return operator_stop.signal() == SIGTERM ? ExitCode::terminated : ExitCode::interrupted;
    }
    std::unique_ptr<PlotSvgRecorder> plot;
    if (!f.plot.empty()) {
        plot = std::make_unique<PlotSvgRecorder>(f.input);
        observers.add(plot.get());
    }
    CutterPath cutter;
    std::unique_ptr<WingPath> wing_path;
    std::unique_ptr<ToolPaths> tool_paths; // a two-tool job: the path by the tool that cut it
    if (!f.cut.empty()) {
        if (job.kind == decks::JobKind::wing) {
            wing_path = std::make_unique<WingPath>(job.wing_zero_in, profile);
            observers.add(wing_path.get());
        } else if (!job.passes.empty()) {
            tool_paths = std::make_unique<ToolPaths>(profile.first_tool);
            observers.add(tool_paths.get());
        } else {
            observers.add(&cutter);
        }
    }
    std::unique_ptr<PressProof> press_proof;
    if (press_job) {
        if (!profile.press_sync) {
            throw DeckError(fmt::format("--press-proof: profile {} has no press synchronisation "
                                        "(give --profile {})",
                                        profile.name, press_job->profile_file));
        }
        press_proof =
            std::make_unique<PressProof>(profile.press, press_job->options.zone_edge_x_in,
                                         press_job->options.safe_height_in, press_job->cycle_card);
        observers.add(press_proof.get());
    }
    if (tapping_job) {
        if (!profile.spindle_sync) {
            throw DeckError(fmt::format("--thread-proof: profile {} has no spindle "
                                        "synchronisation (give --profile {})",
                                        profile.name,
                                        tapping_job->profile_file.empty()
                                            ? std::string("parsons-extended")
                                            : tapping_job->profile_file));
        }
        cabinet.record_tap_samples(true);
    }
    // The replay page's recording (--html), or the embedder's.
    std::unique_ptr<RunTimeline> html_timeline;
    RunTimeline* timeline = f.timeline;
    if (timeline == nullptr && !f.html.empty()) {
        html_timeline = std::make_unique<RunTimeline>();
        timeline = html_timeline.get();
    }
    if (timeline != nullptr) {
        timeline->set_machine(profile);
        observers.add(timeline);
        add_design(*timeline, f);
    }
    ProgressBar progress(deck, !f.quiet);
    if (progress.shown()) {
        observers.add(&progress);
    }
    // A state to be saved needs the signal values kept: an observer that wants nothing more.
    KeepsValues values_kept;
    if (!f.save_state.empty()) {
        observers.add(&values_kept);
    }
    if (!observers.empty()) {
        cabinet.attach(observers.attachable());
    }

    cabinet.watch_interrupt(operator_stop.flag());
    const relaylogic::RunResult result = cabinet.run(deck.cards());
    operator_stop.restore();
    if (out != nullptr) {
        *out = result;
    }
    // A trace whose reader went away stopped the machine: the run ends there, quietly, and
    // leaves no other output of a run nobody asked to stop.
    for (const std::string& gone : {vcd.gone(), events.gone(), path.gone(), gcode.gone()}) {
        if (!gone.empty()) {
            throw BrokenPipe(gone);
        }
    }

    vcd.commit();
    events.commit();
    path.commit();
    gcode.commit();
    if (plot) {
        write_file(f.plot, plot->svg());
    }
    nlohmann::json report = report_json(result, applied, f.input);
    std::string cut_summary;
    if (wing_path) {
        const auto airfoil = decks::open_airfoil(job);
        const decks::WingProof proof = decks::prove_wing(wing_path->path, *airfoil, job.wing);
        write_file(f.cut, decks::wing_cut_svg(proof, wing_path->path, job.wing,
                                              fmt::format("{} wing", job.airfoil)));
        report["cut"] = {{"root",
                          {{"max_gouge_in", fine_length(proof.root.max_gouge_in)},
                           {"max_leftover_in", fine_length(proof.root.max_leftover_in)}}},
                         {"tip",
                          {{"max_gouge_in", fine_length(proof.tip.max_gouge_in)},
                           {"max_leftover_in", fine_length(proof.tip.max_leftover_in)}}}};
        cut_summary = fmt::format("  cut            root section: deepest gouge {:.5f} in, most "
                                  "left standing {:.5f} in; tip section: {:.5f} in, {:.5f} in\n",
                                  proof.root.max_gouge_in, proof.root.max_leftover_in,
                                  proof.tip.max_gouge_in, proof.tip.max_leftover_in);
    } else if (tool_paths) {
        try {
            cut_summary = write_two_tool_cut(prove_two_tool_cut(*tool_paths, job, profile), job,
                                             f.cut, report);
        } catch (const decks::JobError& e) {
            throw DeckError(fmt::format("--cut: {}", e.what()));
        }
    } else if (!f.cut.empty()) {
        const auto airfoil = decks::open_airfoil(job);
        const auto samples = decks::design_samples(*airfoil, job.options, job.work_zero_in);
        const decks::DesignContour design{samples.points, samples.toward_cutter};
        const double radius = job.options.cutter_radius_in;
        const auto path = decks::simplify_path(cutter.path, 1e-7);
        const decks::CutProof proof = decks::prove_cut(path, radius, design, 1.5 * radius);
        write_file(f.cut,
                   decks::cut_svg(proof, path, design, radius,
                                  fmt::format("{}: the cut, from the emulated path", job.airfoil)));
        report["cut"] = {{"max_gouge_in", fine_length(proof.max_gouge_in)},
                         {"max_leftover_in", fine_length(proof.max_leftover_in)},
                         {"max_scallop_in", fine_length(proof.max_scallop_in)},
                         {"machined_points", proof.machined_points},
                         {"design_points", design.points.size()}};
        cut_summary = fmt::format("  cut            deepest gouge {:.5f} in, most left standing "
                                  "{:.5f} in, largest scallop {:.5f} in ({} of {} design points "
                                  "machined)\n",
                                  proof.max_gouge_in, proof.max_leftover_in, proof.max_scallop_in,
                                  proof.machined_points, design.points.size());
    }
    if (press_proof) {
        if (!report["press"].is_object()) {
            report["press"] = nlohmann::json::object();
        }
        report["press"].update(press_block(result, *press_proof, *press_job));
        cut_summary += press_summary(result, *press_proof);
    }
    std::optional<ThreadProof> thread_proof;
    if (tapping_job && result.tapping) {
        thread_proof = prove_threads(*result.tapping, *tapping_job, profile.spindle,
                                     f.thread_tolerance_percent);
        if (!report["tapping"].is_object()) {
            report["tapping"] = nlohmann::json::object();
        }
        add_thread_proof(report["tapping"], *thread_proof);
        cut_summary += thread_summary(*thread_proof);
    }
    if (!f.report.empty()) {
        // A deck name that is not UTF-8 is written with U+FFFD for its bad bytes, not refused.
        write_file(f.report,
                   report.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    }
    if (!f.html.empty()) {
        write_file(f.html, replay_page(*timeline, report, f.input));
    }
    if (!f.save_state.empty()) {
        if (result.stop) {
            write_file(f.save_state,
                       state_json(result, cabinet.resume_point(), applied, fault_specs, f)
                               .dump(1, ' ', false, nlohmann::json::error_handler_t::replace) +
                           "\n");
        } else if (!f.quiet) {
            fmt::print(message_stream(),
                       "  state          the deck completed: no state to save ({} not written)\n",
                       f.save_state);
        }
    }
    if (!f.quiet) {
        fmt::print(message_stream(), "{}{}", summary_text(result, f.input, profile.name),
                   cut_summary);
    }
    if (result.stop && result.stop->reason == relaylogic::StopReason::interrupted) {
        fmt::print(stderr, "parsons: interrupted: {}\n", result.stop->message);
        say_how_to_resume(f);
        return operator_stop.signal() == SIGTERM ? ExitCode::terminated : ExitCode::interrupted;
    }
    if (result.stop) {
        fmt::print(stderr, "parsons: machine stop: {}: {}\n",
                   relaylogic::stop_reason_name(result.stop->reason), result.stop->message);
        say_how_to_resume(f);
        return ExitCode::machine_stop;
    }
    if (press_proof && press_proof->collision()) {
        fmt::print(stderr,
                   "parsons: press proof: {} (the emulation ran as it should: the job is "
                   "unsafe)\n",
                   collision_message(*press_proof, press_job->options.safe_height_in,
                                     press_job->options.zone_edge_x_in));
        return ExitCode::machine_stop;
    }
    if (thread_proof && thread_proof->flagged() > 0) {
        const auto lines = wrong_pitch_lines(*thread_proof);
        fmt::print(stderr,
                   "parsons: thread proof: wrong pitch in {} of {} hole{} (the emulation ran as "
                   "it should: the threads are wrong):\n",
                   lines.size(), thread_proof->holes.size(),
                   thread_proof->holes.size() == 1 ? "" : "s");
        for (const std::string& line : lines) {
            fmt::print(stderr, "  {}\n", line);
        }
        return ExitCode::machine_stop;
    }
    return ExitCode::ok;
}

void add_run_command(CLI::App& app, Command& selected, RunTimeline* timeline) {
    auto flags = std::make_shared<RunRequest>();
    flags->timeline = timeline;
    CLI::App* cmd = app.add_subcommand(
        "run", "Run a deck through the emulated control cabinet and five lead-screw axes");
    cmd->add_option("DECK", flags->input, "The deck to run")->required();
    cmd->add_option("--report", flags->report, "Write the run report as JSON");
    cmd->add_option("--trace", flags->trace,
                    "Write every relay, switch and lamp as a VCD trace "
                    "(GTKWave)");
    cmd->add_option("--events", flags->events, "Write one JSON object per signal change");
    cmd->add_option("--html", flags->html,
                    "Write the run as one self-contained HTML page that replays it: the cabinet's "
                    "relays, counters and lamps and the cutter's path, on machine time (opens "
                    "from disk, no server)");
    cmd->add_option("--path", flags->path, "Write machine time and the five real positions, CSV");
    cmd->add_option("--plot", flags->plot, "Draw positions and speed positions against time, SVG");
    cmd->add_option("--cut", flags->cut,
                    "Sweep the cutter along the path the axes really took and draw the cut "
                    "against the design, SVG (generated decks)");
    cmd->add_option("--job", flags->job, "The job description for --cut (default DECK.job.json)");
    cmd->add_option("--press-proof", flags->press_proof,
                    "Prove a press-feeder job (gen press-feeder's DECK.job.json): the feeder never "
                    "inside the die zone while the die is below its safe height; a collision is "
                    "exit 3");
    cmd->add_option("--thread-proof", flags->thread_proof,
                    "Prove a tapping job (gen tapping's DECK.job.json): the pitch each hole was "
                    "cut with against its tap's; a hole beyond the tolerance is exit 3");
    cmd->add_option("--thread-tolerance", flags->thread_tolerance_percent,
                    "The thread proof's tolerance, percent of the tap's pitch (default: the "
                    "job's, 5)");
    cmd->add_option("--fault", flags->faults,
                    "Inject a fault (repeatable; docs/faults.md): drop-impulse:AXIS:N, "
                    "stuck-relay:AXIS:BANK:DIGIT, dead-relay:AXIS:BANK:DIGIT, "
                    "skip-step:AXIS:SWITCH:N, feed-twice:N, swap-cards:N, short-card:N, "
                    "slip:AXIS:N:M, stale-ratio:N, transfer-hang:N");
    cmd->add_option("--profile", flags->profile, "Machine profile JSON (see 'parsons profile')");
    cmd->add_option("--feed", flags->feed,
                    "cards (separate cards, a feed gap each) or ribbon (Fig. 9: cards end to end, "
                    "no gap); a tape deck always feeds as a ribbon")
        ->check(CLI::IsMember({"cards", "ribbon"}));
    cmd->add_option("--limit", flags->limits,
                    "Soft limits of the job, AXIS=MIN:MAX inches (e.g. table=0:9.5): the machine "
                    "stops with soft_limit before the part passes one");
    cmd->add_flag("-q,--quiet", flags->quiet, "No summary and no progress bar");
    cmd->add_option("--save-state", flags->save_state,
                    "On a stop (or Ctrl-C), write the machine state as JSON: where it stopped, "
                    "and the machine as the stopped card was fed, to --resume from");
    cmd->add_option("--resume", flags->resume,
                    "Resume from a saved state: the deck (corrected) is read again from the "
                    "card the machine stopped on");
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
