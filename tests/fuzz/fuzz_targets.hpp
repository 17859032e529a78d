// The fuzz targets: one per reader of outside input, and one that runs the whole machine.
//
// A target takes any bytes and must end in one of two ways: a result, or the error the reader
// documents for a bad file (cardreader::DeckError for decks and airfoil files,
// axes::ProfileError for machine profiles). Each target then checks what must hold of a
// result it accepted (a card written and read back is the same card; an accepted profile
// runs the machine to an end; a run ends completed or stopped with a reason). Anything else
// -- another exception, a Finding, a crash, a sanitizer report, a hang -- is a finding.
//
// The bodies live in this small library so that two programs share them: the libFuzzer
// executables (fuzz_main.cpp, built with -DPARSONS_FUZZ=ON and clang) and the Catch2 replay
// test (tests/fuzz_replay_test.cpp, in the regular suite), which feeds every kept input under
// tests/fuzz/corpus/<target>/ and tests/fuzz/regressions/<target>/ to the same function.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/card.hpp"
#include "relaylogic/faults.hpp"

#include <vector>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace parsons::fuzz {

using Bytes = std::span<const std::uint8_t>;

// The input as text, byte for byte.
inline std::string as_string(Bytes input) {
    return {reinterpret_cast<const char*>(input.data()), input.size()};
}

// A property of an accepted input that does not hold. Thrown, never caught by a target.
class Finding : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

struct FuzzTarget {
    std::string_view name; // also the folder of its corpus and regressions
    std::string_view what; // one line for docs and --help
    void (*run)(Bytes input);
};

// Every target, in the order the docs list them.
std::span<const FuzzTarget> fuzz_targets();
// The target of that name, or nullptr.
const FuzzTarget* fuzz_target_named(std::string_view name);

// The targets themselves (reader_targets.cpp, source_targets.cpp, machine_target.cpp).
void fuzz_cbn(Bytes input);
void fuzz_bin(Bytes input);
void fuzz_text(Bytes input);
void fuzz_listing(Bytes input);
void fuzz_tape(Bytes input);
void fuzz_five(Bytes input);
void fuzz_airfoil(Bytes input);
void fuzz_profile(Bytes input);
void fuzz_gcode(Bytes input);
void fuzz_machine(Bytes input);
void fuzz_cli(Bytes input);  // cli_target.cpp
void fuzz_argv(Bytes input); // argv_target.cpp
// The command line (after "parsons") the argv target makes of an input; `non_finite` (may be
// null) is set to the last number option given NaN or an infinity.
std::vector<std::string> argv_command_line(Bytes input, std::string* non_finite = nullptr);

// The deck the machine target makes of an input, the profile it runs it with and (if asked)
// the faults of its spindle byte (for the tests that its seeds reach what they are for).
std::vector<cardreader::Card> machine_deck(Bytes input, axes::MachineProfile& profile,
                                           std::vector<relaylogic::Fault>* faults = nullptr);

} // namespace parsons::fuzz
