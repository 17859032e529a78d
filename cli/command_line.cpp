#include "cli/command_line.hpp"

#include "cli/exit_codes.hpp"
#include "cli/support/number_rule.hpp"
#include "outputs/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <system_error>

namespace parsons::cli {

namespace {

// The message for an error, and exit 2: standard output that cannot be written is a
// failed output like any other.
int write_error(const std::string& message) {
    if (!say(stderr, fmt::format("parsons: error: {}\n", message)) && reader_gone(stderr)) {
        return to_int(ExitCode::broken_pipe); // as cat's own error to a closed pipe ends it
    }
    return to_int(ExitCode::bad_input);
}

// A reader went away: the command ends at once, quietly (no message to a stream that is gone;
// a named FIFO or socket is told of on standard error, which still has its reader).
int broken_pipe(const std::string& output) {
    if (output != "standard output" && output != "standard error") {
        say(stderr,
            fmt::format("parsons: {}: the reader went away (broken pipe); stopped\n", output));
    }
    return to_int(ExitCode::broken_pipe);
}

// The stream a failed fmt::print wrote to, when its reader went away.
std::optional<std::string> gone_stream(const std::system_error& e) {
    const bool epipe = e.code() == std::errc::broken_pipe;
    if (std::ferror(stdout) != 0 && (epipe || reader_gone(stdout))) {
        return "standard output";
    }
    if (std::ferror(stderr) != 0 && (epipe || reader_gone(stderr))) {
        return "standard error";
    }
    if (epipe) {
        return "standard output";
    }
    return std::nullopt;
}

} // namespace

void add_strict_flag(CLI::App& cmd, bool& strict) {
    cmd.add_flag("--strict", strict,
                 "Refuse the G-code words the 1952 machine would ignore (F, S, M7-M9, O, T and "
                 "M6, G43 H, G64 P, G28 at the end) instead of warning of each (exit 2, naming "
                 "file, line and word)");
}

void build_command_line(CLI::App& app, Command& selected, const std::string& version,
                        RunTimeline* timeline) {
    app.description("parsons: an emulator of the 1952 Parsons-Stulen punched-card milling "
                    "machine control (US 2,820,187)");
    app.require_subcommand(1);
    app.footer("Run 'parsons COMMAND --help' for each command, with examples.");
    app.set_version_flag("--version", version,
                         "Print the version and the git description of the source, and exit");
    add_punch_command(app, selected);
    add_show_command(app, selected);
    add_convert_command(app, selected);
    add_run_command(app, selected, timeline);
    add_check_command(app, selected);
    add_profile_command(app, selected);
    add_gen_command(app, selected);
    add_demo_command(app, selected);
    add_bench_command(app, selected);
    add_sweep_command(app, selected);
    apply_number_rule(app);
}

int command_line_main(int argc, char** argv, const std::string& version, RunTimeline* timeline) {
    // A reader that goes away (a closed pipe or FIFO) is seen as EPIPE where it happens, so the
    // command ends quietly with every temporary file removed (exit 141), not by SIGPIPE midway.
    std::signal(SIGPIPE, SIG_IGN);
    remove_temporaries_on_signals();
    reset_standard_output();
    CLI::App app;
    Command selected;
    build_command_line(app, selected, version, timeline);

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
            return write_error(
                fmt::format("unknown command '{}' (one of: {}; see parsons --help)", word, names));
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
            return write_error(fmt::format("{} (see '{} --help')", e.what(), command));
        }
        errno = 0;
        app.exit(e);                  // --help and --version: their text, exit 0
        const int seen_errno = errno; // a failed write through std::cout (a full disk)
        try {
            finish_standard_output(seen_errno);
        } catch (const BrokenPipe& gone) {
            return broken_pipe(gone.output());
        } catch (const cardreader::DeckError& error) {
            return write_error(error.what());
        }
        return 0;
    }
    try {
        const ExitCode code = selected();
        finish_standard_output();
        return to_int(code);
    } catch (const BrokenPipe& e) {
        return broken_pipe(e.output());
    } catch (const cardreader::DeckError& e) {
        std::fflush(stdout);
        if (std::ferror(stdout) != 0 && reader_gone(stdout)) {
            return broken_pipe("standard output");
        }
        return write_error(e.what());
    } catch (const std::system_error& e) {
        // fmt reports a failed write to standard output or error this way.
        if (const auto gone = gone_stream(e)) {
            return broken_pipe(*gone);
        }
        if (std::ferror(stdout) != 0) {
            return write_error("standard output: cannot write: " + e.code().message());
        }
        say(stderr, fmt::format("parsons: internal error: {} (please report this)\n", e.what()));
        return to_int(ExitCode::internal);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        say(stderr, fmt::format("parsons: internal error: {} (please report this)\n", e.what()));
        return to_int(ExitCode::internal);
    }
}

} // namespace parsons::cli
