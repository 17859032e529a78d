// The whole command line of parsons: every command, subcommand and option, built once here.
// main() parses with it; the manual pages and the shell completion (cli/support/manual.hpp) are
// written from it, so that neither can drift from what the program accepts.
#pragma once

#include "cli/commands.hpp"
#include "cli/support/cli11_fwd.hpp"

#include <string>

namespace parsons::cli {

// Registers every command on `app`; `version` is what --version prints. `timeline` (may be
// null): where every run is also recorded (the WebAssembly page's hook, web/parsons_web.cpp).
void build_command_line(CLI::App& app, Command& selected, const std::string& version,
                        RunTimeline* timeline = nullptr);

// What `parsons ARGS...` does: parse, run the chosen command, and turn every error into its
// message on standard error and its exit code (exit_codes.hpp). main() is this; so is each
// command the WebAssembly page gives (web/parsons_web.cpp), so both word errors the same.
int command_line_main(int argc, char** argv, const std::string& version,
                      RunTimeline* timeline = nullptr);

} // namespace parsons::cli
