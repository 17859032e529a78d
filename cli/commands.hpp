// The subcommands of `parsons`. Each add_*_command registers its flags on the app and, when
// its subcommand is chosen, sets `selected` to the function that runs it. Running throws
// cardreader::DeckError for bad input (exit 2); the function returns the exit code otherwise.
#pragma once

#include "cli/exit_codes.hpp"
#include "cli/support/cli11_fwd.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/file_plan.hpp"

#include "axes/machine_profile.hpp"
#include "decks/job_file.hpp"
#include "decks/two_tool_job.hpp"
#include "relaylogic/control_cabinet.hpp"

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
// `timeline` (may be null): recorded on every run the command line starts (the page's hook),
// attached as run's replay output (cli/run_outputs.cpp).
void add_run_command(CLI::App& app, Command& selected, RunTimeline* timeline = nullptr);
void add_profile_command(CLI::App& app, Command& selected);
void add_gen_command(CLI::App& app, Command& selected);
// gen gcode (cli/gen_gcode.cpp): a subcommand of gen.
void add_gen_gcode_command(CLI::App& gen, Command& selected);
void add_demo_command(CLI::App& app, Command& selected);
void add_bench_command(CLI::App& app, Command& selected);
void add_check_command(CLI::App& app, Command& selected);
// parsons sweep (cli/sweep_command.cpp): runs parsons itself, so only from the executable.
void add_sweep_command(CLI::App& app, Command& selected);

// --strict, on every command that reads a G-code program (today gen gcode): the words the
// reader would ignore with a warning are refused instead (decks::GcodeReading; docs/gcode.md).
// Defined with the command line (cli/command_line.cpp), so that each such command has it alike.
void add_strict_flag(CLI::App& cmd, bool& strict);

// What `parsons run` is asked to do (the flags of docs/design-rules.md, Interfaces).
struct RunRequest {
    std::string input;
    std::string report;
    std::string trace;
    std::string events;
    std::string path;
    std::string gcode; // the path as G-code (convert DECK -o path.ngc)
    std::string html;  // the run as one self-contained replay page (outputs/replay/replay_page.hpp)
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
    // Not a flag: a run that stops or whose proof objects on purpose (the demo's press job on
    // speed alone, its tapping with a stale ratio): the exit code says so as ever, and the
    // caller tells the finding in its own story, so nothing is said on standard error.
    bool finding_expected = false;
    // Not a flag: where an embedder (the WebAssembly page, web/parsons_web.cpp) wants the run
    // recorded for its viewer; null from the command line.
    RunTimeline* timeline = nullptr;
    // Not a flag: where the benchmark wants the run's time split by phase of the card cycle
    // (relaylogic/phase_clock.hpp); null from the command line.
    relaylogic::PhaseClock* phases = nullptr;
};
// The result of the run goes to *result too, if given (the benchmark counts its impulses).
ExitCode run_deck(const RunRequest& request, relaylogic::RunResult* result = nullptr);

// A deck generated and written: DECK, its job description (DECK.job.json, or --job-out) and (if
// named) the centres CSV.
struct GeneratedJob {
    decks::JobDescription description;
    decks::TemplateDeck deck; // the template job
    decks::WingDeck wing;     // the wing job
    std::size_t cards = 0;
    std::string job_file; // where the job description went; "" for nowhere
};

// The files a generator reads and writes, to compare before it writes anything
// (cli/support/file_plan.hpp): --profile's file, the deck (-o), its job description (job_file_for)
// and, for a press or tapping job, the profile beside that. The caller adds what else it reads or
// writes, then checks.
FilePlan generator_plan(const std::string& profile, const std::string& output,
                        const std::string& job_out, bool writes_profile);

// --job-out FILE, for every generator: where the job description goes (by default beside the
// deck, DECK.job.json, when the deck is a file; a deck to standard output or a device has none).
void add_job_out_option(CLI::App& cmd, std::string& job_out);

// What a generator's summary says it wrote: "d.cbn, d.cbn.job.json and c.csv"; for a deck with
// no job description, why and how to have one.
std::string files_written(const std::string& deck, const std::string& job_file,
                          const std::string& also = {}, const std::string& and_also = {});
class ProgressLine;
// Punches the generated cards into `output` (format from its name or `to`) through the one
// output writer; a card the keypunch refuses is a DeckError naming `command` and the card.
// `progress` (may be null): shows the punching.
cardreader::DeckFingerprint write_cards(const std::vector<cardreader::CardOrders>& cards,
                                        const std::string& output, const std::string& to,
                                        ProgressLine* progress,
                                        const char* command = "gen airfoil");
// `progress` (may be null): where to show how far the generator is (gen on a terminal).
// `job_out`: --job-out (job_file_for).
GeneratedJob generate_job(const decks::JobDescription& description,
                          const axes::MachineProfile& profile, const std::string& output,
                          const std::string& to, const std::string& centres,
                          ProgressLine* progress = nullptr, const std::string& job_out = {});

// A two-tool deck generated and written (DECK and its job description, DECK.job.json or
// --job-out), for gen and demo.
struct GeneratedTwoToolJob {
    decks::JobDescription description;
    decks::TwoToolDeck deck;
    std::string job_file; // where the job description went; "" for nowhere
};
// `airfoil`: "naca 2412" or "dat PATH"; `job_out`: --job-out (job_file_for). Throws
// cardreader::DeckError (exit 2) when the job cannot be made or written.
GeneratedTwoToolJob generate_two_tool_job(const std::string& airfoil, bool closed_te,
                                          const decks::TwoToolOptions& options,
                                          const axes::MachineProfile& profile,
                                          const std::string& output, const std::string& to,
                                          const std::string& job_out = {});

} // namespace parsons::cli
