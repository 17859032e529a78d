#include "outputs/report/run_report.hpp"

#include "outputs/report/contouring_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

namespace parsons::cli {

using cardreader::Axis;
using cardreader::axis_name;

namespace {

// The main screw's travel less what the counters read, modulo their 10 inches.
double screw_vs_counters(const relaylogic::AxisResult& x) {
    return std::remainder(x.screw_in - x.counter_in, 10.0);
}

nlohmann::json tapping_json(const relaylogic::TappingResult& t) {
    using nlohmann::json;
    json holes = json::array();
    for (const relaylogic::HoleRecord& h : t.holes) {
        holes.push_back(
            json{{"card", h.card},
                 {"number", h.number},
                 {"tool_called", h.tool_called},
                 {"tool", h.tool},
                 {"tap_pitch_in", h.tap_pitch_in ? json(*h.tap_pitch_in) : json(nullptr)},
                 {"head_ratio", decimals(h.head_ratio, 6)},
                 {"ratio_used", decimals(h.ratio_used, 6)},
                 {"pitch_ordered_in", decimals(h.pitch_ordered_in, 5)},
                 {"rpm", h.rpm},
                 {"axis", std::string(axis_name(h.axis))},
                 {"sense", h.sense > 0 ? "forward" : "reverse"},
                 {"start_in", decimals(h.start_in, 5)},
                 {"depth_in", decimals(h.depth_in, 3)},
                 {"deepest_in", decimals(h.deepest_in, 5)},
                 {"end_in", decimals(h.end_in, 5)},
                 {"start_seconds", decimals(h.start_s, 6)},
                 {"reverse_seconds", decimals(h.reverse_s, 6)},
                 {"end_seconds", decimals(h.end_s, 6)},
                 {"completed", h.completed}});
        if (h.index_wait) { // rigid tapping's index wait (an addition): the time waited
            holes.back()["index_wait_seconds"] = decimals(h.sync_s - h.start_s, 6);
            holes.back()["index_tool_revs"] = decimals(h.sync_tool_revs, 6);
        }
        if (h.retract != 1) { // the faster retract (an addition): out at retract x S
            holes.back()["retract"] = h.retract;
        }
        if (h.peck_in > 0) { // rigid peck tapping (an addition): the peck and the passes in
            holes.back()["peck_in"] = decimals(h.peck_in, 3);
            holes.back()["pecks"] = h.pecks;
        }
    }
    return json{
        {"tool_on_spindle", t.tool_on_spindle}, {"ratio_in_memory", decimals(t.ratio_in_memory, 6)},
        {"head_exchanges", t.head_exchanges},   {"transfers", t.transfers},
        {"ratios_received", t.ratios_received}, {"holes", holes}};
}

// The press line's lag: how far a synchronised axis fell behind the crank (position and
// speed-only cards apart), when any axis followed.
std::string lag_text(const relaylogic::PressResult& p) {
    std::vector<std::string> parts;
    if (p.max_lag_position_sync_in > 0) {
        parts.push_back(fmt::format("{:.4f} in with position sync", p.max_lag_position_sync_in));
    }
    if (p.max_lag_speed_only_in > 0) {
        parts.push_back(fmt::format("{:.4f} in speed only", p.max_lag_speed_only_in));
    }
    std::string text;
    if (!parts.empty()) {
        text = "; the axes behind the crank by at most " +
               (parts.size() == 2 ? parts[0] + ", " + parts[1] : parts[0]);
    }
    std::vector<std::string> ahead;
    if (p.max_lead_position_sync_in > 0) {
        ahead.push_back(fmt::format("{:.4f} in with position sync", p.max_lead_position_sync_in));
    }
    if (p.max_lead_speed_only_in > 0) {
        ahead.push_back(fmt::format("{:.4f} in speed only", p.max_lead_speed_only_in));
    }
    if (!ahead.empty()) {
        text += "; ahead of it by at most " +
                (ahead.size() == 2 ? ahead[0] + ", " + ahead[1] : ahead[0]);
    }
    return text;
}

// The sync drive asked past its top speed: the first time, and the most asked (null: never).
nlohmann::json saturation_json(const std::optional<relaylogic::DriveSaturation>& s) {
    using nlohmann::json;
    if (!s) {
        return nullptr;
    }
    return json{{"axis", std::string(axis_name(s->axis))},
                {"card", s->card},
                {"number", s->number >= 0 ? json(s->number) : json(nullptr)},
                {"speed", s->speed_position},
                {"seconds", time_s(s->t_s)},
                {"asked_in_per_min", decimals(s->asked_in_per_min, 3)},
                {"crank_speed_factor", decimals(s->crank_factor, 4)},
                {"most_asked_in_per_min", decimals(s->most_asked_in_per_min, 3)},
                {"max_in_per_min", decimals(s->drive_max_in_per_min, 3)}};
}

// The press line's resets: register 14 cleared by switch 16A at sync cards' orders, when any.
std::string reset_text(const relaylogic::PressResult& p) {
    if (p.register_resets == 0) {
        return {};
    }
    return fmt::format(" (register 14 reset {} time{} by switch 16A, angles counted from there)",
                       p.register_resets, p.register_resets == 1 ? "" : "s");
}

std::string join(const std::vector<std::string>& parts, std::string_view sep) {
    std::string out;
    for (const auto& p : parts) {
        out += (out.empty() ? "" : std::string(sep)) + p;
    }
    return out;
}

// Why the part is not where the counters say, from the measuring chain's own figures: what the
// chain does not measure (the part against the reading commutators 96-102 gave) and what the
// counters miscounted (that reading against theirs). Each share with its figure, part minus
// counters, largest first; a share under 0.00005 in (the last decimal printed) is left out,
// and so is where the part came to rest between two crossings (under half a thousandth).
std::vector<std::string> error_causes(const relaylogic::AxisResult& x) {
    struct Share {
        double in;
        std::string words;
    };
    std::vector<Share> shares;
    auto add = [&shares](double in, std::string words) {
        if (std::abs(in) >= 0.00005) {
            shares.push_back({in, std::move(words)});
        }
    };
    const axes::ChainFigures& f = x.chain;
    add(f.instrument_in,
        fmt::format("instrument shaft 74's own screw error {:+.4f} in at {:.3f} in "
                    "(instrument_error_in): the counters measure with that screw and cannot see "
                    "its error",
                    f.instrument_in, f.at_in));
    add(f.cam_160_in, fmt::format("compensating cam 160's correction {:+.4f} in at {:.3f} in "
                                  "(cam_160_in)",
                                  f.cam_160_in, f.at_in));
    add(f.screw_error_in, fmt::format("residual screw error {:+.4f} in at {:.3f} in "
                                      "(screw_error_in)",
                                      f.screw_error_in, f.at_in));
    add(f.lead_in, fmt::format("lead error of lead screw 22 {:+.4f} in at {:.3f} in "
                               "(lead_error_in), which counting screw turns does not measure",
                               f.lead_in, f.at_in));
    add(f.backlash_in, fmt::format("backlash in nut 78 {:+.4f} in, taken up when the motion "
                                   "reversed (backlash_in), which counting screw turns does not "
                                   "measure",
                                   f.backlash_in));
    add(f.slip_in, fmt::format("the lead screw's drive slipped {:+.4f} in (fault slip): the "
                               "counters counted screw turns the part never made",
                               f.slip_in));
    // The counters' share: the reading the commutators gave against what the counters read.
    const double counting = x.error_in - (x.real_in - x.commutator_in);
    std::vector<std::string> how;
    if (x.wrong_way > 0) {
        how.push_back(fmt::format("{} impulse{} of coast counted in the other direction, "
                                  "with the carries of commutators 96-100 "
                                  "(reversing control 214 was already set for the next card)",
                                  x.wrong_way, x.wrong_way == 1 ? "" : "s"));
    }
    if (x.thousandths_uncounted > 0) {
        how.push_back("thousandths not counted while speed switch 236 stood on speed 1 "
                      "(count_hundredths_at_speed_1)");
    }
    if (x.lost_steps > 0) {
        how.push_back(fmt::format("{} stepping-switch step{} lost (impulses came faster than the "
                                  "switches can step)",
                                  x.lost_steps, x.lost_steps == 1 ? "" : "s"));
    }
    if (x.skipped_steps > 0) {
        how.push_back(fmt::format("{} stepping switch{} skipped a position (fault skip-step)",
                                  x.skipped_steps, x.skipped_steps == 1 ? "" : "es"));
    }
    if (how.size() == 1) {
        add(counting, fmt::format("{}: {:+.4f} in", how.front(), counting));
    } else if (how.size() > 1) {
        add(counting,
            fmt::format("the counters miscounted {:+.4f} in: {}", counting, join(how, ", ")));
    } else if (std::abs(counting) >= 0.0005) {
        add(counting, fmt::format("{:+.4f} in between the commutators and the counters not "
                                  "accounted for",
                                  counting));
    }
    const double rest = x.real_in - x.commutator_in - f.sum();
    if (std::abs(rest) >= 0.001) {
        add(rest,
            fmt::format("{:+.4f} in between the part and the commutators not accounted for", rest));
    }
    std::stable_sort(shares.begin(), shares.end(), [](const Share& p, const Share& q) {
        return std::abs(p.in) > std::abs(q.in);
    });
    std::vector<std::string> words;
    for (auto& sh : shares) {
        words.push_back(std::move(sh.words));
    }
    if (words.empty()) {
        words.push_back(fmt::format("the part came to rest {:+.4f} in past the last crossing of "
                                    "commutator 102",
                                    rest));
    }
    return words;
}

} // namespace

nlohmann::json report_json(const relaylogic::RunResult& r, const axes::MachineProfile& profile,
                           const nlohmann::json& profile_applied, const std::string& deck) {
    using nlohmann::json;
    json j;
    j["parsons_version"] = PARSONS_VERSION;
    j["schema_version"] = kReportSchemaVersion;
    j["deck"] = deck;
    j["profile"] = profile.name;
    j["profile_applied"] = profile_applied;
    j["status"] = r.completed ? "completed" : "stopped";
    j["cards_read"] = r.cards_read;
    j["machine_seconds"] = time_s(r.machine_seconds);
    j["measuring_chain"] = profile.measuring_chain == axes::MeasuringChain::screw_turns
                               ? "screw_turns"
                               : "instrument_shaft_74";
    if (r.stop) {
        const auto& s = *r.stop;
        j["stop"] = json{{"reason", relaylogic::stop_reason_name(s.reason)},
                         {"card", s.card},
                         {"card_number", s.card_number >= 0 ? json(s.card_number) : json(nullptr)},
                         {"axis", s.axis ? json(std::string(axis_name(*s.axis))) : json(nullptr)},
                         {"message", s.message},
                         {"lamps", s.lamps}};
    } else {
        j["stop"] = nullptr;
    }
    json axes = json::object();
    for (Axis a : cardreader::kAxes) {
        const auto& x = r.axes.at(cardreader::axis_index(a));
        json ax{{"position", counter_reading(x.counter_in)},
                {"real_position", fine_length(x.real_in)},
                {"position_error", fine_length(x.error_in)},
                {"impulses", x.impulses},
                {"lost_steps", x.lost_steps},
                {"screw_slip", fine_length(x.slip_in)}};
        // The two readings of Fig. 3: the part as the counters measured it (position) and the
        // main screw's turns (turns x lead), and how far apart they are.
        ax["screw_turns_position"] = fine_length(x.screw_in);
        ax["screw_turns_minus_position"] = fine_length(screw_vs_counters(x));
        if (x.fixture_angle_deg) {
            ax["fixture_angle_deg"] = angle_deg(*x.fixture_angle_deg);
        }
        axes[std::string(axis_name(a))] = ax;
    }
    j["axes"] = axes;
    json faults = json::array();
    for (const auto& f : r.faults) {
        faults.push_back(json{{"fault", f.spec}, {"acted", f.acted}, {"effect", f.effect}});
    }
    j["faults"] = faults;
    json cards = json::array();
    for (const auto& c : r.cards) {
        json card{{"index", c.index},
                  {"number", c.number >= 0 ? json(c.number) : json(nullptr)},
                  {"start_seconds", time_s(c.start_s)},
                  {"machine_seconds", time_s(c.end_s - c.start_s)}};
        if (c.cut_unready_s >= 0) {
            card["spindle_not_at_speed"] = json{{"cut_began_seconds", time_s(c.cut_unready_s)},
                                                {"at_speed_seconds", time_s(c.spindle_ready_s)}};
        }
        cards.push_back(card);
    }
    j["cards"] = cards;
    // Condition cards (an addition after EP 0640901): only when the deck used them (the profile
    // has them and a condition card was read), as the press and the tapping below.
    if (r.tool_in_spindle && r.conditions_used) {
        j["tool_in_spindle"] = *r.tool_in_spindle;
        json actions = json::array();
        double saved = 0;
        for (const auto& a : r.actions) {
            saved += a.overlap_s();
            actions.push_back(json{{"event", a.event},
                                   {"condition_card", a.condition_card},
                                   {"motion_card", a.motion_card},
                                   {"axis", std::string(axis_name(a.axis))},
                                   {"position", cardreader::format_inches(a.position)},
                                   {"action", std::string(cardreader::action_name(a.action))},
                                   {"parameter", a.parameter},
                                   {"tripped_seconds", time_s(a.tripped_s)},
                                   {"acknowledged_seconds", time_s(a.acknowledged_s)},
                                   {"motion_end_seconds", time_s(a.motion_end_s)},
                                   {"overlap_seconds", time_s(a.overlap_s())}});
            if (a.every) { // an every-condition's firing (an addition beyond the seed's claims)
                actions.back()["mode"] = "every";
                actions.back()["firing"] = a.firing;
            }
        }
        j["actions"] = actions;
        j["actions_overlap_seconds"] = time_s(saved);
    }
    // Press synchronisation (an addition after EP 0436887): only when a sync card was read.
    if (r.press && r.press->used) {
        const relaylogic::PressResult& p = *r.press;
        auto seconds = [](const std::optional<double>& v) {
            return v ? json(time_s(*v)) : json(nullptr);
        };
        j["press"] = json{{"revolution", p.revolution},
                          {"crank_angle_deg", decimals(p.crank_angle_deg, 3)},
                          {"position_register_14", p.position_register},
                          {"press_stopped", p.press_stopped},
                          {"cycles", p.cycles},
                          {"loop_backs", p.loop_backs},
                          {"mean_cycle_seconds", seconds(p.mean_cycle_s)},
                          {"shortest_cycle_seconds", seconds(p.shortest_cycle_s)},
                          {"longest_cycle_seconds", seconds(p.longest_cycle_s)},
                          {"waited_seconds", time_s(p.waited_s)},
                          {"max_lag_position_sync_in", fine_length(p.max_lag_position_sync_in)},
                          {"max_lag_speed_only_in", fine_length(p.max_lag_speed_only_in)},
                          {"max_lead_position_sync_in", fine_length(p.max_lead_position_sync_in)},
                          {"max_lead_speed_only_in", fine_length(p.max_lead_speed_only_in)},
                          {"register_resets", p.register_resets},
                          {"drive_saturated", saturation_json(p.drive_saturated)}};
        if (const auto& fi = p.feeder_interlock) {
            j["press"]["feeder_interlock"] = json{{"lag_limit_in", fine_length(fi->limit_in)},
                                                  {"holds", fi->holds},
                                                  {"held_seconds", time_s(fi->held_s)},
                                                  {"longest_hold_seconds", time_s(fi->longest_s)},
                                                  {"holding_at_end", fi->holding}};
        }
    }
    // Spindle synchronisation (an addition after EP 0360190): only when a tap card was read.
    if (r.tapping && r.tapping->used) {
        j["tapping"] = tapping_json(*r.tapping);
    }
    // Contouring (an addition after EP 0636958): only when a segment card was read.
    if (r.contouring && r.contouring->used) {
        j["contouring"] = contouring_json(*r.contouring);
    }
    return j;
}

std::string summary_text(const relaylogic::RunResult& r, const std::string& deck,
                         const std::string& profile_name) {
    std::string out;
    auto line = [&out](const std::string& s) { out += s + "\n"; };
    line(fmt::format("parsons run {} (profile {})", deck, profile_name));
    line(fmt::format("  cards run      {}", r.cards_read));
    line(fmt::format("  machine time   {:.3f} s", r.machine_seconds));
    if (r.completed) {
        line("  status         completed");
    } else if (r.stop) {
        const auto& s = *r.stop;
        line(fmt::format("  status         STOPPED: {}", relaylogic::stop_reason_name(s.reason)));
        line(fmt::format("  card           {}{}", s.card,
                         s.card_number >= 0 ? fmt::format(" (number {:04})", s.card_number) : ""));
        line(fmt::format("  axis           {}", s.axis ? std::string(axis_name(*s.axis)) : "-"));
        line(fmt::format("  why            {}", s.message));
        std::string lamps;
        for (const auto& l : s.lamps) {
            lamps += (lamps.empty() ? "" : ", ") + l;
        }
        line(fmt::format("  lamps lit      {}", lamps.empty() ? "-" : lamps));
    }
    line(fmt::format("  {:<9} {:>8} {:>10} {:>10} {:>9} {:>6}", "axis", "counter", "real in",
                     "error in", "impulses", "lost"));
    for (Axis a : cardreader::kAxes) {
        const auto& x = r.axes.at(cardreader::axis_index(a));
        std::string angle =
            x.fixture_angle_deg ? fmt::format("  {:+.3f} deg", *x.fixture_angle_deg) : "";
        line(fmt::format("  {:<9} {:>8.3f} {:>10.5f} {:>+10.5f} {:>9} {:>6}{}", axis_name(a),
                         x.counter_in, x.real_in, x.error_in, x.impulses, x.lost_steps, angle));
    }
    for (const auto& f : r.faults) {
        line(fmt::format("  fault          {}: {}", f.spec, f.effect));
    }
    for (const auto& c : r.cards) {
        if (c.cut_unready_s >= 0) {
            line(fmt::format("  warning: card {}{} began its cut at {:.3f} s with the spindle "
                             "motor still coming to speed (it was at speed at {:.3f} s): nothing "
                             "in the 1952 control waits for the spindle",
                             c.index, c.number >= 0 ? fmt::format(" (number {:04})", c.number) : "",
                             c.cut_unready_s, c.spindle_ready_s));
        }
    }
    for (const auto& a : r.actions) {
        line(fmt::format("  action         event {} ({} at {}, card {}{}): {} at {:.3f} s, "
                         "acknowledged {:.3f} s, {:.3f} s of it while the axes moved",
                         a.event, axis_name(a.axis), cardreader::format_inches(a.position),
                         a.motion_card,
                         a.every ? fmt::format(", every: firing {}", a.firing) : std::string(),
                         cardreader::action_text(a.action, a.parameter), a.tripped_s,
                         a.acknowledged_s, a.overlap_s()));
    }
    if (r.tool_in_spindle && r.conditions_used) {
        line(fmt::format("  tool           {} in the spindle (the condition cards' tool changer)",
                         *r.tool_in_spindle));
    }
    if (r.press && r.press->used) {
        const relaylogic::PressResult& p = *r.press;
        line(fmt::format("  press          revolution {}, crank at {:.2f} deg{}; {} cycle{} of "
                         "the job{}; cards held {:.3f} s for the crank{}{}",
                         p.revolution, p.crank_angle_deg, p.press_stopped ? " (stopped)" : "",
                         p.cycles, p.cycles == 1 ? "" : "s",
                         p.mean_cycle_s
                             ? fmt::format(", {:.3f} s each (shortest {:.3f}, "
                                           "longest {:.3f})",
                                           *p.mean_cycle_s, *p.shortest_cycle_s, *p.longest_cycle_s)
                             : "",
                         p.waited_s, reset_text(p), lag_text(p)));
        if (const auto& fi = p.feeder_interlock) {
            line(fmt::format("  interlock      the feeder held the press {} time{}, {:.3f} s in "
                             "all (longest {:.3f} s){}: a synchronised axis behind by more "
                             "than {:g} in (press.feeder_hold_lag_in)",
                             fi->holds, fi->holds == 1 ? "" : "s", fi->held_s, fi->longest_s,
                             fi->holding ? ", holding it at the end" : "", fi->limit_in));
        }
        if (const std::string drive = press_drive_warning(r); !drive.empty()) {
            line("  warning: " + drive);
        }
    }
    if (r.tapping && r.tapping->used) {
        const relaylogic::TappingResult& t = *r.tapping;
        const std::int64_t done =
            std::count_if(t.holes.begin(), t.holes.end(),
                          [](const relaylogic::HoleRecord& h) { return h.completed; });
        line(fmt::format(
            "  tapping        head 31 of tool {} on gear unit 30, memory 12a holds gear ratio "
            "{:.4f}; {} head exchange{}, {} ratio{} transferred ({} received); {} "
            "hole{} tapped{}",
            t.tool_on_spindle, t.ratio_in_memory, t.head_exchanges,
            t.head_exchanges == 1 ? "" : "s", t.transfers, t.transfers == 1 ? "" : "s",
            t.ratios_received, done, done == 1 ? "" : "s",
            static_cast<std::size_t>(done) < t.holes.size()
                ? fmt::format(" ({} begun)", t.holes.size())
                : std::string()));
        for (std::size_t i = 0; i < t.holes.size(); ++i) {
            if (const std::string miss = tap_hole_warning(r, i); !miss.empty()) {
                line("  warning: " + miss);
            }
        }
    }
    if (r.contouring && r.contouring->used) {
        for (const std::string& l : contouring_lines(*r.contouring)) {
            line(l);
        }
    }
    for (Axis a : cardreader::kAxes) {
        const auto& x = r.axes.at(cardreader::axis_index(a));
        if (std::abs(screw_vs_counters(x)) >= 0.0005 && std::abs(x.error_in) < 0.0005) {
            line(fmt::format("  note: {} screw turns read {:.4f} in, the counters {:.3f} in: the "
                             "{:+.4f} in between (slip, backlash in nut 78, lead error) was "
                             "measured through instrument shaft 74",
                             axis_name(a), x.screw_in, x.counter_in, screw_vs_counters(x)));
        }
        if (std::abs(x.error_in) >= 0.0005) {
            // Silent only if no check stopped the machine on this axis: a skip the balancing
            // circuit caught is named, not called unseen.
            const std::string seen =
                r.stop && r.stop->axis == a
                    ? fmt::format("the {} stop on this axis caught the difference",
                                  relaylogic::stop_reason_name(r.stop->reason))
                : r.stop ? std::string("no 1952 check had caught it when the machine stopped")
                         : std::string("the 1952 checks could not see it");
            line(fmt::format("  warning: {} ends {:+.4f} in from where its counters say ({}): {}",
                             axis_name(a), x.error_in, join(error_causes(x), "; "), seen));
        }
        if (r.completed && x.last_stop_in && std::abs(x.counter_in - *x.last_stop_in) >= 0.001) {
            line(fmt::format("  warning: {} ends at {:.3f} in, not on its last stop {:.3f} in: it "
                             "coasted past (reached the stop too fast) and no later card's check "
                             "was left to catch it",
                             axis_name(a), x.counter_in, *x.last_stop_in));
        }
        if (const std::string turns = counter_turns_warning(r, a); !turns.empty()) {
            line(fmt::format("  warning: {} {}", axis_name(a), turns));
        }
    }
    return out;
}

std::int64_t counter_turns_unseen(const relaylogic::RunResult& r, Axis a) {
    if (!r.completed) {
        return 0;
    }
    const auto& x = r.axes.at(cardreader::axis_index(a));
    const std::int64_t apart = std::llround((x.counted_in - x.ordered_in) * 1000.0);
    // To the nearest whole turn: what is left over (a coast past the stop) has its own warning.
    return (apart >= 0 ? apart + 5000 : apart - 5000) / 10000;
}

std::string counter_turns_warning(const relaylogic::RunResult& r, Axis a) {
    const std::int64_t turns = counter_turns_unseen(r, a);
    if (turns == 0) {
        return "";
    }
    const auto& x = r.axes.at(cardreader::axis_index(a));
    const std::int64_t n = turns < 0 ? -turns : turns;
    const std::string times = n == 1 ? "once" : n == 2 ? "twice" : fmt::format("{} times", n);
    return fmt::format("ends {:+.3f} in from where its cards put it: the cards ordered {:.3f} in, "
                       "the part is at {:.5f} in; its counters read {:.3f}, the card's number, "
                       "having gone round {} more than the cards ordered: a number passed "
                       "unseen (while delay 258 held channel 257 open, say) let the axis run on "
                       "until the counters read it again, which no 1952 check can see",
                       static_cast<double>(turns) * 10.0, x.ordered_in, x.real_in, x.counter_in,
                       times);
}

std::string tap_hole_warning(const relaylogic::RunResult& r, std::size_t i) {
    const relaylogic::TappingResult& t = *r.tapping;
    const relaylogic::HoleRecord& h = t.holes.at(i);
    const std::string hole =
        fmt::format("hole {} (card {}, tool {}, S {})", i + 1, h.card, h.tool, h.rpm);
    if (!h.completed) {
        // The last hole of a run that stopped: the stop says why.
        if (r.stop && i + 1 == t.holes.size()) {
            return "";
        }
        return fmt::format("{} did not come back onto its starting count: the feed stood {:+.4f} "
                           "in from it when the NC gave up after 5 s and the card ended; the next "
                           "card's check is left to find it (docs/tapping.md, \"Near the top\")",
                           hole, h.sense * (h.end_in - h.start_in));
    }
    const double miss = relaylogic::depth_miss_in(h, t.encoder_pulses_per_rev);
    if (miss == 0) {
        return "";
    }
    const double edge_in = h.pitch_ordered_in * h.ratio_used / t.encoder_pulses_per_rev;
    return fmt::format("{} bottomed at {:.4f} in, {:.4f} in {} its depth {:.3f} in: more than "
                       "the NC resolves (a thousandth, or an encoder edge's {:.5f} in); its "
                       "reversal, timed from the speed encoder 32 measured, and the feed drive's "
                       "following did not bring the tap closer (docs/tapping.md, \"Near the "
                       "depth\")",
                       hole, h.deepest_in, std::abs(miss), miss > 0 ? "past" : "short of",
                       h.depth_in, edge_in);
}

std::string press_drive_warning(const relaylogic::RunResult& r, bool name_card) {
    if (!r.press || !r.press->drive_saturated) {
        return "";
    }
    const relaylogic::DriveSaturation& s = *r.press->drive_saturated;
    const std::string card =
        !name_card ? std::string{}
        : s.number >= 0
            ? fmt::format("card {} (number {:04}), {}: ", s.card, s.number, axis_name(s.axis))
            : fmt::format("card {}, {}: ", s.card, axis_name(s.axis));
    const std::string why =
        s.crank_factor > 1.0 ? " (its drift, variation or change of speed)" : "";
    return fmt::format("{}the sync drive was asked {:.3f} in/min on speed {} at {:.3f} s, "
                       "past its top speed of {:.3f} in/min (sync_drive.max_in_per_min), the crank "
                       "at {:.3f} times the press's rated speed{}; the drive ran at its top speed "
                       "and the axis fell behind the crank, past the lag docs/press-sync.md "
                       "bounds (the most asked: {:.3f} in/min)",
                       card, s.asked_in_per_min, s.speed_position, s.t_s, s.drive_max_in_per_min,
                       s.crank_factor, why, s.most_asked_in_per_min);
}

} // namespace parsons::cli
