// The keys of a sweep's grid (cli/sweep_command.cpp): how each reaches its case, as an option
// of `parsons gen FAMILY` (without its dashes) or as a value of the case's profile
// (profile.SECTION...KEY), and the check of every key and value before any case runs.
#pragma once

#include "cli/commands.hpp"
#include "cli/support/cli11_fwd.hpp"
#include "cli/support/sweep_grid.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

// How a key reaches its case: an option of gen FAMILY, or a value of the case's profile.
struct KeyUse {
    std::string key;
    bool profile_value = false; // profile.SECTION...KEY
    std::string pointer;        // its JSON pointer in the profile ("/axes/table/lead_in")
    bool positional = false;    // gen gcode's PROGRAM
    bool several = false;       // an option of several values (--tools 1 2): split at spaces
};

// gen FAMILY's command line (the one parsons has), for looking its options up and parsing a
// case's.
class GenCommandLine {
public:
    GenCommandLine();
    ~GenCommandLine();
    GenCommandLine(const GenCommandLine&) = delete;
    GenCommandLine& operator=(const GenCommandLine&) = delete;
    // gen's subcommand `name`; throws DeckError naming the families when there is none.
    CLI::App* family(const std::string& name);
    // Parses `parsons gen ARGS...`; CLI11's message when it refuses them.
    std::optional<std::string> refusal(const std::vector<std::string>& args);

private:
    std::unique_ptr<CLI::App> app_;
    Command selected_;
};

// The key's use in `family`; throws DeckError naming it when gen FAMILY has no such option, or
// the sweep sets it itself (output, to, job-out, centres, json).
KeyUse key_use(CLI::App& family, const std::string& key);

// The arguments of `parsons gen FAMILY` for one case's gen options (profile values aside).
std::vector<std::string> gen_args(const std::string& family, const std::vector<KeyUse>& uses,
                                  const std::vector<std::string>& values);

// The profile a case's profile values start from: its "profile" key, else gen FAMILY's own
// default (parsons-extended for the additions' jobs), else "" (the 1952 machine).
std::string base_profile(CLI::App& family, const std::vector<KeyUse>& uses,
                         const std::vector<std::string>& values);

// The case's profile as JSON text: the base with each profile value set. Throws DeckError
// naming the key when the profile has no such key or the value is not of its kind.
std::string case_profile(const std::string& base, const std::vector<KeyUse>& uses,
                         const std::vector<std::string>& values);

// Checks every key and value of the grid before a case runs: each value of each key with the
// first case's other values, through gen's command line and, for profile values, the profile
// loaded as a run loads it (a probe file in `scratch`). Throws DeckError naming the first
// refused; the keys' uses otherwise.
std::vector<KeyUse> check_grid(GenCommandLine& gen, const SweepGrid& grid,
                               const std::string& scratch);

} // namespace parsons::cli
