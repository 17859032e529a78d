// The whole machine as a fuzz target: the input bytes become a short, valid-looking deck.
//
// The bytes are read as a recipe rather than as card images, so that almost every input is a
// deck a programmer might have punched: card numbers in order, each check the travel since
// the previous card, slow-downs before the stop, sequence positions 1-5. Single bits of the
// recipe make it wrong the ways real decks were wrong (a check off by some thousandths, the
// motion against the stop, the wrong number of slow-downs, a stray sequence pattern), and the
// bytes left over flip single punches on the finished cards (a card number, a digit, a mark).
//
//   byte 0       cards: 1 + b % 6 (the bound that keeps every input fast)
//   byte 1       bit 0 separate registers, bit 1 count hundredths at speed 1, bit 2 attach an
//                observer, bit 3 switches that follow only 50 steps a second (lost impulses),
//                bit 4 count screw turns (the departure from Fig. 3), bit 5 backlash 0.002 in
//                in every nut 78, bit 6 lead-screw, instrument-shaft and cam 160 tables, bit 7
//                a slip of the table's drive (0.030 in from its 40th impulse)
//   bytes 2-3    first card number, big-endian, modulo 10000
//   per card     1 byte spindle (b % 3), then 4 bytes per axis (table .. tilt):
//                  flags  bits 0-1 start speed 1 + b % 3; bit 2 moves x16; bit 3 a wrong
//                         check; bits 4-5 slow-downs: 0 as many as the speed needs (3 - speed),
//                         1 none, 2 one, 3 two; bit 6 motion against the stop; bit 7 stay put
//                  step   signed travel in thousandths (x16 with bit 2), clamped to 0..9.999
//                  gap    slow-down spacing 0.020 + 0.004 b in; the error of a wrong check
//                  seq    bit 5 set: the pattern is bits 0-4 (0 = never runs); otherwise the
//                         single position 1 + (bits 0-4) % 5
//   then         1 byte, the cabinet's readings and additions (MachineProfile's last group):
//                bit 0 the incremental comparer stops at any speed, bit 1 delay 258 waits for
//                the equality to leave, bit 2 lamps only on a trip, bit 3 the reader refuses a
//                double punch, bit 4 ribbon feed (Fig. 9), bit 5 delay 258 of 0.005 s (too
//                short: a double step), bit 6 the table's travel limits at -0.05 and 2.5 in,
//                bit 7 a steep screw-error table on the table (the part runs 0.8 in a reading
//                inch: impulses closer than 0.001 in of screw travel)
//   then         up to 8 triples (card, column, row): flip that punch (on the finished deck)
//   then         1 byte, condition cards (an addition after EP 0640901): bit 0 on turns the
//                profile's condition units on (parsons-extended's) and reads b >> 1 % 4 + 1
//                conditions of 5 bytes each: the motion card they stand before (b % cards),
//                the event (1 + b % 99), axis (b % 5) and sense (b / 5 % 3), action (1 + b % 8)
//                and its parameter (1 + b / 8 % 5), and the position: b2 < 128 lays it on
//                the watched axis's path on that card (1 + b2 % travel thousandths past the
//                start, in its motion), else (b2 - 128) * 80 thousandths, anywhere. Conditions
//                before one card share one condition card (five to a card). They come after
//                all eight flips (two equal triples flip a hole back), so that inputs kept
//                before condition cards existed replay the same deck.
//   then         1 byte, press synchronisation (an addition after EP 0436887): bit 0 on turns
//                the profile's press on (parsons-extended's, 6 strokes a minute, 2 pulses a
//                degree); bits 1-2: 1 + b % 4 sync cards of 3 bytes each: the motion card they
//                stand before (b % cards), the angle R (b * 360 / 256; none when b % 4 == 3:
//                speed sync only), the speed-synchronised axis (b % 5, none when b / 5 % 3 == 0)
//                with a travel per pulse of 10 + b * 2 hundred-thousandths, the reset of
//                register 14 (switch 16A) when the axis byte's b / 15 % 2 == 1 (with neither R
//                nor an axis, a card of the reset alone); bit 3 a loop card
//                at the end back to the first card, 1 + (b >> 4) % 3 times; bit 4 the press
//                slows 30 % while pressing; bit 5 a lasting change to 0.7 of its speed in the
//                first revolution at 100 deg; bit 6 motor 22 stops in the second revolution at
//                200 deg; bit 7 the crank turns backwards. Two sync cards before one motion
//                card, or one before nothing, are the cabinet's to refuse.
//   then         1 byte, spindle synchronisation (an addition after EP 0360190): bit 0 on turns
//                the profile's spindle on (parsons-extended's motor 27, heads and PC 130);
//                bits 1-2: 1 + b % 4 tap cards of 4 bytes each: the motion card they follow
//                (b % cards), the tool (1 + b % 3: tool 3's head holds a cutter) with the feed
//                axis (b / 3 % 5) and sense (b / 15 % 2), the depth (1 + b * 3 thousandths),
//                the pitch (400 + b * 40 hundred-thousandths) and motor 27's speed S (60 + b
//                rev/min: above 240 the cabinet refuses it); bit 3 the ratios stored per tool;
//                bit 4 fault stale-ratio:1; bit 5 fault transfer-hang:1; bit 6 a lasting
//                change of motor 27 to 0.8 of its speed at 20 s.
//   then         1 byte, the additions of issue 50 (each after its system's own byte, so
//                inputs kept before them replay the same deck): bit 0 every tap card waits for
//                encoder 32's index (column 19; a head whose ratio is not 1/n is refused);
//                bits 1-2 every tap card retracts at k = 1 + b % 4 times S (column 20); bits
//                3-4 q = b % 4: every tap card pecks q / 4 of its depth (at least 0.001 in;
//                columns 21-24); bit 5 the first condition of each condition card is an
//                every-condition (column 14); bit 6 turns contouring on (parsons-extended's
//                stepper axes) and puts 1 + b % 4 segment cards of 4 bytes each at the end of
//                the deck: the end point X, Y, Z (b * 8 thousandths each) and the feed F
//                (5.0 + b * 0.3 in/min); bit 7 the feeder's interlock (press.feeder_hold_lag_in
//                0.002 in, under the drive's own lag at a move's start: it holds the press
//                often) when the press byte turned the press on.
// Missing bytes read as zero: an empty input is one card on which nothing moves, and every
// reading the patent's.
#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/machine_run.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/faults.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace parsons::fuzz {
namespace {

using namespace parsons::cardreader;

constexpr int kMaxCards = 6;
constexpr int kMaxFlips = 8;

class Recipe {
public:
    explicit Recipe(Bytes bytes) : bytes_(bytes) {}
    std::uint8_t next() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0; }
    bool done() const { return pos_ >= bytes_.size(); }

private:
    Bytes bytes_;
    std::size_t pos_ = 0;
};

Thousandths thousandths(int value) {
    return static_cast<Thousandths>(std::clamp(value, 0, int{kMaxThousandths}));
}

void place_slow_downs(AxisOrder& o, int count, int gap) {
    const int direction = o.motion == Motion::forward ? 1 : -1;
    o.slow_down = {};
    for (int i = 0; i < count; ++i) { // the first slow-down is the farther from the stop
        o.slow_down.at(static_cast<std::size_t>(i)) =
            thousandths(o.stop - direction * gap * (count - i));
    }
}

// As a careful programmer punches them: as many slow-downs as the start speed needs, a fast
// start only where the move is long enough for its slow-downs, and a spacing whose numbers
// make no spurious match in the shared banks on the way (the patent's own spacing, 0.100 in,
// changes only the tenths digit). Without such a spacing the deck keeps the hazard.
void honest_slow_downs(AxisOrder& o, Axis axis, int from, int gap) {
    int count = 3 - o.start_speed;
    if (count == 2 && fig8_layout().find(FieldKind::slow_down_2, axis) == nullptr) {
        count = 1;
    }
    const int travel = std::abs(int{o.stop} - from);
    for (int spacing : {gap, 100, 200, 50, 150, 300}) {
        int fits = count;
        while (fits > 0 && fits * spacing >= travel) {
            --fits;
        }
        place_slow_downs(o, fits, spacing);
        o.start_speed = 3 - fits;
        if (spurious_matches_on_path(o, thousandths(from)).empty()) {
            return;
        }
    }
    place_slow_downs(o, count, gap);
    o.start_speed = 3 - count;
}

// One axis of a card; `at` is where the previous card sent the axis, and becomes this stop.
AxisOrder axis_order(Recipe& recipe, Axis axis, int& at) {
    const std::uint8_t flags = recipe.next();
    const int step = static_cast<std::int8_t>(recipe.next()) * ((flags & 0x04) ? 16 : 1);
    const int gap = 20 + 4 * recipe.next();
    const std::uint8_t seq = recipe.next();

    AxisOrder o;
    const int stop = (flags & 0x80) ? at : std::clamp(at + step, 0, int{kMaxThousandths});
    o.stop = thousandths(stop);
    o.motion = stop >= at ? Motion::forward : Motion::reverse;
    o.check = thousandths(std::abs(stop - at));
    o.start_speed = 1 + (flags & 0x03) % 3;
    const bool two_fields = fig8_layout().find(FieldKind::slow_down_2, axis) != nullptr;
    switch ((flags >> 4) & 0x03) {
    case 0:
        honest_slow_downs(o, axis, at, gap);
        break;
    case 1:
        place_slow_downs(o, 0, gap);
        break;
    case 2:
        place_slow_downs(o, 1, gap);
        break;
    default:
        place_slow_downs(o, two_fields ? 2 : 1, gap);
        break;
    }
    // The deck's mistakes, after the slow-downs were placed for the real motion.
    if (flags & 0x08) {
        o.check = thousandths((o.check + gap - 19) % (kMaxThousandths + 1));
    }
    if (flags & 0x40) {
        o.motion = o.motion == Motion::forward ? Motion::reverse : Motion::forward;
    }
    o.sequence = (seq & 0x20) ? static_cast<SequencePattern>(seq & 0x1F)
                              : static_cast<SequencePattern>(1u << ((seq & 0x1F) % 5));
    at = stop;
    return o;
}

// The cabinet byte: the readings of the patent the profile can change, and additions.
void cabinet_options(std::uint8_t bits, axes::MachineProfile& profile) {
    profile.incremental_equality_stops_at_any_speed = (bits & 0x01) != 0;
    profile.delay_258_waits_for_equality_to_leave = (bits & 0x02) != 0;
    profile.lamps_only_on_trip = (bits & 0x04) != 0;
    profile.refuse_double_punch = (bits & 0x08) != 0;
    profile.ribbon_feed = (bits & 0x10) != 0;
    if (bits & 0x20) {
        profile.delay_258_s = 0.005;
    }
    auto& table = profile.axes.at(0);
    if (bits & 0x40) {
        table.travel_min_in = -0.05;
        table.travel_max_in = 2.5;
    }
    if (bits & 0x80) {
        table.screw_error_in = {{0.0, 0.5}, {5.0, -0.5}};
    }
}

// The condition byte and its conditions: condition cards put before the motion cards.
std::vector<CardOrders> with_conditions(Recipe& recipe, std::vector<CardOrders> motion,
                                        const std::vector<std::array<int, kAxisCount>>& from,
                                        axes::MachineProfile& profile) {
    const std::uint8_t bits = recipe.next();
    if ((bits & 0x01) == 0) {
        return motion;
    }
    profile.condition_cards = true;
    std::vector<std::vector<ConditionOrder>> before(motion.size());
    const int conditions = 1 + (bits >> 1) % 4;
    for (int n = 0; n < conditions; ++n) {
        const std::size_t card = recipe.next() % motion.size();
        ConditionOrder c;
        c.event = 1 + recipe.next() % 99;
        const int axis_sense = recipe.next();
        c.axis = kAxes.at(static_cast<std::size_t>(axis_sense % 5));
        c.sense = static_cast<PassingSense>(axis_sense / 5 % 3);
        const int action = recipe.next();
        c.action = static_cast<ActionKind>(1 + action % kActionKinds);
        c.parameter = c.action == ActionKind::tool_change || c.action == ActionKind::dwell ||
                              c.action == ActionKind::lamp
                          ? 1 + action / 8 % 5
                          : 0;
        const int where = recipe.next();
        const AxisOrder& o = motion.at(card).axis(c.axis);
        const int start = from.at(card).at(axis_index(c.axis));
        const int sign = o.motion == Motion::forward ? 1 : -1;
        c.position =
            where < 128
                ? thousandths((start + sign * (1 + where % std::max(1, int{o.check})) + 10000) %
                              10000)
                : thousandths((where - 128) * 80);
        before.at(card).push_back(c);
    }
    std::vector<CardOrders> deck;
    for (std::size_t k = 0; k < motion.size(); ++k) {
        for (std::size_t i = 0; i < before.at(k).size(); i += kConditionsPerCard) {
            CardOrders card;
            card.kind = CardKind::condition;
            for (std::size_t j = i; j < before.at(k).size() && j < i + kConditionsPerCard; ++j) {
                card.conditions.at(static_cast<std::size_t>(card.condition_count++)) =
                    before.at(k).at(j);
            }
            deck.push_back(card);
        }
        deck.push_back(motion.at(k));
    }
    // Numbered in order from the first motion card's number.
    int number = motion.front().number;
    for (CardOrders& o : deck) {
        o.number = number;
        number = (number + 1) % 10000;
    }
    return deck;
}

// The press byte and its sync cards, put before motion cards of a deck that may hold condition
// cards already; the whole deck is numbered again from its first card's number.
std::vector<CardOrders> with_sync(Recipe& recipe, std::vector<CardOrders> deck,
                                  axes::MachineProfile& profile) {
    const std::uint8_t bits = recipe.next();
    if ((bits & 0x01) == 0) {
        return deck;
    }
    profile.press_sync = true;
    profile.press.strokes_per_min = 6;
    profile.press.pulses_per_degree = 2;
    profile.press.reverse = (bits & 0x80) != 0;
    if (bits & 0x10) {
        profile.press.pressing_slowdown = 0.3;
    }
    if (bits & 0x20) {
        profile.press.change_cycle = 1;
        profile.press.change_angle_deg = 100;
        profile.press.change_factor = 0.7;
    }
    if (bits & 0x40) {
        profile.press.stop_cycle = 2;
        profile.press.stop_angle_deg = 200;
    }
    profile.sync_timeout_s = 30;
    std::vector<std::size_t> motion_at;
    for (std::size_t i = 0; i < deck.size(); ++i) {
        if (deck.at(i).kind == CardKind::motion) {
            motion_at.push_back(i);
        }
    }
    std::vector<std::vector<SyncOrder>> before(deck.size());
    const int count = 1 + (bits >> 1) % 4;
    for (int n = 0; n < count; ++n) {
        const std::size_t card = motion_at.at(recipe.next() % motion_at.size());
        SyncOrder o;
        const int angle = recipe.next();
        if (angle % 4 != 3) {
            o.position_sync = true;
            o.angle_deg = angle * 360 / 256;
        }
        const int axis = recipe.next();
        const int travel = recipe.next();
        o.register_reset = axis / 15 % 2 == 1;
        if (axis / 5 % 3 != 0 || (!o.position_sync && !o.register_reset)) {
            o.travel_per_pulse.at(static_cast<std::size_t>(axis % 5)) = 10 + travel * 2;
        }
        before.at(card).push_back(o);
    }
    std::vector<CardOrders> out;
    for (std::size_t i = 0; i < deck.size(); ++i) {
        // Before the card and any condition cards standing before it.
        std::size_t k = i;
        while (k < deck.size() && deck.at(k).kind != CardKind::motion) {
            ++k;
        }
        // i is a motion card or the first of the condition cards before one: its sync cards
        // go first.
        if (i == 0 || deck.at(i - 1).kind == CardKind::motion) {
            for (const SyncOrder& o : before.at(k < deck.size() ? k : i)) {
                CardOrders card;
                card.kind = CardKind::sync;
                card.sync = o;
                out.push_back(card);
            }
        }
        out.push_back(deck.at(i));
    }
    const int first = deck.front().number;
    if (bits & 0x08) {
        CardOrders loop;
        loop.kind = CardKind::sync;
        loop.sync.loop = true;
        loop.sync.loop_to = first;
        loop.sync.loop_count = 1 + (bits >> 4) % 3;
        out.push_back(loop);
    }
    int number = first;
    for (CardOrders& o : out) {
        o.number = number;
        number = (number + 1) % 10000;
    }
    return out;
}

// The spindle byte and its tap cards, each right after a motion card of a deck that may hold
// condition and sync cards already; the whole deck is numbered again from its first card's
// number. The faults it asks for go to *faults.
std::vector<CardOrders> with_taps(Recipe& recipe, std::vector<CardOrders> deck,
                                  axes::MachineProfile& profile,
                                  std::vector<relaylogic::Fault>* faults) {
    const std::uint8_t bits = recipe.next();
    if ((bits & 0x01) == 0) {
        return deck;
    }
    profile.spindle_sync = true;
    if (bits & 0x08) {
        profile.spindle.ratio_source = axes::RatioSource::stored;
    }
    if (bits & 0x40) {
        profile.spindle.change_at_s = 20.0;
        profile.spindle.change_factor = 0.8;
    }
    if (faults != nullptr && (bits & 0x10)) {
        faults->push_back(relaylogic::parse_fault("stale-ratio:1"));
    }
    if (faults != nullptr && (bits & 0x20)) {
        faults->push_back(relaylogic::parse_fault("transfer-hang:1"));
    }
    std::vector<std::size_t> motion_at;
    for (std::size_t i = 0; i < deck.size(); ++i) {
        if (deck.at(i).kind == CardKind::motion) {
            motion_at.push_back(i);
        }
    }
    std::vector<std::vector<TapOrder>> after(deck.size());
    const int count = 1 + (bits >> 1) % 4;
    for (int n = 0; n < count; ++n) {
        const std::size_t card = motion_at.at(recipe.next() % motion_at.size());
        const int tool = recipe.next();
        TapOrder t;
        t.tool = 1 + tool % 3;
        t.axis = kAxes.at(static_cast<std::size_t>(tool / 3 % 5));
        t.motion = tool / 15 % 2 == 0 ? Motion::forward : Motion::reverse;
        t.depth = static_cast<Thousandths>(1 + recipe.next() * 3);
        t.pitch = 400 + recipe.next() * 40;
        t.rpm = 60 + recipe.next();
        after.at(card).push_back(t);
    }
    std::vector<CardOrders> out;
    for (std::size_t i = 0; i < deck.size(); ++i) {
        out.push_back(deck.at(i));
        for (const TapOrder& t : after.at(i)) {
            CardOrders card;
            card.kind = CardKind::tap;
            card.tap = t;
            out.push_back(card);
        }
    }
    int number = deck.front().number;
    for (CardOrders& o : out) {
        o.number = number;
        number = (number + 1) % 10000;
    }
    return out;
}

// The additions' byte (above): tap cards' index wait, retract and peck, every-conditions, and
// segment cards at the end; the whole deck is numbered again from its first card's number.
std::vector<CardOrders> with_additions(Recipe& recipe, std::vector<CardOrders> deck,
                                       axes::MachineProfile& profile) {
    const std::uint8_t bits = recipe.next();
    if (bits == 0) {
        return deck;
    }
    for (CardOrders& o : deck) {
        if (o.kind == CardKind::tap) {
            o.tap.index_wait = (bits & 0x01) != 0;
            o.tap.retract = 1 + (bits >> 1) % 4;
            const int q = (bits >> 3) % 4;
            o.tap.peck = q == 0 ? 0 : static_cast<Thousandths>(std::max(1, o.tap.depth * q / 4));
        } else if (o.kind == CardKind::condition && (bits & 0x20) && o.condition_count > 0) {
            o.conditions.front().mode = ConditionMode::every;
        }
    }
    if (bits & 0x80) {
        profile.press.feeder_hold_lag_in = 0.002;
    }
    if (bits & 0x40) {
        profile.contouring = true;
        const int count = 1 + recipe.next() % 4;
        for (int n = 0; n < count; ++n) {
            CardOrders card;
            card.kind = CardKind::segment;
            for (Thousandths& to : card.segment.to) {
                to = static_cast<Thousandths>(recipe.next() * 8);
            }
            card.segment.feed = 50 + recipe.next() * 3;
            deck.push_back(card);
        }
    }
    int number = deck.front().number;
    for (CardOrders& o : deck) {
        o.number = number;
        number = (number + 1) % 10000;
    }
    return deck;
}

std::vector<Card> deck_from_recipe(Recipe& recipe, axes::MachineProfile& profile,
                                   std::vector<relaylogic::Fault>* faults) {
    const int count = 1 + recipe.next() % kMaxCards;
    recipe.next(); // the profile byte, read by the caller
    const int hi = recipe.next();
    int number = (hi * 256 + recipe.next()) % 10000;
    std::array<int, kAxisCount> at{};
    std::vector<CardOrders> motion;
    std::vector<std::array<int, kAxisCount>> from;
    for (int k = 0; k < count; ++k) {
        CardOrders orders;
        orders.number = number;
        number = (number + 1) % 10000;
        orders.spindle = static_cast<Spindle>(recipe.next() % 3);
        from.push_back(at);
        for (Axis a : kAxes) {
            orders.axis(a) = axis_order(recipe, a, at.at(axis_index(a)));
        }
        motion.push_back(orders);
    }
    cabinet_options(recipe.next(), profile);
    std::vector<std::array<std::uint8_t, 3>> flips;
    for (int flip = 0; flip < kMaxFlips && !recipe.done(); ++flip) {
        const std::uint8_t card = recipe.next();
        const std::uint8_t column = recipe.next();
        flips.push_back({card, column, recipe.next()});
    }
    std::vector<Card> cards;
    for (const CardOrders& orders : with_additions(
             recipe,
             with_taps(recipe,
                       with_sync(recipe, with_conditions(recipe, std::move(motion), from, profile),
                                 profile),
                       profile, faults),
             profile)) {
        EncodeResult punched = encode(orders, fig8_layout());
        if (!punched) {
            throw Finding("machine: the keypunch refused orders the layout holds: " +
                          *punched.error);
        }
        cards.push_back(punched.card);
    }
    for (const auto& [which, where, hole] : flips) {
        Card& card = cards.at(which % cards.size());
        const int column = 1 + where % kColumns;
        const auto row = static_cast<Row>(hole % kRows);
        card.set_column(column, card.column(column) ^ row_bit(row));
    }
    return cards;
}

} // namespace

std::vector<Card> machine_deck(Bytes input, axes::MachineProfile& profile,
                               std::vector<relaylogic::Fault>* faults) {
    Recipe recipe(input);
    return deck_from_recipe(recipe, profile, faults);
}

void fuzz_machine(Bytes input) {
    axes::MachineProfile profile = axes::default_profile();
    std::vector<relaylogic::Fault> faults;
    const std::vector<Card> cards = machine_deck(input, profile, &faults);
    const std::uint8_t machine = input.size() > 1 ? input[1] : 0;
    profile.separate_registers = (machine & 0x01) != 0;
    profile.count_hundredths_at_speed_1 = (machine & 0x02) != 0;
    if (machine & 0x08) {
        profile.max_stepping_rate_per_s = 50;
    }
    if (machine & 0x10) {
        profile.measuring_chain = axes::MeasuringChain::screw_turns;
    }
    for (auto& a : profile.axes) {
        if (machine & 0x20) {
            a.backlash_in = 0.002;
        }
        if (machine & 0x40) {
            a.lead_error_in = {{0.0, 0.0}, {5.0, 0.003}, {10.0, -0.001}};
            a.instrument_error_in = {{0.0, 0.001}, {10.0, 0.002}};
            a.cam_160_in = {{2.0, 0.0005}, {8.0, 0.0015}};
        }
    }
    if (machine & 0x80) {
        faults.push_back(relaylogic::parse_fault("slip:table:40:30"));
    }
    run_machine(cards, profile, (machine & 0x04) != 0, faults);
}

} // namespace parsons::fuzz
