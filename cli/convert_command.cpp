// parsons convert DECK -o OUT: copy a deck card by card into another format.
#include "cli/commands.hpp"
#include "cli/deck_files.hpp"
#include "cli/output_file.hpp"

#include <fmt/format.h>

#include <memory>

namespace parsons::cli {
namespace {

struct ConvertFlags {
    std::string input;
    std::string output;
    std::string to;
    DeckFlags deck;
};

ExitCode run_convert(const ConvertFlags& f) {
    InputDeck deck(f.input, f.deck);
    const auto out_options = deck_options(f.output, f.to, f.deck, "--to");
    OutputFile out(f.output);
    auto sink = cardreader::open_card_sink(out.stream(), out_options);
    long cards = 0;
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
    cmd->add_option("DECK", flags->input, "The deck to read")->required();
    cmd->add_option("-o,--output", flags->output, "The deck to write; format from the extension")
        ->required();
    cmd->add_option("--to", flags->to, "Output format: cbn, bin, text, listing, tape or five");
    add_input_flags(*cmd, flags->deck);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was converted"}}) +
                "Examples:\n"
                "  parsons convert decks/samples/patent-example.csv -o deck.bin\n"
                "  parsons convert deck.bin -o deck.csv      (back to a listing)\n"
                "  parsons convert deck.bin --to text -o cards.dat\n"
                "  parsons convert cards.dat --format text -o cards.cbn");
    cmd->callback([&selected, flags] { selected = [flags] { return run_convert(*flags); }; });
}

} // namespace parsons::cli
