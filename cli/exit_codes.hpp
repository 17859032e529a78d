// The exit codes of `parsons` (docs/design-rules.md, Interfaces).
#pragma once

#include <fmt/format.h>

#include <initializer_list>
#include <string>
#include <utility>

namespace parsons::cli {

enum class ExitCode : int {
    ok = 0,            // the command did what was asked (a deck completed)
    internal = 1,      // a bug in parsons: please report it
    bad_input = 2,     // unreadable input or bad usage; the message names file and where
    machine_stop = 3,  // the machine stopped itself: a check fired (a correct emulation)
    interrupted = 130, // the operator stopped a run with Ctrl-C (128 + SIGINT)
    terminated = 143,  // ... or with SIGTERM (128 + SIGTERM)
    broken_pipe = 141, // the reader of an output went away: ended quietly (128 + SIGPIPE)
};

inline int to_int(ExitCode code) {
    return static_cast<int>(code);
}

// What a command can return, with what each code means for it (2, 141 and 1 are added to every
// command's list: any command can be given bad input, lose the reader of its output, and have a
// bug).
using ExitCodeMeanings = std::initializer_list<std::pair<ExitCode, const char*>>;

// The "Exit codes:" section of a command's --help, from the one list the tests also read.
inline std::string exit_codes_help(ExitCodeMeanings codes) {
    std::string text = "Exit codes:\n";
    for (const auto& [code, meaning] : codes) {
        text += fmt::format("  {:<4} {}\n", to_int(code), meaning);
    }
    text += fmt::format("  {:<4} {}\n", to_int(ExitCode::bad_input),
                        "bad usage or input that cannot be read or written (the message names "
                        "the file and where)");
    text += fmt::format("  {:<4} {}\n", to_int(ExitCode::broken_pipe),
                        "the reader of an output went away (a closed pipe): ended quietly, as "
                        "cat does");
    text += fmt::format("  {:<4} {}\n", to_int(ExitCode::internal),
                        "internal error: a bug in parsons (the message asks you to report it)");
    return text + "\n";
}

} // namespace parsons::cli
