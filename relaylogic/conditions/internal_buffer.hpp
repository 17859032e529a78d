// Internal buffer PFR of EP 0640901 (Siemens, claim 1): an addition, not in the
// 1952 patent.
//
// "The converter (UMS) ... converts the at least one condition record into two further entries
// in the internal buffer (PFR) which contain the condition and the action to be performed
// after its fulfilment"; "the internal buffer (PFR) supplies ... the condition to a monitoring
// unit (PRG) and the action ... to a tripping unit (ALE)". Both entries carry the same
// identifier (claim 3).
//
// Here the buffer is a row of kChannels pairs of registers, each pair a condition entry and an
// action entry with the event identifier in both; pair k feeds channel k of PRG and of ALE.
// Each pair's state is a small relay chain, traced as one signal:
//
//   empty ──UMS stores──► stored ──motion card's relays pick──► armed ──PRG reports──►
//   tripped ──ALE's action acknowledged──► acknowledged ──zeroizing (channel 294)──► empty
//
// Emulation note: the seed's buffer is a computer's memory; parsons draws it as registers of
// holding relays (one per pair), so that every entry is a signal in the trace.
#pragma once

#include "cardreader/condition_card.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/tracer.hpp"

#include <array>
#include <cstdint>

namespace parsons::relaylogic {

enum class PairState : std::uint8_t { empty, stored, armed, tripped, acknowledged };

// The motion entry of PFR (claim 1: "the converter (UMS) enters the motion statement of the
// motion record into an internal buffer (PFR)", which "supplies the motion statement to an
// interpolator (ITP)"): entered as the motion card is sensed, supplied as its relays pick (the
// 1952 storage banks and counters are the interpolator: none of its own), empty at zeroizing.
enum class MotionEntry : std::uint8_t { empty, entered, supplied };

struct ConditionEntry {
    int event = 0;
    cardreader::Axis axis = cardreader::Axis::table;
    cardreader::Thousandths position = 0;
    cardreader::PassingSense sense = cardreader::PassingSense::either;
};

struct ActionEntry {
    int event = 0;
    cardreader::ActionKind action = cardreader::ActionKind::lamp;
    int parameter = 0;
};

struct BufferPair {
    ConditionEntry condition;
    ActionEntry action;
    PairState state = PairState::empty;
    std::int64_t card = 0;        // deck position of the condition card it came from
    int card_number = -1;         // and its number
    int slot = 0;                 // its slot on that card (0-4): columns 1 + 15 slot on
    std::int64_t motion_card = 0; // the motion card it watches (once armed)
    double tripped_s = -1;        // when PRG reported it
    double acknowledged_s = -1;
    // An every-condition (an addition beyond the seed's claims, after Siemens' WHENEVER/EVERY):
    // zeroizing stores it again for the next motion card instead of clearing it, until a cancel.
    bool every = false;
    int firings = 0; // how many motion cards it has fired on (acknowledged) so far
};

// The card column of a field of the pair's condition (offset 0 the event, 8 the action digit).
inline int slot_column(const BufferPair& p, int offset) {
    return 1 + p.slot * cardreader::kConditionSlotColumns + offset;
}

class InternalBuffer {
public:
    // Enough for two condition cards of five before one motion card.
    static constexpr int kChannels = 10;

    explicit InternalBuffer(Tracer& tracer);
    const BufferPair& pair(int k) const { return pairs_.at(static_cast<std::size_t>(k)); }
    BufferPair& pair(int k) { return pairs_.at(static_cast<std::size_t>(k)); }
    void set_state(int k, PairState s);
    // The first empty pair, or -1 when the buffer is full.
    int free_pair() const;
    // A pair holding this event identifier (not empty), or -1.
    int pair_with_event(int event) const;
    // The first pair in state s, or -1.
    int first(PairState s) const;
    bool any(PairState s) const { return first(s) >= 0; }
    void clear(); // zeroizing: every pair back to empty
    MotionEntry motion() const { return motion_; }
    int motion_card_number() const { return motion_number_; }
    // Converter UMS enters a motion card's statement (its number), or PFR supplies it, or
    // zeroizing clears it.
    void set_motion(MotionEntry state, int card_number);
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    Tracer& tracer_;
    std::array<BufferPair, kChannels> pairs_{};
    std::array<SignalId, kChannels> event_signal_{};
    std::array<SignalId, kChannels> state_signal_{};
    MotionEntry motion_ = MotionEntry::empty;
    int motion_number_ = -1;
    SignalId motion_state_;
    SignalId motion_card_;
};

// Converter UMS (claim 1): takes a condition card's records and enters each as a condition
// entry and an action entry of the buffer. Returns an error sentence (naming the condition's
// column) when the buffer cannot take them: an identifier already stored for this motion card
// (or standing as an every-condition), or no free pair. A cancel (an addition) empties the pair
// of its every-condition, or is refused when no every-condition has that identifier.
std::optional<std::string> convert_condition_card(const cardreader::CardOrders& card,
                                                  std::int64_t index, InternalBuffer& buffer);

} // namespace parsons::relaylogic
