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

TEST_CASE("Zeroizing: channel 300 opens the sequence contacts and nothing else, delay 258 of the "
          "last stop runs out in its own time, and device 288 breaks circuit 276 after its "
          "impulse until channel 302",
          "[trace][order][fig10][rule5][rule8]") {
    Recorder rec;
    const axes::MachineProfile profile = axes::default_profile();
    // A second card, so that the reader has indexed it (channel 304) before 258 lets go.
    REQUIRE(
        run_orders({slowing_card(), idle_card(2, {2985, 0, 0, 0, 0})}, profile, &rec).completed);
    const long opened = find(rec, "cabinet.channel_300", 1);
    REQUIRE(opened >= 0);
    const double t300 = rec.changes.at(static_cast<std::size_t>(opened)).t;
    // "…opens all the contacts of the sequence switch mechanisms 224 through channel 300…"
    // (col. 13): no speed switch, stepping relay or delay device changes at that instant.
    for (const Change& ch : rec.changes) {
        if (ch.t != t300) {
            continue;
        }
        INFO(ch.signal);
        CHECK(ch.signal.find("speed_switch_236") == std::string::npos);
        CHECK(ch.signal.find("stepping_relay_256") == std::string::npos);
        CHECK(ch.signal.find("delay_device_258") == std::string::npos);
    }
    // The last axis to stop (the tilt, position 5) stops one shaft step before zeroizing; its
    // delay 258 (0.150 s) outlasts that step (0.100 s) and lets go at its stop + its hold time.
    const long stop = find(rec, "tilt.speed_switch_236", 0, find(rec, "tilt.speed_switch_236", 3));
    REQUIRE(stop >= 0);
    const double stopped = rec.changes.at(static_cast<std::size_t>(stop)).t;
    REQUIRE(stopped + profile.delay_258_s > t300);
    const long released = find(rec, "tilt.delay_device_258", 0, stop);
    REQUIRE(released > opened);
    CHECK(rec.changes.at(static_cast<std::size_t>(released)).t ==
          Approx(stopped + profile.delay_258_s));
    CHECK(find(rec, "tilt.stepping_relay_256", 0, stop) == released + 1);
    CHECK(find(rec, "cabinet.card_reader_134.card", 2) < released);

    // Device 288: closed while circuit 276 delivers the first impulse (the table's, position
    // 1), broken behind the table once it has (bit 1 of device_288).
    const long first_276 = find(rec, "cabinet.circuit_276", 1);
    const long first_288 = find(rec, "cabinet.device_288", 1);
    REQUIRE(first_276 >= 0);
    REQUIRE(first_288 > first_276);
    const long end_276 = find(rec, "cabinet.circuit_276", 0, first_276);
    CHECK(rec.changes.at(static_cast<std::size_t>(first_288)).t ==
          rec.changes.at(static_cast<std::size_t>(end_276)).t);
    CHECK(first_288 > end_276);
    // It falls once, at channel 302, and nothing before channel 302 closes it.
    const auto falls = [&rec] {
        std::vector<Change> f;
        for (const Change& ch : rec.of("cabinet.device_288")) {
            if (ch.new_value == 0) {
                f.push_back(ch);
            }
        }
        return f;
    }();
    REQUIRE(falls.size() == 2); // once a card, from every axis's break (1+2+4+8+16)
    CHECK(falls.front().old_value == 31);
    const long ch302 = find(rec, "cabinet.channel_302", 1);
    const long fell = find(rec, "cabinet.device_288", 0);
    REQUIRE(ch302 >= 0);
    CHECK(fell > ch302);
    CHECK(falls.front().t == rec.changes.at(static_cast<std::size_t>(ch302)).t);
}

TEST_CASE("Device 288: cabinet.device_288 holds the axes whose path it broke, one bit an axis, "
          "set as the step each axis's impulse drove is done, in the order the axes stopped, and "
          "cleared at channel 302",
          "[trace][order][fig10]") {
    // The sequence runs against the axis order: tilt at position 1, vertical 2, cross 3,
    // swivel 4, table 5 (every axis idle: each stops at once when its position comes).
    CardOrders card = idle_card(1, {0, 0, 0, 0, 0});
    const std::array<std::pair<Axis, int>, 5> at = {{{Axis::tilt, 1},
                                                     {Axis::vertical, 2},
                                                     {Axis::cross, 3},
                                                     {Axis::swivel, 4},
                                                     {Axis::table, 5}}};
    for (const auto& [axis, position] : at) {
        card.axis(axis).sequence = static_cast<SequencePattern>(1U << (position - 1));
    }
    Recorder rec;
    REQUIRE(
        run_orders({card, idle_card(2, {0, 0, 0, 0, 0})}, axes::default_profile(), &rec).completed);
    // By hand: bits tilt 16, vertical 4, cross 2, swivel 8, table 1, added one a step.
    const std::vector<std::uint32_t> expected = {16, 20, 22, 30, 31, 0};
    std::vector<std::uint32_t> seen;
    for (const Change& ch : rec.of("cabinet.device_288")) {
        seen.push_back(ch.new_value);
        if (seen.size() == expected.size()) {
            break; // card 1's; card 2's follow
        }
    }
    CHECK(seen == expected);
    // Each break comes at the end of the shaft step that axis's impulse drove (circuit 276
    // lets go at the same instant), and the tilt's stop (contact 238) came before its break.
    const long tilt_stop = find(rec, "tilt.contact_238", 1);
    const long first = find(rec, "cabinet.device_288", 16);
    REQUIRE(tilt_stop >= 0);
    REQUIRE(first > tilt_stop);
    const long end_276 = find(rec, "cabinet.circuit_276", 0, tilt_stop);
    REQUIRE(end_276 >= 0);
    CHECK(rec.changes.at(static_cast<std::size_t>(first)).t ==
          rec.changes.at(static_cast<std::size_t>(end_276)).t);
    // The last break (the table's, 31) stands until channel 302 clears every one.
    const long ch302 = find(rec, "cabinet.channel_302", 1);
    const long cleared = find(rec, "cabinet.device_288", 0);
    REQUIRE(ch302 >= 0);
    CHECK(cleared > ch302);
}

TEST_CASE("Zeroizing: a delay 258 that outlasts the card cycle still holds channel 257 open on the "
          "next card: an equality standing when that card is read is not passed, and the axis runs "
          "on past its stop",
          "[machine][rule5][rule8]") {
    // Card 1 moves the tilt 0.010 in at position 5 (the last stop, one shaft step before
    // zeroizing). Card 2 leaves it there (stop 0.010, check 0) on every position, so its stop
    // equality stands when card 2's reading is complete. With delay 258 at 1.5 s the hold of
    // card 1's stop still runs then: zeroizing does not reset it (col. 13 names what channels
    // 294-304 do, and a timed delay is not among them).
    axes::MachineProfile profile = axes::default_profile();
    CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
    one.axis(Axis::tilt) = order(0, 10, 3, {}, {}, 16);
    CardOrders two = idle_card(2, {0, 0, 0, 0, 10});
    two.axis(Axis::tilt).sequence = 31;

    Recorder held_rec;
    profile.delay_258_s = 1.5;
    const RunResult held = run_orders({one, two}, profile, &held_rec);
    // The hold lets go when its time is up, on card 2.
    const long stop =
        find(held_rec, "tilt.speed_switch_236", 0, find(held_rec, "tilt.speed_switch_236", 3));
    const long released = find(held_rec, "tilt.delay_device_258", 0, stop);
    REQUIRE(released >= 0);
    CHECK(held_rec.changes.at(static_cast<std::size_t>(released)).t ==
          Approx(held_rec.changes.at(static_cast<std::size_t>(stop)).t + 1.5));
    CHECK(find(held_rec, "cabinet.card_reader_134.card", 2) < released);
    // The tilt left its stop before the hold ran out, so the next time its counters read
    // 0.010 is a whole turn of them later (10.000 in).
    CHECK(held.axes.at(axis_index(Axis::tilt)).impulses == 10010);

    // With the default hold (0.150 s, over by card 2) the same deck stops the tilt at once.
    const RunResult short_hold = run_orders({one, two}, axes::default_profile());
    REQUIRE(short_hold.completed);
    CHECK(short_hold.axes.at(axis_index(Axis::tilt)).impulses == 10);
}
