// run --cut FILE (generated decks): the cutter swept along the path the axes really took, drawn
// against the design as SVG, with the deviations in the report ("cut") and the summary. Which
// path is recorded depends on the job: a template job's table and cross slide (CutterPath), a
// wing's cutter centre in the work frame (WingPath), a two-tool job's path by the tool that cut
// it (ToolPaths, outputs/proofs/two_tool_proof.hpp).
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/job_file.hpp"
#include "outputs/output.hpp"
#include "outputs/proofs/cutter_paths.hpp"
#include "outputs/proofs/two_tool_proof.hpp"

#include <memory>
#include <string>

namespace parsons::cli {

class CutOutput : public Output {
public:
    // `job`: the job description the deck was generated with; `profile` must outlive the run.
    CutOutput(std::string svg, const decks::JobDescription& job,
              const axes::MachineProfile& profile);
    relaylogic::MachineObserver* observer() override;
    void finish(RunEnd& end) override;

private:
    std::string finish_wing(nlohmann::json& report) const;
    std::string finish_two_tool(nlohmann::json& report) const;
    std::string finish_template(nlohmann::json& report) const;

    std::string svg_;
    decks::JobDescription job_;
    const axes::MachineProfile& profile_;
    CutterPath cutter_;
    std::unique_ptr<WingPath> wing_path_;
    std::unique_ptr<ToolPaths> tool_paths_; // a two-tool job: the path by the tool that cut it
};

} // namespace parsons::cli
