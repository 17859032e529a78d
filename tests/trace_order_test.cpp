// Traces that show cause before effect (issue 11, item 5): channel 257, contact 238, balancing
// circuit 266, channel 274 / circuit 276 / motor 278, the zeroizing channels 294-304 and each
// commutator's two contact sets are signals, and at one instant a cause is logged before its
// effect, in the observer's events and in the VCD alike.
#include "outputs/traces/trace_outputs.hpp"
#include "tests/machine_support.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

// One card: the table at speed 1 to 2.985 with slow-downs 2.785, 2.885; the others idle.
CardOrders slowing_card(int check = 2985) {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 2985, 1, 2785, 2885, 1);
    c.axis(Axis::table).check = static_cast<Thousandths>(check);
    return c;
}

// Index of the first change of `signal` to `value` at or after `from`; -1 if none.
long find(const Recorder& r, const std::string& signal, std::uint32_t value, long from = 0) {
    for (auto i = static_cast<std::size_t>(from); i < r.changes.size(); ++i) {
        if (r.changes[i].signal == signal && r.changes[i].new_value == value) {
            return static_cast<long>(i);
        }
    }
    return -1;
}

// The changes at one instant, in order, must hold these (signal, value) pairs in this order.
void require_order(const Recorder& r, long anchor,
                   const std::vector<std::pair<std::string, std::uint32_t>>& chain) {
    REQUIRE(anchor >= 0);
    const double t = r.changes.at(static_cast<std::size_t>(anchor)).t;
    long first = anchor;
    while (first > 0 && r.changes.at(static_cast<std::size_t>(first - 1)).t == t) {
        --first;
    }
    long at = first;
    for (const auto& [signal, value] : chain) {
        INFO(signal << " -> " << value);
        const long i = find(r, signal, value, at);
        REQUIRE(i >= 0);
        CHECK(r.changes.at(static_cast<std::size_t>(i)).t == t);
        at = i + 1;
    }
}

} // namespace

TEST_CASE("Trace order: a slow-down runs comparer 122', channel 257, relay 256, switch 236, delay "
          "258 in that order at one instant",
          "[trace][order][fig10]") {
    Recorder rec;
    REQUIRE(run_orders({slowing_card()}, axes::default_profile(), &rec).completed);
    const long to_2 = find(rec, "table.speed_switch_236", 2);
    require_order(rec, to_2,
                  {{"table.absolute_comparer_122a", 1},
                   {"table.channel_257", 1},
                   {"table.stepping_relay_256", 1},
                   {"table.speed_switch_236", 2},
                   {"table.delay_device_258", 1},
                   {"table.channel_257", 0}});
    // Delay 258 lets go exactly its hold time later.
    const long released = find(rec, "table.delay_device_258", 0, to_2);
    REQUIRE(released > 0);
    CHECK(rec.changes.at(static_cast<std::size_t>(released)).t -
              rec.changes.at(static_cast<std::size_t>(to_2)).t ==
          Approx(axes::default_profile().delay_258_s));
}

TEST_CASE("Trace order: the stop runs 236 to off, contact 238, lamps 270 and 272, channel 274, "
          "circuit 276, motor 278 and shaft 280",
          "[trace][order][fig10]") {
    Recorder rec;
    REQUIRE(run_orders({slowing_card()}, axes::default_profile(), &rec).completed);
    const long to_3 = find(rec, "table.speed_switch_236", 3);
    const long off = find(rec, "table.speed_switch_236", 0, to_3);
    require_order(rec, off,
                  {{"table.channel_257", 1},
                   {"table.stepping_relay_256", 1},
                   {"table.speed_switch_236", 0},
                   {"table.contact_238", 1},
                   {"table.lamp_270", 1},
                   {"table.lamp_272", 1},
                   {"cabinet.channel_274", 1},
                   {"cabinet.channel_274", 0},
                   {"cabinet.circuit_276", 1},
                   {"cabinet.motor_278", 1}});
    // One sequence step later: the shaft moves, then motor 278 and circuit 276 let go.
    const long moved = find(rec, "cabinet.stepping_shaft_280", 2, off);
    require_order(
        rec, moved,
        {{"cabinet.stepping_shaft_280", 2}, {"cabinet.motor_278", 0}, {"cabinet.circuit_276", 0}});
}

TEST_CASE("Trace order: a trip runs contact 238, balancing circuit 266, electromagnet 265, master "
          "switch 204 and indicator 268",
          "[trace][order][fig10]") {
    Recorder rec;
    RunResult r = run_orders({slowing_card(2990)}, axes::default_profile(), &rec);
    REQUIRE(r.stop);
    const long off = find(rec, "table.contact_238", 1, find(rec, "table.speed_switch_236", 3));
    require_order(rec, off,
                  {{"table.contact_238", 1},
                   {"table.lamp_270", 1},
                   {"cabinet.balancing_circuit_266", 1},
                   {"cabinet.electromagnet_265", 1},
                   {"cabinet.master_switch_204", 0},
                   {"cabinet.indicator_268", 1}});
    CHECK(rec.value.at("table.lamp_272") == 0); // the dark lamp: comparer 122'' failed
    // The trip sends no stop impulse over channel 274 to the sequence shaft.
    CHECK(find(rec, "cabinet.channel_274", 1, off) == -1);
}

TEST_CASE("Trace order: zeroizing runs contact 290, circuit 292, channel 294 and the absolute "
          "relays, 298 and the incremental ones, 300 and the sequence contacts, 302, 304",
          "[trace][order][fig10]") {
    Recorder rec;
    REQUIRE(run_orders({slowing_card()}, axes::default_profile(), &rec).completed);
    const long home = find(rec, "cabinet.zeroizing_contact_290", 1);
    require_order(rec, home,
                  {{"cabinet.zeroizing_contact_290", 1},
                   {"cabinet.zeroizing_circuit_292", 1},
                   {"cabinet.channel_294", 1},
                   {"table.absolute_storage_356.relay_5", 0},
                   {"cabinet.channel_298", 1},
                   {"table.incremental_storage_318.relay_5", 0},
                   {"cabinet.channel_300", 1},
                   {"table.sequence_switch_224.contact_226", 0},
                   {"cabinet.channel_302", 1},
                   {"cabinet.channel_304", 1}});
    // The reader indexes the next card after channel 304, and the channels fall with it.
    const long fed = find(rec, "cabinet.card_reader_134.card", 2, home);
    CHECK(fed < 0); // a one-card deck: nothing more to feed
    const long fell = find(rec, "cabinet.channel_304", 0, home);
    REQUIRE(fell > home);
    CHECK(rec.changes.at(static_cast<std::size_t>(fell)).t -
              rec.changes.at(static_cast<std::size_t>(home)).t ==
          Approx(axes::default_profile().relay_release_s));
}

TEST_CASE("Trace order: each commutator's contact sets A and B change before the switch they "
          "step, and a dropped impulse shows B behind A",
          "[trace][order][commutator]") {
    Recorder rec;
    REQUIRE(run_orders({slowing_card()}, axes::default_profile(), &rec).completed);
    // The first tenth: commutator 98 and 100 and 102 all change over, then switch 108 steps.
    const long tenth = find(rec, "table.absolute_counter_106", 1);
    require_order(rec, tenth,
                  {{"table.commutator_98.contact_set_a", 1},
                   {"table.commutator_98.contact_set_b", 1},
                   {"table.commutator_100.contact_set_a", 0},
                   {"table.commutator_102.contact_set_a", 0},
                   {"table.absolute_counter_110", 0},
                   {"table.absolute_counter_106", 1}});
    std::size_t a_changes = rec.of("table.commutator_102.contact_set_a").size();
    CHECK(a_changes >= 2985); // one change-over per impulse, coast included
    CHECK(rec.of("table.commutator_102.contact_set_b").size() == a_changes);

    Recorder dropped;
    RunResult r = run_orders({slowing_card()}, axes::default_profile(), &dropped,
                             {drop_impulse(Axis::table, 50)});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::missed_impulse);
    CHECK(dropped.value.at("table.commutator_102.contact_set_a") == 0); // impulse 50: even
    CHECK(dropped.value.at("table.commutator_102.contact_set_b") == 1); // still on 49
}

TEST_CASE("VCD: in each timestamp stepping relay 256 is written before speed switch 236, and "
          "contact 238 after it",
          "[trace][order][vcd]") {
    std::ostringstream out;
    {
        cli::VcdWriter vcd(out, "test date");
        RunResult r = run_orders({slowing_card()}, axes::default_profile(), &vcd);
        REQUIRE(r.completed);
    }
    const std::string text = out.str();
    // Identifier codes by scope.name.
    std::map<std::string, std::string> code;
    std::istringstream header(text.substr(0, text.find("$enddefinitions")));
    std::string token;
    std::string scope;
    while (header >> token) {
        if (token == "$scope") {
            std::string kind;
            header >> kind >> scope;
        } else if (token == "$var") {
            std::string kind, width, id, name;
            header >> kind >> width >> id >> name;
            code[scope + "." + name] = id;
        }
    }
    const std::string relay = code.at("table.stepping_relay_256");
    const std::string sw = code.at("table.speed_switch_236");
    const std::string contact = code.at("table.contact_238");
    std::istringstream body(text.substr(text.find("$enddefinitions")));
    std::string line;
    std::vector<std::string> block;
    int steps_checked = 0;
    int stops_checked = 0;
    auto check_block = [&] {
        long relay_up = -1;
        long switch_at = -1;
        long contact_up = -1;
        for (std::size_t i = 0; i < block.size(); ++i) {
            const std::string& l = block[i];
            if (l == "1" + relay) {
                relay_up = static_cast<long>(i);
            } else if (l.rfind("b", 0) == 0 && l.substr(l.find(' ') + 1) == sw) {
                switch_at = static_cast<long>(i);
            } else if (l == "1" + contact) {
                contact_up = static_cast<long>(i);
            }
        }
        if (relay_up >= 0) {
            REQUIRE(switch_at >= 0);
            CHECK(relay_up < switch_at);
            ++steps_checked;
        }
        if (contact_up >= 0 && switch_at >= 0) {
            CHECK(switch_at < contact_up);
            ++stops_checked;
        }
        block.clear();
    };
    while (std::getline(body, line)) {
        if (!line.empty() && line[0] == '#') {
            check_block();
        } else if (!line.empty() && line[0] != '$') {
            block.push_back(line);
        }
    }
    check_block();
    CHECK(steps_checked == 3); // two slow-downs and the stop
    CHECK(stops_checked >= 1);
}
