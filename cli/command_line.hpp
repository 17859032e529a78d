// The whole command line of parsons: every command, subcommand and option, built once here.
// main() parses with it; the manual pages and the shell completion (cli/manual.hpp) are written
// from it, so that neither can drift from what the program accepts.
#pragma once

#include "cli/commands.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace parsons::cli {

// Registers every command on `app`; `version` is what --version prints.
void build_command_line(CLI::App& app, Command& selected, const std::string& version);

} // namespace parsons::cli
