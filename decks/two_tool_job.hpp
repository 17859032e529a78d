// The two-tool template job: the job that shows the point of EP 0640901 (Siemens,
// claims 5 and 6), an addition to the 1952 machine, which had one cutter changed by hand.
//
// A template (Fig. 4, decks/template_job.hpp) is roughed with the big tool and finished with
// the small one. Between the passes the machine runs the table back to the change position
// (table 0.000: the seed's "change position X=0") and changes the tool. The seed's point is
// that the change need not wait for the table to arrive: a condition card trips it while the
// table is still on its way, so the change and the return move overlap.
//
//   card  1 .. a      pass 1: the template cut with tool 1 (the profile's first tool), its
//                     cutter offset by r1 + allowance, so it leaves the allowance standing
//   card  a+1         lift: the cross slide rises from the trailing edge to the clearance
//                     height (above every cutter centre of both passes, margin/2 to spare)
//   card  a+2         CONDITION CARD: table, reverse, position P: tool change to tool 2
//   card  a+3         RETURN MOVE: the table runs back to 0.000 at the clearance height;
//                     the cross slide (check 0) is punched at sequence position 4 and the
//                     table at 5, so the table's stop is the card's motion end
//   card  a+4 .. n    pass 2: the template cut with tool 2 (radius r2) on the design contour,
//                     from where the machine stands after the change (table 0, clearance)
//
//                  clearance  ----<-------<------ RETURN MOVE ------<-----.
//                     |       ^ tool change tripped here (tripped)       | lift
//   change position   x       P                                          |
//   table 0.000       ^ tripped here (boundary)         .-~~~~~~~~~~~-.  |
//                     |  pass 2 approach          .-~~~'   template    '~~. trailing edge
//
// Two variants, identical but for the position on the condition card:
//   - boundary: P = 0.000, the change position itself. The counter steps onto it with the
//     impulse that reaches the stop, so the change starts as the move ends, as a control
//     without condition cards would start it at the end of the record.
//   - tripped: P is where the table is lead_fraction x tool_change_s before it stops (an
//     estimate from the move's speeds, slow-downs and the motor's acceleration: kinematics
//     below), so the change runs while the table still travels and ends after it has stopped.
// The cabinet feeds the next card only when the change is acknowledged (claim 2), so the
// boundary deck's machine time exceeds the tripped deck's by exactly the time the tripped
// change overlapped the return move, and both leave the same part.
//
// Both passes share one work zero (the larger of the two passes' own, axis by axis, so both
// lie margin_in inside the counters' range): make_template_deck gives each pass its stations
// and its cards; the cards are then planned again (plan_move) in the common frame, every move
// from where the machine really stands, so that every card's check is |stop - previous stop|
// and pass 2 starts from the change position. Station cards are quantised again from their
// cutter centres; approach cards are shifted by the difference of the zeros, rounded to
// thousandths; a card a corner slowed (template_job.hpp) stays slowed.
//
// Emulation note: only the male template of the upper surface, whose trailing edge the cutter
// leaves by rising: after a lower or both-surface pass the lift would run the cutter through
// the part. The kinematics of the trip position ignore the delay 258 hold and the impulses'
// discreteness; the tests measure the real overlap.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "decks/airfoil.hpp"
#include "decks/template_job.hpp"

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace parsons::decks {

enum class ChangeVariant { tripped, boundary };
std::string_view variant_name(ChangeVariant v); // "tripped", "boundary"

struct TwoToolOptions {
    // The template (chord, stations or scallop, spacing, corner slow-down, margin). Its cutter
    // radius is not used: each pass takes its tool's radius from the profile. Upper, male.
    TemplateOptions pass;
    int rough_tool = 1;         // pass 1; its radius from the profile's tools
    int finish_tool = 2;        // pass 2
    double allowance_in = 0.01; // what pass 1 leaves standing on the design
    ChangeVariant variant = ChangeVariant::tripped;
    // tripped: the change is planned to begin this fraction of tool_change_s before the table
    // reaches the change position (< 1, so the change still ends after the move).
    double lead_fraction = 0.75;
};

struct TwoToolPass {
    int tool = 0;
    double radius_in = 0;       // the tool's radius (profile)
    double offset_in = 0;       // the cutter offset the cards were computed with
    TemplateDeck deck;          // as make_template_deck made it (its own work zero)
    std::size_t first_card = 0; // index into TwoToolDeck::cards
    std::size_t card_count = 0;
};

struct TwoToolDeck {
    std::vector<cardreader::CardOrders> cards; // numbered 1.. consecutively, condition included
    std::array<TwoToolPass, 2> passes;
    Eigen::Vector2d work_zero_in = Eigen::Vector2d::Zero(); // shared by both passes
    int clearance = 0;         // the cross slide's height for the return, thousandths
    std::size_t lift_card = 0; // indices into cards
    std::size_t condition_card = 0;
    std::size_t return_card = 0;
    int return_from = 0;       // where the return move starts (table, thousandths)
    int trip_position = 0;     // the condition's table position, thousandths
    double return_move_s = 0;  // estimated: the return move from its start to the stop
    double planned_lead_s = 0; // estimated: from the trip to the stop (0 for boundary)
};

// Throws JobError when the options cannot make the job (a tool the profile lacks, a surface
// other than the male upper one, a part too big, more cards than a deck can number:
// decks/deck_limits.hpp) and PlanError as make_template_deck does.
TwoToolDeck make_two_tool_deck(const Airfoil& airfoil, const TwoToolOptions& options,
                               const axes::MachineProfile& profile);

// The estimated time an axis order takes from the moment its counter steps onto `position`
// (thousandths, between its start `from` and its stop) to its stop: the motor accelerating and
// braking at the profile's rate between the speeds its slow-downs choose.
double time_to_stop_s(const cardreader::AxisOrder& order, int from, int position,
                      const axes::AxisProfile& axis);

} // namespace parsons::decks
