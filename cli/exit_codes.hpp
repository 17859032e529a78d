// The exit codes of `parsons` (DESIGN.md section 6).
#pragma once

namespace parsons::cli {

enum class ExitCode : int {
    ok = 0,           // the command did what was asked (a deck completed)
    internal = 1,     // a bug in parsons: please report it
    bad_input = 2,    // unreadable input or bad usage; the message names file and where
    machine_stop = 3, // the machine stopped itself: a check fired (a correct emulation)
};

inline int to_int(ExitCode code) {
    return static_cast<int>(code);
}

} // namespace parsons::cli
