#include "relaylogic/tapping/tapping_units.hpp"

#include "axes/state_json.hpp"
#include "cardreader/tap_review.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace parsons::relaylogic {
namespace {

using axes::exact;

// The feed creeps onto its starting count for at most this long after the spindle stands.
constexpr double kSettleLimitS = 5.0;

std::uint32_t thousandths(double x) {
    return static_cast<std::uint32_t>(std::lround(std::clamp(x, 0.0, 4e6) * 1000));
}

} // namespace

int net_edges(int reading_change, int edges, int ppr, int last_sense) {
    const int r = ((reading_change % ppr) + ppr) % ppr; // d modulo ppr, 0 .. ppr - 1
    // The candidates r + k ppr within [-edges, edges] with edges - d even: the first at or above
    // -edges, then a revolution apart.
    const int lowest = r - ((r + edges) / ppr) * ppr;
    int best = 0;
    bool found = false;
    for (int d = lowest; d <= edges; d += ppr) {
        if ((edges - d) % 2 != 0) {
            continue;
        }
        // Of two, the one in device 13's sense; of more (beyond what the profile allows), the
        // least in that sense.
        const bool agrees = d == 0 || (d > 0) == (last_sense > 0);
        const bool best_agrees = best == 0 || (best > 0) == (last_sense > 0);
        if (!found || (agrees && !best_agrees) ||
            (agrees == best_agrees && std::abs(d) < std::abs(best))) {
            best = d;
            found = true;
        }
    }
    if (found) {
        return best;
    }
    // No value agrees (a count lost between the registers: never with encoder 32's edges): the
    // nearest to no motion.
    return r > ppr / 2 ? r - ppr : r;
}

void TappingUnits::install(Tracer& tracer, const axes::MachineProfile& profile) {
    if (!profile.spindle_sync) {
        return;
    }
    profile_ = profile;
    tracer_ = &tracer;
    max_feed_in_per_s_ = profile.sync_drive.max_in_per_min / 60.0;
    const axes::SpindleSyncProfile& p = profile.spindle;
    spindle_ = std::make_unique<axes::Spindle>(p);
    spindle_->mount(p.first_tool);
    pc_ = std::make_unique<ProgrammableController>(tracer, p);
    memory_ = std::make_unique<GearRatioMemory>(tracer, p);
    device_13_ =
        std::make_unique<DirectionJudgingDevice>(tracer, 0, PulseSource::spindle_encoder_32);
    counter_33_ = std::make_unique<PositionRegister>(tracer, p.encoder_pulses_per_rev, 0,
                                                     PulseSource::spindle_encoder_32);
    speed_33_ = std::make_unique<SpeedRegister>(tracer, PulseSource::spindle_encoder_32);
    motor_rpm_ = tracer.define("spindle", "motor_27.rpm",
                               "spindle motor 27: its speed, rev/min (reverse shown as its size; "
                               "EP 0360190)",
                               "27", 14);
    tool_rpm_ = tracer.define("spindle", "tool_16.rpm",
                              "tool 16 on head 31: its speed, motor speed x the head's ratio, "
                              "rev/min",
                              "16", 14);
    head_ = tracer.define("spindle", "head_31.tool",
                          "spindle head 31 on the spindle: the tool number it holds", "31", 7,
                          static_cast<std::uint32_t>(p.first_tool));
    phase_signal_ = tracer.define("spindle", "synchronous_control.phase",
                                  "synchronous operation control: 0 idle, 1 tool call, 2 in, 3 "
                                  "out, 4 spindle stopping, 5 feed settling, 6 waiting for "
                                  "encoder 32's index (rigid tapping, an addition)",
                                  "", 3);
    index_signal_ = tracer.define("spindle", "encoder_32.index",
                                  "encoder 32's index: high for the edge onto each whole motor "
                                  "revolution, turning forward (rigid tapping, an addition)",
                                  "32", 1);
    z_cmd_signal_ = tracer.define("spindle", "synchronous_control.depth_called",
                                  "the depth the tool's turns call for (S x A x pitch summed), "
                                  "thousandths of an inch",
                                  "", 14);
    feed_signal_ = tracer.define("spindle", "synchronous_control.feed",
                                 "the follower drive's commanded feed, thousandths of an inch a "
                                 "minute",
                                 "", 14);
}

void TappingUnits::inject(const std::vector<Fault>& faults) {
    for (const Fault& f : faults) {
        if (f.kind == FaultKind::stale_ratio) {
            pc_->stale_ratio_at(f.n);
        } else if (f.kind == FaultKind::transfer_hang) {
            pc_->transfer_hang_at(f.n);
        }
    }
}

void TappingUnits::on_edge(const axes::DetectorEdge& edge, double t) {
    const int sense = device_13_->judge(edge);
    if (sense != 0) {
        counter_33_->count(sense);
        speed_33_->pulse();
        last_edge_s_ = t;
    }
    const bool index = show_index(sense, edge.count);
    if (index) {
        look_for_index(edge.count, t);
    }
}

// Encoder 32's index signal after an edge onto `count` turning `sense`: high on the forward edge
// onto a whole motor revolution, low otherwise (traced on a change). True when high.
bool TappingUnits::show_index(int sense, std::int64_t count) {
    const bool index = sense > 0 && count % profile_.spindle.encoder_pulses_per_rev == 0;
    if (index != index_shown_) {
        index_shown_ = index;
        tracer_->set(index_signal_, index ? 1U : 0U);
    }
    return index;
}

// Rigid tapping's index wait (an addition): the first forward edge onto a count that is a
// multiple of index_every_ (n motor revolutions, A = 1/n: the tool stands at the one angle it has
// at each such index while its head is on) starts the feed's count. Register 14 reads 0 there.
void TappingUnits::look_for_index(std::int64_t m, double t) {
    if (phase_ != Phase::index_wait || index_count_ || m % index_every_ != 0) {
        return;
    }
    index_count_ = m;
    HoleRecord& h = holes_.back();
    h.sync_s = t;
    h.sync_tool_revs = spindle_->tool_revs_at_edge(m);
}

void TappingUnits::catch_up(double t) {
    bool moved = false;
    while (spindle_->next_event_time() <= t) {
        const double at = spindle_->next_event_time();
        if (auto edge = spindle_->advance_to(at)) {
            tracer_->set_time(at);
            on_edge(*edge, at);
            moved = true;
        }
    }
    if (moved) {
        tracer_->set_time(t);
    }
    spindle_->advance_to(t); // the motor stands at t (nothing due: only its clock moves)
}

void TappingUnits::halt() {
    phase_ = Phase::idle;
    reverse_at_s_.reset();
    reversal_scheduled_ = false;
    feed_.speed_in_per_s = 0;
    spindle_->command_rpm(0);
    show();
}

// The card ends: the NC withdraws its tool call, and PC 130 (every relay dropping with the call,
// in one scan) and the NC's side of the handshake answer it in a scan at that instant.
void TappingUnits::withdraw_call(double t) {
    bus_.tool_call = 0;
    pc_->scan(t, bus_, *spindle_);
    memory_->scan(t, bus_);
}

void TappingUnits::jump_to(double t) {
    while (true) {
        const std::int64_t n = spindle_->pulses_by(t);
        if (n > 0) {
            const std::int64_t before = spindle_->count();
            if (phase_ == Phase::index_wait && !index_count_ &&
                spindle_->motor_revs_at(spindle_->pulse_time(1)) > spindle_->motor_revs()) {
                // The index among the edges jumped: the first multiple above the count (forward).
                const std::int64_t e = index_every_;
                const std::int64_t m = (before >= 0 ? before / e : (before - e + 1) / e) * e + e;
                if (m - before <= n) {
                    look_for_index(m, spindle_->pulse_time(m - before));
                }
            }
            const double last_s = spindle_->pulse_time(n);
            const axes::DetectorEdge last = spindle_->skip_pulses(n);
            last_edge_s_ = last_s;
            const int way = last.count >= before ? +1 : -1;
            device_13_->jump_to(last.count, way);
            counter_33_->count_many(n, way);
            speed_33_->count_many(n);
            show_index(way, last.count);
        }
        if (spindle_->next_event_time() > t) {
            spindle_->advance_to(t); // nothing due: only the motor's clock moves
            return;
        }
        // A segment boundary (or, never with an exact pulses_by, an edge left over).
        const double at = spindle_->next_event_time();
        if (auto edge = spindle_->advance_to(at)) {
            on_edge(*edge, at);
        }
    }
}

std::optional<std::string> TappingUnits::refusal(const cardreader::TapOrder& o,
                                                 const axes::MachineProfile& profile) const {
    const axes::SpindleSyncProfile& p = profile.spindle;
    const axes::SpindleHead* head = p.head(o.tool);
    if (head == nullptr) {
        return fmt::format("tool {} is on no spindle head of profile {}", o.tool, profile.name);
    }
    if (!head->pitch_in) {
        return fmt::format("tool {}: its spindle head holds a cutter, not a tap (profile {}): a "
                           "tap card feeds one pitch a turn of the tool, which only a tap may be",
                           o.tool, profile.name);
    }
    if (o.rpm < 1 || o.rpm > p.max_rpm) {
        return fmt::format("spindle speed {} rev/min: motor 27 turns at most {:g} rev/min", o.rpm,
                           p.max_rpm);
    }
    if (o.retract < 1 || o.retract * o.rpm > p.max_rpm) {
        return fmt::format("retract multiple {}: out at {} rev/min; motor 27 turns at most {:g} "
                           "rev/min",
                           o.retract, o.retract * o.rpm, p.max_rpm);
    }
    const double fastest = // rev/s, out at k x S, at the lasting change's speed if it is faster
        o.retract * o.rpm * (p.change_at_s ? std::max(1.0, p.change_factor) : 1.0) / 60.0;
    if (fastest * p.sample_s >= 0.5) {
        return fmt::format("spindle speed {} rev/min turns motor 27 half a revolution or more "
                           "between two samples of interface 33 (sample_s {:g} s): its counter "
                           "could not tell the sense",
                           o.retract * o.rpm, p.sample_s);
    }
    const double feed = o.pitch / 100000.0 * head->ratio * o.rpm;
    if (feed * o.retract > profile.sync_drive.max_in_per_min) {
        return fmt::format("retract multiple {}: pitch {} at {} rev/min out with tool {} (ratio "
                           "{:.4f}) feeds {:.2f} in/min; the sync drive follows at most {:g} "
                           "in/min",
                           o.retract, cardreader::format_pitch(o.pitch), o.retract * o.rpm, o.tool,
                           head->ratio, feed * o.retract, profile.sync_drive.max_in_per_min);
    }
    if (feed > profile.sync_drive.max_in_per_min) {
        return fmt::format(
            "pitch {} at {} rev/min with tool {} (ratio {:.4f}) feeds {:.2f} in/min; "
            "the sync drive follows at most {:g} in/min",
            cardreader::format_pitch(o.pitch), o.rpm, o.tool, head->ratio, feed,
            profile.sync_drive.max_in_per_min);
    }
    if (feed < cardreader::kLeastTapFeedInPerMin) {
        return fmt::format("pitch {} at {} rev/min with tool {} (ratio {:.4f}) feeds {:.3f} "
                           "in/min; the sync drive follows no slower than {:g} in/min",
                           cardreader::format_pitch(o.pitch), o.rpm, o.tool, head->ratio, feed,
                           cardreader::kLeastTapFeedInPerMin);
    }
    if (o.depth < 1) {
        return std::string("depth 0.000: a tap card taps at least 0.001 in");
    }
    if (o.index_wait && !cardreader::motor_revs_per_tool_rev(head->ratio)) {
        return fmt::format("index wait with tool {} (ratio {:.4f}): the ratio is not 1/n, so no "
                           "index of encoder 32 puts the tool at one angle every pass",
                           o.tool, head->ratio);
    }
    return std::nullopt;
}

void TappingUnits::begin(const cardreader::TapOrder& order, double /*t*/) {
    order_ = order;
    phase_ = Phase::tool;
    timed_out_ = false;
    selected_ = false;
    bus_.tool_call = order.tool;
    show();
}

bool TappingUnits::scan(double t) {
    pc_->scan(t, bus_, *spindle_);
    memory_->scan(t, bus_);
    tracer_->set(head_, static_cast<std::uint32_t>(spindle_->tool()));
    if (memory_->transfer_under_way() &&
        t - memory_->request_since_s() >= profile_.spindle.transfer_timeout_s) {
        timed_out_ = true;
        return false;
    }
    if (!bus_.tool_ready) {
        return false;
    }
    if (profile_.spindle.ratio_source == axes::RatioSource::stored && !selected_) {
        memory_->select(order_.tool); // Fig. 7, S31-S33
        selected_ = true;
    }
    return true;
}

HoleRecord& TappingUnits::open_hole(std::int64_t card, int number, int tool_called) {
    HoleRecord h;
    h.card = card;
    h.number = number;
    h.tool_called = tool_called;
    holes_.push_back(std::move(h));
    return holes_.back();
}

double TappingUnits::travel_per_edge() const {
    return memory_->ratio() * (order_.pitch / 100000.0) / profile_.spindle.encoder_pulses_per_rev;
}

// The feed the motor covers running down to rest from `edges_per_sample`.
double TappingUnits::run_down_travel(double edges_per_sample) const {
    const auto& p = profile_.spindle;
    const double s = edges_per_sample / p.encoder_pulses_per_rev / p.sample_s; // rev/s
    const double a = p.run_down_rpm_per_s / 60.0;
    const double revs = s * s / (2 * a);
    return revs * memory_->ratio() * (order_.pitch / 100000.0) +
           0.5 * edges_per_sample * travel_per_edge();
}

void TappingUnits::start(double t, int counter, double real_in) {
    phase_ = order_.index_wait ? Phase::index_wait : Phase::run_in;
    index_count_.reset();
    index_every_ = static_cast<std::int64_t>(
                       cardreader::motor_revs_per_tool_rev(memory_->ratio()).value_or(1)) *
                   profile_.spindle.encoder_pulses_per_rev;
    start_counter_ = counter;
    z_cmd_in_ = 0;
    pass_target_ = order_.peck > 0 ? std::min<int>(order_.peck, order_.depth) : order_.depth;
    last_counter_33_ = counter_33_->value();
    speed_33_->sample(); // the first sample counts from here
    measure_afresh(t);
    const axes::SpindleHead* head = profile_.spindle.head(spindle_->tool());
    HoleRecord& h = holes_.back();
    h.tool = spindle_->tool();
    h.tap_pitch_in = head != nullptr ? head->pitch_in : std::nullopt;
    h.head_ratio = spindle_->ratio();
    h.ratio_used = memory_->ratio();
    h.pitch_ordered_in = order_.pitch / 100000.0;
    h.rpm = order_.rpm;
    h.axis = order_.axis;
    h.sense = order_.motion == cardreader::Motion::forward ? +1 : -1;
    h.start_in = real_in;
    h.depth_in = order_.depth / 1000.0;
    h.start_s = t;
    h.index_wait = order_.index_wait;
    h.retract = order_.retract;
    h.peck_in = order_.peck / 1000.0;
    h.pecks = 1;
    h.sync_s = t;
    h.sync_tool_revs = spindle_->tool_revs();
    spindle_->command_rpm(order_.rpm);
    feed_ = FeedCommand{h.sense, 0.0};
    record(t, real_in);
    show();
}

void TappingUnits::record(double t, double real_in) {
    HoleRecord& h = holes_.back();
    const double z = h.sense * (real_in - h.start_in);
    h.deepest_in = std::max(h.deepest_in, z);
    h.end_in = real_in;
    h.end_s = t;
    if (keep_samples_) {
        h.samples.push_back(TapSample{t, spindle_->tool_revs(), real_in});
    }
}

bool TappingUnits::sample(double t, int counter, double real_in, bool feed_at_rest) {
    const auto& p = profile_.spindle;
    const int ppr = p.encoder_pulses_per_rev;
    speed_33_->sample();
    const int edges = speed_33_->stored(); // n: the motor's speed S over the last sample
    // d: the net edges since the last sample, from the counter's two readings, the sample's
    // edges and device 13's sense (net_edges: at most half a revolution a sample, which the
    // profile keeps).
    const int d =
        net_edges(counter_33_->value() - last_counter_33_, edges, ppr, device_13_->last_sense());
    last_counter_33_ = counter_33_->value();
    const int sense = order_.motion == cardreader::Motion::forward ? +1 : -1;
    int moved = (counter - start_counter_) % 10000;
    if (moved > 5000) {
        moved -= 10000;
    } else if (moved < -5000) {
        moved += 10000;
    }
    const double z_counted = sense * moved / 1000.0;
    const double per_edge = travel_per_edge();
    if (phase_ != Phase::index_wait) {
        z_cmd_in_ += d * per_edge;
    }
    measure_speed(t, d);
    const double depth = pass_target_ / 1000.0; // this pass's (rigid peck tapping)
    record(t, real_in);
    HoleRecord& h = holes_.back();
    if (phase_ == Phase::index_wait) {
        if (!index_count_) {
            feed_ = FeedCommand{sense, 0.0}; // the feed stands until the index
            show();
            return false;
        }
        // The index came in this sample (at most half a revolution a sample): register 14 read 0
        // there, so it now holds the edges since it.
        z_cmd_in_ = ((counter_33_->value() % ppr) + ppr) % ppr * per_edge;
        phase_ = Phase::run_in;
    }
    switch (phase_) {
    case Phase::run_in:
        if (!reverse_at_s_) {
            plan_reversal(t, depth, per_edge);
        }
        break;
    case Phase::run_out:
        if (d < 0 && z_cmd_in_ <= run_down_travel(edges)) {
            spindle_->command_rpm(0);
            phase_ = Phase::stopping;
        }
        break;
    case Phase::stopping:
        if (spindle_->at_rest()) {
            phase_ = Phase::settle;
            settle_since_s_ = t;
        }
        break;
    default:
        break;
    }
    if (phase_ == Phase::settle && moved == 0 && feed_at_rest && pass_target_ < order_.depth) {
        next_peck(t); // back on the starting count, the depth not yet reached: in again
    }
    double v = 0;
    if (phase_ == Phase::settle) {
        // The tool stands clear of the work: the feed creeps onto the count it started from.
        if (moved == 0 && feed_at_rest) {
            h.completed = true;
            phase_ = Phase::idle;
            feed_ = FeedCommand{sense, 0.0};
            withdraw_call(t);
            show();
            return true;
        }
        if (t - settle_since_s_ >= kSettleLimitS) {
            phase_ = Phase::idle;
            feed_ = FeedCommand{sense, 0.0};
            withdraw_call(t);
            show();
            return true;
        }
        v = p.feed_gain_per_s * (0.0 - z_counted);
    } else {
        // The tool's speed as measured, carried to the middle of the coming sample.
        // Once motor 27 is commanded to rest and a sample passes with no edge, it stands: no
        // feed for a speed measured before.
        const double ahead = phase_ == Phase::stopping && d == 0
                                 ? 0.0
                                 : rate_ + accel_ * (t + 0.5 * p.sample_s - mid_s_);
        v = ahead * per_edge + p.feed_gain_per_s * (z_cmd_in_ - z_counted);
    }
    const double speed = std::min(std::abs(v), max_feed_in_per_s_);
    feed_ = FeedCommand{v < 0 ? -sense : sense, speed};
    show();
    return false;
}

// The tool's actual speed from interface 33: the last sample's net edges over the time from the
// edge before them to the last of them, and its change from the sample before.
void TappingUnits::measure_speed(double t, int d) {
    if (d != 0 && last_edge_s_ > prev_edge_s_) {
        const double r = d / (last_edge_s_ - prev_edge_s_);
        const double m = 0.5 * (last_edge_s_ + prev_edge_s_);
        accel_ = measured_ && m > mid_s_ ? (r - rate_) / (m - mid_s_) : 0.0;
        rate_ = r;
        mid_s_ = m;
        measured_ = true;
        prev_edge_s_ = last_edge_s_;
        return;
    }
    // No edge this sample: the motor turns slower than one edge in the time since the last.
    const double bound = 1.0 / std::max(t - last_edge_s_, 1e-9);
    if (std::abs(rate_) > bound) {
        rate_ = rate_ > 0 ? bound : -bound;
        accel_ = 0;
        mid_s_ = t;
    }
}

// The reversal at the depth is judged on the tool's position and its actual speed, both from
// encoder 32 (claim 1: "calculating actual speed of rotation of said tool through operation using
// said gear ratio data and a feedback signal of said spindle motor"). The speed is the edges of
// the last sample over the time between their first and last (interface 33 notes when each edge
// comes), not the edges a sample holds, which at S 180 are 3 or 4 of a 24-edge encoder; the
// position is the net edges counted, carried on at that speed since the last edge. When the
// depth left, less what motor 27 covers running down from that speed, comes within the next
// sample's travel, the NC times the reversal for the instant it is due (a timer, not the next
// sample), so the tap bottoms within an edge of its depth at every S the profile allows.
void TappingUnits::plan_reversal(double t, double depth, double per_edge) {
    const auto& p = profile_.spindle;
    const double rate = rate_ + accel_ * (t - mid_s_); // edges a second, into the work
    if (!measured_ || rate <= 0) {
        return; // not turning into the work yet
    }
    const double revs_per_s = rate / p.encoder_pulses_per_rev;
    const double a = p.run_down_rpm_per_s / 60.0;
    const double stop_travel =
        revs_per_s * revs_per_s / (2 * a) * memory_->ratio() * (order_.pitch / 100000.0);
    const double since_edge = std::min(t - last_edge_s_, 1.0 / rate);
    const double z_now = z_cmd_in_ + rate * since_edge * per_edge;
    const double left = depth - z_now - stop_travel;
    const double feed = rate * per_edge; // inches a second
    if (left <= feed * p.sample_s) {
        reverse_at_s_ = t + std::max(0.0, left / feed);
    }
}

// The tool's speed is measured afresh from t (a pass begins), no reversal timed.
void TappingUnits::measure_afresh(double t) {
    prev_edge_s_ = last_edge_s_;
    rate_ = 0;
    accel_ = 0;
    mid_s_ = t;
    measured_ = false;
    reverse_at_s_.reset();
    reversal_scheduled_ = false;
}

// Rigid peck tapping (an addition): the feed stands on its starting count, motor 27 at rest.
// The next pass goes Q deeper (at most to the depth); its speed is measured afresh as at the
// tap's start, but z_cmd (the edges counted since the tap began) and the tool's angle reference
// are kept, so the feed follows the helix of the first pass: the thread stays in phase.
void TappingUnits::next_peck(double t) {
    pass_target_ = std::min<int>(pass_target_ + order_.peck, order_.depth);
    ++holes_.back().pecks;
    measure_afresh(t);
    spindle_->command_rpm(order_.rpm);
    phase_ = Phase::run_in;
}

std::optional<double> TappingUnits::take_reversal() {
    if (!reverse_at_s_ || reversal_scheduled_) {
        return std::nullopt;
    }
    reversal_scheduled_ = true;
    return reverse_at_s_;
}

void TappingUnits::reverse(double t) {
    if (phase_ != Phase::run_in || !reverse_at_s_) {
        return; // the card ended or the machine stopped first
    }
    // Reverse: run down at the depth, then out at k x S (the faster retract, an addition; k = 1
    // without it). The feed follows the tool's edges as going in, so the pitch holds.
    spindle_->command_rpm(-order_.retract * order_.rpm);
    holes_.back().reverse_s = t;
    phase_ = Phase::run_out;
    reverse_at_s_.reset();
    reversal_scheduled_ = false;
    show();
}

void TappingUnits::show() {
    if (tracer_ == nullptr) {
        return;
    }
    tracer_->set(motor_rpm_, static_cast<std::uint32_t>(std::lround(std::abs(spindle_->rpm()))));
    tracer_->set(tool_rpm_, static_cast<std::uint32_t>(
                                std::lround(std::abs(spindle_->rpm()) * spindle_->ratio())));
    tracer_->set(head_, static_cast<std::uint32_t>(spindle_->tool()));
    tracer_->set(phase_signal_, static_cast<std::uint32_t>(phase_));
    tracer_->set(z_cmd_signal_, thousandths(z_cmd_in_));
    tracer_->set(feed_signal_, thousandths(feed_.speed_in_per_s * 60.0));
}

nlohmann::json TappingUnits::save() const {
    nlohmann::json j;
    j["spindle"] = spindle_->save();
    j["pc130"] = pc_->save();
    j["memory_12a"] = memory_->save();
    j["device_13"] = device_13_->save();
    j["counter_33"] = counter_33_->save();
    j["speed_33"] = speed_33_->save();
    j["bus35"] = {{"tool_call", bus_.tool_call},     {"nc_ready", bus_.nc_ready},
                  {"nc_received", bus_.nc_received}, {"transfer_request", bus_.transfer_request},
                  {"data_valid", bus_.data_valid},   {"data_ratio", exact(bus_.data_ratio)},
                  {"tool_ready", bus_.tool_ready}};
    j["phase"] = static_cast<int>(phase_);
    // When interface 33 counted its last edge: the next tap's first speed is timed from it
    // (found by the property test: a resumed run timed it from 0 and tapped 0.15 µin apart).
    j["last_edge_s"] = exact(last_edge_s_);
    j["holes"] = nlohmann::json::array();
    for (const HoleRecord& h : holes_) {
        j["holes"].push_back(tap_hole_json(h));
    }
    return j;
}

void TappingUnits::load(const nlohmann::json& j) {
    spindle_->load(j.at("spindle"));
    pc_->load(j.at("pc130"));
    memory_->load(j.at("memory_12a"));
    device_13_->load(j.at("device_13"));
    counter_33_->load(j.at("counter_33"));
    speed_33_->load(j.at("speed_33"));
    const nlohmann::json& b = j.at("bus35");
    bus_.tool_call = b.at("tool_call").get<int>();
    bus_.nc_ready = b.at("nc_ready").get<bool>();
    bus_.nc_received = b.at("nc_received").get<bool>();
    bus_.transfer_request = b.at("transfer_request").get<bool>();
    bus_.data_valid = b.at("data_valid").get<bool>();
    bus_.data_ratio = axes::exact(b.at("data_ratio"));
    bus_.tool_ready = b.at("tool_ready").get<bool>();
    const int phase = j.at("phase").get<int>();
    if (phase != 0) {
        throw std::runtime_error("saved state: a tap card was under way (states are saved "
                                 "between cards)");
    }
    phase_ = Phase::idle;
    // (a state saved before it was kept times the next tap's first speed from 0)
    last_edge_s_ = j.contains("last_edge_s") ? axes::exact(j.at("last_edge_s")) : 0.0;
    // (a state saved before the holes were kept has none: the resumed run reports its own)
    holes_.clear();
    if (j.contains("holes")) {
        for (const auto& h : j.at("holes")) {
            holes_.push_back(tap_hole_from_json(h));
        }
    }
    show();
}

} // namespace parsons::relaylogic
