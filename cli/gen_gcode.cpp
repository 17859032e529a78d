// parsons gen gcode PROGRAM: a G-code program as a deck the 1952 machine runs
// (decks/gcode_program.hpp reads it, decks/gcode_job.hpp makes the cards; docs/gcode.md).
#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/json_output.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output_file.hpp"
#include "outputs/report/figures.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/gcode_job.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace parsons::cli {
namespace {

using cardreader::DeckError;

struct GcodeFlags {
    std::string program;
    std::string output;
    std::string to;
    std::string profile;
    std::vector<double> work_zero;
    decks::GcodeJobOptions o;
    bool no_corner_slowdown = false;
    bool json = false;
    bool strict = false;
};

Json gcode_json(const GcodeFlags& f, const decks::GcodeProgram& program,
                const decks::GcodeDeck& deck) {
    Json doc = json_document("gen");
    doc["generator"] = "gcode";
    doc["program"] = f.program;
    doc["units"] = program.millimetres ? "millimetres" : "inches";
    doc["deck"] = f.output;
    doc["cards"] = deck.cards.size();
    doc["approach_cards"] = deck.approach_cards;
    doc["corner_cards"] = deck.corner_cards;
    doc["lines"] = deck.lines;
    doc["arcs"] = deck.arcs;
    doc["tolerance_in"] = f.o.tolerance_in;
    doc["staircase_in"] = fine_length(deck.planned_deviation_in);
    doc["work_zero_in"] = {decimals(deck.work_zero_in.x(), 4), decimals(deck.work_zero_in.y(), 4),
                           decimals(deck.work_zero_in.z(), 4)};
    doc["ignored"] = program.ignored;
    return doc;
}

void print_gcode(const GcodeFlags& f, const decks::GcodeProgram& program,
                 const decks::GcodeDeck& deck) {
    std::FILE* out = message_stream();
    fmt::print(out,
               "generated {}: {} ({} line{}, {} move{} in a straight line, {} arc{}), {} "
               "card{}\n",
               f.output == "-" ? "standard output" : f.output, f.program, program.lines,
               program.lines == 1 ? "" : "s", deck.lines, deck.lines == 1 ? "" : "s", deck.arcs,
               deck.arcs == 1 ? "" : "s", deck.cards.size(), deck.cards.size() == 1 ? "" : "s");
    fmt::print(out, "  units          {} in the program; the deck in thousandths of an inch\n",
               program.millimetres ? "millimetres" : "inches");
    fmt::print(out,
               "  work zero      table {:.3f} in, cross slide {:.3f} in, vertical {:.3f} in "
               "(the program's origin on the counters{})\n",
               deck.work_zero_in.x(), deck.work_zero_in.y(), deck.work_zero_in.z(),
               f.work_zero.empty() ? "" : ", from --work-zero");
    fmt::print(out,
               "  tolerance      {:g} in: arcs in chords, each move a staircase of one axis at a "
               "time (the farthest corner {:.4f} in off its line)\n",
               f.o.tolerance_in, deck.planned_deviation_in);
    fmt::print(out,
               "  cards          {} ({} to bring the machine to the work zero, {} slowed for "
               "a corner)\n",
               deck.cards.size(), deck.approach_cards, deck.corner_cards);
    for (const std::string& i : program.ignored) {
        fmt::print(out, "  ignored        {}\n", i);
    }
}

ExitCode run_gen_gcode(GcodeFlags f) {
    refuse_json_beside_standard_output("gen gcode", f.json, "-o", f.output);
    if (!f.work_zero.empty()) {
        if (f.work_zero.size() != 3) {
            throw DeckError(fmt::format("gen gcode: --work-zero: give three numbers, table, cross "
                                        "slide and vertical in inches (e.g. 1,1,0.5), not {}",
                                        f.work_zero.size()));
        }
        f.o.work_zero_in = Eigen::Vector3d(f.work_zero[0], f.work_zero[1], f.work_zero[2]);
    }
    f.o.corner_slowdown = !f.no_corner_slowdown;
    FilePlan plan;
    plan.read("PROGRAM", f.program);
    plan.read("--profile", AppliedProfile::file_read(f.profile));
    plan.write("-o", f.output);
    plan.check();
    const auto profile = load_profile(f.profile);
    const std::string text = read_text_input(f.program);
    const decks::GcodeProgram program = decks::read_gcode(
        text, f.program == "-" ? "standard input" : f.program, {.strict = f.strict});
    for (const std::string& w : program.warnings) {
        say(stderr, "parsons: warning: " + cardreader::visible_text(w) + "\n");
    }
    decks::GcodeDeck deck;
    try {
        deck = decks::make_gcode_deck(program, f.o, profile);
    } catch (const decks::JobError& e) {
        throw DeckError(fmt::format("gen gcode: {}", e.what()));
    } catch (const decks::PlanError& e) {
        throw DeckError(fmt::format("gen gcode: {}", e.what()));
    }
    write_cards(deck.cards, f.output, f.to, nullptr, "gen gcode");
    if (f.json) {
        print_json_document(gcode_json(f, program, deck));
    } else {
        print_gcode(f, program, deck);
    }
    return ExitCode::ok;
}

} // namespace

void add_gen_gcode_command(CLI::App& gen, Command& selected) {
    auto flags = std::make_shared<GcodeFlags>();
    CLI::App* cmd = gen.add_subcommand(
        "gcode", "A G-code program (G0 G1 G2 G3, G20 G21, G90 G91) as a deck: arcs in chords, "
                 "each move a staircase within the tolerance, speeds by the slow-down rule. A "
                 "post-processor's program (LinuxCNC's, grbl's) is read as written: its words "
                 "for a machine the 1952 one is not (F, S, coolant, O, T M6, G43 H, G64 P, a "
                 "G28 at the end) are ignored, each kind with one warning on standard error; "
                 "--strict refuses them");
    cmd->add_option("PROGRAM", flags->program, "The G-code program to read (- for standard input)")
        ->type_name(file_value(kGcodeExtensions))
        ->required();
    cmd->add_option("-o,--output", flags->output, "The deck to write (.cbn .bin .csv)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Deck format: cbn, bin or listing")
        ->type_name(deck_formats());
    cmd->add_option("--tolerance", flags->o.tolerance_in,
                    "How close the path as cut stays to the program's, inches (at least 0.003)")
        ->capture_default_str();
    cmd->add_option("--work-zero", flags->work_zero,
                    "Where the program's origin is on the counters: table,cross,vertical in "
                    "inches (default: unmoved, or moved to fit the counters' 0 to 9.999)")
        ->delimiter(',');
    cmd->add_option("--margin", flags->o.margin_in,
                    "Default work zero: the program's lowest point this far inside the counters' "
                    "range, inches")
        ->capture_default_str();
    cmd->add_flag("--no-corner-slowdown", flags->no_corner_slowdown,
                  "Do not slow down where the path turns sharply (EP 0636958)");
    cmd->add_option("--profile", flags->profile, "Machine profile (a name or a JSON file)")
        ->type_name(std::string(kProfileValue));
    add_strict_flag(*cmd, flags->strict);
    add_json_flag(*cmd, flags->json);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was written"}}) +
                "Examples:\n"
                "  parsons gen gcode decks/samples/bracket.ngc -o bracket.cbn\n"
                "  parsons run bracket.cbn --path bracket-path.csv\n"
                "  parsons convert bracket.cbn -o bracket-as-cut.ngc   (the path, back to "
                "G-code)\n"
                "  parsons gen gcode decks/samples/bracket.ngc --tolerance 0.01 -o coarse.cbn\n"
                "  parsons gen gcode tests/gcode/linuxcnc-post.ngc --strict -o b.cbn   (exit 2 "
                "at its first ignored word)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_gen_gcode(*flags); }; });
}

} // namespace parsons::cli
