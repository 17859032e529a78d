// The press and thread proofs as outputs (outputs/proofs/proof_outputs.hpp).
#include "outputs/proofs/proof_outputs.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

namespace parsons::cli {
namespace {

const decks::PressFeederJob& synchronised(const decks::PressFeederJob& job,
                                          const axes::MachineProfile& profile) {
    if (!profile.press_sync) {
        throw cardreader::DeckError(
            fmt::format("--press-proof: profile {} has no press synchronisation "
                        "(give --profile {})",
                        profile.name, job.profile_file));
    }
    return job;
}

} // namespace

PressProofOutput::PressProofOutput(const decks::PressFeederJob& job,
                                   const axes::MachineProfile& profile)
    : job_(synchronised(job, profile)), proof_(profile.press, job_.options.zone_edge_x_in,
                                               job_.options.safe_height_in, job_.cycle_card) {}

void PressProofOutput::finish(RunEnd& end) {
    if (!end.report["press"].is_object()) {
        end.report["press"] = nlohmann::json::object();
    }
    end.report["press"].update(press_block(end.result, proof_, job_));
    end.summary += press_summary(end.result, proof_);
}

std::string PressProofOutput::objection() const {
    if (!proof_.collision()) {
        return {};
    }
    return fmt::format(
        "parsons: press proof: {} (the emulation ran as it should: the job is "
        "unsafe)\n",
        collision_message(proof_, job_.options.safe_height_in, job_.options.zone_edge_x_in));
}

ThreadProofOutput::ThreadProofOutput(const decks::TappingJob& job,
                                     const axes::MachineProfile& profile,
                                     std::optional<double> tolerance_percent,
                                     relaylogic::ControlCabinet& cabinet)
    : job_(job), profile_(profile), tolerance_percent_(tolerance_percent) {
    if (!profile.spindle_sync) {
        throw cardreader::DeckError(fmt::format(
            "--thread-proof: profile {} has no spindle "
            "synchronisation (give --profile {})",
            profile.name,
            job.profile_file.empty() ? std::string("parsons-extended") : job.profile_file));
    }
    cabinet.record_tap_samples(true);
}

void ThreadProofOutput::finish(RunEnd& end) {
    if (!end.result.tapping) {
        return;
    }
    proof_ = prove_threads(*end.result.tapping, job_, profile_.spindle, tolerance_percent_);
    if (!end.report["tapping"].is_object()) {
        end.report["tapping"] = nlohmann::json::object();
    }
    add_thread_proof(end.report["tapping"], *proof_);
    end.summary += thread_summary(*proof_);
}

std::string ThreadProofOutput::objection() const {
    if (!proof_ || proof_->flagged() == 0) {
        return {};
    }
    const auto lines = wrong_pitch_lines(*proof_);
    std::string text =
        fmt::format("parsons: thread proof: wrong pitch in {} of {} hole{} (the "
                    "emulation ran as it should: the threads are wrong):\n",
                    lines.size(), proof_->holes.size(), proof_->holes.size() == 1 ? "" : "s");
    for (const std::string& line : lines) {
        text += fmt::format("  {}\n", line);
    }
    return text;
}

} // namespace parsons::cli
