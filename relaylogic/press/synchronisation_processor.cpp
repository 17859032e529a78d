#include "relaylogic/press/synchronisation_processor.hpp"

#include "axes/state_json.hpp"
#include "cardreader/tap_review.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

using cardreader::axis_name;

SynchronisationProcessor::SynchronisationProcessor(Tracer& tracer,
                                                   const axes::MachineProfile& profile)
    : tracer_(tracer), ppd_(profile.press.pulses_per_degree) {
    rated_pulses_per_s_ = profile.press.strokes_per_min * 6.0 * ppd_;
    for (std::size_t i = 0; i < speeds_.size(); ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
            speeds_.at(i).at(k) = profile.axes.at(i).speed_in_per_min.at(k) / 60.0;
        }
    }
    gain_per_s_ = profile.sync_drive.position_gain_per_s;
    block_s_ = profile.speed_sample_s;
    max_in_per_s_ = profile.sync_drive.max_in_per_min / 60.0;
    device_16_ = 360 * ppd_;
    sync_card_ =
        tracer.define("press", "synchronisation_processor_17.sync_card",
                      "a sync card's orders wait for their motion card (EP 0436887)", "17", 1);
    angle_60_ = tracer.define("press", "position_reader_60.angle",
                              "programmed position reader 60: the angle R in detector pulses "
                              "(0 = no position synchronisation)",
                              "60", 14);
    hold_60_ = tracer.define("press", "position_reader_60.hold",
                             "programmed position reader 60's hold relay: the card's motion "
                             "waits for the crank",
                             "60", 1);
    detector_61_ = tracer.define("press", "sync_position_detector_61",
                                 "synchronisation position detector 61: register 14 stands "
                                 "on R",
                                 "61", 1);
    for (cardreader::Axis a : cardreader::kAxes) {
        const std::string axis(axis_name(a));
        feed_62_.at(cardreader::axis_index(a)) =
            tracer.define("press", "feed_speed_reader_62." + axis,
                          "programmed feed speed reader 62: the " + axis +
                              " travel per pulse F, 0.00001 in (0 = not speed-synchronised)",
                          "62", 17);
        output_63_.at(cardreader::axis_index(a)) =
            tracer.define("press", "processor_63." + axis,
                          "processor 63: the " + axis +
                              " speed last sent to the drive, thousandths of an inch a minute",
                          "63", 20);
        behind_63_.at(cardreader::axis_index(a)) =
            tracer.define("press", "processor_63." + axis + ".behind",
                          "processor 63: how far the " + axis +
                              " axis is behind its reference travel (F a pulse since it "
                              "started), ten-thousandths of an inch (0 when on it or ahead)",
                          "63", 16);
        ahead_63_.at(cardreader::axis_index(a)) =
            tracer.define("press", "processor_63." + axis + ".ahead",
                          "processor 63: how far the " + axis +
                              " axis is ahead of its reference travel, ten-thousandths of an "
                              "inch (0 when on it or behind)",
                          "63", 16);
    }
}

void SynchronisationProcessor::take(const cardreader::SyncOrder& order, std::int64_t card,
                                    int number) {
    pending_ = order;
    pending_card_ = card;
    pending_number_ = number;
    tracer_.set(sync_card_, 1);
}

void SynchronisationProcessor::arm() {
    if (!pending_) {
        return;
    }
    if (pending_->position_sync) {
        target_ = pending_->angle_deg * ppd_;
    }
    feed_ = pending_->travel_per_pulse;
    loop_ = pending_->position_sync && pending_->speed_sync();
    pending_.reset();
    tracer_.set(sync_card_, 0);
    show();
}

void SynchronisationProcessor::clear() {
    target_.reset();
    holding_ = false;
    feed_ = {};
    loop_ = false;
    for (Follow& f : follow_) {
        f = Follow{};
    }
    tracer_.set(detector_61_, 0);
    show();
}

bool SynchronisationProcessor::any_speed_synced() const {
    return std::any_of(feed_.begin(), feed_.end(), [](const auto& f) { return f.has_value(); });
}

bool SynchronisationProcessor::hold_unless_at(int register_value, double t) {
    if (!target_) {
        return false;
    }
    if (register_value == *target_) {
        tracer_.set(detector_61_, 1);
        return false;
    }
    holding_ = true;
    hold_since_ = t;
    tracer_.set(hold_60_, 1);
    return true;
}

bool SynchronisationProcessor::detector_61(int register_value) {
    if (!holding_ || register_value != *target_) {
        return false;
    }
    tracer_.set(detector_61_, 1);
    return true;
}

void SynchronisationProcessor::release() {
    holding_ = false;
    tracer_.set(hold_60_, 0);
}

void SynchronisationProcessor::start_axis(cardreader::Axis a, int speed_position,
                                          std::int64_t impulses, int register_14) {
    Follow& f = follow_.at(cardreader::axis_index(a));
    f = Follow{};
    f.started = true;
    f.start_speed = std::clamp(speed_position, 1, 3);
    f.impulses0 = impulses;
    f.register_prev = register_14;
}

double SynchronisationProcessor::per_pulse_in(cardreader::Axis a, int speed_position) const {
    const std::size_t i = cardreader::axis_index(a);
    const Follow& f = follow_.at(i);
    const int k = std::clamp(speed_position, 1, 3);
    if (!feed_.at(i)) {
        return 0.0;
    }
    if (!f.started || k == f.start_speed) {
        return *feed_.at(i) * 1e-5;
    }
    // A slow-down: the 1952 motor's speed at the press's rated speed.
    return speeds_.at(i).at(static_cast<std::size_t>(k - 1)) / rated_pulses_per_s_;
}

// The pulses register 14 moved from `before` to `now`, the short way round device 16's ring.
namespace {
int ring_step(int before, int now, int ring) {
    int d = (now - before) % ring;
    if (d > ring / 2) {
        d -= ring;
    } else if (d < -ring / 2) {
        d += ring;
    }
    return d;
}
} // namespace

void SynchronisationProcessor::switch_at(cardreader::Axis a, int speed_position,
                                         std::int64_t impulses, int register_14) {
    Follow& f = follow_.at(cardreader::axis_index(a));
    if (f.position != 0 && f.position != speed_position) {
        f.leaving = true;
        f.step_impulses = impulses;
        // The pulses since the last block were turned on the position it leaves: they go into
        // the reference at that position's travel a pulse (63 reads register 14 as it steps).
        f.ref_in += per_pulse_in(a, f.position) *
                    std::abs(ring_step(f.register_prev, register_14, device_16_));
        f.register_prev = register_14;
    }
    f.position = speed_position;
}

double SynchronisationProcessor::drive_speed(cardreader::Axis a, int speed_position) const {
    const Follow& f = follow_.at(cardreader::axis_index(a));
    // The correction was computed for the position of its block; it is bounded by half the
    // speed of the position in force, so a correction of speed 1 never rides on speed 3.
    const double base = per_pulse_in(a, speed_position) * rate_out_;
    double v = base + std::clamp(f.out, -0.5 * base, 0.5 * base);
    const double least = cardreader::kLeastTapFeedInPerMin / 60.0;
    if (v < least) {
        // The drive runs no slower than its least steady speed (as for a tap's feed): below it
        // it stops and goes, so the axis keeps the crank's pace without running ahead of it.
        // It runs on until it leaves the equality that stepped switch 236, which the least
        // speed does within delay 258, as the 1952 speed 3 does.
        v = (f.go_out || f.leaving) ? least : 0.0;
    }
    return std::min(v, max_in_per_s_);
}

void SynchronisationProcessor::note_asked(cardreader::Axis a, int speed_position, double t,
                                          std::int64_t card, int number) {
    const double asked = per_pulse_in(a, speed_position) * rate_out_;
    // A relative hair over the top speed is the review's own rounding at the press's fastest
    // (an F of the largest travel per pulse it accepts), not a drive that falls behind.
    if (asked <= max_in_per_s_ * (1 + 1e-9)) {
        return;
    }
    if (!saturation_) {
        DriveSaturation s;
        s.axis = a;
        s.card = card;
        s.number = number;
        s.speed_position = speed_position;
        s.t_s = t;
        s.asked_in_per_min = asked * 60.0;
        s.crank_factor = rate_out_ / rated_pulses_per_s_;
        s.drive_max_in_per_min = max_in_per_s_ * 60.0;
        saturation_ = s;
    }
    saturation_->most_asked_in_per_min = std::max(saturation_->most_asked_in_per_min, asked * 60.0);
}

void SynchronisationProcessor::commanded(cardreader::Axis a, double in_per_s) {
    tracer_.set(output_63_.at(cardreader::axis_index(a)),
                static_cast<std::uint32_t>(std::lround(in_per_s * 60000.0)));
}

bool SynchronisationProcessor::reference_block(
    double rate, bool turning, int register_14,
    const std::array<std::optional<Feedback>, cardreader::kAxisCount>& axes) {
    bool changed = rate_out_ != rate_next_ || turning_out_ != turning_next_;
    rate_out_ = rate_next_;
    rate_next_ = rate;
    turning_out_ = turning_next_;
    turning_next_ = turning;
    const double least = cardreader::kLeastTapFeedInPerMin / 60.0;
    // A loop that corrects once a block takes out at most the lag it sees within two blocks
    // (its correction reaches the drive a block later): the gain is bounded by 1 / (2 blocks).
    const double gain = std::min(gain_per_s_, 0.5 / block_s_);
    most_behind_.reset();
    for (std::size_t i = 0; i < follow_.size(); ++i) {
        Follow& f = follow_.at(i);
        if (f.out != f.next || f.go_out != f.go_next) {
            f.out = f.next;
            f.go_out = f.go_next;
            changed = true;
        }
        f.next = 0;
        f.go_next = false;
        if (!f.started || !feed_.at(i)) {
            continue;
        }
        // The pulses the crank turned, whichever way (the speed, not the velocity, as register
        // 11 counts them).
        const int step = std::abs(ring_step(f.register_prev, register_14, device_16_));
        f.register_prev = register_14;
        const auto& fb = axes.at(i);
        if (!fb) {
            continue; // stopped on its card, or held: the reference waits with it
        }
        if (f.leaving && fb->impulses != f.step_impulses) {
            f.leaving = false; // it has left the equality
            changed = true;
        }
        const cardreader::Axis a = cardreader::kAxes.at(i);
        f.ref_in += per_pulse_in(a, fb->speed_position) * step;
        f.lag_in = f.ref_in - static_cast<double>(fb->impulses - f.impulses0) * 0.001;
        most_behind_ = std::max(most_behind_.value_or(f.lag_in), f.lag_in);
        tracer_.set(behind_63_.at(i), static_cast<std::uint32_t>(
                                          std::clamp(std::lround(f.lag_in * 1e4), 0L, 65535L)));
        tracer_.set(ahead_63_.at(i), static_cast<std::uint32_t>(
                                         std::clamp(std::lround(-f.lag_in * 1e4), 0L, 65535L)));
        const std::size_t kind = loop_ ? 1 : 0;
        worst_lag_.at(kind) = std::max(worst_lag_.at(kind), f.lag_in);
        worst_lead_.at(kind) = std::max(worst_lead_.at(kind), -f.lag_in);
        if (loop_) {
            const double feed = per_pulse_in(a, fb->speed_position) * rate;
            f.next = std::clamp(gain * f.lag_in, -0.5 * feed, 0.5 * feed);
        }
        // Below the least speed: go for the next block only if the axis stays behind its
        // reference through it (the block now runs at the speed in force).
        const double now_travel = f.go_out ? least * block_s_ : 0.0;
        f.go_next = f.lag_in - now_travel >= least * block_s_;
    }
    show();
    return changed;
}

void SynchronisationProcessor::show() {
    if (tracer_.observer() == nullptr) {
        return; // nobody watches: the values need not be worked out (they change at every edge)
    }
    tracer_.set(angle_60_, static_cast<std::uint32_t>(target_.value_or(0)));
    tracer_.set(hold_60_, holding_ ? 1U : 0U);
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        tracer_.set(feed_62_.at(i), static_cast<std::uint32_t>(feed_.at(i).value_or(0)));
    }
}

namespace {

nlohmann::json optional_int(const std::optional<int>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::optional<int> read_optional(const nlohmann::json& j) {
    if (j.is_null()) {
        return std::nullopt;
    }
    if (!j.is_number_integer()) {
        throw axes::StateError("synchronisation_processor_17: expected an integer or null");
    }
    return j.get<int>();
}

nlohmann::json saturation_json(const std::optional<DriveSaturation>& s) {
    if (!s) {
        return nullptr;
    }
    using axes::exact;
    return {{"axis", static_cast<int>(cardreader::axis_index(s->axis))},
            {"card", s->card},
            {"number", s->number},
            {"speed_position", s->speed_position},
            {"t_s", exact(s->t_s)},
            {"asked_in_per_min", exact(s->asked_in_per_min)},
            {"crank_factor", exact(s->crank_factor)},
            {"most_asked_in_per_min", exact(s->most_asked_in_per_min)},
            {"drive_max_in_per_min", exact(s->drive_max_in_per_min)}};
}

std::optional<DriveSaturation> read_saturation(const nlohmann::json& j) {
    if (j.is_null()) {
        return std::nullopt;
    }
    const int axis = axes::read<int>(j, "axis");
    if (axis < 0 || axis >= static_cast<int>(cardreader::kAxisCount)) {
        throw axes::StateError("synchronisation_processor_17: saturated.axis: 0 to 4");
    }
    DriveSaturation s;
    s.axis = cardreader::kAxes.at(static_cast<std::size_t>(axis));
    s.card = axes::read<std::int64_t>(j, "card");
    s.number = axes::read<int>(j, "number");
    s.speed_position = std::clamp(axes::read<int>(j, "speed_position"), 1, 3);
    s.t_s = axes::exact(axes::member(j, "t_s"));
    s.asked_in_per_min = axes::exact(axes::member(j, "asked_in_per_min"));
    s.crank_factor = axes::exact(axes::member(j, "crank_factor"));
    s.most_asked_in_per_min = axes::exact(axes::member(j, "most_asked_in_per_min"));
    s.drive_max_in_per_min = axes::exact(axes::member(j, "drive_max_in_per_min"));
    return s;
}

} // namespace

nlohmann::json SynchronisationProcessor::save() const {
    using axes::exact;
    nlohmann::json feeds = nlohmann::json::array();
    nlohmann::json follow = nlohmann::json::array();
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        feeds.push_back(optional_int(feed_.at(i)));
        const Follow& f = follow_.at(i);
        follow.push_back({{"started", f.started},
                          {"start_speed", f.start_speed},
                          {"impulses0", f.impulses0},
                          {"register_prev", f.register_prev},
                          {"ref_in", exact(f.ref_in)},
                          {"lag_in", exact(f.lag_in)},
                          {"next", exact(f.next)},
                          {"out", exact(f.out)},
                          {"go_next", f.go_next},
                          {"go_out", f.go_out},
                          {"position", f.position},
                          {"leaving", f.leaving},
                          {"step_impulses", f.step_impulses}});
    }
    nlohmann::json pending = nullptr;
    if (pending_) {
        nlohmann::json f = nlohmann::json::array();
        for (const auto& v : pending_->travel_per_pulse) {
            f.push_back(optional_int(v));
        }
        pending = {{"position_sync", pending_->position_sync},
                   {"angle_deg", pending_->angle_deg},
                   {"travel_per_pulse", f},
                   {"register_reset", pending_->register_reset},
                   {"card", pending_card_},
                   {"number", pending_number_}};
    }
    return {{"pending", pending},
            {"target", optional_int(target_)},
            {"holding", holding_},
            {"hold_since", exact(hold_since_)},
            {"feed", feeds},
            {"position_loop", loop_},
            {"follow", follow},
            {"rate_next", exact(rate_next_)},
            {"rate_out", exact(rate_out_)},
            {"turning_next", turning_next_},
            {"turning_out", turning_out_},
            {"worst_lag_in", {exact(worst_lag_.at(0)), exact(worst_lag_.at(1))}},
            {"worst_lead_in", {exact(worst_lead_.at(0)), exact(worst_lead_.at(1))}},
            {"saturated", saturation_json(saturation_)}};
}

void SynchronisationProcessor::load(const nlohmann::json& j) {
    const nlohmann::json& p = axes::member(j, "pending");
    pending_.reset();
    if (!p.is_null()) {
        cardreader::SyncOrder o;
        o.position_sync = axes::read<bool>(p, "position_sync");
        o.angle_deg = axes::read<int>(p, "angle_deg");
        o.register_reset = p.contains("register_reset") && axes::read<bool>(p, "register_reset");
        const auto& f = axes::member(p, "travel_per_pulse");
        for (std::size_t i = 0; i < o.travel_per_pulse.size() && i < f.size(); ++i) {
            o.travel_per_pulse.at(i) = read_optional(f.at(i));
        }
        pending_ = o;
        pending_card_ = axes::read<std::int64_t>(p, "card");
        pending_number_ = axes::read<int>(p, "number");
    }
    target_ = read_optional(axes::member(j, "target"));
    holding_ = axes::read<bool>(j, "holding");
    hold_since_ = axes::exact(axes::member(j, "hold_since"));
    const auto& feeds = axes::member(j, "feed");
    const auto& follow = axes::member(j, "follow");
    const auto& worst = axes::member(j, "worst_lag_in");
    if (!feeds.is_array() || feeds.size() != feed_.size() || !follow.is_array() ||
        follow.size() != feed_.size() || !worst.is_array() || worst.size() != 2) {
        throw axes::StateError("synchronisation_processor_17: five feeds and five follow entries");
    }
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        feed_.at(i) = read_optional(feeds.at(i));
        const nlohmann::json& e = follow.at(i);
        Follow& f = follow_.at(i);
        f.started = axes::read<bool>(e, "started");
        f.start_speed = std::clamp(axes::read<int>(e, "start_speed"), 1, 3);
        f.impulses0 = axes::read<std::int64_t>(e, "impulses0");
        f.register_prev = axes::read<int>(e, "register_prev");
        f.ref_in = axes::exact(axes::member(e, "ref_in"));
        f.lag_in = axes::exact(axes::member(e, "lag_in"));
        f.next = axes::exact(axes::member(e, "next"));
        f.out = axes::exact(axes::member(e, "out"));
        // States saved before stop-and-go: none in force.
        f.go_next = e.contains("go_next") && axes::read<bool>(e, "go_next");
        f.go_out = e.contains("go_out") && axes::read<bool>(e, "go_out");
        f.position = e.contains("position") ? axes::read<int>(e, "position") : 0;
        f.leaving = e.contains("leaving") && axes::read<bool>(e, "leaving");
        f.step_impulses =
            e.contains("step_impulses") ? axes::read<std::int64_t>(e, "step_impulses") : 0;
    }
    loop_ = axes::read<bool>(j, "position_loop");
    rate_next_ = axes::exact(axes::member(j, "rate_next"));
    rate_out_ = axes::exact(axes::member(j, "rate_out"));
    turning_next_ = axes::read<bool>(j, "turning_next");
    turning_out_ = axes::read<bool>(j, "turning_out");
    worst_lag_ = {axes::exact(worst.at(0)), axes::exact(worst.at(1))};
    worst_lead_ = {0.0, 0.0};
    if (j.contains("worst_lead_in")) {
        const auto& lead = axes::member(j, "worst_lead_in");
        if (!lead.is_array() || lead.size() != 2) {
            throw axes::StateError("synchronisation_processor_17: worst_lead_in: two numbers");
        }
        worst_lead_ = {axes::exact(lead.at(0)), axes::exact(lead.at(1))};
    }
    // A state saved before the drive's saturation was recorded: none.
    saturation_ = j.contains("saturated") ? read_saturation(j.at("saturated")) : std::nullopt;
}

} // namespace parsons::relaylogic
