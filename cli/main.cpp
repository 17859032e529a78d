// parsons: the punched-card numerical control of Parsons and Stulen (US 2,820,187), emulated.
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"
#include "cli/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include "cli/version.hpp" // generated: cmake/git_version.cmake

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <string>
#include <system_error>

namespace {

// The message for an error, and exit 2: standard output that cannot be written is a
// failed output like any other.
int write_error(const std::string& message) {
    fmt::print(stderr, "parsons: error: {}\n", message);
    return parsons::cli::to_int(parsons::cli::ExitCode::bad_input);
}

} // namespace

int main(int argc, char** argv) {
    using namespace parsons::cli;
    // A reader that goes away (a closed pipe or FIFO) is a write error with a message and
    // exit 2, not a silent death by SIGPIPE.
    std::signal(SIGPIPE, SIG_IGN);
    CLI::App app;
    Command selected;
    // "parsons 0.1.0 (v0.1.0-12-gabc1234)": the project's version and the source's git
    // description.
    build_command_line(
        app, selected,
        fmt::format("parsons {} ({})", PARSONS_VERSION_NUMBER, PARSONS_GIT_DESCRIPTION));

    // Name an unknown command rather than let CLI11 say only that one is required.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string word = argv[1];
        bool known = false;
        std::string names;
        for (const CLI::App* sub : app.get_subcommands({})) {
            known = known || sub->get_name() == word;
            names += (names.empty() ? "" : ", ") + sub->get_name();
        }
        if (!known) {
            fmt::print(stderr,
                       "parsons: error: unknown command '{}' (one of: {}; see parsons "
                       "--help)\n",
                       word, names);
            return to_int(ExitCode::bad_input);
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() != 0) {
            // CLI11's own message, worded as ours: prefix, the command to ask, exit 2.
            std::string command = "parsons";
            for (const CLI::App* sub = &app; sub != nullptr;) {
                const auto chosen = sub->get_subcommands();
                sub = chosen.empty() ? nullptr : chosen.front();
                if (sub != nullptr) {
                    command += " " + sub->get_name();
                }
            }
            fmt::print(stderr, "parsons: error: {} (see '{} --help')\n", e.what(), command);
            return to_int(ExitCode::bad_input);
        }
        app.exit(e); // --help: the help text, exit 0
        try {
            finish_standard_output();
        } catch (const parsons::cardreader::DeckError& error) {
            return write_error(error.what());
        }
        return 0;
    }
    try {
        const ExitCode code = selected();
        finish_standard_output();
        return to_int(code);
    } catch (const parsons::cardreader::DeckError& e) {
        std::fflush(stdout);
        return write_error(e.what());
    } catch (const std::system_error& e) {
        // fmt reports a failed write to standard output this way.
        if (std::ferror(stdout) != 0) {
            return write_error("standard output: cannot write: " + e.code().message());
        }
        fmt::print(stderr, "parsons: internal error: {} (please report this)\n", e.what());
        return to_int(ExitCode::internal);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        fmt::print(stderr, "parsons: internal error: {} (please report this)\n", e.what());
        return to_int(ExitCode::internal);
    }
}
