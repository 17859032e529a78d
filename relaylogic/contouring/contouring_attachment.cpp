// Contouring (an addition after EP 0636958, Black & Decker) on the card cycle of control cabinet
// 52: a segment card's cycle (contouring_attachment.hpp; docs/contouring.md). Not in the 1952
// patent.
#include "relaylogic/contouring/contouring_attachment.hpp"

#include "cardreader/segment_card.hpp"
#include "relaylogic/control_cabinet.hpp"
#include "relaylogic/run_result.hpp"

#include "axes/contour_json.hpp"
#include "axes/state_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {
namespace {

constexpr double kRampSample = 0.010; // the trace samples a ramp's pulse periods every 10 ms
constexpr double kEnd = 1e-12;

std::uint32_t period_us(double rate) {
    return rate == 0 ? 0
                     : static_cast<std::uint32_t>(
                           std::min(1e7, std::llround(1e6 / std::abs(rate)) * 1.0));
}

} // namespace

ContouringAttachment::ContouringAttachment(Tracer& tracer, const axes::MachineProfile& profile)
    : present_(profile.contouring), profile_(profile.contour),
      tracer_(tracer), motors_{axes::StepperMotor(profile.contour.pull_in_steps_per_s,
                                                  profile.contour.acceleration_steps_per_s2),
                               axes::StepperMotor(profile.contour.pull_in_steps_per_s,
                                                  profile.contour.acceleration_steps_per_s2),
                               axes::StepperMotor(profile.contour.pull_in_steps_per_s,
                                                  profile.contour.acceleration_steps_per_s2)} {
    result_.policy = axes::junction_policy_name(profile_.junctions);
    if (!present_) {
        return;
    }
    for (int i = 0; i < cardreader::kSegmentAxes; ++i) {
        const std::string x(cardreader::segment_axis_letter(i));
        AxisSignals& s = axis_signals_.at(static_cast<std::size_t>(i));
        s.period = tracer.define("contouring", x + ".pulse_period_us",
                                 fmt::format("stepper motor {}: the period of its pulses, "
                                             "microseconds (0: none; claims 3, 11)",
                                             x),
                                 "", 24);
        s.direction = tracer.define("contouring", x + ".direction",
                                    fmt::format("stepper motor {}: 1 its pulses drive it towards "
                                                "plus, 0 towards minus",
                                                x),
                                    "", 1, 1);
        s.lost = tracer.define("contouring", x + ".lost_steps",
                               fmt::format("stepper motor {}: the steps it has lost", x), "", 24);
    }
    segment_signal_ =
        tracer.define("contouring", "segment",
                      "the card number of the segment the tool travels (0: none)", "", 14);
    junction_signal_ = tracer.define("contouring", "junction",
                                     "the control cycle's last decision: 1 pass at the nominal "
                                     "speed, 2 slow (rate difference), 3 slow (short segment), 4 "
                                     "slow (every junction), 5 stopped (next not read)",
                                     "", 3);
    difference_signal_ = tracer.define("contouring", "rate_difference",
                                       "the control cycle's largest change of a motor's pulse "
                                       "rate between the two segments at nominal, steps/s",
                                       "", 24);
    speed_signal_ =
        tracer.define("contouring", "path_speed",
                      "the tool's speed along the path, thousandths of an in/min", "", 24);
}

double ContouringAttachment::s_now(double t) const {
    for (const SpeedPhase& p : plan_.phases) {
        if (t <= p.end()) {
            return p.s_at(t);
        }
    }
    return current_ ? current_->length : 0.0;
}

double ContouringAttachment::v_now(double t) const {
    for (const SpeedPhase& p : plan_.phases) {
        if (t < p.end()) {
            return p.v_at(t);
        }
    }
    return plan_.exit_speed;
}

void ContouringAttachment::show_rates(const Point3& rates, double speed) {
    for (std::size_t i = 0; i < rates.size(); ++i) {
        tracer_.set(axis_signals_[i].period, period_us(rates[i]));
        if (rates[i] != 0) {
            tracer_.set(axis_signals_[i].direction, rates[i] > 0 ? 1 : 0);
        }
    }
    tracer_.set(speed_signal_, static_cast<std::uint32_t>(std::llround(speed * 60000.0)));
}

// The pulse rates jump to `rates` now: the steps each motor loses, into the totals, the trace
// and the junction's record.
void ContouringAttachment::take_losses(const Point3& rates, JunctionRecord* record) {
    double offset2 = 0;
    for (std::size_t i = 0; i < rates.size(); ++i) {
        const std::int64_t n = motors_[i].jump_to(rates[i]);
        if (record != nullptr) {
            record->lost[i] += n;
        }
        tracer_.set(axis_signals_[i].lost, static_cast<std::uint32_t>(motors_[i].lost()));
        const double off = static_cast<double>(motors_[i].offset()) / profile_.steps_per_in;
        offset2 += off * off;
    }
    result_.largest_offset_in = std::max(result_.largest_offset_in, std::sqrt(offset2));
}

// The tool begins segment s now at speed `entry`, its end planned at rest until the next segment
// is known.
void ContouringAttachment::begin(ControlCabinet& cab, const PathSegment& s, double entry) {
    current_ = s;
    ++result_.segments;
    if (result_.first_start_s < 0) {
        result_.first_start_s = cab.now();
    }
    tracer_.set(segment_signal_, static_cast<std::uint32_t>(s.number));
    plan_ = plan_segment(cab.now(), 0, entry, s.length, s.nominal, 0, path_acceleration(profile_));
    ++generation_;
    tick(cab);
}

void ContouringAttachment::replan(ControlCabinet& cab, double exit) {
    const double t = cab.now();
    plan_ = plan_segment(t, s_now(t), v_now(t), current_->length, current_->nominal, exit,
                         path_acceleration(profile_));
    ++generation_;
    tick(cab);
}

// Now: the rates the plan gives, and the next instant to look again (a phase's end, or the next
// sample of a ramp); at the segment's end, the junction.
void ContouringAttachment::tick(ControlCabinet& cab) {
    const double t = cab.now();
    const double end = plan_.phases.empty() ? t : plan_.phases.back().end();
    if (t >= end - kEnd) {
        reach_end(cab);
        return;
    }
    const double v = v_now(t);
    const Point3 rates = motor_rates(*current_, v, profile_.steps_per_in);
    for (std::size_t i = 0; i < rates.size(); ++i) {
        motors_[i].ramp_to(rates[i]);
    }
    show_rates(rates, v);
    double next = end;
    for (const SpeedPhase& p : plan_.phases) {
        if (t < p.end() - kEnd) {
            next = p.acc != 0 ? std::min(p.end(), t + kRampSample) : p.end();
            break;
        }
    }
    cab.schedule_lasting(*this, next, generation_); // the tool travels on past its card
}

void ContouringAttachment::reach_end(ControlCabinet& cab) {
    const double t = cab.now();
    const PathSegment done = *current_;
    // The motors arrive at the plan's exit speed along the segment's direction.
    const Point3 arriving = motor_rates(done, plan_.exit_speed, profile_.steps_per_in);
    for (std::size_t i = 0; i < arriving.size(); ++i) {
        motors_[i].ramp_to(arriving[i]);
    }
    position_ = done.to;
    if (next_) {
        JunctionRecord rec = pending_.value_or(JunctionRecord{});
        rec.at_s = t;
        rec.speed_in_per_min = plan_.exit_speed * 60.0;
        const PathSegment second = *next_;
        next_.reset();
        const Point3 leaving = motor_rates(second, decision_.entry, profile_.steps_per_in);
        take_losses(leaving, &rec);
        result_.junctions.push_back(rec);
        pending_.reset();
        begin(cab, second, decision_.entry);
        if (card_held_) {
            card_held_ = false;
            cab.zeroize(); // the held card's cycle ends: the reader feeds the next
        }
        return;
    }
    JunctionRecord rest;
    take_losses(Point3{}, &rest);
    for (std::size_t i = 0; i < rest.lost.size(); ++i) {
        result_.lost[i] += 0; // counted in the motors
    }
    current_.reset();
    plan_ = SegmentPlan{};
    ++generation_;
    result_.last_end_s = t;
    rested_after_ = done.number;
    show_rates(Point3{}, 0);
    tracer_.set(segment_signal_, 0);
    if (motion_waiting_) {
        motion_waiting_ = false;
        cab.update_motors();
        cab.evaluate_all();
    }
}

// A segment card read: the control cycle, while the tool travels the segment before it.
bool ContouringAttachment::card_read(ControlCabinet& cab) {
    result_.used = true;
    const cardreader::CardOrders& o = cab.orders();
    const Point3 from = current_ ? current_->to : position_;
    const PathSegment s = make_segment(from, o.segment, o.number, cab.cards_read());
    if (s.length <= 0) {
        return true; // the axes stand at its end already: nothing to travel
    }
    if (!current_) {
        if (rested_after_ != 0) {
            JunctionRecord rec;
            rec.first = rested_after_;
            rec.second = s.number;
            rec.kind = JunctionKind::stopped;
            rec.at_s = result_.last_end_s;
            result_.junctions.push_back(rec);
            tracer_.set(junction_signal_, static_cast<std::uint32_t>(JunctionKind::stopped));
        }
        begin(cab, s, 0);
        return true; // the reader indexes the next card while the tool travels
    }
    decision_ = control_cycle(*current_, s, profile_);
    JunctionRecord rec;
    rec.first = current_->number;
    rec.second = s.number;
    rec.kind = decision_.kind;
    rec.decided_s = cab.now();
    rec.decided_at_in = s_now(cab.now());
    rec.difference = decision_.difference;
    pending_ = rec;
    tracer_.set(difference_signal_, static_cast<std::uint32_t>(std::llround(decision_.difference)));
    tracer_.set(junction_signal_, static_cast<std::uint32_t>(decision_.kind));
    next_ = s;
    card_held_ = true;
    replan(cab, decision_.exit);
    return false; // the card stays in the reader until the tool reaches its segment
}

bool ContouringAttachment::holds_motion(ControlCabinet& /*cab*/) {
    if (current_) {
        motion_waiting_ = true;
        return true;
    }
    return false;
}

void ContouringAttachment::on_event(ControlCabinet& cab, int code) {
    if (code == generation_ && current_) {
        tick(cab);
    }
}

// Master switch 204 opened: the pulses cease at once, and the rotors run on past them.
void ContouringAttachment::machine_stopped(ControlCabinet& cab) {
    if (!current_) {
        return;
    }
    const double t = cab.now();
    const double s = s_now(t);
    for (std::size_t i = 0; i < position_.size(); ++i) {
        position_[i] = current_->from[i] + current_->unit[i] * s;
    }
    const Point3 arriving = motor_rates(*current_, v_now(t), profile_.steps_per_in);
    for (std::size_t i = 0; i < arriving.size(); ++i) {
        motors_[i].ramp_to(arriving[i]);
    }
    take_losses(Point3{}, nullptr);
    current_.reset();
    next_.reset();
    ++generation_;
    result_.last_end_s = t;
    show_rates(Point3{}, 0);
}

void ContouringAttachment::save(const ControlCabinet& /*cab*/, nlohmann::json& state) const {
    nlohmann::json j;
    j["moving"] = current_.has_value();
    j["used"] = result_.used;
    nlohmann::json axes = nlohmann::json::array();
    for (std::size_t i = 0; i < motors_.size(); ++i) {
        axes.push_back({{"position_in", position_[i]},
                        {"offset_steps", motors_[i].offset()},
                        {"lost_steps", motors_[i].lost()}});
    }
    j["axes"] = axes;
    state["contouring"] = j;
}

void ContouringAttachment::load(ControlCabinet& /*cab*/, const nlohmann::json& state) {
    if (!state.contains("contouring") || state.at("contouring").is_null()) {
        throw axes::StateError("this profile has contouring and the saved state has none");
    }
    const nlohmann::json& j = state.at("contouring");
    if (axes::read<bool>(j, "moving")) {
        throw axes::StateError("the state was saved while the stepper axes moved along a "
                               "segment: nothing measures a stepper axis, so the run cannot go "
                               "on from the middle of a path (docs/contouring.md)");
    }
    result_.used = axes::read<bool>(j, "used");
    const nlohmann::json& axes_json = j.at("axes");
    if (!axes_json.is_array() || axes_json.size() != motors_.size()) {
        throw axes::StateError("contouring.axes: expected X, Y and Z");
    }
    for (std::size_t i = 0; i < motors_.size(); ++i) {
        const nlohmann::json& a = axes_json.at(i);
        position_[i] = axes::read<double>(a, "position_in");
        motors_[i].restore(axes::read<std::int64_t>(a, "offset_steps"),
                           axes::read<std::int64_t>(a, "lost_steps"));
    }
}

void ContouringAttachment::add_to(RunResult& result) const {
    ContouringResult r = result_;
    for (std::size_t i = 0; i < motors_.size(); ++i) {
        r.lost[i] = motors_[i].lost();
        r.offset_in[i] = static_cast<double>(motors_[i].offset()) / profile_.steps_per_in;
        r.position_in[i] = position_[i];
    }
    if (r.first_start_s >= 0 && r.last_end_s >= 0) {
        r.motion_s = r.last_end_s - r.first_start_s;
    }
    result.contouring = std::move(r);
}

} // namespace parsons::relaylogic
