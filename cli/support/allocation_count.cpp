#include "cli/support/allocation_count.hpp"

#include <atomic>
#include <cstdlib>
#include <new>

#if defined(__SANITIZE_ADDRESS__)
#define PARSONS_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PARSONS_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef PARSONS_COUNT_ALLOCATIONS
#define PARSONS_COUNT_ALLOCATIONS 1
#endif

namespace {
std::atomic<std::uint64_t> g_allocations{0};
} // namespace

namespace parsons::cli {

bool allocations_counted() {
    return PARSONS_COUNT_ALLOCATIONS != 0;
}

std::uint64_t allocations() {
    return g_allocations.load(std::memory_order_relaxed);
}

} // namespace parsons::cli

#if PARSONS_COUNT_ALLOCATIONS
#if defined(__GNUC__) && !defined(__clang__)
// GCC pairs a new expression it sees here with the free below; this operator new is malloc.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
// The replaceable global allocation functions ([new.delete.single]): operator new[] and the
// nothrow forms call this one by default, and the deletes free what malloc gave.
void* operator new(std::size_t size) {
    g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) {
        return p;
    }
    throw std::bad_alloc();
}

void operator delete(void* p) noexcept {
    std::free(p);
}

void operator delete(void* p, std::size_t /*size*/) noexcept {
    std::free(p);
}
#endif
