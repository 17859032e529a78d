// The operator's stop: SIGINT and SIGTERM caught for the length of a command that must end
// in order (a run stops its machine at the next event; a sweep stops its children and removes
// its scratch folder), instead of ending the process where it stands.
#pragma once

#include "cli/exit_codes.hpp"

#include <csignal>

namespace parsons::cli {

class OperatorStop {
public:
    // Catches SIGINT and SIGTERM; an interrupted open or write of an output gives up, and an
    // output whose reader went away sets the flag to SIGPIPE (outputs/output_file.hpp).
    OperatorStop();
    ~OperatorStop() { restore(); }
    OperatorStop(const OperatorStop&) = delete;
    OperatorStop& operator=(const OperatorStop&) = delete;
    // Non-zero once a signal came: the signal's number.
    const volatile std::sig_atomic_t* flag() const;
    int signal() const;
    // The exit code for the signal that came: 143 for SIGTERM, else 130.
    ExitCode interrupted_exit() const;
    // Puts back the handlers found (also when the object goes).
    void restore();

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
    bool restored_ = false;
};

} // namespace parsons::cli
