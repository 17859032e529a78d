// parsons convert DECK -o OUT: copy a deck card by card into another format; or, to a G-code
// file (.ngc, .nc, .gcode, or --to gcode), run the deck and write the machine's path as G-code
// (outputs/traces/gcode_path.hpp; docs/gcode.md).
#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <memory>

namespace parsons::cli {
namespace {

struct ConvertFlags {
    std::string input;
    std::string output;
    std::string to;
    std::string profile;
    DeckFlags deck;
};

bool wants_gcode(const ConvertFlags& f) {
    if (!f.to.empty()) {
        return f.to == "gcode";
    }
    const std::string ext = std::filesystem::path(f.output).extension().string();
    return std::any_of(kGcodeExtensions.begin(), kGcodeExtensions.end(),
                       [&](std::string_view e) { return ext == "." + std::string(e); });
}

// The deck run on the emulated machine, its path written as G-code.
ExitCode convert_to_gcode(const ConvertFlags& f) {
    RunRequest run;
    run.input = f.input;
    run.gcode = f.output;
    run.profile = f.profile;
    run.deck = f.deck;
    run.quiet = true;
    relaylogic::RunResult result;
    const ExitCode code = run_deck(run, &result);
    fmt::print(message_stream(),
               "converted the path of {} card{} ({:.3f} s of machine time{}): {} -> {} "
               "(G-code)\n",
               result.cards_read, result.cards_read == 1 ? "" : "s", result.machine_seconds,
               result.completed ? "" : ", to the machine stop", f.input, f.output);
    return code;
}

ExitCode run_convert(const ConvertFlags& f) {
    if (wants_gcode(f)) {
        return convert_to_gcode(f);
    }
    if (!f.profile.empty()) {
        throw cardreader::DeckError("convert: --profile is for G-code output, where the deck is "
                                    "run; a deck copied card by card needs no machine");
    }
    FilePlan plan;
    plan.read("DECK", f.input);
    plan.write("-o", f.output);
    plan.check();
    InputDeck deck(f.input, f.deck);
    const auto out_options = deck_options(f.output, f.to, f.deck, "--to");
    OutputFile out(f.output);
    auto sink = cardreader::open_card_sink(out.stream(), out_options);
    std::int64_t cards = 0;
    while (auto card = deck.cards().next()) {
        sink->write(*card);
        ++cards;
    }
    out.commit();
    fmt::print(message_stream(), "converted {} card{}: {} ({}) -> {} ({})\n", cards,
               cards == 1 ? "" : "s", f.input, cardreader::format_name(deck.options().format),
               f.output, cardreader::format_name(out_options.format));
    return ExitCode::ok;
}

} // namespace

void add_convert_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<ConvertFlags>();
    CLI::App* cmd = app.add_subcommand("convert", "Convert a deck between file formats");
    cmd->add_option("DECK", flags->input, "The deck to read")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("-o,--output", flags->output, "The deck to write; format from the extension")
        ->type_name(std::string(kDeckValue) + "|" + file_value(kGcodeExtensions))
        ->required();
    cmd->add_option("--to", flags->to,
                    "Output format: cbn, bin, text, listing, tape or five; or gcode, the machine's "
                    "path as it runs the deck")
        ->type_name(deck_formats({"gcode"}));
    cmd->add_option("--profile", flags->profile,
                    "G-code output: the machine profile to run the deck on (a name or a JSON "
                    "file)")
        ->type_name(std::string(kProfileValue));
    add_input_flags(*cmd, flags->deck);
    cmd->footer(
        exit_codes_help(
            {{ExitCode::ok, "the deck was converted"},
             {ExitCode::machine_stop, "G-code output: the machine stopped itself (the path to the "
                                      "stop is written)"},
             {ExitCode::interrupted, "G-code output: the run stopped by the operator with Ctrl-C"},
             {ExitCode::terminated, "G-code output: the run stopped by SIGTERM"}}) +
        "Examples:\n"
        "  parsons convert decks/samples/patent-example.csv -o deck.bin\n"
        "  parsons convert deck.bin -o deck.csv      (back to a listing)\n"
        "  parsons convert deck.bin --to text -o cards.dat\n"
        "  parsons convert cards.dat --format text -o cards.cbn\n"
        "  parsons convert decks/samples/patent-example.csv -o path.ngc   (the path the "
        "machine cut, as G-code)");
    cmd->callback([&selected, flags] { selected = [flags] { return run_convert(*flags); }; });
}

} // namespace parsons::cli
