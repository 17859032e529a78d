// Press synchronisation (an addition after EP 0436887, Mitsubishi) on the card cycle of control
// cabinet 52: sync cards, loop cards and the reader's tape, the press's detector edges and the
// reference blocks of Fig. 6. Not in the 1952 patent.
#include "relaylogic/press/press_attachment.hpp"

#include "relaylogic/control_cabinet.hpp"

#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;

PressAttachment::PressAttachment(Tracer& tracer, const axes::MachineProfile& profile) {
    units_.install(tracer, profile);
}

void PressAttachment::refuse(ControlCabinet& cab, std::optional<Axis> axis,
                             const std::string& message, StopReason reason) {
    cab.machine_stop(reason, axis, message, "sync lamp (an addition)");
}

// The press turns from the start: its first reference block.
void PressAttachment::start(ControlCabinet& cab) {
    schedule_block(cab);
}

// Resuming: the cards the reader had taken from the deck are taken again, their numbers read,
// so that a loop card finds its way back.
bool PressAttachment::resume_deck(ControlCabinet& cab, cardreader::CardSource& deck) {
    for (std::int64_t i = 0; i < deck_taken_; ++i) {
        std::optional<cardreader::Card> card = deck.next();
        if (!card) {
            throw cardreader::DeckError(fmt::format(
                "the deck has {} cards; the saved state resumes after card {}", i, deck_taken_));
        }
        const cardreader::DecodeResult decoded = cardreader::decode(*card, cab.layout());
        tape_.push_back(*card);
        tape_numbers_.push_back(decoded ? decoded.orders.number : -1);
    }
    return true;
}

// The reader takes the next card: from the deck, or, after a loop card sent it back, again
// from the cards it has taken. At the end of the deck a sync card still waiting for its motion
// card stops the machine.
std::optional<cardreader::Card> PressAttachment::next_card(ControlCabinet& cab,
                                                           cardreader::CardSource& deck) {
    if (replay_ < tape_.size()) {
        tape_index_ = replay_++;
        return tape_.at(tape_index_);
    }
    std::optional<cardreader::Card> card = deck.next();
    if (card) {
        ++deck_taken_;
        tape_.push_back(*card);
        tape_numbers_.push_back(-1); // known once the first bank has sensed it
        tape_index_ = tape_.size() - 1;
        replay_ = tape_.size();
    } else if (units_.scp().pending()) {
        const SynchronisationProcessor& scp = units_.scp();
        refuse(cab, std::nullopt,
               fmt::format("card {} (number {:04}): a sync card with no motion card after "
                           "it: the deck ends (its orders are for the motion card that "
                           "follows it; sync cards are an addition after EP 0436887, "
                           "Mitsubishi)",
                           scp.pending_card(), scp.pending_number()));
    }
    return card;
}

// Every card sensed: its number goes on the tape. A motion card cannot follow speed
// synchronisation of an axis it does not move.
void PressAttachment::sensed(ControlCabinet& cab) {
    const cardreader::CardOrders& orders = cab.orders();
    if (tape_index_ < tape_numbers_.size()) {
        tape_numbers_.at(tape_index_) = orders.number;
    }
    if (orders.kind != cardreader::CardKind::motion || !units_.scp().pending()) {
        return;
    }
    const SynchronisationProcessor& scp = units_.scp();
    for (Axis a : cardreader::kAxes) {
        if (scp.pending_order().travel_per_pulse.at(cardreader::axis_index(a)) &&
            orders.axis(a).check == 0) {
            refuse(cab, a,
                   fmt::format("{}: sync card {} (number {:04}) orders speed "
                               "synchronisation of the {} axis, which this card does "
                               "not move (check 0) (sync cards are an addition after "
                               "EP 0436887, Mitsubishi)",
                               cab.card_name(), scp.pending_card(), scp.pending_number(),
                               axis_name(a)));
            return;
        }
    }
}

// A sync card: no axis moves; a reset order operates switch 16A as the card is read, its
// synchronisation waits in readers 60 and 62 for the motion card after it, or, a loop card, it
// sends the reader back at the end of its card cycle.
void PressAttachment::read_card(ControlCabinet& cab) {
    used_ = true;
    const cardreader::CardOrders& orders = cab.orders();
    if (orders.sync.loop) {
        return; // at the end of its card cycle (card_read)
    }
    SynchronisationProcessor& scp = units_.scp();
    if (scp.pending()) {
        refuse(cab, std::nullopt,
               fmt::format("{}: a second sync card before one motion card (card {}, "
                           "number {:04}, waits already; sync cards are an addition after "
                           "EP 0436887, Mitsubishi)",
                           cab.card_name(), scp.pending_card(), scp.pending_number()));
        return;
    }
    if (orders.sync.register_reset) {
        // Read between two cards' motions: no axis follows now (the zeroizing circuit cleared
        // processor 63), so no reference travel jumps with the register.
        units_.position_register().switch_16A();
    }
    if (orders.sync.synchronises()) {
        scp.take(orders.sync, cab.cards_read(), orders.number);
    }
}

bool PressAttachment::card_read(ControlCabinet& cab) {
    if (cab.orders().sync.loop) {
        loop_card(cab);
    }
    return true;
}

// The seed's M99: the reader goes back to the card numbered loop_to, loop_count times; the
// card-number check then expects that number next.
void PressAttachment::loop_card(ControlCabinet& cab) {
    const cardreader::SyncOrder& o = cab.orders().sync;
    ++cycles_;
    const auto it = loops_left_.find(tape_index_);
    const int left = it == loops_left_.end() ? o.loop_count : it->second;
    if (left <= 0) {
        loops_left_.erase(tape_index_); // done: armed again if the reader comes round again
        return;
    }
    std::optional<std::size_t> target;
    for (std::size_t j = tape_index_; j-- > 0;) {
        if (tape_numbers_.at(j) == o.loop_to) {
            target = j;
            break;
        }
    }
    if (!target) {
        refuse(cab, std::nullopt,
               fmt::format("{}: a loop card to card number {:04}, which the deck does not "
                           "hold before it (the seed's M99; sync cards are an addition "
                           "after EP 0436887, Mitsubishi)",
                           cab.card_name(), o.loop_to));
        return;
    }
    loops_left_[tape_index_] = left - 1;
    replay_ = *target;
    cab.expect_card_number(o.loop_to);
    const double now = cab.now();
    if (loop_backs_ > 0) {
        const double cycle = now - last_loop_back_s_;
        shortest_cycle_s_ = loop_backs_ == 1 ? cycle : std::min(shortest_cycle_s_, cycle);
        longest_cycle_s_ = loop_backs_ == 1 ? cycle : std::max(longest_cycle_s_, cycle);
    } else {
        first_loop_back_s_ = now;
    }
    last_loop_back_s_ = now;
    ++loop_backs_;
}

void PressAttachment::relays_picked(ControlCabinet& /*cab*/) {
    units_.scp().arm(); // a sync card's orders into readers 60 and 62
}

// Position reader 60 holds the card's motion until the crank reaches R.
bool PressAttachment::holds_motion(ControlCabinet& cab) {
    return units_.scp().hold_unless_at(units_.position_register().value(), cab.now());
}

// Speed synchronisation: on every position of speed switch 236 a synchronised axis runs on the
// follower drive at processor 63's speed for that position (its travel per pulse times the
// crank's speed, and the position loop's correction on a card with position sync).
bool PressAttachment::drive(ControlCabinet& cab, AxisCircuit& c, bool on) {
    SynchronisationProcessor& scp = units_.scp();
    const int k = c.speed_switch.position();
    if (!(on && k >= 1 && k <= 3 && scp.speed_synced(c.axis))) {
        return false;
    }
    if (!scp.started(c.axis)) {
        scp.start_axis(c.axis, k, c.contact_set_a, units_.position_register().value());
    }
    scp.switch_at(c.axis, k, c.contact_set_a, units_.position_register().value());
    const double v = scp.drive_speed(c.axis, k);
    scp.note_asked(c.axis, k, cab.now(), cab.cards_read(), cab.orders().number);
    c.plant.command_follow(c.direction, v, cab.profile().sync_drive.acceleration_in_per_s2);
    scp.commanded(c.axis, v);
    c.set_powered(on);
    return true;
}

void PressAttachment::zeroized(ControlCabinet& /*cab*/) {
    units_.scp().clear(); // and readers 60 and 62
}

void PressAttachment::on_event(ControlCabinet& cab, int code) {
    if (code == reference_block_event) {
        reference_block(cab); // the blocks run on whatever card is in the reader
    } else {
        sync_release(cab);
    }
}

double PressAttachment::next_clock_event(const ControlCabinet& /*cab*/) const {
    return units_.press().next_event_time();
}

// Fast-forward: every edge of this segment of constant crank speed only counts, but the one
// that brings register 14 onto a held card's angle R.
double PressAttachment::plan_quiet(ControlCabinet& cab) {
    press_quiet_ = 0;
    if (!cab.running()) {
        return axes::kNever;
    }
    const axes::Press& press = units_.press();
    if (press.next_event_is_pulse()) {
        const std::int64_t in_segment = press.pulses_by(axes::kNever);
        const std::int64_t quiet = units_.quiet_edges(in_segment);
        if (quiet > 0) {
            press_quiet_ = quiet;
            // The edge after the stretch, or the stretch's last edge when the segment ends
            // with it (the segment's end then comes up as the press's next event).
            return quiet < in_segment ? press.pulse_time(quiet + 1) : press.pulse_time(quiet);
        }
    }
    return press.next_event_time();
}

void PressAttachment::clock_edges_before(ControlCabinet& cab, double t) {
    press_edges(cab, std::nextafter(t, -axes::kNever));
}

void PressAttachment::clock_edges_at(ControlCabinet& cab, double t) {
    press_edges(cab, t);
}

// Detector edges due by time t: in fast-forward the quiet ones in one jump, then the one due now.
void PressAttachment::press_edges(ControlCabinet& cab, double t) {
    axes::Press& press = units_.press();
    if (cab.jumping() && press_quiet_ > 0) {
        const std::int64_t n = std::min(press_quiet_, press.pulses_by(t));
        if (n > 0) {
            const double first = press.pulse_time(1);
            const double at = press.pulse_time(n);
            const axes::DetectorEdge last = press.skip_pulses(n);
            units_.on_edges(n, last, first, at);
            press_quiet_ -= n;
        }
    }
    if (press.next_event_time() <= t) {
        if (auto edge = press.advance_to(t)) {
            if (units_.on_edge(*edge, t)) {
                // Detector 61 conducts; 60's hold relay drops a relay's time later.
                cab.schedule(*this, t + cab.profile().relay_operate_s, sync_release_event);
            }
        }
    }
}

void PressAttachment::schedule_block(ControlCabinet& cab) {
    cab.schedule(*this, static_cast<double>(block_) * cab.profile().speed_sample_s,
                 reference_block_event, true);
}

// A reference block of Fig. 6: the speeds processor 63 computed last block go to the drives,
// speed register 11 is read, 63 computes the next; and the wait is timed (sync_timeout).
void PressAttachment::reference_block(ControlCabinet& cab) {
    if (!cab.running()) {
        return;
    }
    const axes::MachineProfile& profile = cab.profile();
    const double now = cab.now();
    SynchronisationProcessor& scp = units_.scp();
    const double rate = units_.sample_speed(now);
    std::array<std::optional<SynchronisationProcessor::Feedback>, cardreader::kAxisCount> fb{};
    for (const auto& c : cab.circuits()) {
        if (!scp.speed_synced(c->axis) || !scp.started(c->axis)) {
            continue;
        }
        if (cab.count_due_impulse(*c) && cab.stopped()) {
            return; // the impulse due now stopped the machine
        }
        if (c->powered && !c->stopped) {
            fb.at(cardreader::axis_index(c->axis)) =
                SynchronisationProcessor::Feedback{c->speed_switch.position(), c->contact_set_a};
        }
    }
    if (scp.reference_block(rate, units_.turning(), units_.position_register().value(), fb)) {
        for (const auto& c : cab.circuits()) {
            if (scp.speed_synced(c->axis)) {
                cab.update_motor(*c);
            }
        }
    }
    FeederInterlock* interlock = units_.interlock();
    if (interlock != nullptr) {
        feeder_interlock(cab, *interlock);
    }
    const double timeout = profile.sync_timeout_s;
    if (interlock != nullptr && interlock->holding() && now - interlock->held_since() >= timeout) {
        refuse(cab, std::nullopt,
               fmt::format("{}: the feeder's interlock held the press {:.1f} s (crank at {:.1f} "
                           "deg) and no synchronised axis made its lag up to half of "
                           "press.feeder_hold_lag_in {:g} in; synchronisation control processor "
                           "17 gave up after sync_timeout_s {:.1f} s (the interlock is an "
                           "addition: docs/press-sync.md)",
                           cab.card_name(), now - interlock->held_since(),
                           units_.press().angle_deg(), interlock->limit_in(), timeout),
               StopReason::sync_timeout);
        return;
    }
    if (scp.holding() && now - scp.hold_since() >= timeout) {
        refuse(cab, std::nullopt,
               fmt::format("{}: the card waited {:.1f} s for crank 21 to reach {} deg and "
                           "it did not (crank at {:.1f} deg{}); synchronisation control "
                           "processor 17 gave up after sync_timeout_s {:.1f} s (press "
                           "synchronisation is an addition after EP 0436887, Mitsubishi)",
                           cab.card_name(), now - scp.hold_since(),
                           scp.target_pulses() / units_.press().profile().pulses_per_degree,
                           units_.press().angle_deg(),
                           units_.press().stopped() ? ", motor 22 stopped" : "", timeout),
               StopReason::sync_timeout);
        return;
    }
    // The press's silence is timed from its last pulse, or from the end of a hold of the
    // interlock's, whichever came later (while the interlock holds, it times the hold).
    const double silent_since = std::max(
        units_.last_edge_s(), interlock != nullptr ? interlock->free_since() : -axes::kNever);
    if (!scp.holding() && (interlock == nullptr || !interlock->holding()) &&
        now - silent_since >= timeout) {
        for (const auto& c : cab.circuits()) {
            if (c->powered && scp.speed_synced(c->axis)) {
                refuse(cab, c->axis,
                       fmt::format("{}, {}: speed-synchronised, and detector 10 gave no "
                                   "pulse for {:.1f} s (crank at {:.1f} deg{}): the axis "
                                   "stands; synchronisation control processor 17 gave up "
                                   "after sync_timeout_s {:.1f} s (press synchronisation "
                                   "is an addition after EP 0436887, Mitsubishi)",
                                   cab.card_name(), axis_name(c->axis), now - silent_since,
                                   units_.press().angle_deg(),
                                   units_.press().stopped() ? ", motor 22 stopped" : "", timeout),
                       StopReason::sync_timeout);
                return;
            }
        }
    }
    ++block_;
    schedule_block(cab);
}

// The feeder's interlock at a reference block: the relay the last block computed holds or
// lets go the press now (every edge due by now taken first), and the relay is computed anew from
// the lags processor 63 has just read.
void PressAttachment::feeder_interlock(ControlCabinet& cab, FeederInterlock& interlock) {
    const double now = cab.now();
    const bool hold = interlock.block(units_.scp().most_behind_in(), now);
    axes::Press& press = units_.press();
    if (hold == press.held()) {
        return;
    }
    while (press.next_event_time() <= now) {
        press_edges(cab, now);
    }
    if (hold) {
        press.hold(now);
    } else {
        press.release(now);
    }
}

void PressAttachment::sync_release(ControlCabinet& cab) {
    SynchronisationProcessor& scp = units_.scp();
    if (!scp.holding()) {
        return;
    }
    waited_s_ += cab.now() - scp.hold_since();
    scp.release();
    cab.update_motors();
    cab.evaluate_all();
}

// The cabinet waits on the press: a card held for its angle, or a speed-synchronised axis
// powered (its speed is the press's).
bool PressAttachment::waited_on(const ControlCabinet& cab) const {
    const SynchronisationProcessor& scp = units_.scp();
    if (scp.holding()) {
        return true;
    }
    for (const auto& c : cab.circuits()) {
        if (c->powered && scp.speed_synced(c->axis)) {
            return true;
        }
    }
    return false;
}

void PressAttachment::save(const ControlCabinet& /*cab*/, nlohmann::json& state) const {
    using axes::exact;
    nlohmann::json loops = nlohmann::json::array();
    for (const auto& [index, left] : loops_left_) {
        loops.push_back({index, left});
    }
    state["sync"] = {{"units", units_.save()},
                     {"deck_cards_taken", deck_taken_},
                     {"replay", replay_},
                     {"tape_index", tape_index_},
                     {"loops_left", loops},
                     {"cycles", cycles_},
                     {"loop_backs", loop_backs_},
                     {"first_loop_back_s", exact(first_loop_back_s_)},
                     {"last_loop_back_s", exact(last_loop_back_s_)},
                     {"shortest_cycle_s", exact(shortest_cycle_s_)},
                     {"longest_cycle_s", exact(longest_cycle_s_)},
                     {"waited_s", exact(waited_s_)},
                     {"reference_block", block_},
                     {"used", used_}};
}

void PressAttachment::load(ControlCabinet& /*cab*/, const nlohmann::json& state) {
    using axes::exact;
    using axes::member;
    using axes::read;
    const nlohmann::json& j = state.contains("sync") ? state.at("sync") : nlohmann::json();
    if (j.is_null()) {
        throw axes::StateError("the saved machine has no press; this profile has one");
    }
    units_.load(member(j, "units"));
    deck_taken_ = read<std::int64_t>(j, "deck_cards_taken");
    replay_ = read<std::size_t>(j, "replay");
    tape_index_ = read<std::size_t>(j, "tape_index");
    loops_left_.clear();
    for (const auto& l : member(j, "loops_left")) {
        loops_left_[l.at(0).get<std::size_t>()] = l.at(1).get<int>();
    }
    cycles_ = read<std::int64_t>(j, "cycles");
    loop_backs_ = read<std::int64_t>(j, "loop_backs");
    first_loop_back_s_ = exact(member(j, "first_loop_back_s"));
    last_loop_back_s_ = exact(member(j, "last_loop_back_s"));
    shortest_cycle_s_ = exact(member(j, "shortest_cycle_s"));
    longest_cycle_s_ = exact(member(j, "longest_cycle_s"));
    waited_s_ = exact(member(j, "waited_s"));
    block_ = read<std::int64_t>(j, "reference_block");
    // A state saved before the report knew whether the deck used it: shown, as it was then.
    used_ = !j.contains("used") || read<bool>(j, "used");
    if (deck_taken_ < 0 || replay_ > static_cast<std::size_t>(deck_taken_) || block_ < 1) {
        throw axes::StateError("sync: deck_cards_taken, replay and reference_block out of range");
    }
}

void PressAttachment::add_to(RunResult& result) const {
    PressResult p;
    p.used = used_;
    p.revolution = units_.press().revolution();
    p.crank_angle_deg = units_.press().angle_deg();
    p.position_register = units_.position_register().value();
    p.register_resets = units_.position_register().resets();
    p.press_stopped = units_.press().stopped();
    p.cycles = cycles_;
    p.loop_backs = loop_backs_;
    if (loop_backs_ >= 2) {
        p.mean_cycle_s =
            (last_loop_back_s_ - first_loop_back_s_) / static_cast<double>(loop_backs_ - 1);
        p.shortest_cycle_s = shortest_cycle_s_;
        p.longest_cycle_s = longest_cycle_s_;
    }
    p.waited_s = waited_s_;
    p.max_lag_position_sync_in = units_.scp().worst_lag_in(true);
    p.max_lag_speed_only_in = units_.scp().worst_lag_in(false);
    p.max_lead_position_sync_in = units_.scp().worst_lead_in(true);
    p.max_lead_speed_only_in = units_.scp().worst_lead_in(false);
    p.drive_saturated = units_.scp().saturation();
    if (const FeederInterlock* fi = units_.interlock()) {
        const double t = result.machine_seconds; // the hold in force counted to the end
        p.feeder_interlock = FeederHolds{fi->limit_in(), fi->holds(), fi->held_s(t),
                                         fi->longest_s(t), fi->holding()};
    }
    result.press = p;
}

} // namespace parsons::relaylogic
