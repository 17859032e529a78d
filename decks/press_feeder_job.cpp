// The press-feeder job (decks/press_feeder_job.hpp says what each card does).
#include "decks/press_feeder_job.hpp"

#include "axes/json_text.hpp"
#include "cardreader/sync_card.hpp"
#include "cardreader/sync_review.hpp"
#include "cardreader/tap_review.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"
#include "decks/units.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <tuple>
#include <utility>

namespace parsons::decks {
namespace {

using cardreader::Axis;
using cardreader::AxisOrder;
using cardreader::CardOrders;

constexpr cardreader::SequencePattern kFourth = 0b01000;
constexpr cardreader::SequencePattern kFifth = 0b10000;
constexpr double kMaxPosition_in = 9.999; // the counters' range, whole inches 0-9

[[noreturn]] void refuse(const std::string& what) {
    throw JobError("gen press-feeder: " + what);
}

AxisOrder idle_at(int position, cardreader::SequencePattern seq) {
    AxisOrder o;
    o.start_speed = 3;
    o.stop = position;
    o.check = 0;
    o.sequence = seq;
    return o;
}

// The pulses a second of detector 10 at the press's nominal speed.
double nominal_pulses_per_s(const axes::PressProfile& press) {
    return press.strokes_per_min * 6.0 * press.pulses_per_degree;
}

class Builder {
public:
    Builder(const PressFeederOptions& o, axes::MachineProfile profile)
        : o_(o), profile_(std::move(profile)) {}

    PressFeederDeck build() {
        check_geometry();
        x_ = 0;
        y_ = 0;
        move("home", thousandths(o_.retracted_x_in), thousandths(o_.press_y_in), std::nullopt, 0);
        deck_.cycle_card = next_number();
        move("carry-in", x_, thousandths(o_.carry_in_y_in), std::nullopt, 0);
        move("to the press", x_, thousandths(o_.press_y_in), std::nullopt, 0);
        move("insert", thousandths(o_.insert_x_in), y_, o_.insert_angle_deg, o_.insert_deg);
        move("retract", thousandths(o_.retracted_x_in), y_, std::nullopt, o_.retract_deg);
        move("take-out", thousandths(o_.insert_x_in), y_, o_.takeout_angle_deg, o_.takeout_deg);
        move("carry-out", thousandths(o_.retracted_x_in), y_, std::nullopt, o_.carry_out_deg);
        move("to the conveyor", x_, thousandths(o_.carry_out_y_in), std::nullopt, 0);
        move("return", x_, thousandths(o_.press_y_in), std::nullopt, 0);
        if (o_.cycles > 1) {
            CardOrders c = card();
            c.kind = cardreader::CardKind::sync;
            c.sync.loop = true;
            c.sync.loop_to = deck_.cycle_card;
            c.sync.loop_count = o_.cycles - 1;
            deck_.cards.push_back(c);
        }
        return deck_;
    }

private:
    int next_number() const { return static_cast<int>(deck_.cards.size()) + 1; }
    CardOrders card() const {
        CardOrders c;
        c.number = next_number();
        return c;
    }

    void check_geometry() const {
        const PressFeederOptions& o = o_;
        for (const auto& [name, v] : {std::pair{"--retracted-x", o.retracted_x_in},
                                      {"--zone-edge-x", o.zone_edge_x_in},
                                      {"--insert-x", o.insert_x_in},
                                      {"--carry-in-y", o.carry_in_y_in},
                                      {"--press-y", o.press_y_in},
                                      {"--carry-out-y", o.carry_out_y_in}}) {
            if (!(v >= 0 && v <= kMaxPosition_in)) {
                refuse(fmt::format("{} {}: a position must lie within the counters' range, "
                                   "0.000 to {:.3f} in",
                                   name, v, kMaxPosition_in));
            }
        }
        if (!(thousandths(o.retracted_x_in) < thousandths(o.zone_edge_x_in) &&
              thousandths(o.zone_edge_x_in) < thousandths(o.insert_x_in))) {
            refuse(fmt::format("--retracted-x {:.3f}, --zone-edge-x {:.3f}, --insert-x {:.3f}: "
                               "the feeder must stand outside the die zone when retracted and "
                               "inside it when inserting (retracted < zone edge < insert)",
                               o.retracted_x_in, o.zone_edge_x_in, o.insert_x_in));
        }
        if (thousandths(o.carry_in_y_in) == thousandths(o.press_y_in) ||
            thousandths(o.carry_out_y_in) == thousandths(o.press_y_in)) {
            refuse("--carry-in-y and --carry-out-y must differ from --press-y (the conveyors "
                   "stand beside the press line)");
        }
        const double stroke = profile_.press.stroke_in;
        if (!(o.safe_height_in > 0 && o.safe_height_in < stroke)) {
            refuse(fmt::format("--safe-height {}: give a height above bottom dead centre within "
                               "the press's stroke, 0 to {:.3f} in",
                               o.safe_height_in, stroke));
        }
        if (o.cycles < 1 || o.cycles > cardreader::kMaxLoopCount + 1) {
            refuse(
                fmt::format("--cycles {}: give 1 to {}", o.cycles, cardreader::kMaxLoopCount + 1));
        }
        if (!(o.strokes_per_min > 0 && o.strokes_per_min <= 60)) {
            refuse(fmt::format("--strokes-per-min {}: give a positive speed, at most 60",
                               o.strokes_per_min));
        }
        for (const auto& [name, a] : {std::pair{"--insert-angle", o.insert_angle_deg},
                                      {"--takeout-angle", o.takeout_angle_deg}}) {
            if (a < 0 || a > cardreader::kMaxSyncAngle) {
                refuse(fmt::format("{} {}: a crank angle R is 0 to 359 degrees", name, a));
            }
        }
        for (const auto& [name, d] : {std::pair{"--insert-deg", o.insert_deg},
                                      {"--retract-deg", o.retract_deg},
                                      {"--takeout-deg", o.takeout_deg},
                                      {"--carry-out-deg", o.carry_out_deg}}) {
            if (!(d > 0 && d < 360)) {
                refuse(fmt::format("{} {}: give the crank degrees of the move, more than 0 and "
                                   "less than 360",
                                   name, d));
            }
        }
        if (o.insert_angle_deg + o.insert_deg >= o.takeout_angle_deg) {
            refuse(fmt::format("--insert-angle {} and --insert-deg {}: the insert must be over "
                               "before the take-out starts at {} degrees",
                               o.insert_angle_deg, o.insert_deg, o.takeout_angle_deg));
        }
        // The die's low stretch, and the feeder's crossings of the zone edge as planned.
        const double down = die_angle(o.safe_height_in, true);
        const double up = die_angle(o.safe_height_in, false);
        const double travel = o.insert_x_in - o.retracted_x_in;
        const double share = (o.zone_edge_x_in - o.retracted_x_in) / travel;
        const double insert_in = o.insert_angle_deg + share * o.insert_deg;
        const double takeout_in = o.takeout_angle_deg + share * o.takeout_deg;
        for (const auto& [name, a] : {std::pair{"insert", insert_in}, {"take-out", takeout_in}}) {
            const double w = std::fmod(a, 360.0);
            if (w > down && w < up) {
                refuse(fmt::format("the {} would cross the zone edge X {:.3f} at crank {:.1f} "
                                   "degrees, while die 20 is below its safe height {:.3f} in "
                                   "(from {:.1f} to {:.1f} degrees): change the angles or the "
                                   "geometry",
                                   name, o.zone_edge_x_in, w, o.safe_height_in, down, up));
            }
        }
    }

    // Where the die passes height h going down (first) or up, crank degrees (slider crank).
    double die_angle(double h, bool going_down) const {
        const double r = profile_.press.stroke_in / 2;
        const double l = profile_.press.rod_in;
        auto height = [&](double a) {
            const double s = std::sin(a * std::numbers::pi / 180);
            return r * std::cos(a * std::numbers::pi / 180) + std::sqrt(l * l - r * r * s * s) -
                   (l - r);
        };
        double lo = 0;
        double hi = 180;
        for (int i = 0; i < 60; ++i) {
            const double mid = (lo + hi) / 2;
            (height(mid) > h ? lo : hi) = mid;
        }
        return going_down ? lo : 360.0 - lo;
    }

    // The sync drive follows no slower than it feeds a tap (cardreader::kLeastTapFeedInPerMin):
    // a move given so many degrees that it would crawl is refused.
    void check_follower(const std::string& name, int f, double distance_in, double degrees) const {
        const double speed = f * 1e-5 * nominal_pulses_per_s(profile_.press) * 60.0;
        if (speed < cardreader::kLeastTapFeedInPerMin - 1e-9) {
            refuse(fmt::format("the {} ({:.3f} in over {:.1f} crank degrees at {:g} strokes a "
                               "minute) would follow at {:.3f} in/min: the sync drive follows no "
                               "slower than {:g} in/min; give it fewer degrees or a faster press",
                               name, distance_in, degrees, profile_.press.strokes_per_min, speed,
                               cardreader::kLeastTapFeedInPerMin));
        }
    }

    int travel_per_pulse(const std::string& name, double distance_in, double degrees) const {
        const axes::PressProfile& press = profile_.press;
        const double pulses = degrees * press.pulses_per_degree;
        const int f = static_cast<int>(std::lround(distance_in / pulses * 1e5));
        cardreader::PressLimits limits;
        limits.strokes_per_min = press.strokes_per_min;
        limits.pulses_per_degree = press.pulses_per_degree;
        limits.fastest_factor =
            (1.0 + std::max(0.0, press.variation)) * std::max(1.0, press.change_factor);
        limits.drive_max_in_per_min = profile_.sync_drive.max_in_per_min;
        const double speed = f * 1e-5 * nominal_pulses_per_s(press) * 60.0;
        const double stepping = profile_.max_stepping_rate_per_s * 0.001 * 60.0;
        if (f < 1) {
            refuse(fmt::format("the {} ({:.3f} in over {:g} crank degrees) needs less than "
                               "0.00001 in a detector pulse: give it fewer degrees",
                               name, distance_in, degrees));
        }
        check_follower(name, f, distance_in, degrees);
        if (f > limits.max_travel_per_pulse() || speed > stepping) {
            refuse(fmt::format("the {} ({:.3f} in over {:g} crank degrees at {:g} strokes a "
                               "minute) needs {:.2f} in/min: the sync drive follows at most "
                               "{:.2f} in/min (sync_drive.max_in_per_min) and the counters "
                               "step at most {:.2f} in/min; give it more degrees or a slower "
                               "press",
                               name, distance_in, degrees, press.strokes_per_min, speed,
                               limits.drive_max_in_per_min, stepping));
        }
        return f;
    }

    // One motion card and the sync card before it. The table's move is speed-synchronised
    // over `degrees` of the crank (from angle R if `angle` is given); a move of the cross slide
    // alone follows the press at the travel per pulse that runs it, at the press's rated speed,
    // at the 1952 speed it starts on (its slow-downs then follow as on every synchronised move).
    void move(const std::string& name, int x, int y, std::optional<int> angle, double degrees) {
        const bool table_moves = x != x_;
        const bool cross_moves = y != y_;
        AxisOrder table = idle_at(x_, kFifth);
        AxisOrder cross = idle_at(y_, kFourth);
        if (table_moves) {
            table = plan_move({x_, x, 2, false, kFifth}, profile_.axes.at(0), profile_);
        }
        if (cross_moves) {
            cross = plan_move({y_, y, 1, false, kFourth}, profile_.axes.at(1), profile_);
        }
        CardOrders s = card();
        s.kind = cardreader::CardKind::sync;
        if (degrees > 0) {
            if (table.start_speed != 1) {
                refuse(fmt::format("the {} ({:.3f} in) is too short to start on speed 1, the "
                                   "speed the sync drive follows on: lengthen it",
                                   name, std::abs(x - x_) / 1000.0));
            }
            const double distance = std::abs(x - x_) / 1000.0;
            const int f = travel_per_pulse(name, distance, degrees);
            if (angle && !o_.speed_only) {
                s.sync.position_sync = true;
                s.sync.angle_deg = *angle;
            }
            s.sync.travel_per_pulse.at(cardreader::axis_index(Axis::table)) = f;
            deck_.moves.push_back({name, deck_.cards.size() + 1, degrees, f,
                                   f * 1e-5 * nominal_pulses_per_s(profile_.press) * 60.0});
        } else {
            // Every other move follows the press at the 1952 speed it starts on.
            for (const auto& [axis, from, to, order] :
                 {std::tuple{Axis::table, x_, x, &table}, std::tuple{Axis::cross, y_, y, &cross}}) {
                if (from == to) {
                    continue;
                }
                const std::size_t i = cardreader::axis_index(axis);
                const double speed = profile_.axes.at(i).speed_in_per_min.at(
                    static_cast<std::size_t>(order->start_speed - 1));
                const double pulses_per_s = nominal_pulses_per_s(profile_.press);
                // Rounded down: never faster than the 1952 motor (the drive's cap is speed 1's).
                const int f = std::max(
                    1, static_cast<int>(std::floor(speed / 60.0 / pulses_per_s * 1e5 + 1e-9)));
                const double distance = std::abs(to - from) / 1000.0;
                const double degrees =
                    distance / (f * 1e-5) / static_cast<double>(profile_.press.pulses_per_degree);
                check_follower(name, f, distance, degrees);
                s.sync.travel_per_pulse.at(i) = f;
                deck_.moves.push_back({name + (table_moves && cross_moves
                                                   ? std::string(axis == Axis::table ? " X" : " Y")
                                                   : std::string()),
                                       deck_.cards.size() + 1, degrees, f,
                                       f * 1e-5 * pulses_per_s * 60.0});
            }
        }
        if (s.sync.speed_sync()) {
            deck_.cards.push_back(s);
        }
        CardOrders c = card();
        c.spindle = cardreader::Spindle::off;
        c.axis(Axis::table) = table;
        c.axis(Axis::cross) = cross;
        c.axis(Axis::vertical) = idle_at(0, 0b00001);
        c.axis(Axis::swivel) = idle_at(0, 0b00010);
        c.axis(Axis::tilt) = idle_at(0, 0b00100);
        deck_.cards.push_back(c);
        x_ = x;
        y_ = y;
    }

    const PressFeederOptions& o_;
    axes::MachineProfile profile_;
    PressFeederDeck deck_;
    int x_ = 0;
    int y_ = 0;
};

} // namespace

PressFeederDeck make_press_feeder_deck(const PressFeederOptions& options,
                                       const axes::MachineProfile& profile) {
    return Builder(options, press_feeder_profile(options, profile)).build();
}

axes::MachineProfile press_feeder_profile(const PressFeederOptions& options,
                                          axes::MachineProfile base) {
    base.press_sync = true;
    base.press.strokes_per_min = options.strokes_per_min;
    base.press.start_angle_deg = options.start_angle_deg;
    return base;
}

// ---- The job file ----

namespace {

template <typename T>
T get(const nlohmann::json& j, const char* key) {
    if (!j.contains(key)) {
        throw JobError(fmt::format("{}: missing", key));
    }
    try {
        return j.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
        throw JobError(fmt::format("{}: wrong type", key));
    }
}

} // namespace

std::string press_job_to_json(const PressFeederJob& job) {
    const PressFeederOptions& o = job.options;
    nlohmann::json j = {
        {"job", "press-feeder"},
        {"variant", job.variant},
        {"retracted_x_in", o.retracted_x_in},
        {"zone_edge_x_in", o.zone_edge_x_in},
        {"insert_x_in", o.insert_x_in},
        {"carry_in_y_in", o.carry_in_y_in},
        {"press_y_in", o.press_y_in},
        {"carry_out_y_in", o.carry_out_y_in},
        {"safe_height_in", o.safe_height_in},
        {"strokes_per_min", o.strokes_per_min},
        {"start_angle_deg", o.start_angle_deg},
        {"cycles", o.cycles},
        {"insert_angle_deg", o.insert_angle_deg},
        {"insert_deg", o.insert_deg},
        {"retract_deg", o.retract_deg},
        {"takeout_angle_deg", o.takeout_angle_deg},
        {"takeout_deg", o.takeout_deg},
        {"carry_out_deg", o.carry_out_deg},
        {"cycle_card", job.cycle_card},
        {"profile_file", job.profile_file},
        {"deck_cards", job.deck_cards},
    };
    return axes::json_text(j, 2) + "\n";
}

bool is_press_job(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    return j.is_object() && j.value("job", "") == "press-feeder";
}

PressFeederJob press_job_from_json(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw JobError("not a JSON object");
    }
    if (j.value("job", "") != "press-feeder") {
        throw JobError("job: expected \"press-feeder\"");
    }
    PressFeederJob job;
    PressFeederOptions& o = job.options;
    job.variant = get<std::string>(j, "variant");
    if (job.variant != "position+speed" && job.variant != "speed-only") {
        throw JobError("variant: expected \"position+speed\" or \"speed-only\"");
    }
    o.speed_only = job.variant == "speed-only";
    o.retracted_x_in = get<double>(j, "retracted_x_in");
    o.zone_edge_x_in = get<double>(j, "zone_edge_x_in");
    o.insert_x_in = get<double>(j, "insert_x_in");
    o.carry_in_y_in = get<double>(j, "carry_in_y_in");
    o.press_y_in = get<double>(j, "press_y_in");
    o.carry_out_y_in = get<double>(j, "carry_out_y_in");
    o.safe_height_in = get<double>(j, "safe_height_in");
    o.strokes_per_min = get<double>(j, "strokes_per_min");
    o.start_angle_deg = get<double>(j, "start_angle_deg");
    o.cycles = get<int>(j, "cycles");
    o.insert_angle_deg = get<int>(j, "insert_angle_deg");
    o.insert_deg = get<double>(j, "insert_deg");
    o.retract_deg = get<double>(j, "retract_deg");
    o.takeout_angle_deg = get<int>(j, "takeout_angle_deg");
    o.takeout_deg = get<double>(j, "takeout_deg");
    o.carry_out_deg = get<double>(j, "carry_out_deg");
    job.cycle_card = get<int>(j, "cycle_card");
    job.profile_file = j.value("profile_file", "");
    job.deck_cards = j.value("deck_cards", std::int64_t{0});
    return job;
}

} // namespace parsons::decks
