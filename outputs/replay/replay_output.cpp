// The timeline as an output (outputs/replay/replay_output.hpp).
#include "outputs/replay/replay_output.hpp"

#include "decks/template_job.hpp"
#include "outputs/output_file.hpp"
#include "outputs/replay/replay_page.hpp"

#include <utility>

namespace parsons::cli {
namespace {

// The replay's design: for an airfoil template job, the section the cut grows against in the
// table and cross-slide frame.
void add_design(RunTimeline& timeline, const decks::JobDescription& job) {
    if (job.kind != decks::JobKind::template_2d || !job.passes.empty()) {
        return; // a wing or two-tool job: the replay shows the path alone
    }
    const auto airfoil = decks::open_airfoil(job);
    const auto samples = decks::design_samples(*airfoil, job.options, job.work_zero_in, 400);
    nlohmann::json points = nlohmann::json::array();
    for (const Eigen::Vector2d& p : samples.points) {
        points.push_back({p.x(), p.y()});
    }
    timeline.set_design({{"airfoil", job.airfoil},
                         {"cutter_radius_in", job.options.cutter_radius_in},
                         {"points", std::move(points)}});
}

} // namespace

ReplayOutput::ReplayOutput(RunTimeline* timeline, std::string page, std::string deck,
                           const axes::MachineProfile& profile, const decks::JobDescription* job)
    : own_(timeline == nullptr ? std::make_unique<RunTimeline>() : nullptr),
      timeline_(timeline == nullptr ? own_.get() : timeline), page_(std::move(page)),
      deck_(std::move(deck)) {
    timeline_->set_machine(profile);
    if (job != nullptr) {
        add_design(*timeline_, *job);
    }
}

void ReplayOutput::finish(RunEnd& end) {
    if (!page_.empty()) {
        write_file(page_, replay_page(*timeline_, end.report, deck_));
    }
}

} // namespace parsons::cli
