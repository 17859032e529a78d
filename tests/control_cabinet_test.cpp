// The control cabinet running decks: the behaviour rules of docs/design-rules.md, end to end.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_io.hpp"

#include <catch2/catch.hpp>

#include <fstream>

using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

// The table counter reading at the moment of each change of `signal` to `to`.
std::vector<int> counter_when(const Recorder& r, const std::string& signal, std::uint32_t to) {
    std::map<std::string, std::uint32_t> v;
    std::vector<int> readings;
    for (const auto& c : r.changes) {
        v[c.signal] = c.new_value;
        if (c.signal == signal && c.new_value == to) {
            readings.push_back(static_cast<int>(
                v["table.absolute_counter_104"] * 1000 + v["table.absolute_counter_106"] * 100 +
                v["table.absolute_counter_108"] * 10 + v["table.absolute_counter_110"]));
        }
    }
    return readings;
}

double first_time(const Recorder& r, const std::string& signal, std::uint32_t to) {
    for (const auto& c : r.of(signal)) {
        if (c.new_value == to) {
            return c.t;
        }
    }
    return -1;
}

double last_time(const Recorder& r, const std::string& signal, std::uint32_t to) {
    double t = -1;
    for (const auto& c : r.of(signal)) {
        if (c.new_value == to) {
            t = c.t;
        }
    }
    return t;
}

// Fig. 10's sequence: table and cross at positions 1-2, vertical and swivel at 3-4, tilt at 5.
CardOrders fig10_sequence_card() {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 300, 3, {}, {}, 0b00011);
    c.axis(Axis::cross) = order(0, 200, 3, {}, {}, 0b00011);
    c.axis(Axis::vertical) = order(0, 100, 3, {}, {}, 0b01100);
    c.axis(Axis::swivel) = order(0, 150, 3, {}, {}, 0b01100);
    c.axis(Axis::tilt) = order(0, 50, 3, {}, {}, 0b10000);
    return c;
}

} // namespace

TEST_CASE("Cabinet: the sample deck completes and every axis ends on the last card's stop",
          "[cabinet]") {
    std::ifstream in(source_path("decks/samples/patent-example.csv"));
    DeckOptions options;
    options.format = DeckFormat::listing;
    options.file_name = "patent-example.csv";
    auto deck = open_card_source(in, options);
    ControlCabinet cabinet(parsons::axes::default_profile(), fig8_layout());
    RunResult r = cabinet.run(*deck);
    CHECK(r.completed);
    CHECK_FALSE(r.stop);
    CHECK(r.cards_read == 4);
    const std::array<double, 5> last_stops = {0.100, 0.000, 0.000, 0.000, 0.000};
    for (std::size_t i = 0; i < 5; ++i) {
        INFO(axis_name(kAxes.at(i)));
        CHECK(r.axes.at(i).counter_in == Approx(last_stops.at(i)).margin(1e-9));
        CHECK(std::abs(r.axes.at(i).error_in) < 0.0005);
        CHECK(r.axes.at(i).lost_steps == 0);
    }
}

TEST_CASE("Sequence: table and cross run first, then vertical and swivel, then tilt (Fig. 10)",
          "[cabinet][sequence][fig10]") {
    const CardOrders c = fig10_sequence_card();
    Recorder rec;
    RunResult r = run_orders({c}, parsons::axes::default_profile(), &rec);
    REQUIRE(r.completed);
    const double table_on = first_time(rec, "table.motor_38", 1);
    const double cross_on = first_time(rec, "cross.motor_50", 1);
    const double vertical_on = first_time(rec, "vertical.motor_46", 1);
    const double swivel_on = first_time(rec, "swivel.motor_44", 1);
    const double tilt_on = first_time(rec, "tilt.motor_40", 1);
    CHECK(table_on == cross_on);
    CHECK(vertical_on == swivel_on);
    CHECK(vertical_on > last_time(rec, "table.motor_38", 0));
    CHECK(vertical_on > last_time(rec, "cross.motor_50", 0));
    CHECK(tilt_on > last_time(rec, "vertical.motor_46", 0));
    CHECK(tilt_on > last_time(rec, "swivel.motor_44", 0));
    // Each motor starts exactly once.
    for (const char* m : {"table.motor_38", "cross.motor_50", "vertical.motor_46",
                          "swivel.motor_44", "tilt.motor_40"}) {
        int starts = 0;
        for (const auto& ch : rec.of(m)) {
            starts += ch.new_value == 1 ? 1 : 0;
        }
        CHECK(starts == 1);
    }
}

TEST_CASE("Sequence: the sample compound-angle deck turns the fixture about swivel and tilt at "
          "once (claim 18): both motors start together on each card, each stops on its own "
          "comparers, and the shaft steps past both before the table's position 3",
          "[cabinet][sequence][fig10]") {
    std::ifstream in(source_path("decks/samples/compound-angle.csv"));
    DeckOptions options;
    options.format = DeckFormat::listing;
    options.file_name = "compound-angle.csv";
    auto deck = open_card_source(in, options);
    ControlCabinet cabinet(parsons::axes::default_profile(), fig8_layout());
    Recorder rec;
    cabinet.attach(&rec);
    const RunResult r = cabinet.run(*deck);
    REQUIRE(r.completed);
    REQUIRE(r.cards_read == 2);
    const auto changes = [&rec](const std::string& signal, std::uint32_t to) {
        std::vector<double> t;
        for (const auto& c : rec.of(signal)) {
            if (c.new_value == to) {
                t.push_back(c.t);
            }
        }
        return t;
    };
    const auto swivel_on = changes("swivel.motor_44", 1);
    const auto tilt_on = changes("tilt.motor_40", 1);
    const auto swivel_stop = changes("swivel.speed_switch_236", 0);
    const auto tilt_stop = changes("tilt.speed_switch_236", 0);
    const auto table_stop = changes("table.speed_switch_236", 0);
    const auto shaft_at_3 = changes("cabinet.stepping_shaft_280", 3);
    REQUIRE(swivel_on.size() == 2);
    REQUIRE(tilt_on.size() == 2);
    REQUIRE(swivel_stop.size() >= 2);
    REQUIRE(tilt_stop.size() >= 2);
    REQUIRE(table_stop.size() >= 2);
    REQUIRE(shaft_at_3.size() == 2);
    for (std::size_t card = 0; card < 2; ++card) {
        INFO("card " << card + 1);
        CHECK(swivel_on.at(card) == tilt_on.at(card));     // together, at the card's relays
        CHECK(swivel_stop.at(card) != tilt_stop.at(card)); // each by its own comparers
        const double both = std::max(swivel_stop.at(card), tilt_stop.at(card));
        CHECK(shaft_at_3.at(card) > both);
        CHECK(table_stop.at(card) >= shaft_at_3.at(card));
    }
    CHECK(r.axes.at(3).counter_in == Approx(4.600).margin(1e-9));
    CHECK(r.axes.at(4).counter_in == Approx(4.700).margin(1e-9));
    CHECK(r.axes.at(3).fixture_angle_deg);
    CHECK(r.axes.at(4).fixture_angle_deg);
}

TEST_CASE("Sequence: simultaneous stops are counted as separate impulses by unit 284",
          "[cabinet][sequence][fig10]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table).sequence = 0b00001; // table and cross both at 1, both with check 0:
    c.axis(Axis::cross).sequence = 0b00001; // they stop at the same instant
    c.axis(Axis::vertical).sequence = 0b00100;
    c.axis(Axis::swivel).sequence = 0b01000;
    c.axis(Axis::tilt).sequence = 0b10000;
    Recorder rec;
    RunResult r = run_orders({c}, parsons::axes::default_profile(), &rec);
    CHECK(r.completed);
    const auto unit = rec.of("cabinet.unit_284");
    REQUIRE_FALSE(unit.empty());
    CHECK(unit.front().new_value == 1);
    // Two impulses: the shaft goes 1 -> 2 -> 3 without an axis stopping at 2.
    const auto shaft = rec.of("cabinet.stepping_shaft_280");
    REQUIRE(shaft.size() >= 2);
    CHECK(shaft[0].new_value == 2);
    CHECK(shaft[1].new_value == 3);
    CHECK(first_time(rec, "vertical.speed_switch_236", 0) >= shaft[1].t);
}

TEST_CASE("Sequence: a pattern that can never enable an axis stops with sequence_stall",
          "[cabinet][sequence]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table).sequence = 0; // never enabled
    c.axis(Axis::cross).sequence = 0b00001;
    c.axis(Axis::vertical).sequence = 0b00010;
    c.axis(Axis::swivel).sequence = 0b00100;
    c.axis(Axis::tilt).sequence = 0b01000;
    RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::sequence_stall);
    CHECK(r.stop->message.find("position 5") != std::string::npos);
    CHECK(r.stop->message.find("table (pattern none)") != std::string::npos);
    CHECK_FALSE(r.completed);
}

TEST_CASE("Card order: a card out of numerical order stops the machine before any axis moves",
          "[cabinet][card-number]") {
    CardOrders first = idle_card(1, {0, 0, 0, 0, 0});
    CardOrders second = idle_card(3, {0, 0, 0, 0, 0});
    second.axis(Axis::table) = order(0, 500, 3, {}, {}, 1);
    RunResult r = run_orders({first, second});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::out_of_order_card);
    CHECK(r.stop->card == 2);
    CHECK(r.stop->message.find("card number 0003 follows 0001 (expected 0002)") !=
          std::string::npos);
    CHECK(r.axes.at(0).impulses == 0);
}

TEST_CASE("Duplicate contacts: an impulse missed by one contact set stops with missed_impulse",
          "[cabinet][faults]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::cross) = order(0, 300, 3, {}, {}, 0b00010);
    RunResult r = run_orders({c}, parsons::axes::default_profile(), nullptr,
                             {drop_impulse(Axis::cross, 120)});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::missed_impulse);
    CHECK(r.stop->axis == Axis::cross);
    CHECK(r.stop->message.find("impulse 120 of commutator 102") != std::string::npos);
    CHECK(r.axes.at(1).counter_in == Approx(0.120).margin(0.0015));
}

TEST_CASE("Speed switch: the table's counter reads 8.785, 8.885 and 8.985 as switch 236 steps "
          "1 to 2, 2 to 3 and 3 to off (the sample deck's card 1, claim 11)",
          "[cabinet][speed-switch][fig10]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 8985, 1, 8785, 8885, 1);
    Recorder rec;
    REQUIRE(run_orders({c}, parsons::axes::default_profile(), &rec).completed);
    CHECK(counter_when(rec, "table.speed_switch_236", 2) == std::vector<int>{8785});
    CHECK(counter_when(rec, "table.speed_switch_236", 3) == std::vector<int>{8885});
    CHECK(counter_when(rec, "table.speed_switch_236", 0) == std::vector<int>{8985});
}

TEST_CASE("Shared banks: a spurious match at 8.050 slows the table early (9.050 with slow-downs "
          "8.850, 8.950)",
          "[cabinet][fig12]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 9050, 1, 8850, 8950, 1);
    Recorder rec;
    RunResult r = run_orders({c}, parsons::axes::default_profile(), &rec);
    const auto to_speed_2 = counter_when(rec, "table.speed_switch_236", 2);
    REQUIRE_FALSE(to_speed_2.empty());
    CHECK(to_speed_2.front() == 8050);
    // It then reaches speed 3 at 8.850 and takes 8.950 for its stop: the check disagrees.
    CHECK(counter_when(rec, "table.speed_switch_236", 3).front() == 8850);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.axes.at(0).counter_in == Approx(8.950));
}

TEST_CASE("Shared banks: with separate registers (a departure) the same card completes",
          "[cabinet][fig12]") {
    auto profile = parsons::axes::default_profile();
    profile.separate_registers = true;
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 9050, 1, 8850, 8950, 1);
    RunResult r = run_orders({c}, profile);
    CHECK(r.completed);
    CHECK(r.axes.at(0).counter_in == Approx(9.050));
}

TEST_CASE("Coast: with a heavy table, slow-downs 0.040 and 0.020 before the stop overshoot and the "
          "next card stops with check_mismatch, 0.200 and 0.100 before complete",
          "[cabinet][coast]") {
    // Delay 258 (0.150 s) hides the numbers passed during its hold, so slow-downs must lie
    // some 0.013 in apart at speed 1; with the default 0.2 in/s2 the table then always brakes
    // in time. A heavy fixture (0.05 in/s2 to change speed, 0.1 to coast to rest) shows rule 7.
    auto heavy = parsons::axes::default_profile();
    heavy.axes.at(0).acceleration_in_per_s2 = 0.05;
    heavy.axes.at(0).braking_in_per_s2 = 0.1;
    auto deck = [](int slow1, int slow2) {
        CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
        one.axis(Axis::table) = order(0, 2985, 1, slow1, slow2, 1);
        CardOrders two = idle_card(2, {2985, 0, 0, 0, 0});
        two.axis(Axis::table) = order(2985, 3985, 3, {}, {}, 1);
        return std::vector<CardOrders>{one, two};
    };
    // 2.945 / 2.965 / 2.985 differ in one digit only: no spurious matches in the shared banks.
    RunResult close = run_orders(deck(2945, 2965), heavy);
    REQUIRE(close.stop);
    CHECK(close.stop->reason == StopReason::check_mismatch);
    CHECK(close.stop->card == 2);
    CHECK(close.stop->axis == Axis::table);
    RunResult proper = run_orders(deck(2785, 2885), heavy);
    CHECK(proper.completed);
    CHECK(proper.axes.at(0).counter_in == Approx(3.985));
    CHECK(std::abs(proper.axes.at(0).error_in) < 0.0005);
}

TEST_CASE("Speed switch: speed column 0 / 0-1 / 0-1-2 steps it one, two, three times from off, "
          "and then three, two, one steps reach off (Fig. 10)",
          "[cabinet][speed-switch][fig10]") {
    auto [speed, slow1, slow2, steps_to_off] = GENERATE(table<int, int, int, int>({
        {1, 2785, 2885, 3},
        {2, 2885, -1, 2},
        {3, -1, -1, 1},
    }));
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) =
        order(0, 2985, speed, slow1 < 0 ? std::nullopt : std::optional<int>(slow1),
              slow2 < 0 ? std::nullopt : std::optional<int>(slow2), 1);
    Recorder rec;
    RunResult r = run_orders({c}, parsons::axes::default_profile(), &rec);
    REQUIRE(r.completed);
    const double motor_on = first_time(rec, "table.motor_38", 1);
    int from_card = 0;
    int from_comparer = 0;
    for (const auto& ch : rec.of("table.speed_switch_236")) {
        (ch.t < motor_on ? from_card : from_comparer) += 1;
    }
    CHECK(from_card == speed);
    CHECK(from_comparer == steps_to_off);
}

TEST_CASE("Stepping rate: impulses faster than the switches can step are lost and show up as "
          "position error",
          "[cabinet][counters]") {
    auto fast = parsons::axes::default_profile();
    fast.axes.at(0).speed_in_per_min = {15.0, 1.8, 0.6}; // 250 impulses/s, switches take 100/s
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 2985, 1, 2785, 2885, 1);
    RunResult r = run_orders({c}, fast);
    CHECK(r.axes.at(0).lost_steps > 0);
    CHECK(std::abs(r.axes.at(0).error_in) > 0.002);
    RunResult normal = run_orders({c});
    CHECK(normal.axes.at(0).lost_steps == 0);
    CHECK(std::abs(normal.axes.at(0).error_in) < 0.0005);
}

TEST_CASE("Travel limits: an axis that runs past its limit stops the machine", "[cabinet]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    c.axis(Axis::table).motion = Motion::reverse; // counts down from 0.000 through 9.999
    c.axis(Axis::table).check = 9900;             // what the counters would count
    RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::limit_switch);
    CHECK(r.axes.at(0).real_in <= -0.5);
}

TEST_CASE("Travel limits: a part at its limit switch stops with limit_switch and the limit-switch "
          "lamp, and the movement range keeps soft_limit",
          "[cabinet][limits]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    c.axis(Axis::table).motion = Motion::reverse; // counts down from 0.000 through 9.999
    c.axis(Axis::table).check = 9900;
    const RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(std::string(stop_reason_name(r.stop->reason)) == "limit_switch");
    CHECK(r.stop->lamps ==
          std::vector<std::string>{"indicator 268", "limit-switch lamp (table; an addition)"});
    // A movement range the same card would pass: soft_limit, before anything moves.
    auto p = parsons::axes::default_profile();
    p.axes.at(0).soft_limits = true;
    p.axes.at(0).soft_min_in = -0.05;
    p.axes.at(0).soft_max_in = 5.0;
    const RunResult soft = run_orders({c}, p);
    REQUIRE(soft.stop);
    CHECK(std::string(stop_reason_name(soft.stop->reason)) == "soft_limit");
    CHECK(soft.axes.at(0).impulses == 0);
    // The stop codes page gives each a row of its own.
    const std::string codes = read_bytes(source_path("docs/stop-codes.md"));
    CHECK(codes.find("| `limit_switch` |") != std::string::npos);
    CHECK(codes.find("| `soft_limit` |") != std::string::npos);
}

TEST_CASE("Bad punch: in parsons-safe a double punch stops the machine naming card and column, "
          "as an addition",
          "[cabinet][bad-punch]") {
    Card card = encode(idle_card(1, {0, 0, 0, 0, 0}), fig8_layout()).card;
    card.punch(13, Row::r5);
    card.punch(13, Row::r7);
    VectorDeck deck({card});
    ControlCabinet cabinet(parsons::axes::safe_profile(), fig8_layout());
    RunResult r = cabinet.run(deck);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::bad_punch);
    CHECK(r.stop->message.find("card 1, column 13: double punch") != std::string::npos);
    CHECK(r.stop->message.find("an addition of this emulator") != std::string::npos);
}

TEST_CASE("Bad punch: in parsons-1952 a double punch in a digit column closes two relays of its "
          "bank, and the comparer conducts at both (rule 12)",
          "[cabinet][bad-punch][fig13]") {
    // Table: speed 3 to 0.300, check 0.300; column 13 (the stop's tenths) also punched in row 1:
    // bank 352 holds relays 1 and 3, so the comparer conducts at 0.100 already.
    CardOrders o = idle_card(1, {0, 0, 0, 0, 0});
    o.axis(Axis::table) = order(0, 300, 3, {}, {}, 1);
    Card card = encode(o, fig8_layout()).card;
    card.punch(13, Row::r1);
    REQUIRE_FALSE(decode(card, fig8_layout()));
    Recorder rec;
    VectorDeck deck({card});
    ControlCabinet cabinet(parsons::axes::default_profile(), fig8_layout());
    cabinet.attach(&rec);
    RunResult r = cabinet.run(deck);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch); // stopped at 0.100, check 0.300
    CHECK(r.axes.at(0).counter_in == Approx(0.100));
    CHECK(rec.value.at("table.absolute_storage_352.relay_1") == 1);
    CHECK(rec.value.at("table.absolute_storage_352.relay_3") == 1);
    CHECK(rec.value.at("table.absolute_storage_352.relay_2") == 0);

    SECTION("a double punch in the check closes two relays of the incremental bank") {
        Card checked = encode(o, fig8_layout()).card;
        checked.punch(17, Row::r1); // check 0.300 also 0.100: 322 holds 1 and 3
        VectorDeck d2({checked});
        ControlCabinet c2(parsons::axes::default_profile(), fig8_layout());
        Recorder r2;
        c2.attach(&r2);
        RunResult rr = c2.run(d2);
        REQUIRE(rr.stop); // at 0.100 comparer 122'' alone conducts: speed 3 steps to off
        CHECK(rr.stop->reason == StopReason::check_mismatch);
        CHECK(rr.stop->lamps.back() == "table lamp 272 (incremental comparer 122'' conducting)");
        CHECK(rr.axes.at(0).counter_in == Approx(0.100));
        CHECK(r2.value.at("table.incremental_storage_322.relay_1") == 1);
        CHECK(r2.value.at("table.incremental_storage_322.relay_3") == 1);
    }
    SECTION("any other bad punch still stops the reader, named as an addition") {
        Card stray = encode(o, fig8_layout()).card;
        stray.punch(76, Row::r5);
        VectorDeck d3({stray});
        ControlCabinet c3(parsons::axes::default_profile(), fig8_layout());
        RunResult s3 = c3.run(d3);
        REQUIRE(s3.stop);
        CHECK(s3.stop->reason == StopReason::bad_punch);
        CHECK(s3.stop->message.find("column 76") != std::string::npos);
        CHECK(s3.stop->message.find("an addition of this emulator") != std::string::npos);
    }
}

TEST_CASE("Screw error: the part is where the screw plus the residual error of cam 160 puts it, "
          "the counters cannot see it, the report can",
          "[cabinet][axes]") {
    auto profile = parsons::axes::default_profile();
    profile.axes.at(0).screw_error_in = {{0.0, 0.0}, {5.0, 0.004}}; // 0.8 thousandths an inch
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 2500, 3, {}, {}, 1);
    RunResult r = run_orders({c}, profile);
    REQUIRE(r.completed);
    CHECK(r.axes.at(0).counter_in == Approx(2.500));
    // The counters read through instrument shaft 74: the stop impulse comes as they pass
    // 2.4995, with the part at 2.4995 plus the residual error there, 0.004 * 2.4995 / 5; the
    // coast then moves the part itself 0.00025 on.
    const double part = 2.4995 + 0.004 * 2.4995 / 5 + 0.00025;
    CHECK(r.axes.at(0).real_in == Approx(part).margin(1e-9));
    CHECK(r.axes.at(0).error_in == Approx(part - 2.5).margin(1e-9));
}

TEST_CASE("Sine plate: the report gives the fixture angles of swivel and tilt", "[cabinet][axes]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::tilt) = order(0, 1000, 3, {}, {}, 0b10000);
    RunResult r = run_orders({c});
    REQUIRE(r.completed);
    // tilt: sin(angle) = (0.99975 - 5) / 10: the stop, a quarter-thousandth short of it, from
    // the level position at mid-travel
    CHECK(*r.axes.at(4).fixture_angle_deg ==
          Approx(std::asin((0.99975 - 5.0) / 10.0) * 180 / 3.14159265358979).margin(1e-6));
    CHECK_FALSE(r.axes.at(0).fixture_angle_deg);
}

TEST_CASE("Counting hundredths at speed 1, the patent's answer to stepping-rate loss, lets a "
          "fast table reach its stop exactly (col. 8)",
          "[cabinet][counters]") {
    auto fast = parsons::axes::default_profile();
    fast.axes.at(0).speed_in_per_min = {9.0, 1.8, 0.6}; // 150 impulses/s; the switches take 100
    fast.axes.at(0).acceleration_in_per_s2 = 10.0;
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    // Slow-downs on whole hundredths, where the standing thousandths switch is right again.
    c.axis(Axis::table) = order(0, 2980, 1, 2780, 2880, 1);
    // Counting every thousandth, the switches lose steps; the increment counter falls behind
    // and the check catches it at the stop.
    RunResult plain = run_orders({c}, fast);
    CHECK(plain.axes.at(0).lost_steps > 0);
    REQUIRE(plain.stop);
    CHECK(plain.stop->reason == StopReason::check_mismatch);
    fast.count_hundredths_at_speed_1 = true;
    Recorder rec;
    RunResult hundredths = run_orders({c}, fast, &rec);
    REQUIRE(hundredths.completed);
    CHECK(hundredths.axes.at(0).lost_steps == 0);
    CHECK(std::abs(hundredths.axes.at(0).error_in) < 0.0005);
    CHECK(hundredths.axes.at(0).counter_in == Approx(2.980));
    // While on speed 1 the thousandths switch 110 stood still: its first step comes after the
    // first slow-down.
    const double slowed = first_time(rec, "table.speed_switch_236", 2);
    REQUIRE(slowed > 0);
    CHECK(first_time(rec, "table.absolute_counter_110", 1) > slowed);
}

TEST_CASE("Counters count as the motion column set them: coast that runs on after the next card "
          "has set reverse is counted down (rule 3)",
          "[cabinet][counters]") {
    // Card 1 takes the table forward at speed 1 with no slow-downs, last in the sequence, so
    // it coasts on after its stop; card 2 sets reverse while the table is still coasting.
    CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
    one.axis(Axis::table) = order(0, 1000, 1, {}, {}, 0b10000);
    one.axis(Axis::tilt).sequence = 0b00001;
    CardOrders two = idle_card(2, {1000, 0, 0, 0, 0});
    two.axis(Axis::table) = order(1000, 900, 3, {}, {}, 0b00001);
    // The earlier reading lets the stop come at speed 1 (incremental equality), so it coasts.
    auto p = parsons::axes::default_profile();
    p.incremental_equality_stops_at_any_speed = true;
    Recorder rec;
    run_orders({one, two}, p, &rec);
    const double reverse_set = first_time(rec, "table.reversing_control_214", 1);
    const double motor_on_again = [&] {
        for (const auto& ch : rec.of("table.motor_38")) {
            if (ch.new_value == 1 && ch.t > reverse_set) {
                return ch.t;
            }
        }
        return 1e9;
    }();
    REQUIRE(reverse_set > 0);
    int counted_down_while_coasting_forward = 0;
    for (const auto& ch : rec.of("table.absolute_counter_110")) {
        if (ch.t > reverse_set && ch.t < motor_on_again) {
            CHECK(ch.new_value == (ch.old_value + 9) % 10); // a step down
            ++counted_down_while_coasting_forward;
        }
    }
    CHECK(counted_down_while_coasting_forward > 0);
}

TEST_CASE("Profile: a card cycle too short for the relays and speed switches is refused",
          "[cabinet][profile]") {
    CHECK_THROWS_WITH(parsons::axes::profile_from_json(R"({"reader_cycle_s": 0.305})",
                                                       parsons::axes::default_profile()),
                      Catch::Contains("second_bank_s + 3 stepping_switch_step_s <= "
                                      "reader_cycle_s must hold"));
    CHECK_NOTHROW(parsons::axes::profile_from_json(R"({"reader_cycle_s": 0.33})",
                                                   parsons::axes::default_profile()));
}

TEST_CASE("Sequence: the spindle's cutting signal follows the last position of the sequence, "
          "position 5 when the tilt runs there",
          "[cabinet][sequence][fig10][mutation]") {
    const CardOrders c = fig10_sequence_card();
    Recorder rec;
    REQUIRE(run_orders({c}, parsons::axes::default_profile(), &rec).completed);
    const std::string cutting = "cabinet.spindle_control_165.cutting";
    const double tilt_on = first_time(rec, "tilt.motor_40", 1);
    const double tilt_off = last_time(rec, "tilt.motor_40", 0);
    REQUIRE(tilt_on > 0);
    // Rises once, as the tilt starts at position 5, and falls as it stops: never while the
    // axes of positions 1-4 run (the swivel still runs at position 4).
    std::vector<Change> rises;
    for (const auto& ch : rec.of(cutting)) {
        if (ch.new_value == 1) {
            rises.push_back(ch);
        }
    }
    REQUIRE(rises.size() == 1);
    CHECK(rises.front().t == tilt_on);
    CHECK(last_time(rec, cutting, 0) >= tilt_off); // as the shaft steps on from position 5

    SECTION("with the spindle off nothing cuts, whatever runs at position 5") {
        CardOrders off = c;
        off.spindle = Spindle::off;
        Recorder r;
        REQUIRE(run_orders({off}, parsons::axes::default_profile(), &r).completed);
        CHECK(first_time(r, cutting, 1) == -1);
        CHECK(first_time(r, "tilt.motor_40", 1) > 0);
    }
}

TEST_CASE("Profile: the card cycle must leave the first bank's relays relay_operate_s to pick "
          "before the second bank senses the card",
          "[cabinet][profile][mutation]") {
    using parsons::axes::default_profile;
    using parsons::axes::profile_from_json;
    // first_bank_s 0.15 + relay_operate_s 0.15 reaches second_bank_s 0.30 exactly: refused.
    CHECK_THROWS_WITH(profile_from_json(R"({"relay_operate_s": 0.15})", default_profile()),
                      Catch::Contains("first_bank_s + relay_operate_s < second_bank_s"));
    CHECK_NOTHROW(profile_from_json(R"({"relay_operate_s": 0.149})", default_profile()));
    // The same rule read from the other side: the first bank moved up to the relays' time.
    CHECK_THROWS_WITH(
        profile_from_json(R"({"first_bank_s": 0.2, "relay_operate_s": 0.1})", default_profile()),
        Catch::Contains("first_bank_s + relay_operate_s < second_bank_s"));
    CHECK_NOTHROW(
        profile_from_json(R"({"first_bank_s": 0.2, "relay_operate_s": 0.099})", default_profile()));
}

TEST_CASE("Profile: braking below 0.001 in/s2, the least an axis may have, is refused",
          "[cabinet][profile][mutation]") {
    using parsons::axes::default_profile;
    using parsons::axes::profile_from_json;
    CHECK_THROWS_WITH(
        profile_from_json(R"({"axes": {"cross": {"braking_in_per_s2": 0.0009}}})",
                          default_profile()),
        Catch::Contains("braking_in_per_s2: must be a number at least 0.001, not 0.0009"));
    const auto least = profile_from_json(R"({"axes": {"cross": {"braking_in_per_s2": 0.001}}})",
                                         default_profile());
    CHECK(least.axes.at(1).braking_in_per_s2 == 0.001);
    // Its neighbour, the acceleration, has the same floor.
    CHECK_THROWS_WITH(
        profile_from_json(R"({"axes": {"cross": {"acceleration_in_per_s2": 0.0009}}})",
                          default_profile()),
        Catch::Contains("acceleration_in_per_s2: must be a number at least 0.001, not 0.0009"));
    CHECK_NOTHROW(profile_from_json(R"({"axes": {"cross": {"acceleration_in_per_s2": 0.001}}})",
                                    default_profile()));
}

TEST_CASE("Profile: limit switches at one place (travel_min_in equal to travel_max_in) are "
          "refused",
          "[cabinet][profile][mutation]") {
    using parsons::axes::default_profile;
    using parsons::axes::profile_from_json;
    CHECK_THROWS_WITH(
        profile_from_json(R"({"axes": {"tilt": {"travel_min_in": 2, "travel_max_in": 2}}})",
                          default_profile()),
        Catch::Contains("travel_min_in must be below travel_max_in"));
    CHECK_THROWS_WITH(
        profile_from_json(R"({"axes": {"tilt": {"travel_min_in": 3, "travel_max_in": 2}}})",
                          default_profile()),
        Catch::Contains("travel_min_in must be below travel_max_in"));
    CHECK_NOTHROW(profile_from_json(
        R"({"axes": {"tilt": {"travel_min_in": 2, "travel_max_in": 2.001}}})", default_profile()));
}
