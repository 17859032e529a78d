// The outputs of `parsons run` (cli/run_outputs.hpp): the table, and the one output that is the
// command's own, the saved state (it names the command that resumes from it).
#include "cli/run_outputs.hpp"

#include "axes/json_text.hpp"
#include "axes/profile_json.hpp"
#include "axes/state_json.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/file_plan.hpp"
#include "outputs/output_file.hpp"
#include "outputs/plots/plot_output.hpp"
#include "outputs/proofs/cut_output.hpp"
#include "outputs/proofs/proof_outputs.hpp"
#include "outputs/replay/replay_output.hpp"
#include "outputs/report/report_output.hpp"
#include "outputs/traces/gcode_path.hpp"
#include "outputs/traces/trace_output.hpp"
#include "outputs/traces/trace_outputs.hpp"
#include "outputs/traces/vcd_trace_output.hpp"

#include <fmt/format.h>

namespace parsons::cli {
namespace {

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

// Keeps the tracer's values current (a saved state writes them) and nothing else: the cabinet
// may still fast-forward.
class KeepsValues : public relaylogic::MachineObserver {
public:
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
};

// --save-state FILE: on a stop, the machine state to --resume from.
class SavedStateOutput : public Output {
public:
    explicit SavedStateOutput(RunSetup& s)
        : request_(s.request), applied_(s.applied), faults_(s.fault_specs), cabinet_(s.cabinet) {}
    // A state to be saved needs the signal values kept: an observer that wants nothing more.
    relaylogic::MachineObserver* observer() override { return &values_kept_; }
    void finish(RunEnd& end) override {
        const RunRequest& f = request_;
        if (end.result.stop) {
            write_file(f.save_state, axes::json_text(state_json(end.result, cabinet_.resume_point(),
                                                                applied_, faults_, f),
                                                     1) +
                                         "\n");
        } else if (!f.quiet) {
            fmt::print(message_stream(),
                       "  state          the deck completed: no state to save ({} not written)\n",
                       f.save_state);
        }
    }

private:
    const RunRequest& request_;
    const AppliedProfile& applied_;
    std::vector<std::string> faults_;
    relaylogic::ControlCabinet& cabinet_;
    KeepsValues values_kept_;
};

// Where the five axes stand before the first card (a resumed run: where the state left them).
std::array<double, 5> real_positions(const relaylogic::ControlCabinet& cabinet) {
    std::array<double, 5> real{};
    for (std::size_t i = 0; i < real.size() && i < cabinet.circuits().size(); ++i) {
        real.at(i) = cabinet.circuits()[i]->plant.real_in_at(cabinet.now());
    }
    return real;
}

std::string deck_name(const RunRequest& f) {
    return f.input == "-" ? std::string("standard input") : f.input;
}

} // namespace

const std::vector<RunOutputOption>& run_output_options() {
    using Made = std::unique_ptr<Output>;
    static const std::vector<RunOutputOption> table{
        {"--trace", [](const RunRequest& f) { return !f.trace.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<VcdTraceOutput>(s.request.trace,
                                                     gtkwave_save_file_for(s.request.trace),
                                                     real_positions(s.cabinet));
         },
         true},
        {"--events", [](const RunRequest& f) { return !f.events.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<TraceOutput<EventsJsonlWriter>>(s.request.events);
         },
         true},
        {"--path", [](const RunRequest& f) { return !f.path.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<TraceOutput<PathCsvWriter>>(s.request.path);
         },
         true},
        {"-o", [](const RunRequest& f) { return !f.gcode.empty(); }, // convert DECK -o path.ngc
         [](RunSetup& s) -> Made {
             return std::make_unique<TraceOutput<GcodePathWriter>>(s.request.gcode,
                                                                   deck_name(s.request));
         },
         true},
        {"--plot", [](const RunRequest& f) { return !f.plot.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<PlotOutput>(s.request.plot, s.request.input);
         }},
        {"--cut", [](const RunRequest& f) { return !f.cut.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<CutOutput>(s.request.cut, *s.job, s.applied.profile());
         }},
        {"--press-proof", [](const RunRequest& f) { return !f.press_proof.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<PressProofOutput>(*s.press_job, s.applied.profile());
         }},
        {"--thread-proof", [](const RunRequest& f) { return !f.thread_proof.empty(); },
         [](RunSetup& s) -> Made {
             return std::make_unique<ThreadProofOutput>(*s.tapping_job, s.applied.profile(),
                                                        s.request.thread_tolerance_percent,
                                                        s.cabinet);
         }},
        {"--report", [](const RunRequest& f) { return !f.report.empty(); },
         [](RunSetup& s) -> Made { return std::make_unique<ReportOutput>(s.request.report); }},
        // The replay page, or the embedder's recording (the exhibit page) with no page.
        {"--html", [](const RunRequest& f) { return !f.html.empty() || f.timeline != nullptr; },
         [](RunSetup& s) -> Made {
             return std::make_unique<ReplayOutput>(s.request.timeline, s.request.html,
                                                   s.request.input, s.applied.profile(), s.job);
         }},
        {"--save-state", [](const RunRequest& f) { return !f.save_state.empty(); },
         [](RunSetup& s) -> Made { return std::make_unique<SavedStateOutput>(s); }},
    };
    return table;
}

} // namespace parsons::cli
