// The subcommands of `parsons`. Each add_*_command registers its flags on the app and, when
// its subcommand is chosen, sets `selected` to the function that runs it. Running throws
// cardreader::DeckError for bad input (exit 2); the function returns the exit code otherwise.
#pragma once

#include "cli/deck_files.hpp"
#include "cli/exit_codes.hpp"

#include "axes/machine_profile.hpp"
#include "decks/job_file.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

class RunTimeline;
using Command = std::function<ExitCode()>;

void add_punch_command(CLI::App& app, Command& selected);
void add_convert_command(CLI::App& app, Command& selected);
void add_show_command(CLI::App& app, Command& selected);
// `timeline` (may be null): recorded on every run the command line starts (the page's hook).
void add_run_command(CLI::App& app, Command& selected, RunTimeline* timeline = nullptr);
void add_profile_command(CLI::App& app, Command& selected);
void add_gen_command(CLI::App& app, Command& selected);
// gen gcode (cli/gen_gcode.cpp): a subcommand of gen.
void add_gen_gcode_command(CLI::App& gen, Command& selected);
void add_demo_command(CLI::App& app, Command& selected);
void add_bench_command(CLI::App& app, Command& selected);
void add_check_command(CLI::App& app, Command& selected);

// What `parsons run` is asked to do (the flags of docs/design-rules.md, Interfaces).
struct RunRequest {
    std::string input;
    std::string report;
    std::string trace;
    std::string events;
    std::string path;
    std::string gcode; // the path as G-code (convert DECK -o path.ngc)
    std::string html;  // the run as one self-contained replay page (cli/replay_page.hpp)
    std::string plot;
    std::string cut;
    std::string job;
    std::string press_proof;  // the press-feeder job file to prove the run against
    std::string thread_proof; // the tapping job file to prove the run's threads against
    std::optional<double> thread_tolerance_percent; // --thread-tolerance (else the job's)
    std::string profile;
    std::string feed; // cards | ribbon; empty: as the profile (and the deck's format) say
    std::vector<std::string> faults;
    std::vector<std::string> limits;
    std::string save_state;
    std::string resume;
    bool quiet = false;
    bool impulse_level = false;
    DeckFlags deck;
    // Not a flag: where an embedder (the WebAssembly page, web/parsons_web.cpp) wants the run
    // recorded for its viewer; null from the command line.
    RunTimeline* timeline = nullptr;
};
// The result of the run goes to *result too, if given (the benchmark counts its impulses).
ExitCode run_deck(const RunRequest& request, relaylogic::RunResult* result = nullptr);

// A deck generated and written: DECK, DECK.job.json and (if named) the centres CSV.
struct GeneratedJob {
    decks::JobDescription description;
    decks::TemplateDeck deck; // the template job
    decks::WingDeck wing;     // the wing job
    std::size_t cards = 0;
};
class ProgressLine;
// Punches the generated cards into `output` (format from its name or `to`) through the one
// output writer; a card the keypunch refuses is a DeckError naming `command` and the card.
// `progress` (may be null): shows the punching.
cardreader::DeckFingerprint write_cards(const std::vector<cardreader::CardOrders>& cards,
                                        const std::string& output, const std::string& to,
                                        ProgressLine* progress,
                                        const char* command = "gen airfoil");
// `progress` (may be null): where to show how far the generator is (gen on a terminal).
GeneratedJob generate_job(const decks::JobDescription& description,
                          const axes::MachineProfile& profile, const std::string& output,
                          const std::string& to, const std::string& centres,
                          ProgressLine* progress = nullptr);

} // namespace parsons::cli
