// parsons punch LISTING -o DECK: the keypunch. Reads a listing, punches one card per five rows.
// With --json, what it says about the deck is one document for scripts (docs/json-output.md).
#include "cli/commands.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/json_output.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output_file.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

namespace parsons::cli {
namespace {

struct PunchFlags {
    std::string listing;
    std::string output;
    std::string to;
    bool json = false;
    DeckFlags deck;
};

ExitCode run_punch(const PunchFlags& f) {
    refuse_json_beside_standard_output("punch", f.json, "-o", f.output);
    FilePlan plan;
    plan.read("LISTING", f.listing);
    plan.write("-o", f.output);
    plan.check();
    DeckFlags in = f.deck;
    in.format = "listing";
    InputDeck listing(f.listing, in);
    const auto out_options = deck_options(f.output, f.to, f.deck, "--to");
    OutputFile out(f.output);
    auto sink = cardreader::open_card_sink(out.stream(), out_options);
    std::int64_t cards = 0;
    while (auto card = listing.cards().next()) {
        sink->write(*card);
        ++cards;
    }
    out.commit();
    if (f.json) {
        Json doc = json_document("punch");
        doc["listing"] = f.listing;
        doc["deck"] = f.output;
        doc["format"] = std::string(cardreader::format_name(out_options.format));
        doc["layout"] = out_options.layout->name;
        doc["code"] = f.deck.code;
        doc["cards"] = cards;
        print_json_document(doc);
        return ExitCode::ok;
    }
    fmt::print(message_stream(), "punched {} card{} from {} into {} ({}, layout {})\n", cards,
               cards == 1 ? "" : "s", f.listing, f.output,
               cardreader::format_name(out_options.format), out_options.layout->name);
    return ExitCode::ok;
}

} // namespace

void add_punch_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<PunchFlags>();
    CLI::App* cmd = app.add_subcommand("punch", "Keypunch a listing into a deck of cards");
    cmd->add_option("LISTING", flags->listing,
                    "The listing: CSV, one row per axis per card (docs/deck-formats.md)")
        ->type_name(file_value(cardreader::format_extensions(cardreader::DeckFormat::listing)))
        ->required();
    cmd->add_option("-o,--output", flags->output,
                    "The deck to punch; format from the extension (.cbn .bin .txt/.crd .csv/.lst)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Output format: cbn, bin, text, listing, tape or five")
        ->type_name(deck_formats());
    cmd->add_option("--code", flags->deck.code, "Keypunch code for text card images: 029 or 026")
        ->type_name(code_names())
        ->capture_default_str();
    cmd->add_option("--layout", flags->deck.layout, "Card layout")
        ->type_name(layout_names())
        ->capture_default_str();
    add_json_flag(*cmd, flags->json);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was punched"}}) +
                "Examples:\n"
                "  parsons punch decks/samples/patent-example.csv -o deck.cbn\n"
                "  parsons punch decks/samples/patent-example.csv -o deck.txt --json");
    cmd->callback([&selected, flags] { selected = [flags] { return run_punch(*flags); }; });
}

} // namespace parsons::cli
