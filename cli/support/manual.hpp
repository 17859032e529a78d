// The manual pages and the shell completion of parsons, written from the command line itself
// (cli/command_line.hpp): one man page per command and subcommand (parsons(1),
// parsons-run(1), parsons-gen-airfoil(1), ...), each option with its description and default,
// the exit codes and examples of its --help; and a completion script for bash and one for zsh
// that offer each command's subcommands and options. Built at build time by parsons_manual
// (cli/manual_main.cpp) into build/man/ and build/completion/; tests/manual_test.cpp checks
// that every option of every command is in its page and both scripts.
#pragma once

#include "cli/support/cli11_fwd.hpp"

#include <string>
#include <vector>

namespace parsons::cli {

struct ManPage {
    std::string name; // "parsons-gen-airfoil": the file is NAME.1
    std::string text; // roff, man macros
};

// A page for the program and one for every command below it, depth first.
std::vector<ManPage> man_pages(const CLI::App& app, const std::string& version);

// `complete -F _parsons parsons`: subcommands, options, and files after an option that takes
// a value or where no option is typed.
std::string bash_completion(const CLI::App& app);
// `#compdef parsons`: the same, with each option's and command's description.
std::string zsh_completion(const CLI::App& app);

// Each command's words as the completion reads them (the same options, hidden ones left out):
// for tests/fuzz/argv_target.cpp, which builds command lines of them.
struct CommandWords {
    std::string path;               // "gen airfoil"; "" for the program
    std::vector<std::string> flags; // the names of options that take no value
    std::vector<std::pair<std::string, std::string>> valued; // option name, its value's type name
    std::vector<std::string> positionals; // each positional's type name, in order
    bool has_subcommands = false;
};
std::vector<CommandWords> command_words(const CLI::App& app);

// Every command path of the program ("", "run", "gen airfoil", ...) with its app, depth first.
std::vector<std::pair<std::string, const CLI::App*>> command_paths(const CLI::App& app);
// The names an option is typed by: "--report", "-o", ... (none for a positional).
std::vector<std::string> option_names(const CLI::Option& option);

} // namespace parsons::cli
