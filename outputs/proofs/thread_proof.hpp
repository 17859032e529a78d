// The thread proof (`parsons run DECK --thread-proof JOB`): from the tool's true revolutions and
// the part's true position on the feed axis, sampled through each tap (RunResult.tapping, with
// ControlCabinet::record_tap_samples), the pitch each hole's thread really has, against the pitch
// of the tap that cut it. Spindle synchronisation is an addition after EP 0360190
// (Mitsubishi); docs/tapping.md tells the figures.
//
// A thread's pitch is the tool's advance into the work per tool revolution. The proof judges it
// going in, over the full-thread zone: from the plate's surface down to the thread's depth less
// the tap's chamfer (chamfer_revs x the tap's pitch: the last threads are not full).
//
//    depth d below the surface                 d(r): the samples (tool revolutions r, depth d),
//      0 -+- surface ......... r0               joined by straight lines (linear interpolation)
//         |  rev 1: d(r0+1) - d(r0)            per-revolution pitch k = d(r0+k) - d(r0+k-1),
//         |  rev 2: ...                          k = 1 .. whole revolutions in the zone
//   zone -+- depth - chamfer . r1               mean pitch = zone / (r1 - r0)
//         |  (chamfer: not judged)              error = pitch - the tap's, in % of the tap's
//  depth -+-                                    a hole is flagged when the worst revolution's
//                                               error is beyond the tolerance (5 %)
//
// The tap's pitch is the real tool's (the head on the spindle while it cut, HoleRecord
// tap_pitch_in), so a wrong ratio in memory 12a (fault stale-ratio) shows as a wrong pitch.
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/tapping_job.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

// What one hole's thread is judged against.
struct ThreadGauge {
    double surface_in = 0; // the plate's surface on the feed axis
    int sense = -1;        // +1 / -1: the part's travel into the work
    double tap_pitch_in = 0;
    double thread_depth_in = 0; // below the surface
    double chamfer_revs = 3.0;
    double tolerance_percent = 5.0;
};

struct ThreadMeasure {
    bool measured = false;
    std::string not_measured; // why, when not
    double zone_in = 0;       // the full-thread zone's length below the surface
    double entry_revs = 0;    // the tool's revolutions when its point reached the surface
    double revolutions = 0;   // across the zone
    std::vector<double> per_revolution_in; // each whole revolution's advance, from the surface
    double mean_pitch_in = 0;
    double worst_pitch_in = 0; // the revolution furthest from the tap's pitch
    int worst_revolution = 0;  // 1 = the first from the surface
    double mean_error_percent = 0;
    double worst_error_percent = 0;
    bool flagged = false; // |worst error| beyond the tolerance
};

// Pure: the measure of one thread from its samples (in time order).
ThreadMeasure measure_thread(const std::vector<relaylogic::TapSample>& samples,
                             const ThreadGauge& gauge);

struct ProvedHole {
    relaylogic::HoleRecord record; // without its samples
    std::optional<decks::TappingHole> job_hole;
    ThreadGauge gauge;
    ThreadMeasure measure;
    std::vector<std::string> faults; // why it is flagged besides the pitch
    bool flagged = false;
    int hole_number() const { return job_hole ? job_hole->hole : 0; }
};

struct ThreadProof {
    double chamfer_revs = 0;
    std::optional<double> tolerance_override; // --thread-tolerance
    std::vector<ProvedHole> holes;
    std::int64_t flagged() const;
};

// Every hole of the run against the job. tolerance_percent: --thread-tolerance (else each hole's
// from the job).
ThreadProof prove_threads(const relaylogic::TappingResult& tapping, const decks::TappingJob& job,
                          const axes::SpindleSyncProfile& spindle,
                          std::optional<double> tolerance_percent);

// The proof's keys: added to the report's tapping block and to each of its holes.
void add_thread_proof(nlohmann::json& tapping_block, const ThreadProof& proof);
// The summary's lines ("  thread proof   ...").
std::string thread_summary(const ThreadProof& proof);
// One line per flagged hole: "hole 4 (card 0008, tool 2): pitch cut 0.04688 in ...".
std::vector<std::string> wrong_pitch_lines(const ThreadProof& proof);

} // namespace parsons::cli
