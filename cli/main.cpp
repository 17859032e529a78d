// parsons: the punched-card numerical control of Parsons and Stulen (US 2,820,187), emulated.
#include "cli/command_line.hpp"
#include "cli/support/child_process.hpp"

#include "cli/version.hpp" // generated: cmake/git_version.cmake

#include <fmt/format.h>

int main(int argc, char** argv) {
    // "parsons 0.1.0 (v0.1.0-12-gabc1234)": the project's version and the source's git
    // description.
    // This process is the parsons executable: sweep may start it as children
    // (cli/support/child_process.hpp).
    parsons::cli::register_parsons_executable();
    return parsons::cli::command_line_main(
        argc, argv,
        fmt::format("parsons {} ({})", PARSONS_VERSION_NUMBER, PARSONS_GIT_DESCRIPTION));
}
