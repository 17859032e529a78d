// The tapping job (decks/tapping_job.hpp says what each card does).
#include "decks/tapping_job.hpp"

#include "axes/json_text.hpp"
#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/number_text.hpp"
#include "decks/template_job.hpp"
#include "decks/units.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace parsons::decks {
namespace {

using cardreader::Axis;
using cardreader::AxisOrder;
using cardreader::CardOrders;

constexpr double kMaxPosition_in = 9.999; // the counters' range
constexpr int kLeastWholeRevs = 2;        // a full-thread zone the proof can judge
constexpr int kMaxRpmOnCard = 9999;       // S: four digits on the tap card
constexpr int kMostRows = 9;
constexpr int kMostHolesPerRow = 9;
// Two cards a hole (a motion card, a tap card): the largest plate is far inside a deck.
static_assert(2 * kMostRows * kMostHolesPerRow <= kMaxDeckCards, "every plate fits a deck");

// Whether thousandths(in) lies in the counters' 0 .. 9999 (false for NaN and infinities).
bool in_counters(double in) {
    const double thousandths = in * 1000.0;
    return thousandths > -0.5 && thousandths < 9999.5;
}

[[noreturn]] void refuse(const std::string& what) {
    throw JobError("gen tapping: " + what);
}

AxisOrder idle_at(int position, cardreader::SequencePattern seq) {
    AxisOrder o;
    o.start_speed = 3;
    o.stop = static_cast<cardreader::Thousandths>(position);
    o.check = 0;
    o.sequence = seq;
    return o;
}

// The sequence of a motion card: the head first (position 1), the idle swivel and tilt, then
// the cross slide (4) and the table (5).
constexpr cardreader::SequencePattern kVertical = 0b00001;
constexpr cardreader::SequencePattern kSwivel = 0b00010;
constexpr cardreader::SequencePattern kTilt = 0b00100;
constexpr cardreader::SequencePattern kCross = 0b01000;
constexpr cardreader::SequencePattern kTable = 0b10000;

class Builder {
public:
    Builder(const TappingOptions& o, const axes::MachineProfile& profile)
        : o_(o), profile_(profile) {}

    TappingDeck build() {
        check_options();
        std::vector<std::pair<int, int>> places; // table, cross (thousandths), in tapping order
        std::vector<int> rows;
        for (int r = 0; r < o_.rows; ++r) {
            for (int k = 0; k < o_.holes_per_row; ++k) {
                const int i = r % 2 == 0 ? k : o_.holes_per_row - 1 - k;
                const double x_in = o_.first_x_in + i * o_.spacing_x_in;
                const double y_in = o_.first_y_in + r * o_.spacing_y_in;
                check_position("the holes' table positions (--first-x, --spacing-x)", x_in);
                check_position("the holes' cross positions (--first-y, --spacing-y)", y_in);
                places.emplace_back(thousandths(x_in), thousandths(y_in));
                rows.push_back(r);
            }
        }
        const int start = thousandths(o_.surface_in + o_.clearance_in);
        for (std::size_t h = 0; h < places.size(); ++h) {
            move(places[h].first, places[h].second, start);
            tap(static_cast<int>(h) + 1, rows[h], places[h].first, places[h].second);
        }
        return deck_;
    }

private:
    int next_number() const { return static_cast<int>(deck_.cards.size()) + 1; }

    // Checked in inches, before thousandths(): a position far outside would not fit an int.
    static void check_position(const std::string& what, double in) {
        if (!in_counters(in)) {
            refuse(fmt::format("{}: {} in is outside the counters' range, 0.000 to {:.3f} in", what,
                               fixed(in), kMaxPosition_in));
        }
    }

    void check_options() const {
        const TappingOptions& o = o_;
        if (o.rows < 1 || o.rows > kMostRows) {
            refuse(fmt::format("--rows {}: give 1 to {}", o.rows, kMostRows));
        }
        if (o.holes_per_row < 1 || o.holes_per_row > kMostHolesPerRow) {
            refuse(
                fmt::format("--holes-per-row {}: give 1 to {}", o.holes_per_row, kMostHolesPerRow));
        }
        for (const auto& [name, v] : {std::pair{"--first-x", o.first_x_in},
                                      {"--first-y", o.first_y_in},
                                      {"--surface", o.surface_in}}) {
            if (!(v >= 0 && v <= kMaxPosition_in)) {
                refuse(fmt::format("{} {}: a position must lie within the counters' range, 0.000 "
                                   "to {:.3f} in",
                                   name, v, kMaxPosition_in));
            }
        }
        for (const auto& [name, v] :
             {std::pair{"--spacing-x", o.spacing_x_in}, {"--spacing-y", o.spacing_y_in}}) {
            if (!(v * 1000.0 >= 0.5)) { // thousandths(v) >= 1, and no overflow for a huge one
                refuse(fmt::format("{} {}: give the holes' spacing, at least 0.001 in", name, v));
            }
        }
        for (const auto& [name, v] :
             {std::pair{"--clearance", o.clearance_in}, {"--thread-depth", o.thread_depth_in}}) {
            if (std::isfinite(v) && !in_counters(v)) {
                refuse(fmt::format("{} {}: more than the counters' range, 0.000 to {:.3f} in, can "
                                   "hold",
                                   name, v, kMaxPosition_in));
            }
        }
        if (!(thousandths(o.clearance_in) >= 1)) {
            refuse(fmt::format("--clearance {}: give at least 0.001 in, so that motor 27 runs up "
                               "before the tap reaches the plate",
                               o.clearance_in));
        }
        if (!(thousandths(o.thread_depth_in) >= 1)) {
            refuse(fmt::format("--thread-depth {}: give at least 0.001 in", o.thread_depth_in));
        }
        if (thousandths(o.surface_in) - thousandths(o.thread_depth_in) < 0) {
            refuse(fmt::format("--surface {:.3f} and --thread-depth {:.3f}: the hole's bottom "
                               "would lie below the vertical's zero (the tap goes in counting "
                               "down): raise the surface",
                               o.surface_in, o.thread_depth_in));
        }
        if (thousandths(o.surface_in) + thousandths(o.clearance_in) >
            thousandths(kMaxPosition_in)) {
            refuse(fmt::format("--surface {:.3f} and --clearance {:.3f}: the tap's start, {:.3f} "
                               "in, is outside the counters' range (at most {:.3f} in)",
                               o.surface_in, o.clearance_in, o.surface_in + o.clearance_in,
                               kMaxPosition_in));
        }
        if (!(o.tolerance_percent > 0 && o.tolerance_percent < 100)) {
            refuse(fmt::format("--tolerance {}: give a percentage of the pitch, more than 0 and "
                               "less than 100",
                               o.tolerance_percent));
        }
        if (o.tools.empty()) {
            refuse("--tools: give at least one tool");
        }
        if (o.retract < 1 || o.retract > cardreader::kMaxTapRetract) {
            refuse(
                fmt::format("--retract {}: give 1 to {}", o.retract, cardreader::kMaxTapRetract));
        }
        if (o.peck_in != 0 && !(o.peck_in * 1000.0 >= 0.5 && o.peck_in * 1000.0 < 9999.5)) {
            refuse(fmt::format("--peck {}: give 0.001 to 9.999 in (or 0 for one pass)", o.peck_in));
        }
        if (o.rpm && (*o.rpm < 1 || *o.rpm > kMaxRpmOnCard)) {
            refuse(fmt::format("--rpm {}: give 1 to {} rev/min", *o.rpm, kMaxRpmOnCard));
        }
    }

    // The head of a tool, refused when none holds it or it holds no tap.
    const axes::SpindleHead& head_of(int tool) const {
        const axes::SpindleHead* head = profile_.spindle.head(tool);
        if (head == nullptr) {
            std::string held;
            for (const auto& h : profile_.spindle.heads) {
                held += fmt::format("{}{}", held.empty() ? "" : ", ", h.tool);
            }
            refuse(fmt::format("--tools: no spindle head 31 of profile {} holds tool {} (its "
                               "heads hold tools {})",
                               profile_.name, tool, held.empty() ? "none" : held));
        }
        if (!head->pitch_in) {
            refuse(fmt::format("--tools: tool {} is a cutter (radius {:.4f} in), not a tap", tool,
                               head->radius_in.value_or(0.0)));
        }
        return *head;
    }

    // S for a tap: the given one, or the fastest motor 27 and the follower drive allow, out
    // at k x S with the faster retract (an addition; k = 1 without it).
    int rpm_for(const axes::SpindleHead& head, int pitch) const {
        const double tool_in_per_motor_rev = pitch / 1e5 * head.ratio;
        const double drive_max = profile_.sync_drive.max_in_per_min;
        const double max_rpm = profile_.spindle.max_rpm;
        const int k = o_.retract;
        const int fastest = static_cast<int>(
            std::floor(std::min(max_rpm, drive_max / tool_in_per_motor_rev) / k + 1e-9));
        const int rpm = o_.rpm.value_or(fastest);
        const std::string out =
            k > 1 ? fmt::format(" (out at --retract {} x S = {} rev/min)", k, k * rpm) : "";
        if (k * rpm > max_rpm + 1e-9) {
            refuse(fmt::format("--rpm {}{}: spindle motor 27 turns at most {:g} rev/min (max_rpm "
                               "of profile {})",
                               rpm, out, max_rpm, profile_.name));
        }
        if (tool_in_per_motor_rev * k * rpm > drive_max + 1e-9 || rpm < 1) {
            refuse(fmt::format("tool {} (pitch {:.5f} in, gear ratio {:.4f}) at S {} rev/min{} "
                               "needs a feed of {:.2f} in/min; the follower drive follows at most "
                               "{:g} in/min (sync_drive.max_in_per_min): give --rpm {} or less",
                               head.tool, pitch / 1e5, head.ratio, rpm, out,
                               tool_in_per_motor_rev * k * rpm, drive_max, fastest));
        }
        return rpm;
    }

    // The run-up's travel: motor 27 runs up to S at run_up_rpm_per_s, the feed following the
    // tool from its first turn, and the NC's sample and the drive's lag on top (two samples at
    // full feed).
    double run_up_travel_in(double feed_in_per_min, int rpm) const {
        const axes::SpindleSyncProfile& s = profile_.spindle;
        const double run_up_s = rpm / s.run_up_rpm_per_s;
        const double v = feed_in_per_min / 60.0;
        const double run_up = v * run_up_s / 2 + 2 * v * s.sample_s;
        if (!o_.index_wait) {
            return run_up;
        }
        // With the index wait the feed may start at full speed v (the motor at S when the index
        // comes): it falls behind by the index's sample, the NC's and the drive's two, and the
        // drive's acceleration to v, L = 3 v sample_s + v^2 / 2a, and takes that up at the
        // drive's fastest, vmax, gaining vmax - v: vmax L / (vmax - v) of travel.
        const double acc = profile_.sync_drive.acceleration_in_per_s2;
        const double vmax = profile_.sync_drive.max_in_per_min / 60.0;
        const double lag = 3 * v * s.sample_s + v * v / (2 * acc);
        return std::max(run_up, vmax * lag / std::max(vmax - v, 1e-9));
    }

    // The motion card to a hole: the head to the start height first, then the cross slide and
    // the table.
    void move(int x, int y, int z) {
        CardOrders c;
        c.number = next_number();
        c.spindle = cardreader::Spindle::off;
        c.axis(Axis::vertical) =
            z == z_ ? idle_at(z_, kVertical)
                    : plan_move({z_, z, 1, false, kVertical}, profile_.axes.at(2), profile_);
        c.axis(Axis::swivel) = idle_at(0, kSwivel);
        c.axis(Axis::tilt) = idle_at(0, kTilt);
        c.axis(Axis::cross) =
            y == y_ ? idle_at(y_, kCross)
                    : plan_move({y_, y, 1, false, kCross}, profile_.axes.at(1), profile_);
        c.axis(Axis::table) =
            x == x_ ? idle_at(x_, kTable)
                    : plan_move({x_, x, 2, false, kTable}, profile_.axes.at(0), profile_);
        deck_.cards.push_back(c);
        x_ = x;
        y_ = y;
        z_ = z;
    }

    void tap(int hole, int row, int x, int y) {
        const int tool = o_.tools.at(static_cast<std::size_t>(row) % o_.tools.size());
        const axes::SpindleHead& head = head_of(tool);
        const int pitch = static_cast<int>(std::lround(*head.pitch_in * 1e5));
        if (pitch < 1 || pitch > cardreader::kMaxPitch) {
            refuse(fmt::format("tool {}: its pitch {} in is not 0.00001 to 0.99999 in per "
                               "revolution (a tap card holds five decimals)",
                               tool, *head.pitch_in));
        }
        const int rpm = rpm_for(head, pitch);
        const double feed = pitch / 1e5 * head.ratio * rpm;
        const double chamfer_in = profile_.spindle.chamfer_revs * *head.pitch_in;
        if (o_.thread_depth_in - chamfer_in < kLeastWholeRevs * *head.pitch_in) {
            refuse(fmt::format(
                "--thread-depth {:.3f}: tool {}'s tap (pitch {:.5f} in) leaves "
                "its last {:g} threads unfinished (chamfer_revs), {:.4f} in; give "
                "at least {:.3f} in so that {} full threads are left to prove",
                o_.thread_depth_in, tool, *head.pitch_in, profile_.spindle.chamfer_revs, chamfer_in,
                std::ceil((chamfer_in + kLeastWholeRevs * *head.pitch_in) * 1000) / 1000,
                kLeastWholeRevs));
        }
        const double run_up = run_up_travel_in(feed, rpm);
        if (o_.clearance_in < run_up) {
            refuse(fmt::format("--clearance {:.3f}: tool {} at S {} rev/min feeds {:.4f} in while "
                               "motor 27 runs up and the feed takes up the speed; the tap would "
                               "enter the plate before it is at speed: give at least {:.3f} in",
                               o_.clearance_in, tool, rpm, run_up,
                               std::ceil(run_up * 1000) / 1000));
        }
        CardOrders c;
        c.number = next_number();
        c.kind = cardreader::CardKind::tap;
        c.tap.tool = tool;
        c.tap.axis = Axis::vertical;
        c.tap.motion = cardreader::Motion::reverse;
        c.tap.depth = static_cast<cardreader::Thousandths>(thousandths(o_.clearance_in) +
                                                           thousandths(o_.thread_depth_in));
        c.tap.pitch = pitch;
        c.tap.rpm = rpm;
        c.tap.index_wait = o_.index_wait;
        c.tap.retract = o_.retract;
        c.tap.peck = static_cast<cardreader::Thousandths>(thousandths(o_.peck_in));
        deck_.cards.push_back(c);
        TappingHole h;
        h.hole = hole;
        h.row = row + 1;
        h.card = c.number;
        h.x_in = x / 1000.0;
        h.y_in = y / 1000.0;
        h.tool = tool;
        h.tap_pitch_in = pitch / 1e5;
        h.head_ratio = head.ratio;
        h.rpm = rpm;
        h.feed_in_per_min = feed;
        h.surface_in = thousandths(o_.surface_in) / 1000.0;
        h.start_in = z_ / 1000.0;
        h.thread_depth_in = thousandths(o_.thread_depth_in) / 1000.0;
        h.clearance_in = thousandths(o_.clearance_in) / 1000.0;
        h.tolerance_percent = o_.tolerance_percent;
        deck_.holes.push_back(h);
    }

    const TappingOptions& o_;
    const axes::MachineProfile& profile_;
    TappingDeck deck_;
    int x_ = 0;
    int y_ = 0;
    int z_ = 0;
};

} // namespace

TappingDeck make_tapping_deck(const TappingOptions& options, const axes::MachineProfile& profile) {
    const axes::MachineProfile p = tapping_profile(options, profile);
    return Builder(options, p).build();
}

axes::MachineProfile tapping_profile(const TappingOptions& options, axes::MachineProfile base) {
    base.spindle_sync = true;
    base.spindle.ratio_source = options.ratio_source;
    return base;
}

const char* ratio_source_name(axes::RatioSource source) {
    return source == axes::RatioSource::stored ? "stored" : "transferred";
}

std::optional<axes::RatioSource> ratio_source_named(const std::string& name) {
    if (name == "transferred") {
        return axes::RatioSource::transferred;
    }
    if (name == "stored") {
        return axes::RatioSource::stored;
    }
    return std::nullopt;
}

const TappingHole* TappingJob::hole_on_card(int number) const {
    for (const TappingHole& h : holes) {
        if (h.card == number) {
            return &h;
        }
    }
    return nullptr;
}

// ---- The job file ----

namespace {

template <typename T>
T get(const nlohmann::json& j, const std::string& key, const std::string& where = "") {
    if (!j.contains(key)) {
        throw JobError(fmt::format("{}{}: missing", where, key));
    }
    try {
        return j.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
        throw JobError(fmt::format("{}{}: wrong type", where, key));
    }
}

nlohmann::json hole_json(const TappingHole& h) {
    return {{"hole", h.hole},
            {"row", h.row},
            {"card", h.card},
            {"table_in", h.x_in},
            {"cross_in", h.y_in},
            {"tool", h.tool},
            {"tap_pitch_in", h.tap_pitch_in},
            {"head_ratio", h.head_ratio},
            {"rpm", h.rpm},
            {"feed_in_per_min", h.feed_in_per_min},
            {"surface_in", h.surface_in},
            {"start_in", h.start_in},
            {"thread_depth_in", h.thread_depth_in},
            {"clearance_in", h.clearance_in},
            {"tolerance_percent", h.tolerance_percent}};
}

TappingHole hole_from(const nlohmann::json& j, std::size_t index) {
    const std::string where = fmt::format("holes[{}].", index);
    if (!j.is_object()) {
        throw JobError(fmt::format("holes[{}]: expected an object", index));
    }
    TappingHole h;
    h.hole = get<int>(j, "hole", where);
    h.row = get<int>(j, "row", where);
    h.card = get<int>(j, "card", where);
    h.x_in = get<double>(j, "table_in", where);
    h.y_in = get<double>(j, "cross_in", where);
    h.tool = get<int>(j, "tool", where);
    h.tap_pitch_in = get<double>(j, "tap_pitch_in", where);
    h.head_ratio = get<double>(j, "head_ratio", where);
    h.rpm = get<int>(j, "rpm", where);
    h.feed_in_per_min = get<double>(j, "feed_in_per_min", where);
    h.surface_in = get<double>(j, "surface_in", where);
    h.start_in = get<double>(j, "start_in", where);
    h.thread_depth_in = get<double>(j, "thread_depth_in", where);
    h.clearance_in = get<double>(j, "clearance_in", where);
    h.tolerance_percent = get<double>(j, "tolerance_percent", where);
    if (!(h.tap_pitch_in > 0)) {
        throw JobError(where + "tap_pitch_in: must be more than 0");
    }
    if (!(h.tolerance_percent > 0 && h.tolerance_percent < 100)) {
        throw JobError(where + "tolerance_percent: must be more than 0 and less than 100");
    }
    if (!(h.thread_depth_in > 0)) {
        throw JobError(where + "thread_depth_in: must be more than 0");
    }
    return h;
}

} // namespace

std::string tapping_job_to_json(const TappingJob& job) {
    nlohmann::json holes = nlohmann::json::array();
    for (const TappingHole& h : job.holes) {
        holes.push_back(hole_json(h));
    }
    const nlohmann::json j = {
        {"job", "tapping"},
        {"ratio_source", ratio_source_name(job.ratio_source)},
        {"feed_axis", std::string(cardreader::axis_name(job.feed_axis))},
        {"sense", job.sense == cardreader::Motion::forward ? "forward" : "reverse"},
        {"rows", job.rows},
        {"holes_per_row", job.holes_per_row},
        {"clearance_in", job.clearance_in},
        {"thread_depth_in", job.thread_depth_in},
        {"tolerance_percent", job.tolerance_percent},
        {"chamfer_revs", job.chamfer_revs},
        {"holes", holes},
        {"profile_file", job.profile_file},
        {"deck_cards", job.deck_cards},
    };
    return axes::json_text(j, 2) + "\n";
}

bool is_tapping_job(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    return j.is_object() && j.value("job", "") == "tapping";
}

TappingJob tapping_job_from_json(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object()) {
        throw JobError("not a JSON object");
    }
    if (j.value("job", "") != "tapping") {
        throw JobError("job: expected \"tapping\"");
    }
    TappingJob job;
    const auto source = ratio_source_named(get<std::string>(j, "ratio_source"));
    if (!source) {
        throw JobError("ratio_source: expected \"transferred\" or \"stored\"");
    }
    job.ratio_source = *source;
    const auto axis = cardreader::axis_named(get<std::string>(j, "feed_axis"));
    if (!axis) {
        throw JobError("feed_axis: expected table, cross, vertical, swivel or tilt");
    }
    job.feed_axis = *axis;
    const std::string sense = get<std::string>(j, "sense");
    if (sense != "forward" && sense != "reverse") {
        throw JobError("sense: expected \"forward\" or \"reverse\"");
    }
    job.sense = sense == "forward" ? cardreader::Motion::forward : cardreader::Motion::reverse;
    job.rows = get<int>(j, "rows");
    job.holes_per_row = get<int>(j, "holes_per_row");
    job.clearance_in = get<double>(j, "clearance_in");
    job.thread_depth_in = get<double>(j, "thread_depth_in");
    job.tolerance_percent = get<double>(j, "tolerance_percent");
    if (!(job.tolerance_percent > 0 && job.tolerance_percent < 100)) {
        throw JobError("tolerance_percent: must be more than 0 and less than 100");
    }
    job.chamfer_revs = get<double>(j, "chamfer_revs");
    if (!j.contains("holes") || !j.at("holes").is_array()) {
        throw JobError("holes: expected an array");
    }
    std::size_t index = 0;
    for (const auto& h : j.at("holes")) {
        job.holes.push_back(hole_from(h, index++));
    }
    job.profile_file = j.value("profile_file", "");
    job.deck_cards = j.value("deck_cards", std::int64_t{0});
    return job;
}

} // namespace parsons::decks
