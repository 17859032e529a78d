#include "relaylogic/counters.hpp"

#include <catch2/catch.hpp>

using namespace parsons::relaylogic;

TEST_CASE("Stepping switch: ten positions, a carry on the tenth step, a borrow going back",
          "[counters]") {
    SteppingSwitch sw;
    for (int i = 1; i <= 9; ++i) {
        CHECK_FALSE(sw.step(+1, i, 0.01).carry);
    }
    CHECK(sw.position() == 9);
    auto s = sw.step(+1, 10, 0.01);
    CHECK(s.taken);
    CHECK(s.carry);
    CHECK(sw.position() == 0);
    CHECK(sw.step(-1, 11, 0.01).carry);
    CHECK(sw.position() == 9);
}

TEST_CASE("Stepping switch: an impulse sooner than its stepping time is lost", "[counters]") {
    SteppingSwitch sw;
    CHECK(sw.step(+1, 1.000, 0.010).taken);
    CHECK_FALSE(sw.step(+1, 1.005, 0.010).taken);
    CHECK(sw.step(+1, 1.010, 0.010).taken);
    CHECK(sw.position() == 2);
    CHECK(sw.lost() == 1);
}

TEST_CASE("Increment counter 112: switches 310-316 carry into each other over channel 333 "
          "(Fig. 11)",
          "[counters][fig11]") {
    Tracer tracer;
    IncrementCounter counter(tracer, "table");
    for (int i = 0; i < 1234; ++i) {
        counter.impulse(i, 0.01);
    }
    CHECK(counter.digits() == Digits{1, 2, 3, 4});
    counter.clear();
    CHECK(counter.value() == 0);
}

TEST_CASE("Absolute counter 104-110: each switch steps only on its own commutator (Fig. 12)",
          "[counters][fig12]") {
    Tracer tracer;
    AbsoluteCounter counter(tracer, "table");
    // 0.099 -> 0.100: commutators 102, 100 and 98 close together.
    for (int i = 0; i < 99; ++i) {
        counter.impulse(+1, (i + 1) % 10 == 0, false, false, i, 0.01);
    }
    CHECK(counter.value() == 99);
    counter.impulse(+1, true, true, false, 100, 0.01);
    CHECK(counter.value() == 100);
    // Only the thousandths commutator: the others stay where they are (no carry).
    counter.impulse(+1, false, false, false, 101, 0.01);
    CHECK(counter.value() == 101);
    counter.impulse(-1, false, false, false, 102, 0.01);
    CHECK(counter.value() == 100);
}
