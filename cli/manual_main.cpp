// parsons_manual OUTDIR: writes parsons' manual pages (OUTDIR/man/man1/NAME.1) and its shell
// completion (OUTDIR/completion/parsons.bash and _parsons) from the command line itself. Run
// by the build (cli/CMakeLists.txt); cli/support/manual.hpp says what is in them.
#include "cli/command_line.hpp"
#include "cli/support/manual.hpp"

#include "cli/version.hpp" // generated: cmake/git_version.cmake

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

void write(const std::filesystem::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) {
        throw std::runtime_error("cannot write " + file.string());
    }
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        fmt::print(stderr, "usage: parsons_manual OUTDIR\n");
        return 2;
    }
    try {
        using namespace parsons::cli;
        CLI::App app;
        Command selected;
        const std::string version =
            fmt::format("parsons {} ({})", PARSONS_VERSION_NUMBER, PARSONS_GIT_DESCRIPTION);
        build_command_line(app, selected, version);
        const std::filesystem::path out = argv[1];
        std::filesystem::create_directories(out / "man" / "man1");
        std::filesystem::create_directories(out / "completion");
        for (const ManPage& page : man_pages(app, version)) {
            write(out / "man" / "man1" / (page.name + ".1"), page.text);
        }
        write(out / "completion" / "parsons.bash", bash_completion(app));
        write(out / "completion" / "_parsons", zsh_completion(app));
        return 0;
    } catch (const std::exception& e) {
        fmt::print(stderr, "parsons_manual: {}\n", e.what());
        return 1;
    }
}
