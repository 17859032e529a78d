// Control cabinet 52 with the press synchronisation of EP 0436887 (Mitsubishi): sync cards,
// loop cards and the reader's tape, the press's detector edges and the reference blocks of
// Fig. 6. An addition, not in the 1952 patent.
#include "relaylogic/control_cabinet.hpp"

#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {

using cardreader::axis_name;

// Resuming a run with press synchronisation: the cards the reader had taken from the deck are
// taken again, their numbers read, so that a loop card finds its way back.
void ControlCabinet::resume_tape(std::int64_t taken) {
    std::vector<cardreader::Card> saved_tape;
    for (std::int64_t i = 0; i < taken; ++i) {
        std::optional<cardreader::Card> card = deck_->next();
        if (!card) {
            throw cardreader::DeckError(fmt::format(
                "the deck has {} cards; the saved state resumes after card {}", i, taken));
        }
        const cardreader::DecodeResult decoded = cardreader::decode(*card, layout_);
        tape_.push_back(*card);
        tape_numbers_.push_back(decoded ? decoded.orders.number : -1);
    }
}

// A sync card (an addition after EP 0436887): no axis moves; its orders wait in readers 60 and
// 62 for the motion card after it, or, a loop card, it sends the reader back at the end of its
// card cycle.
void ControlCabinet::sync_card() {
    sync_card_ = true;
    if (!sync_.present()) {
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}, column {}: a sync card (an addition after EP 0436887, "
                                 "Mitsubishi): profile {} has no press synchronisation; the "
                                 "built-in profile parsons-extended has it",
                                 card_name(), layout_.extension_column, profile_.name),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    if (orders_.sync.loop) {
        return; // at the end of its card cycle (read_complete)
    }
    SynchronisationProcessor& scp = sync_.scp();
    if (scp.pending()) {
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}: a second sync card before one motion card (card {}, "
                                 "number {:04}, waits already; sync cards are an addition after "
                                 "EP 0436887, Mitsubishi)",
                                 card_name(), scp.pending_card(), scp.pending_number()),
                     "sync lamp (an addition)");
        return;
    }
    scp.take(orders_.sync, cards_read_, orders_.number);
}

// The seed's M99: the reader goes back to the card numbered loop_to, loop_count times; the
// card-number check then expects that number next.
void ControlCabinet::loop_card() {
    const cardreader::SyncOrder& o = orders_.sync;
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
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}: a loop card to card number {:04}, which the deck does not "
                                 "hold before it (the seed's M99; sync cards are an addition "
                                 "after EP 0436887, Mitsubishi)",
                                 card_name(), o.loop_to),
                     "sync lamp (an addition)");
        return;
    }
    loops_left_[tape_index_] = left - 1;
    replay_ = *target;
    previous_number_ = (o.loop_to + 9999) % 10000;
    if (loop_backs_ > 0) {
        const double cycle = now_ - last_loop_back_s_;
        shortest_cycle_s_ = loop_backs_ == 1 ? cycle : std::min(shortest_cycle_s_, cycle);
        longest_cycle_s_ = loop_backs_ == 1 ? cycle : std::max(longest_cycle_s_, cycle);
    } else {
        first_loop_back_s_ = now_;
    }
    last_loop_back_s_ = now_;
    ++loop_backs_;
}

// Detector edges due by time t: in fast-forward the quiet ones in one jump, then the one due now.
void ControlCabinet::press_edges(double t) {
    axes::Press& press = sync_.press();
    if (jumping_ && press_quiet_ > 0) {
        const std::int64_t n = std::min(press_quiet_, press.pulses_by(t));
        if (n > 0) {
            const double at = press.pulse_time(n);
            const axes::DetectorEdge last = press.skip_pulses(n);
            sync_.on_edges(n, last, at);
            press_quiet_ -= n;
        }
    }
    if (press.next_event_time() <= t) {
        if (auto edge = press.advance_to(t)) {
            if (sync_.on_edge(*edge, t)) {
                // Detector 61 conducts; 60's hold relay drops a relay's time later.
                schedule(t + profile_.relay_operate_s, EventKind::sync_release);
            }
        }
    }
}

void ControlCabinet::schedule_block() {
    schedule(static_cast<double>(block_) * profile_.speed_sample_s, EventKind::reference_block);
}

// A reference block of Fig. 6: the speeds processor 63 computed last block go to the drives,
// speed register 11 is read, 63 computes the next; and the wait is timed (sync_timeout).
void ControlCabinet::reference_block() {
    if (deck_finished_ || stop_) {
        return;
    }
    SynchronisationProcessor& scp = sync_.scp();
    const int pulses = sync_.sample_speed();
    if (scp.reference_block(pulses, profile_.sync_drive.max_in_per_min / 60.0)) {
        for (auto& c : circuits_) {
            if (scp.speed_synced(c->axis)) {
                update_motor(*c);
            }
        }
    }
    const double timeout = profile_.sync_timeout_s;
    if (scp.holding() && now_ - scp.hold_since() >= timeout) {
        machine_stop(StopReason::sync_timeout, std::nullopt,
                     fmt::format("{}: the card waited {:.1f} s for crank 21 to reach {} deg and "
                                 "it did not (crank at {:.1f} deg{}); synchronisation control "
                                 "processor 17 gave up after sync_timeout_s {:.1f} s (press "
                                 "synchronisation is an addition after EP 0436887, Mitsubishi)",
                                 card_name(), now_ - scp.hold_since(),
                                 scp.target_pulses() / sync_.press().profile().pulses_per_degree,
                                 sync_.press().angle_deg(),
                                 sync_.press().stopped() ? ", motor 22 stopped" : "", timeout),
                     "sync lamp (an addition)");
        return;
    }
    if (!scp.holding() && now_ - sync_.last_edge_s() >= timeout) {
        for (const auto& c : circuits_) {
            if (c->powered && scp.speed_synced(c->axis)) {
                machine_stop(StopReason::sync_timeout, c->axis,
                             fmt::format("{}, {}: speed-synchronised, and detector 10 gave no "
                                         "pulse for {:.1f} s (crank at {:.1f} deg{}): the axis "
                                         "stands; synchronisation control processor 17 gave up "
                                         "after sync_timeout_s {:.1f} s (press synchronisation "
                                         "is an addition after EP 0436887, Mitsubishi)",
                                         card_name(), axis_name(c->axis),
                                         now_ - sync_.last_edge_s(), sync_.press().angle_deg(),
                                         sync_.press().stopped() ? ", motor 22 stopped" : "",
                                         timeout),
                             "sync lamp (an addition)");
                return;
            }
        }
    }
    ++block_;
    schedule_block();
}

void ControlCabinet::sync_release() {
    SynchronisationProcessor& scp = sync_.scp();
    if (!scp.holding()) {
        return;
    }
    waited_s_ += now_ - scp.hold_since();
    scp.release();
    update_motors();
    for (auto& c : circuits_) {
        evaluate(*c);
    }
}

// The cabinet waits on the press: a card held for its angle, or a speed-synchronised axis
// powered (its speed is the press's).
bool ControlCabinet::waiting_on_press() const {
    const SynchronisationProcessor& scp = sync_.scp();
    if (scp.holding()) {
        return true;
    }
    for (const auto& c : circuits_) {
        if (c->powered && scp.speed_synced(c->axis)) {
            return true;
        }
    }
    return false;
}

// Nothing can happen but the press turning and the reference blocks: no axis moves, no other
// event is queued, and nothing waits on the press.
bool ControlCabinet::idle() const {
    if (queue_.size() != static_cast<std::size_t>(blocks_queued_) || unqueued_release_s_ > now_) {
        return false;
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        if (next_axis_event(i) != axes::kNever) {
            return false;
        }
    }
    return !waiting_on_press();
}

nlohmann::json ControlCabinet::capture_sync() const {
    if (!sync_.present()) {
        return nullptr;
    }
    using axes::exact;
    nlohmann::json loops = nlohmann::json::array();
    for (const auto& [index, left] : loops_left_) {
        loops.push_back({index, left});
    }
    return {{"units", sync_.save()},
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
            {"reference_block", block_}};
}

void ControlCabinet::resume_sync(const nlohmann::json& j) {
    using axes::exact;
    using axes::member;
    using axes::read;
    if (!sync_.present()) {
        if (!j.is_null()) {
            throw axes::StateError("the saved machine has a press; this profile has none");
        }
        return;
    }
    if (j.is_null()) {
        throw axes::StateError("the saved machine has no press; this profile has one");
    }
    sync_.load(member(j, "units"));
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
    if (deck_taken_ < 0 || replay_ > static_cast<std::size_t>(deck_taken_) || block_ < 1) {
        throw axes::StateError("sync: deck_cards_taken, replay and reference_block out of range");
    }
}

} // namespace parsons::relaylogic
