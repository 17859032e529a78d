// The subcommands of `parsons`. Each add_*_command registers its flags on the app and, when
// its subcommand is chosen, sets `selected` to the function that runs it. Running throws
// cardreader::DeckError for bad input (exit 2); the function returns the exit code otherwise.
#pragma once

#include "cli/exit_codes.hpp"

#include <CLI/CLI.hpp>

#include <functional>

namespace parsons::cli {

using Command = std::function<ExitCode()>;

void add_punch_command(CLI::App& app, Command& selected);
void add_convert_command(CLI::App& app, Command& selected);
void add_show_command(CLI::App& app, Command& selected);
void add_run_command(CLI::App& app, Command& selected);
void add_profile_command(CLI::App& app, Command& selected);

} // namespace parsons::cli
