// parsons profile [--profile FILE]: print the machine profile in force as JSON.
#include "cli/commands.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/value_names.hpp"

#include "axes/profile_json.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

namespace parsons::cli {
namespace {

ExitCode run_profile(const std::string& file) {
    fmt::print("{}", axes::profile_to_json(load_profile(file)));
    return ExitCode::ok;
}

} // namespace

void add_profile_command(CLI::App& app, Command& selected) {
    auto file = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "profile", "Print the machine profile (every time and rate of the machine) as JSON");
    cmd->add_option("--profile", *file, "A profile file to apply over the built-in default")
        ->type_name(file_value({"json"}));
    cmd->footer(exit_codes_help({{ExitCode::ok, "the profile was printed"}}) +
                "Examples:\n"
                "  parsons profile > my-machine.json     (then edit it)\n"
                "  parsons run decks/samples/patent-example.csv --profile my-machine.json");
    cmd->callback([&selected, file] { selected = [file] { return run_profile(*file); }; });
}

} // namespace parsons::cli
