// The tapping job in the CLI (decks/tapping_job.hpp; spindle synchronisation, an addition after
// EP 0360190, Mitsubishi): generating it (`parsons gen tapping`) and running it with its proof
// (`parsons run DECK --thread-proof JOB`, thread_proof.hpp).
#pragma once

#include "axes/machine_profile.hpp"
#include "cli/commands.hpp"
#include "cli/support/cli11_fwd.hpp"
#include "decks/tapping_job.hpp"

#include <string>

namespace parsons::cli {

// A tapping deck generated (and, if output is not empty, written: DECK, DECK.job.json and
// DECK.profile.json, the profile to run it under).
struct GeneratedTappingJob {
    decks::TappingJob job;
    decks::TappingDeck deck;
    axes::MachineProfile profile;
    std::string job_file; // where the job description went; "" for nowhere
};

// `base`: the profile the job's profile starts from (parsons-extended). Throws
// cardreader::DeckError (exit 2) when the plate cannot be tapped or a file cannot be written.
// `job_out`: --job-out (job_file_for); the job's profile goes beside the job description.
GeneratedTappingJob generate_tapping_job(const decks::TappingOptions& options,
                                         const axes::MachineProfile& base,
                                         const std::string& output, const std::string& to,
                                         const std::string& job_out = {});

void add_tapping_command(CLI::App& gen, Command& selected);

} // namespace parsons::cli
