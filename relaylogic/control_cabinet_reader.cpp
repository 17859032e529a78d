// Control cabinet 52, the reader and the two banks: card reader 134 feeds a card (zeroizing's
// channel 304 indexed it); the first bank of brushes senses it (the card-number check, the
// card's kind, the checks on a card before anything moves); the holding relays pick (storage
// 350-356 and 318-324, sequence switches 224, spindle control 165); the second bank steps the
// speed switches 236 through stepping device 252 (handle()); read_complete closes the circuits.
#include "relaylogic/card_reader.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;

void ControlCabinet::feed() {
    if (stop_) {
        return;
    }
    // A card of a later system that moved no axis by the 1952 columns (a condition or a sync
    // card) took the reader's cycle: its time ends as the reader feeds the next card.
    if (own_card_ != nullptr && record_times_ && !timings_.empty() &&
        timings_.back().end_s <= timings_.back().start_s) {
        timings_.back().end_s = now_;
    }
    if (keep_resume_point_) {
        resume_point_ = capture();
    }
    tracer_.set(zeroizing_, 0);
    for (SignalId channel :
         {channel_294_, channel_298_, channel_300_, channel_302_, channel_304_}) {
        tracer_.set(channel, 0);
    }
    card_ = next_card();
    own_card_ = nullptr;
    if (stop_) {
        return; // the attachment the reader takes its cards through refused
    }
    if (!card_) {
        for (const auto& a : attachments_) {
            a->deck_ended(*this);
            if (stop_) {
                return;
            }
        }
        deck_finished_ = true;
        tracer_.set(reader_feeding_, 0);
        return;
    }
    ++cards_read_;
    if (record_times_) {
        timings_.push_back(CardTiming{cards_read_, -1, now_, now_});
    }
    orders_ = cardreader::CardOrders{};
    orders_.number = -1;
    tracer_.set(reader_card_, static_cast<std::uint32_t>(cards_read_));
    tracer_.set(reader_feeding_, 1);
    // Col. 6: "Five separate cards, one for each lead screw, may be employed if desired.
    // However, it is desirable from the standpoint of economy and speed to condense the punched
    // information into a single card for a given position of the parts controlled by the five
    // lead screws." Each card of such a step passes the brushes in a card cycle of its own, and
    // the motors may run only once the fifth is read ("when all five axes speed switches 236
    // are thus set", col. 12): the banks are timed in the step's last cycle.
    // Emulation note: the brushes sense the five cards of a step together, as the one card they
    // reassemble into, in the fifth card's cycle (the holding relays of Fig. 13 would keep each
    // axis's orders from its own card's cycle): the checks of the first bank (card number, bad
    // punch, movement range) are made once a step, that late. The motors run the same.
    const int cards = std::max(1, deck_->cards_a_step());
    const double earlier = (cards - 1) * profile_.reader_cycle_s;
    // Fig. 9: on a ribbon (or tape) the next card follows with no gap; it is sensed sooner.
    // Every physical card but the deck's first saves the gap (so four in a first step of five).
    const int gaps = !profile_.ribbon_feed ? 0 : cards_read_ > 1 ? cards : cards - 1;
    const double gap = gaps * profile_.feed_gap_s;
    schedule(now_ + (earlier + profile_.first_bank_s - gap), EventKind::first_bank);
    schedule(now_ + (earlier + profile_.second_bank_s - gap), EventKind::second_bank);
    schedule(now_ + (earlier + profile_.reader_cycle_s - gap), EventKind::read_complete);
}

void ControlCabinet::first_bank() {
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_brushes(now_, cards_read_, *card_, layout_);
    }
    SensedCard sensed = sense_card(*card_, layout_, profile_.refuse_double_punch);
    if (!sensed.decoded) {
        const auto& bad = *sensed.decoded.bad_punch;
        machine_stop(StopReason::bad_punch, std::nullopt,
                     fmt::format("card {}, column {}: {}: the reader stops the machine (bad-punch "
                                 "refusal, an addition of this emulator: a 1952 reader would "
                                 "sense the holes as they are)",
                                 cards_read_, bad.column, bad.what),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    orders_ = sensed.decoded.orders;
    extra_relays_ = sensed.extra;
    if (record_times_) {
        timings_.back().number = orders_.number;
    }
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_card(now_, cards_read_, orders_);
    }
    // The card-number check (col. 8, no numeral): each card must be the previous one + 1
    // (0000 follows 9999).
    if (previous_number_ && orders_.number != (*previous_number_ + 1) % 10000) {
        machine_stop(StopReason::out_of_order_card, std::nullopt,
                     fmt::format("{}: card number {:04} follows {:04} (expected {:04}); stopped "
                                 "before any axis moved",
                                 card_name(), orders_.number, *previous_number_,
                                 (*previous_number_ + 1) % 10000),
                     "card-number lamp");
        return;
    }
    previous_number_ = orders_.number;
    tracer_.set(card_number_check_, static_cast<std::uint32_t>(orders_.number));
    if (first_bank_refuses()) {
        return;
    }
    // The brushes have sensed the card; the holding relays pick a relay's operate time later.
    schedule(now_ + profile_.relay_operate_s, EventKind::relays_pick);
}

// After the card-number check: a later kind of card goes to its attachment (none moves an
// axis by the 1952 columns); a motion card is checked before anything moves. True if the
// card goes no further here.
bool ControlCabinet::first_bank_refuses() {
    for (const auto& a : attachments_) {
        a->sensed(*this);
        if (stop_) {
            return true;
        }
    }
    if (orders_.kind != cardreader::CardKind::motion) {
        for (const auto& a : attachments_) {
            if (a->card_kind() == orders_.kind) {
                own_card_ = a.get();
            }
        }
        if (own_card_ == nullptr) {
            refuse_unattached_card(*this, orders_.kind); // the registry words the refusal
        } else {
            own_card_->read_card(*this);
        }
        return true;
    }
    for (const auto& a : attachments_) {
        a->check_motion_card(*this);
        if (stop_) {
            return true;
        }
    }
    return !move_within_soft_limits();
}

// The reader takes the next card: from the deck, or through the attachment that keeps the
// cards it has taken (press synchronisation: a loop card sends the reader back among them).
std::optional<cardreader::Card> ControlCabinet::next_card() {
    const InPhase reading(phases_, Phase::read_decode);
    if (supplier_ == nullptr) {
        return deck_->next();
    }
    return supplier_->next_card(*this, *deck_);
}

// The movement range, judged on the card before anything moves: where would each axis end
// if it travels exactly its check in the sense of its motion column?
bool ControlCabinet::move_within_soft_limits() {
    for (const auto& c : circuits_) {
        const auto& p = c->plant.profile();
        if (!p.soft_limits) {
            continue;
        }
        const cardreader::AxisOrder& o = orders_.axis(c->axis);
        const double from = c->plant.real_in();
        const double move = (o.motion == cardreader::Motion::forward ? 1 : -1) * o.check / 1000.0;
        const double to = from + move;
        if (to > p.soft_max_in || to < p.soft_min_in) {
            machine_stop(StopReason::soft_limit, c->axis,
                         fmt::format("{}, {}: this card moves it {:+.3f} in, from {:.4f} to {:.4f} "
                                     "in, past its soft limit {:.3f} in (movement range {:.3f} .. "
                                     "{:.3f} in); stopped before any axis moved (soft limits are "
                                     "an addition of this emulator, after Mitsubishi's movement "
                                     "range)",
                                     card_name(), axis_name(c->axis), move, from, to,
                                     to > p.soft_max_in ? p.soft_max_in : p.soft_min_in,
                                     p.soft_min_in, p.soft_max_in),
                         fmt::format("soft-limit lamp ({}; an addition)", axis_name(c->axis)));
            return false;
        }
    }
    return true;
}

void ControlCabinet::relays_pick() {
    tracer_.set(spindle_165_, static_cast<std::uint32_t>(orders_.spindle));
    command_spindle();
    last_sequence_position_ = 0;
    for (auto& c : circuits_) {
        c->order = orders_.axis(c->axis);
        c->set_direction(c->order.motion);
        c->ordered += (c->order.motion == cardreader::Motion::forward ? 1 : -1) * c->order.check;
        std::array<int, 3> numbers{};
        std::size_t count = 0;
        for (const auto& sd : c->order.slow_down) {
            if (sd) {
                numbers.at(count++) = *sd;
            }
        }
        numbers.at(count++) = c->order.stop;
        c->absolute_storage.store(std::span<const int>(numbers.data(), count));
        c->incremental_storage.store(c->order.check);
        // A double-punched digit column picks a second relay of its bank (parsons-1952).
        const auto& extra = extra_relays_.at(cardreader::axis_index(c->axis));
        for (std::size_t field = 0; field < kNumberFields; ++field) {
            for (std::size_t i = 0; i < 4; ++i) {
                const unsigned mask = extra.at(field).at(i);
                if (mask == 0) {
                    continue; // the common case: one punch a column
                }
                HoldingRelayBank& bank = field < 3
                                             ? c->absolute_storage.bank(static_cast<int>(i))
                                             : c->incremental_storage.bank(static_cast<int>(i));
                for (int d = 0; d < 10; ++d) {
                    if ((mask >> d & 1U) != 0) {
                        bank.pick(d);
                    }
                }
            }
        }
        c->sequence_switch.close_pattern(c->order.sequence);
        for (int p = 5; p >= 1; --p) {
            if (c->sequence_switch.closed(p)) {
                last_sequence_position_ = std::max(last_sequence_position_, p);
                break;
            }
        }
        c->compare();
    }
    // Every relay has picked: balancing circuit 266 sees each axis through contact 238 (236
    // stands on off until the second bank), before any motor starts.
    for (auto& c : circuits_) {
        if (watch_balance(*c, "as the card was read, before any motor started")) {
            break;
        }
    }
    for (const auto& a : attachments_) {
        a->relays_picked(*this);
    }
}

// The second bank: the speed columns step each speed switch 236 through stepping device 252,
// one step a stepping time (a card of a later kind moves no axis by them).
void ControlCabinet::second_bank() {
    if (own_card_ != nullptr) {
        return;
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        for (int k = 0; k < circuits_[i]->order.start_speed; ++k) {
            schedule(now_ + k * profile_.stepping_switch_step_s, EventKind::speed_step_252,
                     static_cast<int>(i));
        }
    }
}

void ControlCabinet::read_complete() {
    reading_complete_ = true;
    tracer_.set(reader_feeding_, 0);
    if (own_card_ != nullptr) {
        reading_complete_ = false; // no axis moves by the 1952 columns
        if (own_card_->card_read(*this) && !stop_) {
            tracer_.set(channel_304_, 1); // nothing to move: the reader indexes the next card
            schedule(now_, EventKind::feed);
        }
        return;
    }
    for (const auto& a : attachments_) {
        if (a->holds_motion(*this)) {
            return; // e.g. position reader 60 holds the card's motion until the crank reaches R
        }
    }
    update_motors();
    evaluate_all();
}

} // namespace parsons::relaylogic
