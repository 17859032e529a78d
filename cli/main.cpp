// parsons: the punched-card numerical control of Parsons and Stulen (US 2,820,187), emulated.
#include "cli/commands.hpp"
#include "cli/exit_codes.hpp"

#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
    using namespace parsons::cli;
    CLI::App app{"parsons: an emulator of the 1952 Parsons-Stulen punched-card milling machine "
                 "control (US 2,820,187)"};
    app.require_subcommand(1);
    app.footer("Run 'parsons COMMAND --help' for each command, with examples.");
    Command selected;
    add_punch_command(app, selected);
    add_show_command(app, selected);
    add_convert_command(app, selected);
    add_run_command(app, selected);
    add_check_command(app, selected);
    add_profile_command(app, selected);
    add_gen_command(app, selected);
    add_demo_command(app, selected);
    add_bench_command(app, selected);

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
        const int code = app.exit(e);
        return code == 0 ? 0 : to_int(ExitCode::bad_input);
    }
    try {
        return to_int(selected());
    } catch (const parsons::cardreader::DeckError& e) {
        std::fflush(stdout);
        fmt::print(stderr, "parsons: error: {}\n", e.what());
        return to_int(ExitCode::bad_input);
    } catch (const std::exception& e) {
        std::fflush(stdout);
        fmt::print(stderr, "parsons: internal error: {} (please report this)\n", e.what());
        return to_int(ExitCode::internal);
    }
}
