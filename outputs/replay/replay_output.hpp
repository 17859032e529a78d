// The run's timeline (outputs/replay/run_timeline.hpp) as an output: recorded for the replay
// page (run --html FILE, outputs/replay/replay_page.hpp) or for an embedder that keeps it (the
// exhibit page, web/parsons_web.cpp), or both.
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/job_file.hpp"
#include "outputs/output.hpp"
#include "outputs/replay/run_timeline.hpp"

#include <memory>
#include <string>

namespace parsons::cli {

class ReplayOutput : public Output {
public:
    // `timeline`: the embedder's recording, or null for one of the output's own; `page`: the
    // replay page to write (--html), "" for none; `job`: the job description read for the run,
    // null for none (an airfoil template job's design is drawn under the cut).
    ReplayOutput(RunTimeline* timeline, std::string page, std::string deck,
                 const axes::MachineProfile& profile, const decks::JobDescription* job);
    relaylogic::MachineObserver* observer() override { return timeline_; }
    void finish(RunEnd& end) override;

private:
    std::unique_ptr<RunTimeline> own_;
    RunTimeline* timeline_;
    std::string page_;
    std::string deck_;
};

} // namespace parsons::cli
