// The libFuzzer entry point, compiled once per target with PARSONS_FUZZ_TARGET naming it
// ("cbn", "machine", ...). libFuzzer supplies main(); a Finding or any other exception that
// leaves the target ends the process and libFuzzer keeps the input as a crash.
#include "tests/fuzz/fuzz_targets.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const parsons::fuzz::FuzzTarget* const target = [] {
        const auto* t = parsons::fuzz::fuzz_target_named(PARSONS_FUZZ_TARGET);
        if (t == nullptr) {
            std::fprintf(stderr, "no fuzz target named '%s'\n", PARSONS_FUZZ_TARGET);
            std::abort();
        }
        return t;
    }();
    target->run({data, size});
    return 0;
}
