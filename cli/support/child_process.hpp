// parsons running itself as a child process: `parsons sweep` runs each case as `parsons gen`
// then `parsons run`, so that each case is a whole, separate machine (its own memory, its own
// exit code) and the cases of a sweep run on every core.
//
// Only the parsons executable may do it: main.cpp registers the process as parsons before the
// command line runs. An embedding of the command line (the WebAssembly page, the cli fuzz
// target, a test program) is no parsons executable, and a command that would start children
// refuses there (exit 2) rather than start copies of the embedding.
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace parsons::cli {

// Called by main.cpp: this process is the parsons executable (/proc/self/exe).
void register_parsons_executable();
bool parsons_executable_registered();

// Starts `parsons ARGS...` (args without the program's name), standard input from /dev/null,
// standard output and error to the files `out` and `err` (made or emptied). Returns its pid.
// Throws DeckError when it cannot be started, or when this process is no parsons executable.
pid_t start_parsons(const std::vector<std::string>& args, const std::string& out,
                    const std::string& err);

// A child that ended: its exit code, or 128 + the signal that ended it.
struct ChildEnd {
    pid_t pid = -1;
    int exit_code = 0;
};

// Waits for any child to end. nullopt-like pid -1 when the wait was interrupted by a signal
// (the caller looks at its operator's stop) or there is no child.
ChildEnd wait_for_child();

} // namespace parsons::cli
