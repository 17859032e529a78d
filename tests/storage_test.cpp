#include "relaylogic/counters.hpp"
#include "relaylogic/storage.hpp"

#include <catch2/catch.hpp>

using namespace parsons::relaylogic;

TEST_CASE("Absolute storage: 8.785 / 8.885 / 8.985 close relay 8 of 350, relays 7, 8, 9 of 352, "
          "relay 8 of 354 and relay 5 of 356 (Fig. 12)",
          "[storage][fig12]") {
    Tracer tracer;
    AbsoluteStorage storage(tracer, "table", false);
    storage.store({8785, 8885, 8985});
    CHECK(storage.bank(0).closed_relays() == std::vector<int>{8});
    CHECK(storage.bank(1).closed_relays() == std::vector<int>{7, 8, 9});
    CHECK(storage.bank(2).closed_relays() == std::vector<int>{8});
    CHECK(storage.bank(3).closed_relays() == std::vector<int>{5});
    CHECK(storage.conducts(value_digits(8785)));
    CHECK(storage.conducts(value_digits(8885)));
    CHECK(storage.conducts(value_digits(8985)));
    CHECK_FALSE(storage.conducts(value_digits(8784)));
    CHECK_FALSE(storage.conducts(value_digits(8986)));
    storage.clear();
    for (int b = 0; b < 4; ++b) {
        CHECK(storage.bank(b).closed_relays().empty());
    }
    CHECK_FALSE(storage.conducts(value_digits(8985)));
}

TEST_CASE("Absolute storage: shared banks also conduct at spurious numbers (9.050 with 8.850, "
          "8.950 matches 8.050), separate registers do not",
          "[storage][fig12]") {
    Tracer tracer;
    AbsoluteStorage shared(tracer, "table", false);
    shared.store({8850, 8950, 9050});
    CHECK(shared.conducts(value_digits(8050)));
    CHECK(shared.conducts(value_digits(9850)));
    AbsoluteStorage separate(tracer, "cross", true);
    separate.store({8850, 8950, 9050});
    CHECK_FALSE(separate.conducts(value_digits(8050)));
    CHECK(separate.conducts(value_digits(8950)));
}

TEST_CASE("Incremental storage: 0.485 closes relay 0 of 324, 4 of 322, 8 of 320, 5 of 318 and the "
          "comparer conducts when counter 112 reaches 0.485 (Fig. 11)",
          "[storage][counters][fig11]") {
    Tracer tracer;
    IncrementalStorage storage(tracer, "table");
    storage.store(485);
    CHECK(storage.bank(0).closed_relays() == std::vector<int>{0}); // 324
    CHECK(storage.bank(1).closed_relays() == std::vector<int>{4}); // 322
    CHECK(storage.bank(2).closed_relays() == std::vector<int>{8}); // 320
    CHECK(storage.bank(3).closed_relays() == std::vector<int>{5}); // 318
    IncrementCounter counter(tracer, "table");
    for (int i = 1; i <= 484; ++i) {
        counter.impulse(i * 0.1, 0.01);
        INFO("impulse " << i);
        REQUIRE_FALSE(storage.conducts(counter.digits()));
    }
    counter.impulse(48.5, 0.01);
    CHECK(counter.value() == 485);
    CHECK(storage.conducts(counter.digits()));
    counter.impulse(48.6, 0.01);
    CHECK_FALSE(storage.conducts(counter.digits()));
}
