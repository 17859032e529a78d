// Running a parsons command line inside a fuzz target's own process, for the cli and argv
// targets.
#pragma once

#include <string>
#include <vector>

namespace parsons::fuzz {

// Runs `parsons ARGS…` through cli::command_line_main in this process with the standard input,
// output and error moved to the descriptors `in`, `out` and `err` for the run (the caller keeps
// and closes them), then puts the process's own streams back; the exit code.
int run_in_process(std::vector<std::string> args, int in, int out, int err);

} // namespace parsons::fuzz
