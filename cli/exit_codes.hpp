// The exit codes of `parsons` (DESIGN.md section 6).
#pragma once

namespace parsons::cli {

enum class ExitCode : int {
    ok = 0,            // the command did what was asked (a deck completed)
    internal = 1,      // a bug in parsons: please report it
    bad_input = 2,     // unreadable input or bad usage; the message names file and where
    machine_stop = 3,  // the machine stopped itself: a check fired (a correct emulation)
    interrupted = 130, // the operator stopped a run with Ctrl-C (128 + SIGINT)
    terminated = 143,  // ... or with SIGTERM (128 + SIGTERM)
};

inline int to_int(ExitCode code) {
    return static_cast<int>(code);
}

} // namespace parsons::cli
