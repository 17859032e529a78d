// The thread proof (outputs/proofs/thread_proof.hpp says what it measures and how).
#include "outputs/proofs/thread_proof.hpp"

#include "outputs/report/figures.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/template_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace parsons::cli {
namespace {

using cardreader::DeckError;

// A sample as the proof reads it: the tool's revolutions and the depth below the surface.
struct Point {
    double r = 0;
    double d = 0;
};

// The samples going in: up to the tool's furthest turn (the spindle reverses there), in strictly
// increasing revolutions (a sample that adds no turn adds nothing to d(r)).
std::vector<Point> going_in(const std::vector<relaylogic::TapSample>& samples,
                            const ThreadGauge& g) {
    std::vector<Point> pts;
    if (samples.empty()) {
        return pts;
    }
    const auto peak =
        std::max_element(samples.begin(), samples.end(),
                         [](const auto& a, const auto& b) { return a.tool_revs < b.tool_revs; });
    for (auto it = samples.begin(); it != std::next(peak); ++it) {
        const Point p{it->tool_revs, g.sense * (it->feed_in - g.surface_in)};
        if (pts.empty() || p.r > pts.back().r) {
            pts.push_back(p);
        }
    }
    return pts;
}

// The revolutions at which the depth first reaches D going in (NaN: never).
double revs_at_depth(const std::vector<Point>& pts, double depth) {
    if (pts.front().d >= depth) {
        return pts.front().r;
    }
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const Point& a = pts[i];
        const Point& b = pts[i + 1];
        if (a.d < depth && b.d >= depth) {
            return a.r + (depth - a.d) / (b.d - a.d) * (b.r - a.r);
        }
    }
    return std::numeric_limits<double>::quiet_NaN();
}

// The depth at R revolutions (R within the samples' span).
double depth_at_revs(const std::vector<Point>& pts, double revs) {
    auto it = std::lower_bound(pts.begin(), pts.end(), revs,
                               [](const Point& p, double r) { return p.r < r; });
    if (it == pts.begin()) {
        return pts.front().d;
    }
    if (it == pts.end()) {
        return pts.back().d;
    }
    const Point& b = *it;
    const Point& a = *std::prev(it);
    return a.d + (revs - a.r) / (b.r - a.r) * (b.d - a.d);
}

double percent(double pitch, double tap) {
    return (pitch - tap) / tap * 100.0;
}

} // namespace

ThreadMeasure measure_thread(const std::vector<relaylogic::TapSample>& samples,
                             const ThreadGauge& g) {
    ThreadMeasure m;
    const std::vector<Point> pts = going_in(samples, g);
    if (pts.size() < 2) {
        m.not_measured = "no samples of the tap going in";
        return m;
    }
    double deepest = pts.front().d;
    for (const Point& p : pts) {
        deepest = std::max(deepest, p.d);
    }
    m.zone_in = std::min(g.thread_depth_in, deepest) - g.chamfer_revs * g.tap_pitch_in;
    if (!(m.zone_in > 0)) {
        m.not_measured = fmt::format("the tap went {:.4f} in into the work: no full thread above "
                                     "its chamfer",
                                     std::max(deepest, 0.0));
        return m;
    }
    m.entry_revs = revs_at_depth(pts, 0.0);
    const double bottom_revs = revs_at_depth(pts, m.zone_in);
    m.revolutions = bottom_revs - m.entry_revs;
    const int whole = static_cast<int>(std::floor(m.revolutions + 1e-9));
    if (!(whole >= 1)) {
        m.not_measured = fmt::format("the full-thread zone ({:.4f} in) holds less than one tool "
                                     "revolution",
                                     m.zone_in);
        return m;
    }
    m.measured = true;
    m.mean_pitch_in = m.zone_in / m.revolutions;
    double below = depth_at_revs(pts, m.entry_revs);
    for (int k = 1; k <= whole; ++k) {
        const double next = depth_at_revs(pts, m.entry_revs + k);
        const double pitch = next - below;
        m.per_revolution_in.push_back(pitch);
        if (k == 1 ||
            std::abs(pitch - g.tap_pitch_in) > std::abs(m.worst_pitch_in - g.tap_pitch_in)) {
            m.worst_pitch_in = pitch;
            m.worst_revolution = k;
        }
        below = next;
    }
    m.mean_error_percent = percent(m.mean_pitch_in, g.tap_pitch_in);
    m.worst_error_percent = percent(m.worst_pitch_in, g.tap_pitch_in);
    m.flagged = std::abs(m.worst_error_percent) > g.tolerance_percent;
    return m;
}

std::int64_t ThreadProof::flagged() const {
    return static_cast<std::int64_t>(
        std::count_if(holes.begin(), holes.end(), [](const ProvedHole& h) { return h.flagged; }));
}

ThreadProof prove_threads(const relaylogic::TappingResult& tapping, const decks::TappingJob& job,
                          const axes::SpindleSyncProfile& spindle,
                          std::optional<double> tolerance_percent) {
    ThreadProof proof;
    proof.chamfer_revs = spindle.chamfer_revs;
    proof.tolerance_override = tolerance_percent;
    for (const relaylogic::HoleRecord& r : tapping.holes) {
        ProvedHole h;
        h.record = r;
        h.record.samples.clear();
        if (const decks::TappingHole* jh = job.hole_on_card(r.number)) {
            h.job_hole = *jh;
        }
        ThreadGauge& g = h.gauge;
        g.sense = r.sense;
        g.chamfer_revs = spindle.chamfer_revs;
        g.tap_pitch_in = r.tap_pitch_in.value_or(0.0);
        if (h.job_hole) {
            g.surface_in = h.job_hole->surface_in;
            g.thread_depth_in = h.job_hole->thread_depth_in;
            g.tolerance_percent = h.job_hole->tolerance_percent;
        } else {
            // A tap card the job does not know: the job's clearance above its start.
            g.surface_in = r.start_in + r.sense * job.clearance_in;
            g.thread_depth_in = r.depth_in - job.clearance_in;
            g.tolerance_percent = job.tolerance_percent;
            h.faults.push_back(fmt::format("card {:04} is no hole of the job", r.number));
        }
        if (tolerance_percent) {
            g.tolerance_percent = *tolerance_percent;
        }
        if (r.tool == 0) {
            // The machine stopped before the tool was ready (a hung transfer): nothing cut.
            h.measure.not_measured = "the machine stopped before the tap began";
            h.flagged = !h.faults.empty();
            proof.holes.push_back(std::move(h));
            continue;
        }
        if (!r.tap_pitch_in) {
            h.faults.push_back(fmt::format("head {} holds a cutter, not a tap", r.tool));
        } else {
            h.measure = measure_thread(r.samples, g);
        }
        if (h.job_hole && h.job_hole->tool != r.tool) {
            h.faults.push_back(
                fmt::format("tool {} cut it; the job calls for tool {}", r.tool, h.job_hole->tool));
        }
        if (r.completed && r.tap_pitch_in && !h.measure.measured) {
            h.faults.push_back(h.measure.not_measured);
        }
        h.flagged = h.measure.flagged || !h.faults.empty();
        proof.holes.push_back(std::move(h));
    }
    return proof;
}

void add_thread_proof(nlohmann::json& block, const ThreadProof& proof) {
    using nlohmann::json;
    block["thread_tolerance_percent"] =
        proof.tolerance_override ? json(*proof.tolerance_override) : json(nullptr);
    block["chamfer_revs"] = proof.chamfer_revs;
    block["holes_flagged"] = proof.flagged();
    json worst = nullptr;
    double worst_abs = -1;
    if (!block.contains("holes") || !block["holes"].is_array()) {
        block["holes"] = json::array();
    }
    json& holes = block["holes"];
    for (std::size_t i = 0; i < proof.holes.size(); ++i) {
        const ProvedHole& h = proof.holes[i];
        const ThreadMeasure& m = h.measure;
        if (i >= holes.size()) {
            holes.push_back(json{{"card", h.record.card}, {"number", h.record.number}});
        }
        json& j = holes[i];
        j["hole"] = h.job_hole ? json(h.job_hole->hole) : json(nullptr);
        j["tap_pitch_in"] = h.record.tap_pitch_in ? json(*h.record.tap_pitch_in) : json(nullptr);
        j["surface_in"] = decimals(h.gauge.surface_in, 6);
        j["thread_depth_in"] = decimals(h.gauge.thread_depth_in, 6);
        j["tolerance_percent"] = h.gauge.tolerance_percent;
        j["measured"] = m.measured;
        j["full_thread_in"] = m.measured ? json(decimals(m.zone_in, 6)) : json(nullptr);
        j["revolutions_measured"] = m.measured ? json(decimals(m.revolutions, 4)) : json(nullptr);
        auto pitch = [&](double v) { return m.measured ? json(decimals(v, 6)) : json(nullptr); };
        auto pct = [&](double v) { return m.measured ? json(decimals(v, 3)) : json(nullptr); };
        j["mean_pitch_in"] = pitch(m.mean_pitch_in);
        j["worst_pitch_in"] = pitch(m.worst_pitch_in);
        j["worst_revolution"] = m.measured ? json(m.worst_revolution) : json(nullptr);
        j["mean_error_percent"] = pct(m.mean_error_percent);
        j["worst_error_percent"] = pct(m.worst_error_percent);
        j["flagged"] = h.flagged;
        j["findings"] = h.faults;
        if (m.measured && std::abs(m.worst_error_percent) > worst_abs) {
            worst_abs = std::abs(m.worst_error_percent);
            worst = json{{"card", h.record.card},
                         {"number", h.record.number},
                         {"hole", h.job_hole ? json(h.job_hole->hole) : json(nullptr)},
                         {"worst_error_percent", decimals(m.worst_error_percent, 3)}};
        }
    }
    block["worst_hole"] = worst;
}

namespace {

// The tool that cut it, or the one the card called for when nothing was cut.
std::string hole_name(const ProvedHole& h) {
    const int tool = h.record.tool != 0 ? h.record.tool : h.record.tool_called;
    return h.job_hole ? fmt::format("hole {} (card {:04}, tool {})", h.job_hole->hole,
                                    h.record.number, tool)
                      : fmt::format("card {:04} (tool {})", h.record.number, tool);
}

// "5 % of the pitch" when every hole has the same tolerance, else "per hole".
std::string tolerance_words(const ThreadProof& proof) {
    if (proof.tolerance_override) {
        return fmt::format("{:g} % of the pitch", *proof.tolerance_override);
    }
    if (proof.holes.empty()) {
        return "none to apply";
    }
    const double first = proof.holes.front().gauge.tolerance_percent;
    for (const ProvedHole& h : proof.holes) {
        if (h.gauge.tolerance_percent != first) {
            return "the job's, per hole";
        }
    }
    return fmt::format("{:g} % of the pitch", first);
}

} // namespace

std::string thread_summary(const ThreadProof& proof) {
    std::string out =
        fmt::format("  thread proof   {} hole{}, tolerance {}; {} flagged\n", proof.holes.size(),
                    proof.holes.size() == 1 ? "" : "s", tolerance_words(proof), proof.flagged());
    for (const ProvedHole& h : proof.holes) {
        const ThreadMeasure& m = h.measure;
        if (h.record.tool == 0) {
            out += fmt::format("    {:<28} not cut: {}\n", hole_name(h), m.not_measured);
            continue;
        }
        std::string figures = "not measured";
        if (m.measured) {
            figures =
                fmt::format("pitch {:.5f} in (tap {:.5f}, {:+.2f} %), worst revolution {} "
                            "{:.5f} in ({:+.2f} %) over {:.1f} revolutions",
                            m.mean_pitch_in, h.gauge.tap_pitch_in,
                            decimals(m.mean_error_percent, 2), m.worst_revolution, m.worst_pitch_in,
                            decimals(m.worst_error_percent, 2), m.revolutions);
        } else if (!m.not_measured.empty()) {
            figures = "not measured: " + m.not_measured;
        }
        out += fmt::format("    {:<28} {}; ratio {:.4f} in 12a, head's {:.4f}: {}\n", hole_name(h),
                           figures, h.record.ratio_used, h.record.head_ratio,
                           h.flagged ? "WRONG" : "ok");
    }
    return out;
}

std::vector<std::string> wrong_pitch_lines(const ThreadProof& proof) {
    std::vector<std::string> lines;
    for (const ProvedHole& h : proof.holes) {
        if (!h.flagged) {
            continue;
        }
        const ThreadMeasure& m = h.measure;
        std::vector<std::string> parts;
        if (m.measured) {
            parts.push_back(
                fmt::format("pitch cut {:.5f} in a revolution (worst revolution {:.5f} in, "
                            "{:+.1f} %) against the tap's {:.5f} in (tolerance {:g} %); "
                            "memory 12a held gear ratio {:.4f}, head {}'s is {:.4f}",
                            m.mean_pitch_in, m.worst_pitch_in, m.worst_error_percent,
                            h.gauge.tap_pitch_in, h.gauge.tolerance_percent, h.record.ratio_used,
                            h.record.tool, h.record.head_ratio));
        }
        parts.insert(parts.end(), h.faults.begin(), h.faults.end());
        std::string line = hole_name(h) + ":";
        for (std::size_t i = 0; i < parts.size(); ++i) {
            line += (i == 0 ? " " : "; ") + parts[i];
        }
        lines.push_back(line);
    }
    return lines;
}

} // namespace parsons::cli
