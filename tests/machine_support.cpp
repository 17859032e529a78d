#include "tests/machine_support.hpp"

#include <catch2/catch.hpp>

namespace parsons::test {

using namespace parsons::cardreader;

void Recorder::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
    names_.push_back(info.scope + "." + info.name);
    value[names_.back()] = initial;
}

void Recorder::on_signal(double t, relaylogic::SignalId id, std::uint32_t old_value,
                         std::uint32_t new_value) {
    const std::string& name = names_.at(id);
    changes.push_back({t, name, old_value, new_value});
    value[name] = new_value;
    if (name == "cabinet.zeroizing_circuit_292" && new_value == 1) {
        at_zeroize.push_back(value);
    }
}

std::vector<Change> Recorder::of(const std::string& signal) const {
    std::vector<Change> out;
    for (const auto& c : changes) {
        if (c.signal == signal) {
            out.push_back(c);
        }
    }
    return out;
}

int Recorder::counter(const std::map<std::string, std::uint32_t>& s, const std::string& axis) {
    return static_cast<int>(
        s.at(axis + ".absolute_counter_104") * 1000 + s.at(axis + ".absolute_counter_106") * 100 +
        s.at(axis + ".absolute_counter_108") * 10 + s.at(axis + ".absolute_counter_110"));
}

AxisOrder order(int from, int stop, int speed, std::optional<int> slow1, std::optional<int> slow2,
                SequencePattern seq) {
    AxisOrder o;
    o.motion = stop >= from ? Motion::forward : Motion::reverse;
    o.start_speed = speed;
    if (slow1) {
        o.slow_down[0] = static_cast<Thousandths>(*slow1);
    }
    if (slow2) {
        o.slow_down[1] = static_cast<Thousandths>(*slow2);
    }
    o.stop = static_cast<Thousandths>(stop);
    o.check = static_cast<Thousandths>(stop > from ? stop - from : from - stop);
    o.sequence = seq;
    return o;
}

CardOrders idle_card(int number, const std::array<int, 5>& at) {
    CardOrders c;
    c.number = number;
    c.spindle = Spindle::forward;
    for (Axis a : kAxes) {
        const int p = at.at(axis_index(a));
        c.axis(a) = order(p, p, 3, {}, {}, static_cast<SequencePattern>(1u << axis_index(a)));
    }
    return c;
}

relaylogic::RunResult run_orders(const std::vector<CardOrders>& cards,
                                 const axes::MachineProfile& profile,
                                 relaylogic::MachineObserver* observer,
                                 const std::vector<relaylogic::Fault>& faults,
                                 relaylogic::Pace pace) {
    std::vector<Card> punched;
    for (const auto& o : cards) {
        auto e = encode(o, fig8_layout());
        if (!e) {
            throw std::runtime_error(*e.error);
        }
        punched.push_back(e.card);
    }
    VectorDeck deck(punched);
    relaylogic::ControlCabinet cabinet(profile, fig8_layout());
    cabinet.set_pace(pace);
    for (const auto& f : faults) {
        cabinet.add_fault(f);
    }
    if (observer != nullptr) {
        cabinet.attach(observer);
    }
    return cabinet.run(deck);
}

void require_same(const relaylogic::RunResult& a, const relaylogic::RunResult& b) {
    REQUIRE(a.completed == b.completed);
    REQUIRE(a.cards_read == b.cards_read);
    REQUIRE(a.machine_seconds == b.machine_seconds);
    REQUIRE(a.stop.has_value() == b.stop.has_value());
    if (a.stop) {
        REQUIRE(a.stop->reason == b.stop->reason);
        REQUIRE(a.stop->card == b.stop->card);
        REQUIRE(a.stop->axis == b.stop->axis);
        REQUIRE(a.stop->message == b.stop->message);
        REQUIRE(a.stop->lamps == b.stop->lamps);
    }
    for (std::size_t i = 0; i < a.axes.size(); ++i) {
        INFO("axis " << i);
        REQUIRE(a.axes.at(i).counter_in == b.axes.at(i).counter_in);
        REQUIRE(a.axes.at(i).counted_in == b.axes.at(i).counted_in);
        REQUIRE(a.axes.at(i).real_in == b.axes.at(i).real_in);
        REQUIRE(a.axes.at(i).impulses == b.axes.at(i).impulses);
        REQUIRE(a.axes.at(i).lost_steps == b.axes.at(i).lost_steps);
        REQUIRE(a.axes.at(i).slip_in == b.axes.at(i).slip_in);
        REQUIRE(a.axes.at(i).screw_in == b.axes.at(i).screw_in);
        REQUIRE(a.axes.at(i).commutator_in == b.axes.at(i).commutator_in);
        REQUIRE(a.axes.at(i).wrong_way == b.axes.at(i).wrong_way);
        REQUIRE(a.axes.at(i).thousandths_uncounted == b.axes.at(i).thousandths_uncounted);
        REQUIRE(a.axes.at(i).chain.sum() == Approx(b.axes.at(i).chain.sum()).margin(1e-12));
    }
    REQUIRE(a.faults.size() == b.faults.size());
    for (std::size_t i = 0; i < a.faults.size(); ++i) {
        REQUIRE(a.faults.at(i).effect == b.faults.at(i).effect);
    }
    REQUIRE(a.actions.size() == b.actions.size());
    for (std::size_t i = 0; i < a.actions.size(); ++i) {
        REQUIRE(a.actions.at(i).event == b.actions.at(i).event);
        REQUIRE(a.actions.at(i).tripped_s == b.actions.at(i).tripped_s);
        REQUIRE(a.actions.at(i).acknowledged_s == b.actions.at(i).acknowledged_s);
        REQUIRE(a.actions.at(i).motion_end_s == b.actions.at(i).motion_end_s);
    }
    REQUIRE(a.tool_in_spindle == b.tool_in_spindle);
    REQUIRE(a.press.has_value() == b.press.has_value());
    if (a.press) {
        REQUIRE(a.press->revolution == b.press->revolution);
        REQUIRE(a.press->crank_angle_deg == b.press->crank_angle_deg);
        REQUIRE(a.press->position_register == b.press->position_register);
        REQUIRE(a.press->press_stopped == b.press->press_stopped);
        REQUIRE(a.press->cycles == b.press->cycles);
        REQUIRE(a.press->loop_backs == b.press->loop_backs);
        REQUIRE(a.press->mean_cycle_s == b.press->mean_cycle_s);
        REQUIRE(a.press->waited_s == b.press->waited_s);
    }
    REQUIRE(a.tapping.has_value() == b.tapping.has_value());
    if (a.tapping) {
        REQUIRE(a.tapping->tool_on_spindle == b.tapping->tool_on_spindle);
        REQUIRE(a.tapping->ratio_in_memory == b.tapping->ratio_in_memory);
        REQUIRE(a.tapping->head_exchanges == b.tapping->head_exchanges);
        REQUIRE(a.tapping->transfers == b.tapping->transfers);
        REQUIRE(a.tapping->holes.size() == b.tapping->holes.size());
        for (std::size_t i = 0; i < a.tapping->holes.size(); ++i) {
            const auto& x = a.tapping->holes.at(i);
            const auto& y = b.tapping->holes.at(i);
            REQUIRE(x.start_s == y.start_s);
            REQUIRE(x.reverse_s == y.reverse_s);
            REQUIRE(x.end_s == y.end_s);
            REQUIRE(x.deepest_in == y.deepest_in);
            REQUIRE(x.end_in == y.end_in);
            REQUIRE(x.completed == y.completed);
        }
    }
    REQUIRE(a.cards.size() == b.cards.size());
    for (std::size_t i = 0; i < a.cards.size(); ++i) {
        REQUIRE(a.cards.at(i).start_s == b.cards.at(i).start_s);
        REQUIRE(a.cards.at(i).end_s == b.cards.at(i).end_s);
    }
}

} // namespace parsons::test
