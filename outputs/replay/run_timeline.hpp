// The run as the exhibit page plays it back (web/, docs/web.md): every signal the cabinet
// defines, every change of one, the five real positions at every impulse, the cards, the
// stop and the finish, in machine time. The WebAssembly page records a run with it and hands
// the arrays to the viewer as they are; `parsons run --html FILE` embeds them in one
// self-contained page. The viewer only applies the recorded changes: nothing is computed
// twice.
#pragma once

#include "axes/machine_profile.hpp"
#include "relaylogic/machine_observer.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace parsons::cli {

class RunTimeline : public relaylogic::MachineObserver {
public:
    static constexpr std::size_t kMotionRecord = 8;

    // A deck with more changes than this is recorded up to the limit (the header says so); the
    // report of the run stays whole. 8 million changes are 128 MB of arrays.
    explicit RunTimeline(std::size_t max_changes = 8'000'000);

    // The machine the run is on: its swivel and tilt screws' geometry turns each motion record's
    // two fixture screws into the fixture's angles (axes::fixture_angle_deg).
    void set_machine(const axes::MachineProfile& profile) { profile_ = profile; }

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    // The tracer appends every change to the record's arrays itself (in bulk, no call a
    // change); on_signal() only when the record is one of several observers.
    relaylogic::ChangeLog* change_log() override { return &log_; }
    void on_signal(double t, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_motion(double t, const std::array<double, 5>& real_in) override;
    // The first motion record: where the axes stand as the run begins.
    void on_run_start(double t, const std::array<double, 5>& real_in) override;
    // The card under the brushes: its holes (web/reader.js), and once, the wiring they pick by.
    void on_brushes(double t, std::int64_t index, const cardreader::Card& card,
                    const cardreader::CardLayout& layout) override;
    void on_card(double t, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double t, const relaylogic::StopInfo& stop) override;
    void on_condition(double t, const relaylogic::ConditionEvent& event) override;
    void on_finish(double t) override;

    // For an airfoil template job: the design the cut grows against (docs/web.md).
    void set_design(nlohmann::json design) { design_ = std::move(design); }

    // Everything but the arrays: signals, cards, stop, finish, counts, and every signal's value
    // after the last change recorded ("final_values": where "to the end" lands at once).
    nlohmann::json header() const;
    // The same as JSON text. Without the signals (the same for every run on one machine
    // profile) it is quick to write; "signals_signature" tells a reader whether the signals it
    // has are these (signals_text()).
    std::string header_text(bool with_signals = true) const;
    std::string signals_text() const;
    std::string cards_text() const; // the cards, nlohmann's number text
    // The header without the signals for the live page, which parses it at once: nlohmann's own
    // number text, not json_text's shortest (every 17-digit double of the design tried at each
    // precision with snprintf took 58 of the demo deck's 85 ms first press in WebAssembly).
    std::string page_header_text() const;

    // The arrays, one entry a change: machine time (s), signal id, new value.
    const std::vector<double>& change_times() const { return log_.t; }
    const std::vector<std::uint32_t>& change_ids() const { return log_.id; }
    const std::vector<std::uint32_t>& change_values() const { return log_.value; }
    // Eight numbers a motion record: machine time, then table, cross, vertical, swivel, tilt
    // (inches), then the swivel's and the tilt's fixture angle (degrees).
    const std::vector<double>& motion() const { return motion_; }

    // Header and arrays in one JSON document, the arrays packed (packed_record) as base64
    // (what `run --html` embeds).
    std::string embedded_json() const;

private:
    bool full() const { return log_.t.size() >= log_.limit; }
    // Every signal after the last change recorded.
    std::vector<std::uint32_t> final_values() const;

    axes::MachineProfile profile_;
    bool full_ = false;                   // a motion record came past the changes' limit
    nlohmann::json header_fields() const; // all but the signals and the cards
    // The signals and the cards as JSON text, written as they come, without the closing "]".
    std::string signals_text_;
    std::uint64_t signals_hash_ = 0xcbf29ce484222325ULL; // FNV-1a over every definition
    std::string cards_text_;
    std::string brushes_text_;        // {"holes":..,"index":..,"t":..} a card the brushes sensed
    std::string brush_wiring_text_;   // relaylogic::brush_wiring of the reader's layout
    std::string record_texts() const; // "cards":[..],"brushes":[..],"brush_wiring":[..],
    nlohmann::json conditions_ = nlohmann::json::array();
    nlohmann::json stop_;
    nlohmann::json design_;
    double finish_ = -1;
    relaylogic::ChangeLog log_;
    std::vector<double> motion_;
    std::vector<std::uint32_t> initial_values_; // every signal as it was defined
    // The fixture's two angles for the last swivel and tilt screw positions (on_motion).
    bool angles_known_ = false;
    std::array<double, 2> angle_screws_{};
    std::array<double, 2> angles_{};
};

// The record's four arrays packed exactly, a few bytes a number (layout in run_timeline.cpp,
// read by unpack() in web/viewer.js).
std::string packed_record(const std::vector<double>& change_t,
                          const std::vector<std::uint32_t>& change_id,
                          const std::vector<std::uint32_t>& change_v,
                          const std::vector<double>& motion);

// The bytes of `data` as base64 (RFC 4648, with padding).
std::string base64(const unsigned char* data, std::size_t size);

} // namespace parsons::cli
