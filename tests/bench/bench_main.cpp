// parsons_bench: the same as `parsons bench` (cli/bench_command.cpp), as a program of its own.
//
//   build-release/tests/bench/parsons_bench [--runs N] [--json] ...
#include "cli/commands.hpp"

#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace parsons::cli;
    CLI::App app{"parsons_bench: how fast the emulator runs (the same as 'parsons bench')"};
    Command selected;
    add_bench_command(app, selected);
    // Everything after the program name goes to the bench subcommand (its child processes are
    // started as "PROGRAM bench ...").
    std::vector<std::string> args = {"bench"};
    for (int i = argc > 1 && std::string(argv[1]) == "bench" ? 2 : 1; i < argc; ++i) {
        args.emplace_back(argv[i]);
    }
    std::vector<char*> argv2 = {argv[0]};
    for (auto& a : args) {
        argv2.push_back(a.data());
    }
    try {
        app.parse(static_cast<int>(argv2.size()), argv2.data());
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        return to_int(selected());
    } catch (const std::exception& e) {
        fmt::print(stderr, "parsons_bench: error: {}\n", e.what());
        return 1;
    }
}
