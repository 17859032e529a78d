// The press and thread proofs as outputs of a run (run --press-proof JOB, --thread-proof JOB):
// each adds its block to the report and its lines to the summary, and objects (exit 3) when it
// finds the job wrong though the machine ran as it should.
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/press_feeder_job.hpp"
#include "decks/tapping_job.hpp"
#include "outputs/output.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <optional>
#include <string>

namespace parsons::cli {

class PressProofOutput : public Output {
public:
    // Throws DeckError when `profile` has no press synchronisation.
    PressProofOutput(const decks::PressFeederJob& job, const axes::MachineProfile& profile);
    relaylogic::MachineObserver* observer() override { return &proof_; }
    void finish(RunEnd& end) override;
    std::string objection() const override;

private:
    decks::PressFeederJob job_;
    PressProof proof_;
};

class ThreadProofOutput : public Output {
public:
    // Throws DeckError when `profile` has no spindle synchronisation; has `cabinet` record the
    // tool's samples through each tap. `profile` must outlive the run.
    ThreadProofOutput(const decks::TappingJob& job, const axes::MachineProfile& profile,
                      std::optional<double> tolerance_percent, relaylogic::ControlCabinet& cabinet);
    void finish(RunEnd& end) override;
    std::string objection() const override;

private:
    decks::TappingJob job_;
    const axes::MachineProfile& profile_;
    std::optional<double> tolerance_percent_;
    std::optional<ThreadProof> proof_;
};

} // namespace parsons::cli
