// Press synchronisation (an addition after EP 0436887, Mitsubishi) as an attachment of control
// cabinet 52 (relaylogic/attachment.hpp): the press turns on a clock of its own; a sync card's
// orders wait in readers 60 and 62 for the motion card after it, whose motion position reader
// 60 holds until crank 21 reaches the angle R, or whose every speed follows the press (processor
// 63, one reference block of Fig. 6 at a time); a loop card (the seed's M99) sends the reader
// back among the cards it has taken, as round a ribbon made into an endless loop. The units
// are relaylogic/press/sync_units.hpp's.
#pragma once

#include "relaylogic/attachment.hpp"
#include "relaylogic/press/press_result.hpp"
#include "relaylogic/press/sync_units.hpp"

#include <map>

namespace parsons::relaylogic {

class PressAttachment final : public Attachment {
public:
    PressAttachment(Tracer& tracer, const axes::MachineProfile& profile);
    // The profile has a press (otherwise the registry keeps none).
    bool present() const { return units_.present(); }

    std::string_view name() const override { return "sync"; }
    std::optional<cardreader::CardKind> card_kind() const override {
        return cardreader::CardKind::sync;
    }
    void start(ControlCabinet& cab) override;
    bool resume_deck(ControlCabinet& cab, cardreader::CardSource& deck) override;
    bool supplies_cards() const override { return true; }
    std::optional<cardreader::Card> next_card(ControlCabinet& cab,
                                              cardreader::CardSource& deck) override;
    void sensed(ControlCabinet& cab) override;
    void read_card(ControlCabinet& cab) override;
    bool card_read(ControlCabinet& cab) override;
    void relays_picked(ControlCabinet& cab) override;
    bool holds_motion(ControlCabinet& cab) override;
    bool holding() const override { return units_.scp().holding(); }
    bool drive(ControlCabinet& cab, AxisCircuit& c, bool on) override;
    void zeroized(ControlCabinet& cab) override;
    void on_event(ControlCabinet& cab, int code) override;
    double next_clock_event(const ControlCabinet& cab) const override;
    double plan_quiet(ControlCabinet& cab) override;
    void clock_edges_before(ControlCabinet& cab, double t) override;
    void clock_edges_at(ControlCabinet& cab, double t) override;
    bool waited_on(const ControlCabinet& cab) const override;
    void save(const ControlCabinet& cab, nlohmann::json& state) const override;
    void load(ControlCabinet& cab, const nlohmann::json& state) override;
    void add_to(RunResult& result) const override;

private:
    enum Code : int { reference_block_event = 0, sync_release_event = 1 };
    void loop_card(ControlCabinet& cab);
    void press_edges(ControlCabinet& cab, double t);
    void schedule_block(ControlCabinet& cab);
    void reference_block(ControlCabinet& cab);
    void sync_release(ControlCabinet& cab);
    void feeder_interlock(ControlCabinet& cab, FeederInterlock& interlock);
    void refuse(ControlCabinet& cab, std::optional<cardreader::Axis> axis,
                const std::string& message, StopReason reason = StopReason::sync_refused);

    SyncUnits units_;
    bool used_ = false; // a sync card was read (the report shows the press)
    // The cards the reader has taken (a loop card sends it back among them) and their numbers.
    std::vector<cardreader::Card> tape_;
    std::vector<int> tape_numbers_;
    std::size_t replay_ = 0;      // the next card comes from tape_[replay_] if within it
    std::size_t tape_index_ = 0;  // the card in the reader
    std::int64_t deck_taken_ = 0; // cards taken from the deck itself
    std::map<std::size_t, int> loops_left_;
    std::int64_t cycles_ = 0;
    std::int64_t loop_backs_ = 0;
    double last_loop_back_s_ = 0;
    double first_loop_back_s_ = 0;
    double shortest_cycle_s_ = 0;
    double longest_cycle_s_ = 0;
    double waited_s_ = 0;
    std::int64_t block_ = 1;       // the reference block queued next: at block_ x speed_sample_s
    std::int64_t press_quiet_ = 0; // fast-forward: edges that only count, ahead of the press
};

} // namespace parsons::relaylogic
