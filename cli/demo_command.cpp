// parsons demo: the built-in default job. Generate a NACA 2412 template deck for a 6-inch
// chord, run it on the emulated machine, prove the cut, and write everything to one folder.
#include "cli/commands.hpp"
#include "cli/output_file.hpp"

#include "cardreader/card_svg.hpp"
#include "cardreader/layout.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

namespace parsons::cli {
namespace {

ExitCode run_demo(const std::string& dir) {
    make_folder(dir + "/cards");
    decks::JobDescription description;
    description.airfoil = "naca 2412";
    description.options.chord_in = 6.0;
    description.options.cutter_radius_in = 0.25;
    description.options.surface = decks::Surface::upper;
    description.options.scallop_in = 0.002;
    const std::string deck = dir + "/naca2412.cbn";
    const GeneratedJob job =
        generate_job(description, axes::default_profile(), deck, "", dir + "/centres.csv");
    fmt::print("generated {}: NACA 2412 upper surface, 6 in chord, cutter radius 0.25 in, {} "
               "stations (scallop target 0.002 in), {} cards\n",
               deck, job.deck.stations.size(), job.deck.cards.size());
    for (std::size_t i = 0; i < std::min<std::size_t>(3, job.deck.cards.size()); ++i) {
        const auto punched = cardreader::encode(job.deck.cards[i], cardreader::fig8_layout());
        cardreader::CardPictureNotes notes;
        notes.caption = fmt::format("naca2412.cbn · card {} · layout fig8", i + 1);
        write_file(fmt::format("{}/cards/card-{:04}.svg", dir, i + 1),
                   cardreader::card_svg(punched.card, cardreader::fig8_layout(), notes));
    }
    RunRequest run;
    run.input = deck;
    run.report = dir + "/report.json";
    run.trace = dir + "/trace.vcd";
    run.plot = dir + "/plot.svg";
    run.cut = dir + "/cut.svg";
    run.path = dir + "/path.csv";
    const ExitCode code = run_deck(run);
    if (code == ExitCode::machine_stop) {
        // The generator makes the demo's deck to run through: a stop on it is a bug.
        throw std::logic_error("the machine stopped on the demo's own deck");
    }
    fmt::print("\nwrote {0}/naca2412.cbn (+ .job.json), {0}/cards/, {0}/report.json, "
               "{0}/plot.svg, {0}/cut.svg, {0}/trace.vcd (gtkwave), {0}/path.csv, "
               "{0}/centres.csv\n",
               dir);
    return code;
}

} // namespace

void add_demo_command(CLI::App& app, Command& selected) {
    auto dir = std::make_shared<std::string>("out/demo");
    CLI::App* cmd = app.add_subcommand(
        "demo", "The default job: generate a NACA 2412 template deck, run it, prove the cut");
    cmd->add_option("--out", *dir, "Folder for everything the demo writes")->capture_default_str();
    cmd->footer(exit_codes_help({{ExitCode::ok, "the demo ran and its deck completed"},
                                 {ExitCode::interrupted, "stopped by the operator with Ctrl-C"},
                                 {ExitCode::terminated, "stopped by SIGTERM"}}) +
                "Example:\n  parsons demo            (then open out/demo/cut.svg and plot.svg)");
    cmd->callback([&selected, dir] { selected = [dir] { return run_demo(*dir); }; });
}

} // namespace parsons::cli
