#include "cli/command_line.hpp"

namespace parsons::cli {

void build_command_line(CLI::App& app, Command& selected, const std::string& version) {
    app.description("parsons: an emulator of the 1952 Parsons-Stulen punched-card milling "
                    "machine control (US 2,820,187)");
    app.require_subcommand(1);
    app.footer("Run 'parsons COMMAND --help' for each command, with examples.");
    app.set_version_flag("--version", version,
                         "Print the version and the git description of the source, and exit");
    add_punch_command(app, selected);
    add_show_command(app, selected);
    add_convert_command(app, selected);
    add_run_command(app, selected);
    add_check_command(app, selected);
    add_profile_command(app, selected);
    add_gen_command(app, selected);
    add_demo_command(app, selected);
    add_bench_command(app, selected);
}

} // namespace parsons::cli
