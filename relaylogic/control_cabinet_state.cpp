// Control cabinet 52, saved state and result: the machine captured at a card's feed (run
// --save-state), loaded again (--resume), and what a run reports.
#include "relaylogic/control_cabinet.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;

nlohmann::json ControlCabinet::capture() const {
    using axes::exact;
    nlohmann::json axes = nlohmann::json::object();
    for (const auto& c : circuits_) {
        axes[std::string(axis_name(c->axis))] = c->save();
    }
    nlohmann::json times = nlohmann::json::array();
    for (const CardTiming& ct : timings_) {
        nlohmann::json row{ct.index, ct.number, exact(ct.start_s), exact(ct.end_s)};
        if (ct.cut_unready_s >= 0) {
            row.push_back(exact(ct.cut_unready_s));
            row.push_back(exact(ct.spindle_ready_s));
        }
        times.push_back(row);
    }
    nlohmann::json faults = nlohmann::json::array();
    for (const FaultEffect& e : effects_) {
        faults.push_back({{"fault", e.spec}, {"acted", e.acted}, {"effect", e.effect}});
    }
    nlohmann::json state{{"machine_seconds", exact(now_)},
                         {"event_sequence", seq_},
                         {"cards_read", cards_read_},
                         {"card_number_check", previous_number_ ? nlohmann::json(*previous_number_)
                                                                : nlohmann::json(nullptr)},
                         {"last_card_number", orders_.number},
                         {"spindle", static_cast<int>(orders_.spindle)},
                         {"spindle_motor",
                          {{"turning", static_cast<int>(spindle_motor_.turning())},
                           {"ready_s", exact(spindle_motor_.ready_s())}}},
                         {"last_sequence_position", last_sequence_position_},
                         {"axes", axes},
                         {"stepping_shaft_280", shaft_.save()},
                         {"signals", tracer_.save()},
                         {"card_times", times},
                         {"faults", faults}};
    for (const auto& a : attachments_) {
        a->save(*this, state);
    }
    save_absent(attachments_, state); // the later systems this machine does not have
    return state;
}

void ControlCabinet::resume(const nlohmann::json& j) {
    using axes::exact;
    using axes::member;
    using axes::read;
    now_ = exact(member(j, "machine_seconds"));
    seq_ = read<std::uint64_t>(j, "event_sequence");
    cards_read_ = read<std::int64_t>(j, "cards_read");
    const auto& number = member(j, "card_number_check");
    previous_number_ = number.is_null() ? std::nullopt : std::optional(number.get<int>());
    orders_ = cardreader::CardOrders{};
    orders_.number = read<int>(j, "last_card_number");
    orders_.spindle = static_cast<cardreader::Spindle>(read<int>(j, "spindle"));
    last_sequence_position_ = read<int>(j, "last_sequence_position");
    if (j.contains("spindle_motor")) { // states saved before the spindle motor had a time
        const auto& m = member(j, "spindle_motor");
        const int turning = read<int>(m, "turning");
        if (turning < 0 || turning > 2) {
            throw axes::StateError("spindle_motor.turning: expected 0, 1 or 2");
        }
        spindle_motor_.restore(static_cast<axes::SpindleTurning>(turning),
                               exact(member(m, "ready_s")));
        spindle_changing_ = spindle_motor_.ready_s() > now_;
    }
    const auto& axes = member(j, "axes");
    for (auto& c : circuits_) {
        c->load(member(axes, std::string(axis_name(c->axis)).c_str()));
    }
    shaft_.load(member(j, "stepping_shaft_280"));
    tracer_.load(member(j, "signals"));
    timings_.clear();
    for (const auto& t : member(j, "card_times")) {
        CardTiming ct{t.at(0).get<std::int64_t>(), t.at(1).get<int>(), exact(t.at(2)),
                      exact(t.at(3))};
        if (t.size() >= 6) {
            ct.cut_unready_s = exact(t.at(4));
            ct.spindle_ready_s = exact(t.at(5));
        }
        timings_.push_back(ct);
    }
    load_all(*this, attachments_, j); // and those it does not have: the state must agree
    effects_.clear();
    for (const auto& e : member(j, "faults")) {
        effects_.push_back(FaultEffect{read<std::string>(e, "fault"), read<bool>(e, "acted"),
                                       read<std::string>(e, "effect")});
    }
    if (cards_read_ < 0 || now_ < 0) {
        throw axes::StateError("cards_read and machine_seconds must not be negative");
    }
    reading_complete_ = false;
    deck_finished_ = false;
    stop_.reset();
    resuming_ = true;
}

std::vector<std::string> ControlCabinet::panel_lamps() const {
    std::vector<std::string> lamps;
    const std::vector<std::string> lit = balancing_.lamps();
    auto check_lamps = lit.begin();
    if (check_lamps != lit.end() && *check_lamps == "indicator 268") {
        lamps.push_back(*check_lamps++);
    }
    for (const auto& c : circuits_) {
        const std::string_view axis = cardreader::axis_name(c->axis);
        if (c->lamp_270_lit()) {
            lamps.push_back(fmt::format("{} lamp 270 (absolute comparer 122' conducting)", axis));
        }
        if (c->lamp_272_lit()) {
            lamps.push_back(
                fmt::format("{} lamp 272 (incremental comparer 122'' conducting)", axis));
        }
    }
    lamps.insert(lamps.end(), check_lamps, lit.end());
    return lamps;
}

RunResult ControlCabinet::result() const {
    RunResult r;
    r.completed = deck_finished_ && !stop_;
    r.cards_read = cards_read_;
    r.machine_seconds = now_;
    r.stop = stop_;
    if (r.stop) {
        // The report's lamps are the panel at the end, every axis at rest: a lamp whose
        // comparer stopped conducting as its axis coasted off the number is dark by then.
        r.stop->lamps = panel_lamps();
    }
    r.cards = timings_;
    r.faults = effects_;
    for (const auto& a : attachments_) {
        a->add_to(r);
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        const AxisCircuit& c = *circuits_[i];
        AxisResult& a = r.axes.at(i);
        a.counter_in = c.absolute_counter.value() / 1000.0;
        a.real_in = c.plant.real_in();
        // The counters read 0 .. 9.999 and wrap; the error counts the wraps (switch 104's turns),
        // so a part 10 inches from where the counters say is not reported as on the spot.
        a.error_in = a.real_in - static_cast<double>(c.absolute_counter.unwrapped_value()) / 1000.0;
        a.impulses = c.plant.impulses();
        a.lost_steps = c.absolute_counter.lost() + c.increment_counter.lost();
        if (orders_.number >= 0) {
            a.last_stop_in = c.order.stop / 1000.0;
        }
        a.slip_in = c.plant.slip_in();
        a.screw_in = c.plant.screw_in();
        a.commutator_in = static_cast<double>(c.plant.commutator_index()) / 1000.0;
        a.chain = c.plant.chain_figures();
        a.wrong_way = c.wrong_way;
        a.ordered_in = static_cast<double>(c.ordered) / 1000.0;
        a.counted_in = static_cast<double>(c.absolute_counter.unwrapped_value()) / 1000.0;
        a.thousandths_uncounted = c.thousandths_uncounted;
        for (std::size_t k = 0; k < 4; ++k) {
            a.skipped_steps += c.absolute_counter.stepping_switch(k).skipped() ? 1 : 0;
            a.skipped_steps += c.increment_counter.stepping_switch(k).skipped() ? 1 : 0;
        }
        if (c.axis == Axis::swivel || c.axis == Axis::tilt) {
            a.fixture_angle_deg = c.plant.fixture_angle_deg(c.axis == Axis::tilt);
        }
    }
    return r;
}

} // namespace parsons::relaylogic
