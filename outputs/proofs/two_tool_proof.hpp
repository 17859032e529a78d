// The two-tool job's cut (decks/two_tool_job.hpp; condition cards, an addition after
// EP 0640901), proved per tool (`parsons run DECK --cut SVG`, two_tool_proof.cpp; generating the
// job is `parsons gen two-tool`, cli/gen_command.cpp).
//
// The proof sweeps each stretch of the recorded path with the radius of the tool that was in
// the spindle while it was cut: a stretch ends where a tool change is acknowledged (the new
// tool is in the spindle from then on, axes/tool_changer.hpp). Each stretch is proved alone
// against the design, and the surface the whole job left is, per design point, the least
// deviation over the stretches (a gouge by any tool stays a gouge; material stands only where
// no tool took it).
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/cut_proof.hpp"
#include "decks/job_file.hpp"
#include "decks/two_tool_job.hpp"
#include "relaylogic/machine_observer.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace parsons::cli {

// The cutter centre (table, cross slide) at every impulse, in stretches by the tool in the
// spindle.
class ToolPaths : public relaylogic::MachineObserver {
public:
    struct Stretch {
        int tool = 0;
        std::vector<Eigen::Vector2d> path;
    };
    explicit ToolPaths(int first_tool) { stretches.push_back({first_tool, {}}); }
    void on_motion(double /*t*/, const std::array<double, 5>& real) override {
        const Eigen::Vector2d p(real[0], real[1]);
        auto& path = stretches.back().path;
        if (path.empty() || p != path.back()) {
            path.push_back(p);
        }
    }
    void on_condition(double /*t*/, const relaylogic::ConditionEvent& e) override {
        if (e.kind != relaylogic::ConditionEventKind::acknowledged ||
            e.action != cardreader::ActionKind::tool_change) {
            return;
        }
        // The new tool starts where the old one stands.
        const auto& last = stretches.back().path;
        Stretch next{e.tool_in_spindle, {}};
        if (!last.empty()) {
            next.path.push_back(last.back());
        }
        stretches.push_back(std::move(next));
    }
    std::vector<Stretch> stretches;
};

struct TwoToolCut {
    struct Pass {
        int tool = 0;
        double radius_in = 0;
        std::vector<Eigen::Vector2d> path; // simplified
        decks::CutProof proof;
    };
    decks::DesignContour design;
    std::vector<Pass> passes; // one per stretch that machined something
    decks::CutProof combined; // per design point the least deviation over the passes
};

// Proves every stretch with its tool's radius (the profile's; the job's if the profile has no
// such tool). Throws decks::JobError for a job whose airfoil cannot be opened.
TwoToolCut prove_two_tool_cut(const ToolPaths& paths, const decks::JobDescription& job,
                              const axes::MachineProfile& profile);

// The combination of several proofs of one design (exposed for the tests).
decks::CutProof combine_proofs(const std::vector<decks::CutProof>& proofs,
                               const decks::DesignContour& design);

// Writes the picture to `svg` and the figures into report["cut"]; returns the summary lines.
std::string write_two_tool_cut(const TwoToolCut& cut, const decks::JobDescription& job,
                               const std::string& svg, nlohmann::json& report);

} // namespace parsons::cli
