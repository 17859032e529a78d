// How many times this process has allocated from the heap, for `parsons bench`'s allocations
// a card (docs/performance.md). The count is kept by this program's own global operator new,
// a relaxed increment and nothing else; builds with AddressSanitizer keep the sanitizer's own
// (it checks every new against its delete) and count nothing.
#pragma once

#include <cstdint>

namespace parsons::cli {

// Whether this build counts (false under AddressSanitizer).
bool allocations_counted();
// Heap allocations through operator new since the process started.
std::uint64_t allocations();

} // namespace parsons::cli
