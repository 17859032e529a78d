// The outputs of `parsons run`, as a table: each output option with the test of whether a run
// asks for it and the factory of its output (outputs/output.hpp). run_command.cpp makes the
// outputs a run asks for in the table's order, attaches them, and finishes them in that order
// with the result; adding an output is one entry here and its class in outputs/.
#pragma once

#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "outputs/output.hpp"

#include "decks/job_file.hpp"
#include "decks/press_feeder_job.hpp"
#include "decks/tapping_job.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

// What an output's factory may read: the request, the machine as the run applies it, the job
// descriptions read for the run, and the cabinet before its first card.
struct RunSetup {
    const RunRequest& request;
    AppliedProfile& applied;
    const std::vector<std::string>&
        fault_specs;                  // as the run applies them (a resumed run: the state's)
    const decks::JobDescription* job; // --cut's and --html's, null for none
    const std::optional<decks::PressFeederJob>& press_job;
    const std::optional<decks::TappingJob>& tapping_job;
    relaylogic::ControlCabinet& cabinet;
};

struct RunOutputOption {
    const char* option; // as `parsons run --help` names it
    bool (*wanted)(const RunRequest& request);
    std::unique_ptr<Output> (*make)(RunSetup& setup);
    // Opens its file when made (a FIFO waits there for its reader): an operator's signal that
    // ends the wait ends the run before any card.
    bool opens_when_made = false;
};

// In the order the outputs are made and finished: the traces, the plot, the cut and the proofs
// (which add to the report), the report, the replay page (which embeds the report), the state.
const std::vector<RunOutputOption>& run_output_options();

} // namespace parsons::cli
