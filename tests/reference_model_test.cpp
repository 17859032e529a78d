// A second, deliberately simple model of the machine checked against the relay-level one.
//
// The reference model is plain integer arithmetic: each card moves each axis by its check
// in the direction of its motion column, modulo the counters' 10 inches, and a valid deck
// always completes. The relay-level emulation must agree on random valid decks, card by card:
// the absolute counters read what the model says at every zeroizing, and the run completes.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/deck_review.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

struct ReferenceModel {
    std::array<int, 5> position{};
    void apply(const CardOrders& card) {
        for (Axis a : kAxes) {
            const AxisOrder& o = card.axis(a);
            const int sign = o.motion == Motion::forward ? +1 : -1;
            int& p = position.at(axis_index(a));
            p = ((p + sign * o.check) % 10000 + 10000) % 10000;
        }
    }
};

// Records the absolute counter of each axis at each zeroizing, by signal id (cheap).
class CounterSnapshots : public MachineObserver {
public:
    void on_signal_defined(const SignalInfo& info, std::uint32_t initial) override {
        values_.push_back(initial);
        for (std::size_t a = 0; a < 5; ++a) {
            if (info.scope != axis_name(kAxes.at(a))) {
                continue;
            }
            const std::array<const char*, 4> names = {
                "absolute_counter_104", "absolute_counter_106", "absolute_counter_108",
                "absolute_counter_110"};
            for (std::size_t d = 0; d < 4; ++d) {
                if (info.name == names.at(d)) {
                    ids_.at(a).at(d) = info.id;
                }
            }
        }
        if (info.name == "zeroizing_circuit_292") {
            zeroize_ = info.id;
        }
    }
    void on_signal(double, SignalId id, std::uint32_t, std::uint32_t v) override {
        values_.at(id) = v;
        if (id == zeroize_ && v == 1) {
            std::array<int, 5> snap{};
            for (std::size_t a = 0; a < 5; ++a) {
                int n = 0;
                for (std::size_t d = 0; d < 4; ++d) {
                    n = n * 10 + static_cast<int>(values_.at(ids_.at(a).at(d)));
                }
                snap.at(a) = n;
            }
            snapshots.push_back(snap);
        }
    }
    std::vector<std::array<int, 5>> snapshots;

private:
    std::vector<std::uint32_t> values_;
    std::array<std::array<SignalId, 4>, 5> ids_{};
    SignalId zeroize_ = 0;
};

// A random sequence pattern set: the axes in a random order, split into consecutive groups;
// a group starting at position p with g axes has all of them punched at p .. p+g-1.
std::array<SequencePattern, 5> random_patterns(std::mt19937& rng) {
    std::array<std::size_t, 5> order = {0, 1, 2, 3, 4};
    std::shuffle(order.begin(), order.end(), rng);
    std::array<SequencePattern, 5> patterns{};
    std::size_t i = 0;
    int position = 1;
    while (i < 5) {
        const std::size_t g = std::min<std::size_t>(5 - i, 1 + rng() % 2);
        SequencePattern bits = 0;
        for (std::size_t k = 0; k < g; ++k) {
            bits =
                static_cast<SequencePattern>(bits | (1u << (position - 1 + static_cast<int>(k))));
        }
        for (std::size_t k = 0; k < g; ++k) {
            patterns.at(order.at(i + k)) = bits;
        }
        position += static_cast<int>(g);
        i += g;
    }
    return patterns;
}

// A valid order from `from` to a random stop: slow-downs 0.200 and 0.100 before the stop as
// the patent advises, fewer on short moves, none where they would share banks spuriously.
AxisOrder random_order(std::mt19937& rng, Axis axis, int from, SequencePattern seq) {
    const int stop = static_cast<int>(rng() % 10000);
    const int travel = std::abs(stop - from);
    const int sign = stop >= from ? +1 : -1;
    AxisOrder o;
    if (travel >= 300 && axis == Axis::table) {
        o = order(from, stop, 1, stop - sign * 200, stop - sign * 100, seq);
    } else if (travel >= 150) {
        o = order(from, stop, 2, stop - sign * 100, std::nullopt, seq);
    } else {
        o = order(from, stop, 3, std::nullopt, std::nullopt, seq);
    }
    if (!spurious_matches_on_path(o, static_cast<Thousandths>(from)).empty()) {
        o = order(from, stop, 3, std::nullopt, std::nullopt, seq);
    }
    return o;
}

} // namespace

TEST_CASE("Reference model: the relay-level machine agrees with plain integer arithmetic on "
          "random valid decks",
          "[cabinet][reference]") {
    std::mt19937 rng(1952);
    const int decks = 40;
    for (int deck = 0; deck < decks; ++deck) {
        const int cards = 1 + static_cast<int>(rng() % 3);
        std::vector<CardOrders> orders;
        std::array<int, 5> at{};
        ReferenceModel model;
        std::vector<std::array<int, 5>> expected;
        for (int n = 0; n < cards; ++n) {
            CardOrders c;
            c.number = n + 1;
            c.spindle = static_cast<Spindle>(rng() % 3);
            const auto patterns = random_patterns(rng);
            for (Axis a : kAxes) {
                const auto i = axis_index(a);
                c.axis(a) = random_order(rng, a, at.at(i), patterns.at(i));
                at.at(i) = c.axis(a).stop;
            }
            orders.push_back(c);
            model.apply(c);
            expected.push_back(model.position);
        }
        CounterSnapshots snaps;
        RunResult r = run_orders(orders, parsons::axes::default_profile(), &snaps);
        INFO("deck " << deck);
        REQUIRE(r.completed);
        CHECK(r.cards_read == cards);
        REQUIRE(snaps.snapshots.size() == expected.size());
        for (std::size_t k = 0; k < expected.size(); ++k) {
            INFO("card " << k + 1);
            CHECK(snaps.snapshots.at(k) == expected.at(k));
        }
        for (std::size_t i = 0; i < 5; ++i) {
            CHECK(std::lround(r.axes.at(i).counter_in * 1000) == model.position.at(i));
            CHECK(std::abs(r.axes.at(i).error_in) < 0.0005);
        }
    }
}

TEST_CASE("Cabinet: any orders at all end, completed or stopped with a reason, never hung",
          "[cabinet][reference]") {
    std::mt19937 rng(2026);
    int completed = 0;
    int stopped = 0;
    for (int deck = 0; deck < 200; ++deck) {
        std::vector<CardOrders> orders;
        const int cards = 1 + static_cast<int>(rng() % 3);
        int number = static_cast<int>(rng() % 10000);
        for (int n = 0; n < cards; ++n) {
            CardOrders c = parsons::test::random_orders(rng, fig8_layout());
            c.number = rng() % 8 == 0 ? c.number : (number + n) % 10000; // mostly in order
            orders.push_back(c);
        }
        const RunResult r = run_orders(orders);
        INFO("deck " << deck);
        CHECK(r.completed != r.stop.has_value());
        CHECK(r.cards_read >= 1);
        CHECK(r.machine_seconds < 1e5); // bounded: limits and checks end every card
        (r.completed ? completed : stopped) += 1;
    }
    CHECK(stopped > 0);
}
