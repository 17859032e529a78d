#include "tests/fuzz/fuzz_targets.hpp"

#include <array>

namespace parsons::fuzz {
namespace {

constexpr std::array<FuzzTarget, 12> kTargets = {{
    {"cbn", "column-binary decks (.cbn), as SIMH writes them", fuzz_cbn},
    {"bin", "IBM 1130 binary decks (.bin)", fuzz_bin},
    {"text", "80-column text card images, in 029 and 026 code", fuzz_text},
    {"listing", "the listing (.csv): one row per axis per card", fuzz_listing},
    {"tape", "eight-channel perforated tape (.tape), 161 frames a card", fuzz_tape},
    {"five", "five per-axis cards a step (.five), reassembled into one", fuzz_five},
    {"airfoil", "airfoil coordinate files (.dat), Selig and Lednicer", fuzz_airfoil},
    {"profile", "machine profiles (JSON), then a short run with the profile", fuzz_profile},
    {"gcode", "G-code programs (gen gcode), then the deck made of them", fuzz_gcode},
    {"machine", "a short valid-looking deck, some punches flipped, run on the machine",
     fuzz_machine},
    {"cli", "command lines whose outputs name inputs, other outputs, links, - and /dev/null",
     fuzz_cli},
    {"argv",
     "command lines of every command's options, from the completion's definitions, "
     "with hostile values",
     fuzz_argv},
}};

} // namespace

std::span<const FuzzTarget> fuzz_targets() {
    return kTargets;
}

const FuzzTarget* fuzz_target_named(std::string_view name) {
    for (const FuzzTarget& t : kTargets) {
        if (t.name == name) {
            return &t;
        }
    }
    return nullptr;
}

} // namespace parsons::fuzz
