// The proof of a two-tool job's cut (outputs/proofs/two_tool_proof.hpp): each stretch of the path
// swept with the radius of the tool that cut it, and the surface the passes left together.
#include "outputs/proofs/two_tool_proof.hpp"

#include "outputs/output_file.hpp"
#include "outputs/report/run_report.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/cut_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace parsons::cli {
namespace {

double radius_of(int tool, const decks::JobDescription& job, const axes::MachineProfile& profile) {
    if (auto r = profile.tool_radius_in(tool)) {
        return *r;
    }
    for (const auto& p : job.passes) {
        if (p.tool == tool) {
            return p.radius_in;
        }
    }
    throw decks::JobError(fmt::format("tool {} cut part of the path, but neither the machine "
                                      "profile nor the job gives its radius",
                                      tool));
}

nlohmann::json figures(const decks::CutProof& proof) {
    return {{"max_gouge_in", fine_length(proof.max_gouge_in)},
            {"max_leftover_in", fine_length(proof.max_leftover_in)},
            {"max_scallop_in", fine_length(proof.max_scallop_in)},
            {"machined_points", proof.machined_points}};
}

} // namespace

decks::CutProof combine_proofs(const std::vector<decks::CutProof>& proofs,
                               const decks::DesignContour& design) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    decks::CutProof out;
    const std::size_t n = design.points.size();
    out.deviation_in.assign(n, kNaN);
    out.cut_contour.assign(n, Eigen::Vector2d::Constant(kNaN));
    for (std::size_t i = 0; i < n; ++i) {
        double dev = kNaN;
        for (const decks::CutProof& p : proofs) {
            const double d = i < p.deviation_in.size() ? p.deviation_in[i] : kNaN;
            if (!std::isnan(d) && (std::isnan(dev) || d < dev)) {
                dev = d;
            }
        }
        out.deviation_in[i] = dev;
        if (std::isnan(dev)) {
            continue;
        }
        ++out.machined_points;
        out.cut_contour[i] = design.points[i] + dev * design.normals[i].normalized();
        out.max_gouge_in = std::max(out.max_gouge_in, -dev);
        out.max_leftover_in = std::max(out.max_leftover_in, dev);
    }
    out.max_scallop_in = decks::max_cusp(out.deviation_in);
    return out;
}

TwoToolCut prove_two_tool_cut(const ToolPaths& paths, const decks::JobDescription& job,
                              const axes::MachineProfile& profile) {
    TwoToolCut cut;
    const auto airfoil = decks::open_airfoil(job);
    const auto samples = decks::design_samples(*airfoil, job.options, job.work_zero_in);
    cut.design = {samples.points, samples.toward_cutter};
    std::vector<decks::CutProof> proofs;
    for (const ToolPaths::Stretch& s : paths.stretches) {
        if (s.path.empty()) {
            continue;
        }
        TwoToolCut::Pass pass;
        pass.tool = s.tool;
        pass.radius_in = radius_of(s.tool, job, profile);
        pass.path = decks::simplify_path(s.path, 1e-7);
        pass.proof = decks::prove_cut(pass.path, pass.radius_in, cut.design, 1.5 * pass.radius_in);
        if (pass.proof.machined_points == 0) {
            continue; // a stretch that never came near the work (a change at the start, say)
        }
        proofs.push_back(pass.proof);
        cut.passes.push_back(std::move(pass));
    }
    cut.combined = combine_proofs(proofs, cut.design);
    return cut;
}

std::string write_two_tool_cut(const TwoToolCut& cut, const decks::JobDescription& job,
                               const std::string& svg, nlohmann::json& report) {
    // The picture: the surface both passes left, with the path and cutter of the last pass
    // (the finish) drawn along it.
    std::vector<Eigen::Vector2d> path;
    double radius = job.options.cutter_radius_in;
    std::string finish = "no pass machined the design";
    if (!cut.passes.empty()) {
        path = cut.passes.back().path;
        radius = cut.passes.back().radius_in;
        finish = fmt::format("path and cutter of the last pass, tool {}", cut.passes.back().tool);
    }
    write_file(svg, decks::cut_svg(cut.combined, path, cut.design, radius,
                                   fmt::format("{}: the cut of {} passes, from the emulated path "
                                               "({})",
                                               job.airfoil, cut.passes.size(), finish)));
    nlohmann::json passes = nlohmann::json::array();
    std::string lines = fmt::format(
        "  cut            all passes: deepest gouge {:.5f} in, most left standing {:.5f} in, "
        "largest scallop {:.5f} in ({} of {} design points machined)\n",
        cut.combined.max_gouge_in, cut.combined.max_leftover_in, cut.combined.max_scallop_in,
        cut.combined.machined_points, cut.design.points.size());
    for (std::size_t k = 0; k < cut.passes.size(); ++k) {
        const TwoToolCut::Pass& p = cut.passes[k];
        nlohmann::json j = {{"pass", k + 1}, {"tool", p.tool}, {"radius_in", p.radius_in}};
        j.update(figures(p.proof));
        passes.push_back(j);
        lines += fmt::format("  {:<15}tool {}, radius {:.4f} in: deepest gouge {:.5f} in, most "
                             "left standing {:.5f} in, largest scallop {:.5f} in\n",
                             fmt::format("cut, pass {}", k + 1), p.tool, p.radius_in,
                             p.proof.max_gouge_in, p.proof.max_leftover_in, p.proof.max_scallop_in);
    }
    nlohmann::json j = figures(cut.combined);
    j["design_points"] = cut.design.points.size();
    j["allowance_in"] = job.allowance_in;
    j["passes"] = passes;
    report["cut"] = j;
    return lines;
}

} // namespace parsons::cli
