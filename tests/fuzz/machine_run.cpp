// Running a fuzzed deck: through the card reader, on the cabinet at both paces, and checked.
//
// The cabinet's two paces are a differential test that costs nothing to write: fast-forward
// (the default) must end every deck exactly as impulse level does, event for event
// (relaylogic/control_cabinet.hpp), so any difference in the result is a finding.
#include "tests/fuzz/machine_run.hpp"

#include "tests/fuzz/fuzz_targets.hpp"

#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>

namespace parsons::fuzz {
namespace {

using namespace parsons::cardreader;
using relaylogic::Pace;
using relaylogic::RunResult;

// Machine time only runs forwards and every position is a number. Attached to the
// fast-forward run it says it does not follow impulses, so that the cabinet still jumps.
class RunChecker : public relaylogic::MachineObserver {
public:
    explicit RunChecker(bool follows_impulses) : follows_(follows_impulses) {}
    bool follows_impulses() const override { return follows_; }
    void on_signal(double t, relaylogic::SignalId, std::uint32_t, std::uint32_t) override {
        check_time(t);
    }
    void on_motion(double t, const std::array<double, 5>& real_in) override {
        check_time(t);
        for (double x : real_in) {
            if (!std::isfinite(x)) {
                throw Finding(fmt::format("machine: an axis position is {} at {} s", x, t));
            }
        }
    }

private:
    void check_time(double t) {
        if (!std::isfinite(t) || t < last_s_) {
            throw Finding(fmt::format("machine: time {} s after {} s", t, last_s_));
        }
        last_s_ = t;
    }
    bool follows_;
    double last_s_ = 0;
};

RunResult run_once(const std::string& deck_file, const axes::MachineProfile& profile, Pace pace,
                   bool observe, const std::vector<relaylogic::Fault>& faults) {
    std::istringstream in(deck_file);
    DeckOptions options;
    options.format = DeckFormat::cbn;
    options.file_name = "fuzz.cbn";
    auto deck = open_card_source(in, options);
    relaylogic::ControlCabinet cabinet(profile, fig8_layout());
    cabinet.set_pace(pace);
    for (const auto& f : faults) {
        cabinet.add_fault(f);
    }
    RunChecker checker(pace == Pace::impulse_level);
    if (observe) {
        cabinet.attach(&checker);
    }
    try {
        return cabinet.run(*deck);
    } catch (const DeckError& e) {
        throw Finding(
            fmt::format("machine: the reader refused a deck the writer wrote: {}", e.what()));
    }
}

void check_run(const RunResult& run, std::size_t cards) {
    if (run.completed == run.stop.has_value()) {
        throw Finding("machine: a run must end either completed or stopped with a reason");
    }
    // A loop card (press synchronisation's M99) sends the reader back over cards it read: each
    // loop-back reads at most the whole deck again.
    const long deck = static_cast<long>(cards);
    const long loop_backs = run.press ? run.press->loop_backs : 0;
    if (loop_backs < 0 || run.cards_read < 0 || run.cards_read > deck * (1 + loop_backs) ||
        (run.completed && loop_backs == 0 && run.cards_read != deck) ||
        (run.completed && run.cards_read < deck)) {
        throw Finding(fmt::format("machine: {} cards read of a deck of {} with {} loop-back{}{}",
                                  run.cards_read, cards, loop_backs, loop_backs == 1 ? "" : "s",
                                  run.completed ? ", completed" : ""));
    }
    if (!std::isfinite(run.machine_seconds) || run.machine_seconds < 0) {
        throw Finding(fmt::format("machine: the run took {} s", run.machine_seconds));
    }
    for (const auto& axis : run.axes) {
        if (!std::isfinite(axis.counter_in) || !std::isfinite(axis.real_in) ||
            !std::isfinite(axis.error_in) || !std::isfinite(axis.fixture_angle_deg.value_or(0))) {
            throw Finding("machine: an axis result is not a number");
        }
    }
}

std::string summary(const RunResult& r) {
    std::string text =
        fmt::format("{} after {} cards at {} s", r.completed ? "completed" : "stopped",
                    r.cards_read, r.machine_seconds);
    if (r.stop) {
        text += fmt::format(" ({}, card {}: {})", relaylogic::stop_reason_name(r.stop->reason),
                            r.stop->card, r.stop->message);
    }
    for (std::size_t i = 0; i < r.axes.size(); ++i) {
        const auto& a = r.axes.at(i);
        text += fmt::format("; {}: counter {} real {} impulses {} lost {}", axis_name(kAxes.at(i)),
                            a.counter_in, a.real_in, a.impulses, a.lost_steps);
    }
    for (const auto& x : r.actions) {
        text += fmt::format("; event {} tripped {} acknowledged {}", x.event, x.tripped_s,
                            x.acknowledged_s);
    }
    if (r.tapping) {
        for (const auto& h : r.tapping->holes) {
            text +=
                fmt::format("; tap card {} tool {} deepest {} end {} at {} s{}", h.card, h.tool,
                            h.deepest_in, h.end_in, h.end_s, h.completed ? "" : " (not completed)");
        }
    }
    return text;
}

bool same_run(const RunResult& a, const RunResult& b) {
    if (a.completed != b.completed || a.cards_read != b.cards_read ||
        a.machine_seconds != b.machine_seconds || a.stop.has_value() != b.stop.has_value()) {
        return false;
    }
    if (a.stop && (a.stop->reason != b.stop->reason || a.stop->card != b.stop->card ||
                   a.stop->axis != b.stop->axis || a.stop->message != b.stop->message ||
                   a.stop->lamps != b.stop->lamps)) {
        return false;
    }
    for (std::size_t i = 0; i < a.axes.size(); ++i) {
        const auto& x = a.axes.at(i);
        const auto& y = b.axes.at(i);
        if (x.counter_in != y.counter_in || x.real_in != y.real_in || x.impulses != y.impulses ||
            x.lost_steps != y.lost_steps || x.screw_in != y.screw_in || x.slip_in != y.slip_in) {
            return false;
        }
    }
    // Condition cards (an addition): the same actions, tripped and acknowledged at the same
    // instants, and the same tool in the spindle.
    if (a.actions.size() != b.actions.size() || a.tool_in_spindle != b.tool_in_spindle) {
        return false;
    }
    for (std::size_t i = 0; i < a.actions.size(); ++i) {
        const auto& x = a.actions.at(i);
        const auto& y = b.actions.at(i);
        if (x.event != y.event || x.tripped_s != y.tripped_s ||
            x.acknowledged_s != y.acknowledged_s || x.motion_end_s != y.motion_end_s) {
            return false;
        }
    }
    // Tap cards (an addition): the same holes, cut as deep, reversed and ended at the same
    // instants, by the same heads with the same ratio in memory 12a.
    if (a.tapping.has_value() != b.tapping.has_value()) {
        return false;
    }
    if (a.tapping) {
        const auto& x = *a.tapping;
        const auto& y = *b.tapping;
        if (x.holes.size() != y.holes.size() || x.tool_on_spindle != y.tool_on_spindle ||
            x.ratio_in_memory != y.ratio_in_memory || x.head_exchanges != y.head_exchanges ||
            x.ratios_received != y.ratios_received) {
            return false;
        }
        for (std::size_t i = 0; i < x.holes.size(); ++i) {
            const auto& h = x.holes.at(i);
            const auto& k = y.holes.at(i);
            if (h.tool != k.tool || h.ratio_used != k.ratio_used || h.deepest_in != k.deepest_in ||
                h.end_in != k.end_in || h.reverse_s != k.reverse_s || h.end_s != k.end_s ||
                h.completed != k.completed || h.pecks != k.pecks || h.sync_s != k.sync_s) {
                return false;
            }
        }
    }
    // Press synchronisation (an addition): the crank where it stands, the cards held as long,
    // the axes as far behind, and the feeder's interlock holding the press as often and as long.
    if (a.press.has_value() != b.press.has_value()) {
        return false;
    }
    if (a.press) {
        const auto& x = *a.press;
        const auto& y = *b.press;
        if (x.revolution != y.revolution || x.crank_angle_deg != y.crank_angle_deg ||
            x.position_register != y.position_register || x.waited_s != y.waited_s ||
            x.max_lag_position_sync_in != y.max_lag_position_sync_in ||
            x.max_lag_speed_only_in != y.max_lag_speed_only_in ||
            x.feeder_interlock.has_value() != y.feeder_interlock.has_value()) {
            return false;
        }
        if (x.feeder_interlock && (x.feeder_interlock->holds != y.feeder_interlock->holds ||
                                   x.feeder_interlock->held_s != y.feeder_interlock->held_s)) {
            return false;
        }
    }
    // Contouring (an addition): the same segments, junctions decided alike, the same steps lost.
    if (a.contouring.has_value() != b.contouring.has_value()) {
        return false;
    }
    if (a.contouring) {
        const auto& x = *a.contouring;
        const auto& y = *b.contouring;
        if (x.segments != y.segments || x.junctions.size() != y.junctions.size() ||
            x.lost != y.lost || x.position_in != y.position_in || x.motion_s != y.motion_s ||
            x.largest_offset_in != y.largest_offset_in) {
            return false;
        }
    }
    return true;
}

} // namespace

void run_machine(const std::vector<Card>& cards, const axes::MachineProfile& profile, bool observe,
                 const std::vector<relaylogic::Fault>& faults) {
    std::ostringstream file;
    auto sink = make_cbn_sink(file, "fuzz.cbn");
    for (const Card& card : cards) {
        sink->write(card);
    }
    const RunResult fast = run_once(file.str(), profile, Pace::fast_forward, observe, faults);
    check_run(fast, cards.size());
    const RunResult reference = run_once(file.str(), profile, Pace::impulse_level, observe, faults);
    check_run(reference, cards.size());
    if (!same_run(fast, reference)) {
        throw Finding("machine: fast-forward and impulse level end differently:\n  fast-forward: " +
                      summary(fast) + "\n  impulse level: " + summary(reference));
    }
    if (!observe) {
        // Impulse level with no observer passes quiet stretches on fast-forward's own plan
        // (ControlCabinet::run_impulses); the reference that plans nothing is impulse level
        // with an observer that follows every impulse.
        const RunResult followed = run_once(file.str(), profile, Pace::impulse_level, true, faults);
        check_run(followed, cards.size());
        if (!same_run(followed, reference)) {
            throw Finding("machine: impulse level with and without an observer end differently:\n"
                          "  followed: " +
                          summary(followed) + "\n  no observer: " + summary(reference));
        }
    }
}

} // namespace parsons::fuzz
