// What a run of control cabinet 52 reports (ControlCabinet::run): each axis, each card's
// times, the stop, the faults, and each attachment's part (relaylogic/attachment.hpp), present
// only when the machine has that attachment.
#pragma once

#include "axes/chain_figures.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/conditions/condition_units.hpp"
#include "relaylogic/contouring/contouring_result.hpp"
#include "relaylogic/faults.hpp"
#include "relaylogic/machine_observer.hpp"
#include "relaylogic/press/press_result.hpp"
#include "relaylogic/tapping/tapping_units.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace parsons::relaylogic {

struct AxisResult {
    double counter_in = 0;                   // what absolute counter 104-110 reads
    double real_in = 0;                      // where the part really is
    double error_in = 0;                     // real - counter, the counter's wraps counted
    std::int64_t impulses = 0;               // commutator 102 impulses the screw produced
    std::int64_t lost_steps = 0;             // impulses the stepping switches could not follow
    std::optional<double> fixture_angle_deg; // swivel and tilt
    std::optional<double> last_stop_in;      // the stop of the last card read, if any
    double slip_in = 0;                      // a slip fault: how far the part lags the screw
    double screw_in = 0;                     // the main screw's travel (turns x lead)
    int skipped_steps = 0;                   // skip faults that acted on its switches
    // Why the part is not where the counters say: the reading commutators 96-102 gave (net
    // crossings x 0.001 in), the part against that reading cause by cause, and what the
    // counters miscounted (relaylogic/axis_circuit.hpp).
    double commutator_in = 0;
    axes::ChainFigures chain;
    std::int64_t wrong_way = 0;
    std::int64_t thousandths_uncounted = 0;
    // Where the motion cards read put the part (the sum of their checks, each in its motion's
    // sense, from the reference zero), and what the counters counted, their turns included:
    // 10 in apart when a card ran its axis a whole turn of the counters past its number, which
    // no 1952 check can see (outputs/report/run_report.hpp, counter_turns_unseen).
    double ordered_in = 0;
    double counted_in = 0;
};

struct CardTiming {
    std::int64_t index = 0;
    int number = -1;
    double start_s = 0;
    double end_s = 0;
    // The card's cut began while the spindle motor was still running up, down or reversing
    // (column 1 changed at this card): when the cut began, and when the motor was at speed.
    // Negative: it did not.
    double cut_unready_s = -1;
    double spindle_ready_s = -1;
};

struct RunResult {
    bool completed = false;
    std::int64_t cards_read = 0;
    double machine_seconds = 0;
    std::optional<StopInfo> stop;
    std::array<AxisResult, cardreader::kAxisCount> axes{};
    std::vector<CardTiming> cards;   // each card's machine time, if asked for (record_card_times)
    std::vector<FaultEffect> faults; // what each injected fault did
    // The attachments' parts. Condition cards: the actions acknowledged, and the tool in the
    // spindle (when the profile has a tool changer).
    std::vector<ActionRecord> actions;
    std::optional<int> tool_in_spindle;
    bool conditions_used = false;     // a condition card was read: the report shows them only then
    std::optional<PressResult> press; // when the profile has press synchronisation
    std::optional<TappingResult> tapping;       // when the profile has spindle synchronisation
    std::optional<ContouringResult> contouring; // when the profile has contouring
};

} // namespace parsons::relaylogic
