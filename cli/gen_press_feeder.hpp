// The press-feeder job in the CLI (decks/press_feeder_job.hpp; press synchronisation, an
// addition after EP 0436887, Mitsubishi): generating it (`parsons gen press-feeder`, with the
// speed-only variant's timing found by running it) and proving it (`parsons run DECK
// --press-proof JOB`, press_proof.cpp).
#pragma once

#include "axes/machine_profile.hpp"
#include "cli/commands.hpp"
#include "cli/support/cli11_fwd.hpp"
#include "decks/press_feeder_job.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <string>
#include <vector>

namespace parsons::cli {

// A press-feeder deck generated (and, if output is not empty, written: DECK, DECK.job.json and
// DECK.profile.json, the profile to run it under).
struct GeneratedPressJob {
    decks::PressFeederJob job;
    decks::PressFeederDeck deck;
    axes::MachineProfile profile;
    // The crank angles at which the position deck's feeder enters the die zone, on the insert
    // and on the take-out, at the nominal press speed (the speed-only variant is timed to them).
    double insert_entry_deg = 0;
    double takeout_entry_deg = 0;
    int revolutions_per_cycle = 1;
    std::string job_file; // where the job description went; "" for nowhere
};

// `base`: the profile the job's profile starts from (parsons-extended). Throws
// cardreader::DeckError (exit 2) when the geometry cannot make the job or a file cannot be
// written.
// `job_out`: --job-out (job_file_for); the job's profile goes beside the job description.
GeneratedPressJob generate_press_job(decks::PressFeederOptions options,
                                     const axes::MachineProfile& base, const std::string& output,
                                     const std::string& to, const std::string& job_out = {});

// Runs cards under a profile (fast-forward unless an observer follows impulses).
relaylogic::RunResult run_cards(const std::vector<cardreader::CardOrders>& cards,
                                const axes::MachineProfile& profile,
                                relaylogic::MachineObserver* observer);

void add_press_feeder_command(CLI::App& gen, Command& selected);

} // namespace parsons::cli
