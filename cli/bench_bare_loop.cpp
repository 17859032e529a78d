// The bare stepping-chain loop (cli/bench_bare_loop.hpp).
#include "cli/bench_bare_loop.hpp"

#include "relaylogic/counters.hpp"
#include "relaylogic/tracer.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

namespace parsons::cli::bench {

BareLoop bare_stepping_chain(std::int64_t impulses, int runs) {
    constexpr double kInterval = 1e-4;      // 10,000 impulses a second
    constexpr double kMinInterval = 0.5e-4; // the switches could take twice that
    BareLoop out;
    out.impulses = impulses;
    std::vector<double> times;
    for (int r = 0; r < runs; ++r) {
        relaylogic::Tracer tracer; // no observer: as the impulse level runs
        relaylogic::AbsoluteCounter absolute(tracer, "bare");
        relaylogic::IncrementCounter increment(tracer, "bare");
        const auto t0 = std::chrono::steady_clock::now();
        for (std::int64_t k = 1; k <= impulses; ++k) {
            // Commutators 100, 98, 96 close with 102 when the reading passes a whole
            // hundredth, tenth or inch (axes/lead_screw_axis.hpp, take_impulse).
            const bool hundredths = k % 10 == 0;
            const bool tenths = hundredths && k % 100 == 0;
            const bool inches = tenths && k % 1000 == 0;
            const double t = static_cast<double>(k) * kInterval;
            absolute.impulse(+1, hundredths, tenths, inches, t, kMinInterval);
            increment.impulse(t, kMinInterval);
        }
        times.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        out.reading = absolute.value() + increment.value();
    }
    std::sort(times.begin(), times.end());
    out.seconds = times.at(times.size() / 2);
    return out;
}

} // namespace parsons::cli::bench
