// PC 130 and gear ratio data memory 12a of EP 0360190 (Mitsubishi), an addition: the
// PC's ladder (Fig. 4 left, S1-S8), the NC's operation I (Fig. 4 right, S11-S16), the stored
// ratios of the second embodiment (Figs. 5-7, S31-S33), the faults stale-ratio and
// transfer-hang, busy() and the state file. The two units are driven scan by scan as the
// cabinet drives them (the PC, then the NC, in the same instant) with the real spindle plant.
#include "tests/machine_support.hpp"

#include "axes/spindle.hpp"
#include "relaylogic/tapping/gear_ratio_memory.hpp"
#include "relaylogic/tapping/programmable_controller.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace parsons;
using namespace parsons::relaylogic;
using parsons::test::Change;
using parsons::test::Recorder;

namespace {

// Scans of 1/8 s and an exchange of 1/2 s: every time below is exact in binary.
axes::SpindleSyncProfile pc_profile(axes::RatioSource source = axes::RatioSource::transferred) {
    axes::SpindleSyncProfile p;
    p.pc_scan_s = 0.125;
    p.head_change_s = 0.5;
    p.ratio_source = source;
    return p; // heads: T1 0.25, T2 1/3, T3 0.5; T1 on the spindle
}

// PC 130, the NC's side with 12a, bus 35 and the spindle, scanned as the cabinet scans them.
struct Rig {
    explicit Rig(const axes::SpindleSyncProfile& p)
        : profile(p), pc(tracer, p), nc(tracer, p), spindle(p) {
        spindle.mount(p.first_tool);
        tracer.attach(&rec);
    }

    // The spindle moved to t, then one scan of the PC and one of the NC at t.
    void scan_at(double when) {
        while (spindle.next_event_time() <= when) {
            spindle.advance_to(spindle.next_event_time());
        }
        spindle.advance_to(when);
        tracer.set_time(when);
        pc.scan(when, bus, spindle);
        nc.scan(when, bus);
        t = when + profile.pc_scan_s;
    }
    // n scans at the PC's pace; the row after each.
    std::vector<std::string> scans(int n) {
        std::vector<std::string> out;
        for (int i = 0; i < n; ++i) {
            scan_at(t);
            out.push_back(row());
        }
        return out;
    }
    // Scans until busy() is false (at most `limit`); their rows.
    std::vector<std::string> scans_while_busy(int limit = 100) {
        std::vector<std::string> out;
        while (pc.busy(bus) && static_cast<int>(out.size()) < limit) {
            scan_at(t);
            out.push_back(row());
        }
        return out;
    }

    std::uint32_t v(const std::string& name) const { return rec.value.at("spindle." + name); }
    std::string flag(const std::string& name, const char* shown) const {
        return v(name) != 0 ? shown : "---";
    }
    // Relays CR1-CR8 (digit = picked), the bus's lines (request, ready, data valid, received,
    // tool ready), what the data lines and register 132 hold, the NC's step, the head on the
    // spindle, 12a, buffer 9, the NC's request_since and busy(): all from the trace but the
    // head, since and busy.
    std::string row() const {
        static const std::array<const char*, 8> relays = {
            "cr1_tool_call",    "cr2_exchange", "cr3_exchanged", "cr4_head_on",
            "cr5_ratio_change", "cr6_request",  "cr7_transfer",  "cr8_done"};
        std::string r;
        for (std::size_t i = 0; i < relays.size(); ++i) {
            r += v(std::string("pc130.") + relays.at(i)) != 0 ? static_cast<char>('1' + i) : '-';
        }
        return fmt::format("{} {} {} {} {} {} lines={} reg={} S{} head={} 12a={} buf={} since={} "
                           "{}",
                           r, flag("bus35.transfer_request", "req"), flag("bus35.nc_ready", "rdy"),
                           flag("bus35.data_valid", "dat"), flag("bus35.nc_received", "rcv"),
                           flag("bus35.tool_ready", "trd"), v("bus35.data_ratio"),
                           v("pc130.register_132"), v("nc10.operation_i"), spindle.tool(),
                           v("memory_12a.ratio"), v("interface_9.buffer"), nc.request_since_s(),
                           pc.busy(bus) ? "busy" : "idle");
    }

    axes::SpindleSyncProfile profile;
    Tracer tracer;
    Recorder rec;
    ProgrammableController pc;
    GearRatioMemory nc;
    axes::Spindle spindle;
    Bus35 bus;
    double t = 0; // the next scan's time
};

// The changes of one signal after time `after`.
std::vector<Change> changes_after(const Recorder& r, double after) {
    std::vector<Change> out;
    for (const Change& c : r.changes) {
        if (c.t > after) {
            out.push_back(c);
        }
    }
    return out;
}

bool same(const std::vector<Change>& a, const std::vector<Change>& b) {
    if (a.size() != b.size()) {
        return false;
    }
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (a[i].t != b[i].t || a[i].signal != b[i].signal || a[i].old_value != b[i].old_value ||
            a[i].new_value != b[i].new_value) {
            return false;
        }
    }
    return true;
}

// The first embodiment with an exchange from T1 to T2, scan by scan (t = 0, 0.125, ...).
const std::vector<std::string> kTransfer = {
    // S1: CR1 sees the call of T2; CR2's timer runs 0.125 .. 0.625 with the motor at rest
    "1------- --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 busy",
    "12------ --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 busy",
    "12------ --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 busy",
    "12------ --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 busy",
    "12------ --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 busy",
    // 0.625: the timer is done, T2's head is on (CR3); its switch (CR4) a scan later
    "1-3----- --- --- --- --- --- lines=0 reg=0 S0 head=2 12a=250000 buf=0 since=-1 busy",
    "1-34---- --- --- --- --- --- lines=0 reg=0 S0 head=2 12a=250000 buf=0 since=-1 busy",
    // S2 yes, S3: T2's ratio into register 132
    "1-345--- --- --- --- --- --- lines=0 reg=333333 S0 head=2 12a=250000 buf=0 since=-1 busy",
    // S4 the request; the NC sees it (S11) at 1.0, S12, S13 ready
    "1-3456-- req --- --- --- --- lines=0 reg=333333 S11 head=2 12a=250000 buf=0 since=1 busy",
    "1-3456-- req --- --- --- --- lines=0 reg=333333 S12 head=2 12a=250000 buf=0 since=1 busy",
    "1-3456-- req rdy --- --- --- lines=0 reg=333333 S13 head=2 12a=250000 buf=0 since=1 busy",
    // S5 yes, S6: the data on the lines; S14 into the buffer, S15 received
    "1-34567- req rdy dat --- --- lines=333333 reg=333333 S14 head=2 12a=250000 buf=333333 "
    "since=1 busy",
    "1-34567- req rdy dat rcv --- lines=333333 reg=333333 S15 head=2 12a=250000 buf=333333 "
    "since=1 busy",
    // S8 yes: request and data drop, tool ready; the NC's S16 into 12a
    "1-34---8 --- rdy --- rcv trd lines=0 reg=333333 S16 head=2 12a=333333 buf=333333 since=-1 "
    "busy",
    // the NC sees the request gone: ready and received drop; nothing more to do
    "1-34---8 --- --- --- --- trd lines=0 reg=333333 S0 head=2 12a=333333 buf=0 since=-1 idle",
};

} // namespace

TEST_CASE("PC 130: a head exchange then the ratio's transfer, every step of Fig. 4 a scan of "
          "its own, none early",
          "[pc130][fig4]") {
    Rig rig(pc_profile());
    CHECK(rig.nc.ratio() == 0.25);
    CHECK_FALSE(rig.pc.busy(rig.bus));
    rig.bus.tool_call = 2;
    CHECK(rig.pc.busy(rig.bus)); // a call not yet answered

    CHECK(rig.scans_while_busy() == kTransfer);
    CHECK(rig.pc.exchanges() == 1);
    CHECK(rig.pc.transfers() == 1);
    CHECK(rig.nc.received() == 1);
    CHECK(rig.nc.ratio() == 1.0 / 3.0); // exactly the head's ratio
    CHECK(rig.spindle.ratio() == 1.0 / 3.0);
    CHECK_FALSE(rig.nc.transfer_under_way());
    CHECK(rig.bus.tool_ready);

    // Nothing moves while the call stands and nothing is pending.
    const std::string last = kTransfer.back();
    CHECK(rig.scans(3) == std::vector<std::string>(3, last));

    // The NC clears its call at the end of the card: the PC drops everything in one scan.
    rig.bus.tool_call = 0;
    CHECK(rig.pc.busy(rig.bus));
    CHECK(rig.scans_while_busy() ==
          std::vector<std::string>{"-------- --- --- --- --- --- lines=0 reg=333333 S0 head=2 "
                                   "12a=333333 buf=0 since=-1 idle"});
    CHECK_FALSE(rig.bus.tool_ready);
}

TEST_CASE("PC 130: the exchange completes at the first scan at or after head_change_s, never "
          "before",
          "[pc130][fig4]") {
    axes::SpindleSyncProfile p = pc_profile();
    p.head_change_s = 0.45;
    Rig rig(p);
    rig.bus.tool_call = 3;
    rig.scan_at(0.0);   // CR1
    rig.scan_at(0.125); // CR2: the timer starts
    REQUIRE(rig.pc.exchanging());
    const double done = 0.125 + 0.45;
    rig.scan_at(std::nextafter(done, 0.0));
    CHECK(rig.spindle.tool() == 1);
    CHECK(rig.pc.exchanges() == 0);
    CHECK(rig.pc.exchanging());
    CHECK(rig.v("pc130.cr3_exchanged") == 0);
    rig.scan_at(done);
    CHECK(rig.spindle.tool() == 3);
    CHECK(rig.pc.exchanges() == 1);
    CHECK_FALSE(rig.pc.exchanging());
    CHECK(rig.v("pc130.cr2_exchange") == 0);
    CHECK(rig.v("pc130.cr3_exchanged") == 1);
    CHECK(rig.v("pc130.cr4_head_on") == 0); // its switch is read at the next scan

    // At the PC's pace, 0.45 s after 0.125 is first reached by the scan at 0.625.
    Rig paced(p);
    paced.bus.tool_call = 3;
    const auto rows = paced.scans(6);
    CHECK(rows.at(4).substr(0, 8) == "12------");
    CHECK(rows.at(4).find("head=1") != std::string::npos);
    CHECK(rows.at(5).substr(0, 8) == "1-3-----");
    CHECK(rows.at(5).find("head=3") != std::string::npos);
}

TEST_CASE("PC 130: the exchange waits for the motor at rest", "[pc130][fig4]") {
    Rig rig(pc_profile());
    rig.spindle.command_rpm(60.0);
    rig.bus.tool_call = 2;
    // 0 .. 0.5: the motor turns; CR1 stands, CR2 does not pick, and the PC stays busy.
    for (const std::string& row : rig.scans(5)) {
        CHECK(row.substr(0, 8) == "1-------");
        CHECK(row.find("busy") != std::string::npos);
    }
    // Run down from 60 rev/min at 320 rev/min/s: at rest at 0.6875, after the scan at 0.625.
    rig.spindle.command_rpm(0.0);
    CHECK(rig.scans(1).at(0).substr(0, 8) == "1-------");
    CHECK_FALSE(rig.spindle.at_rest());
    rig.scan_at(rig.t); // 0.75
    REQUIRE(rig.spindle.at_rest());
    CHECK(rig.v("pc130.cr2_exchange") == 1);
    rig.scans(3); // 0.875 .. 1.125: the timer runs 0.75 .. 1.25
    CHECK(rig.spindle.tool() == 1);
    rig.scan_at(rig.t); // 1.25
    CHECK(rig.spindle.tool() == 2);
    CHECK(rig.pc.exchanges() == 1);
}

TEST_CASE("PC 130: the called head already on: no exchange, no transfer, tool ready at the "
          "third scan",
          "[pc130][fig4]") {
    Rig rig(pc_profile());
    rig.bus.tool_call = 1;
    CHECK(rig.scans_while_busy() ==
          std::vector<std::string>{
              "1------- --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 "
              "busy",
              "1--4---- --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 "
              "busy",
              "1--4---8 --- --- --- --- trd lines=0 reg=0 S0 head=1 12a=250000 buf=0 since=-1 "
              "idle"});
    CHECK(rig.pc.exchanges() == 0);
    CHECK(rig.pc.transfers() == 0);
    CHECK(rig.nc.received() == 0);
    CHECK(rig.rec.of("spindle.bus35.transfer_request").empty());
}

TEST_CASE("Memory 12a: the run starts with the first tool's ratio (not the first head's)",
          "[pc130][fig6]") {
    axes::SpindleSyncProfile p = pc_profile();
    p.first_tool = 3;
    Tracer tracer;
    GearRatioMemory nc(tracer, p);
    CHECK(nc.ratio() == 0.5);
    p.first_tool = 9; // no such head: nothing stored
    GearRatioMemory none(tracer, p);
    CHECK(none.ratio() == 0.0);
}

TEST_CASE("PC 130 and 12a, second embodiment: the head exchanged, no transfer, and the NC selects "
          "the ratio stored for the tool (S31-S33)",
          "[pc130][fig7]") {
    Rig rig(pc_profile(axes::RatioSource::stored));
    rig.bus.tool_call = 3;
    const auto rows = rig.scans_while_busy();
    REQUIRE(rows.size() == 8); // 0 CR1, 1-4 timer, 5 mounted, 6 CR4, 7 CR8
    CHECK(rows.at(5).substr(0, 8) == "1-3-----");
    CHECK(rows.at(6).substr(0, 8) == "1-34----");
    CHECK(rows.back() ==
          "1-34---8 --- --- --- --- trd lines=0 reg=0 S0 head=3 12a=250000 buf=0 since=-1 idle");
    for (std::size_t i = 0; i + 1 < rows.size(); ++i) {
        CHECK(rows.at(i).find("trd") == std::string::npos); // tool ready only at the end
    }
    CHECK(rig.pc.exchanges() == 1);
    CHECK(rig.pc.transfers() == 0);
    CHECK(rig.rec.of("spindle.bus35.transfer_request").empty());
    CHECK(rig.rec.of("spindle.bus35.data_valid").empty());
    CHECK(rig.nc.ratio() == 0.25); // the PC does not touch 12a

    CHECK(rig.nc.select(3)); // S31-S33
    CHECK(rig.nc.ratio() == 0.5);
    CHECK(rig.v("memory_12a.ratio") == 500000);
    CHECK(rig.nc.select(2));
    CHECK(rig.nc.ratio() == 1.0 / 3.0);
    CHECK_FALSE(rig.nc.select(7)); // nothing stored for T7: 12a unchanged
    CHECK(rig.nc.ratio() == 1.0 / 3.0);
    CHECK(rig.nc.received() == 0);
}

TEST_CASE("PC 130, fault stale-ratio: at the Nth exchange S2 answers no, so the head is exchanged, "
          "nothing is requested and 12a keeps the old ratio",
          "[pc130][faults]") {
    Rig rig(pc_profile());
    rig.pc.stale_ratio_at(2);
    // Exchange 1 (T1 -> T2) transfers as usual.
    rig.bus.tool_call = 2;
    CHECK(rig.scans_while_busy() == kTransfer);
    rig.bus.tool_call = 0;
    rig.scans_while_busy();
    // Exchange 2 (T2 -> T3): tool ready two scans after the head is on, no request.
    const double from = rig.t - 0.0625; // before the next scan
    rig.bus.tool_call = 3;
    const auto rows = rig.scans_while_busy();
    REQUIRE(rows.size() == 8);
    CHECK(rows.at(6).substr(0, 8) == "1-34----");
    CHECK(rows.back() ==
          "1-34---8 --- --- --- --- trd lines=0 reg=333333 S0 head=3 12a=333333 buf=0 since=-1 "
          "idle");
    CHECK(rig.spindle.ratio() == 0.5);  // the real head turns the tool at 0.5 ...
    CHECK(rig.nc.ratio() == 1.0 / 3.0); // ... the NC computes with T2's
    CHECK(rig.pc.exchanges() == 2);
    CHECK(rig.pc.transfers() == 1);
    CHECK(rig.nc.received() == 1);
    CHECK(changes_after(rig.rec, from).size() > 0);
    for (const Change& c : changes_after(rig.rec, from)) {
        CHECK(c.signal != "spindle.bus35.transfer_request");
        CHECK(c.signal != "spindle.nc10.operation_i");
    }
}

TEST_CASE("PC 130, fault transfer-hang: request and ready stand, the data never arrives, busy "
          "forever, request_since where it started",
          "[pc130][faults]") {
    // The PC in S6 without data, the NC in S13 with ready up.
    const auto hung_row = [](int reg, int head, int ratio_12a, double since) {
        return fmt::format(
            "1-34567- req rdy --- --- --- lines=0 reg={} S13 head={} 12a={} buf=0 since={} busy",
            reg, head, ratio_12a, since);
    };

    SECTION("the first transfer hangs") {
        Rig rig(pc_profile());
        rig.pc.transfer_hang_at(1);
        rig.bus.tool_call = 2;
        const auto rows = rig.scans(200);
        // As kTransfer up to S13; from the scan of S6 on it stands.
        for (std::size_t i = 0; i < 11; ++i) {
            CHECK(rows.at(i) == kTransfer.at(i));
        }
        for (std::size_t i = 11; i < rows.size(); ++i) {
            CHECK(rows.at(i) == hung_row(333333, 2, 250000, 1.0));
        }
        CHECK(rig.pc.busy(rig.bus));
        CHECK(rig.nc.transfer_under_way());
        CHECK(rig.nc.request_since_s() == 1.0);
        CHECK(rig.pc.transfers() == 1);
        CHECK(rig.nc.received() == 0);
        CHECK(rig.rec.of("spindle.bus35.data_valid").empty());
        CHECK(rig.rec.of("spindle.bus35.data_ratio").empty());
    }
    SECTION("transfers count apart from exchanges: stale at exchange 1, hang at transfer 1 (the "
            "second exchange's)") {
        Rig rig(pc_profile());
        rig.pc.stale_ratio_at(1);
        rig.pc.transfer_hang_at(1);
        rig.bus.tool_call = 2;
        CHECK(rig.scans_while_busy().back().substr(0, 8) == "1-34---8"); // stale: no transfer
        CHECK(rig.pc.transfers() == 0);
        rig.bus.tool_call = 0;
        rig.scans_while_busy();
        rig.bus.tool_call = 3;                  // exchange 2, transfer 1: hangs
        const double start = rig.t + 8 * 0.125; // call, 4 timer scans, mount, CR4, CR5, request
        const auto rows = rig.scans(100);
        CHECK(rows.back() == hung_row(500000, 3, 250000, start));
        CHECK(rig.nc.request_since_s() == start);
        CHECK(rig.pc.busy(rig.bus));
        CHECK(rig.pc.transfers() == 1);
        CHECK(rig.nc.ratio() == 0.25);
    }
}

TEST_CASE("PC 130: a call that names another tool with no scan between drops the last answer "
          "first, then answers the new tool from S1",
          "[pc130][fig4]") {
    Rig rig(pc_profile());
    rig.bus.tool_call = 2;
    CHECK(rig.scans_while_busy() == kTransfer);
    rig.bus.tool_call = 3;
    CHECK(rig.pc.busy(rig.bus));
    const auto rows = rig.scans_while_busy();
    REQUIRE(rows.size() == 16);
    CHECK(rows.at(0) ==
          "-------- --- --- --- --- --- lines=0 reg=333333 S0 head=2 12a=333333 buf=0 since=-1 "
          "busy");
    CHECK(rows.at(1).substr(0, 8) == "1-------");
    CHECK(rows.at(2).substr(0, 8) == "12------");
    CHECK(rows.at(6).find("head=3") != std::string::npos);
    for (std::size_t i = 0; i + 2 < rows.size(); ++i) {
        CHECK(rows.at(i).find("trd") == std::string::npos);
    }
    CHECK(rows.back() ==
          "1-34---8 --- --- --- --- trd lines=0 reg=500000 S0 head=3 12a=500000 buf=0 since=-1 "
          "idle");
    CHECK(rig.pc.exchanges() == 2);
    CHECK(rig.pc.transfers() == 2);
}

TEST_CASE("PC 130: an exchange once started completes, busy, though the call is withdrawn or "
          "changed",
          "[pc130][fig4]") {
    Rig rig(pc_profile());
    rig.bus.tool_call = 2;
    rig.scans(2); // CR1, CR2: the timer runs 0.125 .. 0.625

    SECTION("withdrawn") {
        rig.bus.tool_call = 0;
        const auto rows = rig.scans_while_busy();
        REQUIRE(rows.size() == 4); // 0.25 .. 0.625
        for (std::size_t i = 0; i < 3; ++i) {
            CHECK(rows.at(i) == "-2------ --- --- --- --- --- lines=0 reg=0 S0 head=1 12a=250000 "
                                "buf=0 since=-1 busy");
        }
        CHECK(rows.back() == "-------- --- --- --- --- --- lines=0 reg=0 S0 head=2 12a=250000 "
                             "buf=0 since=-1 idle");
        CHECK(rig.pc.exchanges() == 1);
    }
    SECTION("another tool called: T2's head goes on, then T3 is answered with its own exchange") {
        rig.bus.tool_call = 3;
        const auto rows = rig.scans_while_busy();
        CHECK(rows.at(2).substr(0, 8) == "-2------");          // 0.5: CR1 waits for the timer
        CHECK(rows.at(3).find("head=2") != std::string::npos); // 0.625: T2 mounted, CR1 for T3
        CHECK(rows.at(3).substr(0, 8) == "1-------");
        CHECK(rows.at(4).substr(0, 8) == "12------");
        CHECK(rows.back().find("trd") != std::string::npos);
        CHECK(rows.back().find("head=3 12a=500000") != std::string::npos);
        CHECK(rig.pc.exchanges() == 2);
        CHECK(rig.pc.transfers() == 1);
    }
}

TEST_CASE("PC 130: a tool with no head is not answered and keeps nothing busy", "[pc130]") {
    Rig rig(pc_profile());
    rig.bus.tool_call = 7;
    CHECK_FALSE(rig.pc.busy(rig.bus));
    CHECK(rig.scans(3) == std::vector<std::string>(3, "-------- --- --- --- --- --- lines=0 "
                                                      "reg=0 S0 head=1 12a=250000 buf=0 "
                                                      "since=-1 idle"));
}

TEST_CASE("PC 130 and 12a: saved at any scan of an exchange and transfer, loaded into fresh "
          "units, the run continues identically",
          "[pc130][state]") {
    const int at = GENERATE(0, 2, 5, 7, 8, 9, 10, 11, 12, 13);
    Rig whole(pc_profile());
    whole.bus.tool_call = 2;
    std::vector<double> since;
    std::vector<bool> busy;
    for (int i = 0; i < 16; ++i) {
        whole.scan_at(whole.t);
        since.push_back(whole.nc.request_since_s());
        busy.push_back(whole.pc.busy(whole.bus));
    }

    Rig first(pc_profile());
    first.bus.tool_call = 2;
    first.scans(at + 1);
    const std::string pc_state = first.pc.save().dump();
    const std::string nc_state = first.nc.save().dump();
    const std::string bus_state = save_bus35(first.bus).dump();
    const std::string spindle_state = first.spindle.save().dump();
    const std::string trace_state = first.tracer.save().dump();

    // Fresh units, the tracer's values loaded before the recorder is attached.
    axes::SpindleSyncProfile p = pc_profile();
    Tracer tracer;
    Recorder rec;
    ProgrammableController pc(tracer, p);
    GearRatioMemory nc(tracer, p);
    axes::Spindle spindle(p);
    pc.load(nlohmann::json::parse(pc_state));
    nc.load(nlohmann::json::parse(nc_state));
    spindle.load(nlohmann::json::parse(spindle_state));
    Bus35 bus = load_bus35(nlohmann::json::parse(bus_state));
    tracer.load(nlohmann::json::parse(trace_state));
    tracer.attach(&rec);
    CHECK(bus == first.bus);
    CHECK(nc.request_since_s() == first.nc.request_since_s());
    CHECK(pc.busy(bus) == first.pc.busy(first.bus));

    for (int i = at + 1; i < 16; ++i) {
        const double when = 0.125 * i;
        tracer.set_time(when);
        pc.scan(when, bus, spindle);
        nc.scan(when, bus);
        INFO("scan " << i << " after a save at " << at);
        CHECK(nc.request_since_s() == since.at(static_cast<std::size_t>(i)));
        CHECK(pc.busy(bus) == busy.at(static_cast<std::size_t>(i)));
    }
    CHECK(same(rec.changes, changes_after(whole.rec, 0.125 * at)));
    CHECK(bus == whole.bus);
    CHECK(spindle.tool() == 2);
    CHECK(pc.exchanges() == whole.pc.exchanges());
    CHECK(pc.transfers() == whole.pc.transfers());
    CHECK(nc.received() == whole.nc.received());
    CHECK(nc.ratio() == whole.nc.ratio());
    CHECK(pc.save() == whole.pc.save());
    CHECK(nc.save() == whole.nc.save());
}
