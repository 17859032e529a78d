// The proof of the cut as an output (outputs/proofs/cut_output.hpp).
#include "outputs/proofs/cut_output.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/cut_proof.hpp"
#include "decks/cut_svg.hpp"
#include "outputs/output_file.hpp"
#include "outputs/report/run_report.hpp"

#include <fmt/format.h>

#include <utility>

namespace parsons::cli {

CutOutput::CutOutput(std::string svg, const decks::JobDescription& job,
                     const axes::MachineProfile& profile)
    : svg_(std::move(svg)), job_(job), profile_(profile) {
    if (job_.kind == decks::JobKind::wing) {
        wing_path_ = std::make_unique<WingPath>(job_.wing_zero_in, profile_);
    } else if (!job_.passes.empty()) {
        tool_paths_ = std::make_unique<ToolPaths>(profile_.first_tool);
    }
}

relaylogic::MachineObserver* CutOutput::observer() {
    if (wing_path_) {
        return wing_path_.get();
    }
    if (tool_paths_) {
        return tool_paths_.get();
    }
    return &cutter_;
}

void CutOutput::finish(RunEnd& end) {
    if (wing_path_) {
        end.summary += finish_wing(end.report);
    } else if (tool_paths_) {
        end.summary += finish_two_tool(end.report);
    } else {
        end.summary += finish_template(end.report);
    }
}

std::string CutOutput::finish_wing(nlohmann::json& report) const {
    const decks::JobDescription& job = job_;
    const auto airfoil = decks::open_airfoil(job);
    const decks::WingProof proof = decks::prove_wing(wing_path_->path, *airfoil, job.wing);
    write_file(svg_, decks::wing_cut_svg(proof, wing_path_->path, job.wing,
                                         fmt::format("{} wing", job.airfoil)));
    report["cut"] = {{"root",
                      {{"max_gouge_in", fine_length(proof.root.max_gouge_in)},
                       {"max_leftover_in", fine_length(proof.root.max_leftover_in)}}},
                     {"tip",
                      {{"max_gouge_in", fine_length(proof.tip.max_gouge_in)},
                       {"max_leftover_in", fine_length(proof.tip.max_leftover_in)}}}};
    return fmt::format("  cut            root section: deepest gouge {:.5f} in, most "
                       "left standing {:.5f} in; tip section: {:.5f} in, {:.5f} in\n",
                       proof.root.max_gouge_in, proof.root.max_leftover_in, proof.tip.max_gouge_in,
                       proof.tip.max_leftover_in);
}

std::string CutOutput::finish_two_tool(nlohmann::json& report) const {
    try {
        return write_two_tool_cut(prove_two_tool_cut(*tool_paths_, job_, profile_), job_, svg_,
                                  report);
    } catch (const decks::JobError& e) {
        throw cardreader::DeckError(fmt::format("--cut: {}", e.what()));
    }
}

std::string CutOutput::finish_template(nlohmann::json& report) const {
    const decks::JobDescription& job = job_;
    const auto airfoil = decks::open_airfoil(job);
    const auto samples = decks::design_samples(*airfoil, job.options, job.work_zero_in);
    const decks::DesignContour design{samples.points, samples.toward_cutter};
    const double radius = job.options.cutter_radius_in;
    const auto path = decks::simplify_path(cutter_.path, 1e-7);
    const decks::CutProof proof = decks::prove_cut(path, radius, design, 1.5 * radius);
    write_file(svg_,
               decks::cut_svg(proof, path, design, radius,
                              fmt::format("{}: the cut, from the emulated path", job.airfoil)));
    report["cut"] = {{"max_gouge_in", fine_length(proof.max_gouge_in)},
                     {"max_leftover_in", fine_length(proof.max_leftover_in)},
                     {"max_scallop_in", fine_length(proof.max_scallop_in)},
                     {"machined_points", proof.machined_points},
                     {"design_points", design.points.size()}};
    return fmt::format("  cut            deepest gouge {:.5f} in, most left standing "
                       "{:.5f} in, largest scallop {:.5f} in ({} of {} design points "
                       "machined)\n",
                       proof.max_gouge_in, proof.max_leftover_in, proof.max_scallop_in,
                       proof.machined_points, design.points.size());
}

} // namespace parsons::cli
