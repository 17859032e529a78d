// What a generated deck was computed to cut, written beside it (DECK.job.json) so that
// `parsons run DECK --cut SVG` can compare the cut with the design: the airfoil source, the
// job options and where the work's origin lies in the counters' range. The two-tool job
// (decks/two_tool_job.hpp) is a template job with its passes listed: the tool of each and the
// radius its cards were computed for ("job": "two-tool" in the file, which a parsons from
// before it refuses instead of proving the cut with one radius).
#pragma once

#include "decks/airfoil.hpp"
#include "decks/template_job.hpp"
#include "decks/wing_job.hpp"

#include <memory>
#include <string>
#include <vector>

namespace parsons::decks {

enum class JobKind { template_2d, wing };

// One pass of a two-tool job: the tool that cuts it, that tool's radius (the machine
// profile's) and the cutter offset its cards were computed with (radius + allowance).
struct PassDescription {
    int tool = 0;
    double radius_in = 0;
    double offset_in = 0;
};

struct JobDescription {
    JobKind kind = JobKind::template_2d;
    std::string airfoil; // "naca 2412" or "dat PATH"
    bool closed_trailing_edge = false;
    TemplateOptions options; // the template job, and where its work zero lies
    Eigen::Vector2d work_zero_in = Eigen::Vector2d::Zero();
    WingOptions wing; // the wing job, and its zero (cross, table, vertical)
    Eigen::Vector3d wing_zero_in = Eigen::Vector3d::Zero();
    // The two-tool job: its passes in order (empty for a one-tool job), what the first leaves
    // standing, and where its tool change is tripped ("tripped" or "boundary").
    std::vector<PassDescription> passes;
    double allowance_in = 0;
    std::string variant;
    // The deck it was generated with (cardreader::DeckFingerprint); empty in older files.
    std::int64_t deck_cards = 0;
    std::string deck_fingerprint;
};

std::string job_to_json(const JobDescription& job);
// Throws JobError("KEY: what is wrong").
JobDescription job_from_json(const std::string& text);
// The airfoil a job names. Throws JobError, or cardreader::DeckError for a bad .dat file.
std::unique_ptr<Airfoil> open_airfoil(const JobDescription& job);

} // namespace parsons::decks
