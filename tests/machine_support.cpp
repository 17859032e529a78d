#include "tests/machine_support.hpp"

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

} // namespace parsons::test
