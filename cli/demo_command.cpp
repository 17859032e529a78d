// parsons demo: the built-in default job. Generate a NACA 2412 template deck for a 6-inch
// chord, run it on the emulated machine, prove the cut, and write everything to one folder.
// Then the job that shows the point of EP 0640901 (condition cards, an addition): the same
// template roughed and finished with two tools, once with the tool change tripped at the change
// position and once during the return move (decks/two_tool_job.hpp), run under
// parsons-extended; the difference of their machine times is what the seed saves. Then the
// press feeder (EP 0436887) and the tapping job (EP 0360190): a plate tapped with two taps on two
// heads, the gear ratio transferred by PC 130 and stored in advance, and once with a head
// exchange that sends no ratio, which the thread proof names hole by hole.
#include "cli/commands.hpp"
#include "cli/gen_press_feeder.hpp"
#include "cli/gen_tapping.hpp"
#include "outputs/output_file.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "outputs/proofs/two_tool_proof.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/card_svg.hpp"
#include "cardreader/layout.hpp"
#include "cli/support/deck_files.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace parsons::cli {
namespace {

struct TwoToolRun {
    std::string deck;
    decks::TwoToolDeck job;
    relaylogic::RunResult result;
    ExitCode code = ExitCode::ok;
};

TwoToolRun run_two_tool(const std::string& dir, decks::ChangeVariant variant) {
    TwoToolRun r;
    const std::string name = std::string("two-tool-") + std::string(decks::variant_name(variant));
    r.deck = dir + "/" + name + ".csv";
    decks::TwoToolOptions options;
    options.pass.chord_in = 6.0;
    options.pass.scallop_in = 0.002;
    options.variant = variant;
    const auto profile = axes::extended_profile();
    r.job = generate_two_tool_job("naca 2412", false, options, profile, r.deck, "").deck;
    RunRequest run;
    run.input = r.deck;
    run.profile = profile.name;
    run.report = dir + "/" + name + ".report.json";
    run.cut = dir + "/" + name + ".cut.svg";
    run.quiet = true;
    r.code = run_deck(run, &r.result);
    if (r.code == ExitCode::machine_stop) {
        throw std::logic_error("the machine stopped on the demo's own two-tool deck");
    }
    return r;
}

// Both variants of the two-tool job; the machine time each takes and what tripping the change
// early saved.
ExitCode run_two_tool_demo(const std::string& dir) {
    fmt::print("\ntwo tools (condition cards, an addition after EP 0640901; profile "
               "parsons-extended): NACA 2412 roughed with tool 1, finished with tool 2\n");
    const TwoToolRun boundary = run_two_tool(dir, decks::ChangeVariant::boundary);
    if (boundary.code != ExitCode::ok) {
        return boundary.code;
    }
    fmt::print("  {}: tool change tripped as the table reaches the change position 0.000 in, "
               "machine time {:.3f} s\n",
               boundary.deck, boundary.result.machine_seconds);
    const TwoToolRun tripped = run_two_tool(dir, decks::ChangeVariant::tripped);
    if (tripped.code != ExitCode::ok) {
        return tripped.code;
    }
    fmt::print("  {}: tool change tripped at table {:.3f} in during the return move, machine "
               "time {:.3f} s\n",
               tripped.deck, tripped.job.trip_position / 1000.0, tripped.result.machine_seconds);
    fmt::print("  the tool change overlapped the return move by {:.3f} s: the time EP 0640901 "
               "saves\n",
               boundary.result.machine_seconds - tripped.result.machine_seconds);
    return ExitCode::ok;
}

// The press-feeder job (press synchronisation, an addition after EP 0436887), both variants,
// with the press slowing 25 % in the second cycle: the proof's figures side by side.
ExitCode run_press_demo(const std::string& dir) {
    fmt::print("\npress feeder (press synchronisation, an addition after EP 0436887; profile "
               "parsons-extended): 3 cycles, the press slowing 25 % from its second revolution "
               "at 180 deg; every move follows the press, the speed-only deck without the crank's "
               "position\n");
    for (bool speed_only : {false, true}) {
        decks::PressFeederOptions o;
        o.cycles = 3;
        o.speed_only = speed_only;
        const std::string deck =
            dir + (speed_only ? "/press-feeder-speed-only.csv" : "/press-feeder.csv");
        GeneratedPressJob g = generate_press_job(o, axes::extended_profile(), deck, "");
        g.profile.press.change_cycle = 2;
        g.profile.press.change_angle_deg = 180;
        g.profile.press.change_factor = 0.75;
        write_file(deck + ".slowing.json", axes::profile_to_json(g.profile));
        RunRequest run;
        run.input = deck;
        run.profile = deck + ".slowing.json";
        run.press_proof = deck + ".job.json";
        run.report = deck + ".report.json";
        run.quiet = true;
        relaylogic::RunResult result;
        const ExitCode code = run_deck(run, &result);
        const auto report = nlohmann::json::parse(read_text_file(run.report));
        const auto& p = report.at("press");
        const double with_position = p.at("max_lag_position_sync_in").get<double>();
        const std::string behind =
            speed_only ? fmt::format("{:.4f} in", p.at("max_lag_speed_only_in").get<double>())
                       : fmt::format("{:.4f} in on its position-sync moves", with_position);
        fmt::print("  {} ({}): smallest clearance {:.4f} in, least time margin {} s, behind the "
                   "crank by at most {}, {}\n",
                   deck, g.job.variant, p.at("min_clearance_in").get<double>(),
                   p.at("min_time_margin_s").dump(), behind,
                   p.at("collision").is_null()
                       ? std::string("no collision")
                       : fmt::format("COLLISION in cycle {} at {:.2f} s, crank {:.1f} deg",
                                     p.at("collision").at("cycle").get<std::int64_t>(),
                                     p.at("collision").at("machine_seconds").get<double>(),
                                     p.at("collision").at("crank_angle_deg").get<double>()));
        if (code != ExitCode::ok && code != ExitCode::machine_stop) {
            return code;
        }
        if (code == ExitCode::machine_stop && (!speed_only || result.stop)) {
            throw std::logic_error("the demo's press-feeder deck did not run as planned");
        }
    }
    return ExitCode::ok;
}

// One run of the tapping job for the demo: its report's tapping block.
struct TappingRun {
    ExitCode code = ExitCode::ok;
    nlohmann::json block;
};

TappingRun run_tapping(const std::string& deck, const std::string& report,
                       const std::vector<std::string>& faults) {
    RunRequest run;
    run.input = deck;
    run.thread_proof = deck + ".job.json";
    run.report = report;
    run.faults = faults;
    run.quiet = true;
    TappingRun r;
    r.code = run_deck(run);
    r.block = nlohmann::json::parse(read_text_file(report)).at("tapping");
    return r;
}

// "worst pitch error +0.21 % (hole 3)"
std::string worst_of(const nlohmann::json& block) {
    const auto& w = block.at("worst_hole");
    if (w.is_null()) {
        return "no hole measured";
    }
    return fmt::format("worst pitch error {:+.2f} % (hole {})",
                       w.at("worst_error_percent").get<double>(), w.at("hole").dump());
}

// The tapping job (spindle synchronisation, an addition after EP 0360190): the ratio
// transferred, stored, and a head exchange without its transfer (stale-ratio:1).
ExitCode run_tapping_demo(const std::string& dir) {
    decks::TappingOptions o;
    const auto base = axes::extended_profile();
    fmt::print("\ntapping (spindle synchronisation, an addition after EP 0360190; profile "
               "parsons-extended): {} holes in {} rows, tool 1 then tool 2 on their own spindle "
               "heads, each hole's pitch proved to {:g} %\n",
               o.rows * o.holes_per_row, o.rows, o.tolerance_percent);
    for (axes::RatioSource source : {axes::RatioSource::transferred, axes::RatioSource::stored}) {
        o.ratio_source = source;
        const std::string name = decks::ratio_source_name(source);
        const std::string deck = dir + "/tapping-" + name + ".csv";
        generate_tapping_job(o, base, deck, "");
        const TappingRun r = run_tapping(deck, deck + ".report.json", {});
        if (r.code != ExitCode::ok) {
            throw std::logic_error("the demo's tapping deck did not run as planned");
        }
        fmt::print("  {} (ratio {}): {} holes, {}, {} head exchange{}, {} ratio{} transferred; "
                   "every hole within tolerance\n",
                   deck, name, r.block.at("holes").size(), worst_of(r.block),
                   r.block.at("head_exchanges").get<std::int64_t>(),
                   r.block.at("head_exchanges").get<std::int64_t>() == 1 ? "" : "s",
                   r.block.at("transfers").get<std::int64_t>(),
                   r.block.at("transfers").get<std::int64_t>() == 1 ? "" : "s");
    }
    const std::string deck = dir + "/tapping-transferred.csv";
    const TappingRun stale =
        run_tapping(deck, dir + "/tapping-stale-ratio.report.json", {"stale-ratio:1"});
    if (stale.code != ExitCode::machine_stop ||
        stale.block.at("holes_flagged").get<std::int64_t>() == 0) {
        throw std::logic_error("the demo's stale-ratio run did not cut the wrong pitch it should");
    }
    fmt::print("  {} --fault stale-ratio:1 (head exchange 1 sends no ratio): {} of {} holes "
               "flagged\n",
               deck, stale.block.at("holes_flagged").get<std::int64_t>(),
               stale.block.at("holes").size());
    for (const auto& h : stale.block.at("holes")) {
        if (!h.at("flagged").get<bool>() || !h.at("measured").get<bool>()) {
            continue;
        }
        fmt::print("    hole {} (card {:04}, tool {}): pitch cut {:.5f} in against the tap's "
                   "{:.5f} in ({:+.1f} %, worst revolution {:+.1f} %); memory 12a held ratio "
                   "{:.4f}, the head's is {:.4f}\n",
                   h.at("hole").dump(), h.at("number").get<int>(), h.at("tool").get<int>(),
                   h.at("mean_pitch_in").get<double>(), h.at("tap_pitch_in").get<double>(),
                   h.at("mean_error_percent").get<double>(),
                   h.at("worst_error_percent").get<double>(), h.at("ratio_used").get<double>(),
                   h.at("head_ratio").get<double>());
    }
    return ExitCode::ok;
}

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
    finish_standard_output(); // a reader gone (`| head -1`) ends the demo here, as it does bench
    RunRequest run;
    run.input = deck;
    run.report = dir + "/report.json";
    run.trace = dir + "/trace.vcd";
    run.plot = dir + "/plot.svg";
    run.cut = dir + "/cut.svg";
    run.path = dir + "/path.csv";
    ExitCode code = run_deck(run);
    if (code == ExitCode::machine_stop) {
        // The generator makes the demo's deck to run through: a stop on it is a bug.
        throw std::logic_error("the machine stopped on the demo's own deck");
    }
    if (code == ExitCode::ok) {
        finish_standard_output();
        code = run_two_tool_demo(dir);
    }
    if (code == ExitCode::ok) {
        finish_standard_output();
        code = run_press_demo(dir);
    }
    if (code == ExitCode::ok) {
        finish_standard_output();
        code = run_tapping_demo(dir);
    }
    fmt::print("\nwrote {0}/naca2412.cbn (+ .job.json), {0}/cards/, {0}/report.json, "
               "{0}/plot.svg, {0}/cut.svg, {0}/trace.vcd (gtkwave), {0}/path.csv, "
               "{0}/centres.csv, and for two tools {0}/two-tool-boundary.csv and "
               "{0}/two-tool-tripped.csv (each + .job.json, .report.json, .cut.svg), and for the "
               "press feeder "
               "{0}/press-feeder.csv and {0}/press-feeder-speed-only.csv (each + .job.json, "
               ".profile.json, .slowing.json, .report.json), and for tapping "
               "{0}/tapping-transferred.csv and {0}/tapping-stored.csv (each + .job.json, "
               ".profile.json, .report.json) and {0}/tapping-stale-ratio.report.json\n",
               dir);
    fmt::print("\nevery claim of the five patents, with a command that shows it at work and what "
               "to look for: docs/claims.md (installed under share/doc/parsons/docs/)\n");
    return code;
}

// --out /dev/null (any character device): the demo reads back what it writes (its job files and
// reports), so it writes into a scratch folder of its own and removes it at the end.
ExitCode run_demo_into(const std::string& out) {
    FilePlan plan; // it reads nothing of the user's: "-" is the one folder refused
    plan.write_folder("--out", out, [](const std::string&) { return false; });
    plan.check();
    if (!character_device(out)) {
        return run_demo(out);
    }
    const ScratchFolder scratch("parsons-demo");
    const ExitCode code = run_demo(scratch.path());
    fmt::print("(--out {}: the demo wrote into the scratch folder {} and removed it)\n", out,
               scratch.path());
    return code;
}

} // namespace

void add_demo_command(CLI::App& app, Command& selected) {
    auto dir = std::make_shared<std::string>("out/demo");
    CLI::App* cmd = app.add_subcommand(
        "demo", "The default job: generate a NACA 2412 template deck, run it, prove the cut; "
                "then the two-tool job with its tool change tripped early (EP 0640901), the "
                "press feeder (EP 0436887) and the tapping job (EP 0360190)");
    cmd->add_option("--out", *dir, "Folder for everything the demo writes")->capture_default_str();
    cmd->footer(exit_codes_help({{ExitCode::ok, "the demo ran and its deck completed"},
                                 {ExitCode::interrupted, "stopped by the operator with Ctrl-C"},
                                 {ExitCode::terminated, "stopped by SIGTERM"}}) +
                "Example:\n  parsons demo            (then open out/demo/cut.svg and plot.svg)");
    cmd->callback([&selected, dir] { selected = [dir] { return run_demo_into(*dir); }; });
}

} // namespace parsons::cli
