#include "relaylogic/fast_forward.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <optional>

namespace parsons::relaylogic {
namespace {

using axes::floor_div;

constexpr std::int64_t kForever = std::numeric_limits<std::int64_t>::max();
constexpr std::array<std::int64_t, 4> kUnits = {1000, 100, 10, 1}; // digits from the inch down
// Beyond this many numbers the banks could match, stepping one by one is cheaper.
constexpr std::int64_t kMostMatches = 1000;

int mod10(std::int64_t v) {
    return static_cast<int>(((v % 10) + 10) % 10);
}

std::int64_t mod10000(std::int64_t v) {
    return ((v % 10000) + 10000) % 10000;
}

// Impulses until the counter first reads a number: 1 .. 10000 (0 means a full turn).
std::int64_t impulses_until(std::int64_t distance) {
    const std::int64_t j = mod10000(distance);
    return j == 0 ? 10000 : j;
}

// How many relays of a bank a mask closes (at most ten bits: no library call for a popcount).
std::int64_t relays_in(unsigned mask) {
    std::int64_t n = 0;
    for (; mask != 0; mask &= mask - 1) {
        ++n;
    }
    return n;
}

// Calls f(x) for every bit x set in mask, lowest first.
template <typename F>
void each_relay(unsigned mask, F&& f) {
    for (; mask != 0; mask &= mask - 1) {
        f(std::countr_zero(mask));
    }
}

// The least distance(w) over every 4-digit number w whose digit i is in allowed[i] (bit x =
// digit x), or nothing if there are more than kMostMatches such numbers.
template <typename Distance>
std::optional<std::int64_t> least_over_matches(const std::array<unsigned, 4>& allowed,
                                               Distance distance) {
    std::int64_t count = 1;
    for (unsigned mask : allowed) {
        count *= relays_in(mask);
    }
    if (count > kMostMatches) {
        return std::nullopt;
    }
    std::int64_t best = kForever;
    each_relay(allowed[0], [&](int a) {
        each_relay(allowed[1], [&](int b) {
            each_relay(allowed[2], [&](int c) {
                each_relay(allowed[3], [&](int d) {
                    best = std::min(best, distance(((a * std::int64_t{10} + b) * 10 + c) * 10 + d));
                });
            });
        });
    });
    return best;
}

// Absolute comparer 122': the first coming impulse after which it conducts, or kForever.
// Returns nullopt when the banks hold too many numbers to search. With `watch`, the same for
// the readings it watches on this axis instead (condition cards: one a channel).
std::optional<std::int64_t> first_absolute_equality(const AxisCircuit& c,
                                                    const CounterWatch* watch = nullptr) {
    const std::int64_t k0 = c.plant.commutator_index();
    const int d = c.plant.moving_direction();
    const int sigma = c.direction * d;
    std::array<int, 4> offset{};
    for (std::size_t i = 0; i < 4; ++i) {
        const int position = c.absolute_counter.stepping_switch(i).position();
        offset.at(i) = mod10(position - sigma * mod10(floor_div(k0, kUnits.at(i))));
    }
    // The screw digit x of unit i that puts switch i on counter digit v: v = o + sigma x.
    auto screw_digit = [&](std::size_t i, int v) { return mod10(sigma * (v - offset.at(i))); };
    auto distance = [&](std::int64_t w) { return impulses_until(d * (w - k0)); };
    // The first impulse after which the counter reads `number` (a reading, not a bank).
    auto until_reading = [&](int number) {
        const Digits v = value_digits(number);
        std::int64_t w = 0;
        for (std::size_t i = 0; i < 4; ++i) {
            w = w * 10 + screw_digit(i, v.at(i));
        }
        return distance(w);
    };
    if (watch != nullptr) {
        std::int64_t first = kForever;
        watch->each_watched(c.axis, c.direction, [&](int position) {
            first = std::min(first, until_reading(position));
        });
        return first;
    }
    if (c.absolute_storage.separate_registers()) {
        std::int64_t first = kForever;
        for (int number : c.absolute_storage.numbers()) {
            first = std::min(first, until_reading(number));
        }
        return first;
    }
    std::array<unsigned, 4> allowed{};
    for (std::size_t i = 0; i < 4; ++i) {
        each_relay(c.absolute_storage.bank(static_cast<int>(i)).closed_mask(),
                   [&](int v) { allowed.at(i) |= 1U << screw_digit(i, v); });
    }
    return least_over_matches(allowed, distance);
}

// Incremental comparer 122'': the first coming impulse after which it conducts.
std::optional<std::int64_t> first_incremental_equality(const AxisCircuit& c) {
    std::array<unsigned, 4> allowed{};
    for (std::size_t i = 0; i < 4; ++i) {
        allowed.at(i) = c.incremental_storage.bank(static_cast<int>(i)).closed_mask();
    }
    const std::int64_t v = c.increment_counter.value();
    return least_over_matches(allowed, [v](std::int64_t w) { return impulses_until(w - v); });
}

} // namespace

bool soft_limit_trips(const axes::AxisProfile& p, int d, double x, double v) {
    const double coast = v * v / (2 * p.braking_in_per_s2);
    return d > 0 ? x + axes::kInchesPerImpulse + coast > p.soft_max_in
                 : x - axes::kInchesPerImpulse - coast < p.soft_min_in;
}

std::int64_t quiet_impulses(const AxisCircuit& c, const QuietConditions& q) {
    const axes::LeadScrewAxis& plant = c.plant;
    if (!plant.next_event_is_impulse() || q.counting_hundredths || q.faulty_switch_ahead) {
        return 0;
    }
    // No switch may be asked to step sooner than it can: every impulse of this phase comes at
    // least (the least screw travel between impulses) / (its fastest speed) after the one
    // before, and the first one after every switch's last step. Through instrument shaft 74
    // an error table can bring the impulses closer than 0.001 in of screw travel (the
    // profile fuzz finding of issue 11, tests/fuzz/regressions/profile/).
    const double u_max = std::max(plant.phase_start_speed(), plant.phase_end_speed());
    const double ready = q.min_interval_s * (1 + 1e-6);
    if (u_max <= 0 || plant.least_screw_per_impulse() / u_max < ready) {
        return 0;
    }
    double last_step = -axes::kNever;
    for (std::size_t i = 0; i < 4; ++i) {
        last_step = std::max({last_step, c.absolute_counter.stepping_switch(i).last_step_s(),
                              c.increment_counter.stepping_switch(i).last_step_s()});
    }
    if (plant.next_event_time() - last_step < ready) {
        return 0;
    }
    std::int64_t first_event = kForever;
    if (q.next_fault_impulse > c.contact_set_a) {
        first_event = q.next_fault_impulse - c.contact_set_a;
    }
    if (plant.slipping_ahead()) {
        if (plant.impulses_to_slip() < 1) {
            return 0; // slipping now: one impulse at a time
        }
        first_event = std::min(first_event, plant.impulses_to_slip());
    }
    if (!q.machine_stopped) {
        first_event = std::min(first_event, plant.impulses_to_limit());
        if (q.watching_soft_limits) {
            // Exact at constant speed; while the speed changes, judged at the phase's fastest,
            // which trips no later than the real watch (the impulses after go one by one).
            const int d = plant.moving_direction();
            const double v = plant.phase_acceleration() == 0 ? plant.phase_start_speed() : u_max;
            const std::int64_t trips = plant.first_impulse_where(
                [&](double x) { return soft_limit_trips(plant.profile(), d, x, v); });
            if (trips > 0) {
                first_event = std::min(first_event, trips);
            }
        }
    }
    const auto absolute = first_absolute_equality(c);
    const auto incremental = first_incremental_equality(c);
    if (!absolute || !incremental) {
        return 0;
    }
    first_event = std::min({first_event, *absolute, *incremental});
    for (const CounterWatch* watch : q.watches) {
        if (!q.machine_stopped && watch->watching(c.axis)) {
            first_event = std::min(first_event, *first_absolute_equality(c, watch));
        }
    }
    return first_event == kForever ? kForever : first_event - 1;
}

void jump_quiet_impulses(AxisCircuit& c, std::int64_t n) {
    axes::LeadScrewAxis& plant = c.plant;
    const std::int64_t k0 = plant.commutator_index();
    const int d = plant.moving_direction();
    const std::int64_t kn = k0 + d * n;
    // Absolute counter: switch i stepped once for every crossing of a multiple of its unit
    // (the crossing's upper reading), in the sense reversing control 214 set.
    Digits absolute{};
    std::array<double, 4> absolute_last{};
    std::int64_t inch_turns =
        0; // switch 104's net passes 9 -> 0, as one-by-one stepping counts them
    for (std::size_t i = 0; i < 4; ++i) {
        const std::int64_t m = kUnits.at(i);
        const SteppingSwitch& sw = c.absolute_counter.stepping_switch(i);
        const std::int64_t steps = d * (floor_div(kn, m) - floor_div(k0, m));
        absolute.at(i) = mod10(sw.position() + c.direction * steps);
        if (i == 0) {
            inch_turns = floor_div(sw.position() + c.direction * steps, 10);
        }
        absolute_last.at(i) = sw.last_step_s();
        if (steps > 0) {
            // The last impulse of the stretch whose upper reading is a multiple of m.
            const std::int64_t j =
                d > 0 ? floor_div(kn, m) * m - k0 : k0 - (-floor_div(-(kn + 1), m)) * m + 1;
            absolute_last.at(i) = plant.impulse_time(j);
        }
    }
    // Increment counter: a decimal counter of the impulses, 310 first.
    const std::int64_t v = c.increment_counter.value();
    const Digits increment = value_digits(static_cast<int>((v + n) % 10000));
    std::array<double, 4> increment_last{};
    for (std::size_t i = 0; i < 4; ++i) {
        const std::int64_t m = kUnits.at(3 - i);
        increment_last.at(i) = c.increment_counter.stepping_switch(i).last_step_s();
        if ((v + n) / m > v / m) {
            increment_last.at(i) = plant.impulse_time((v + n) / m * m - v);
        }
    }
    const double t_last = plant.impulse_time(n);
    c.absolute_counter.jump(absolute, absolute_last, inch_turns);
    c.increment_counter.jump(increment, increment_last);
    plant.skip_impulses(n);
    c.contact_set_a += n;
    c.contact_set_b += n;
    c.wrong_way += d != c.direction ? n : 0; // (hundredths-only counting is never jumped)
    c.show_contacts();
    c.compare();
    c.speed_switch.equality_left(t_last);
}

} // namespace parsons::relaylogic
