// Helpers of the press-synchronisation tests (an addition after EP 0436887): the press the
// tests run, sync and motion cards built in code, and an independent press's edge times to
// check the cabinet's instants against (tests/press_sync_test.cpp,
// tests/press_position_data_test.cpp).
#pragma once

#include "tests/machine_support.hpp"

#include "axes/press.hpp"

#include <string>

namespace parsons::test {

// parsons-extended with a 2-stroke, 4-pulse-a-degree press (12 deg/s, 48 pulses/s) and
// separate registers.
axes::MachineProfile press_profile();

cardreader::CardOrders sync_card(int number, cardreader::SyncOrder order);
cardreader::SyncOrder position_sync(int angle);
cardreader::SyncOrder speed_sync(cardreader::Axis a, int travel);
cardreader::SyncOrder loop_to(int card, int count);

// The table moves from `from` to `to` at speed 1 with slow-downs 0.100 and 0.050 before the stop;
// every other axis stands.
cardreader::CardOrders table_move(int number, int from, int to);

// Records everything, but lets fast-forward jump (it does not follow impulses).
class SparseRecorder : public Recorder {
public:
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
};

// The pulses detector 10 has given by time t (an independent press).
long count_at(const axes::PressProfile& p, double t);
// The first time a signal changes to `value`, or -1.
double first_time(const Recorder& r, const std::string& signal, std::uint32_t value);
// The n-th time (1 = the first) a signal changes to `value`, or -1.
double nth_time(const Recorder& r, const std::string& signal, std::uint32_t value, int n);
// The time of the edge that brings the count to `count`.
double edge_time(const axes::PressProfile& p, long count);
// Detector pulses an independent press gives in (a, b].
long pulses_between(const axes::PressProfile& p, double a, double b);

} // namespace parsons::test
