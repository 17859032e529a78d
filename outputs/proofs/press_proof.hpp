// The press-feeder proof (`parsons run DECK --press-proof JOB`): an observer that at every
// event of the run — every detector edge of the press, every impulse of the feeder — checks
// that the feeder is never inside the die zone (table beyond the zone edge) while die 20 is
// below its safe height. Press synchronisation is an addition after EP 0436887
// (Mitsubishi); docs/press-sync.md tells the figures.
//
// How: the press is a machine of its own that the control never drives, so the proof turns a
// copy of it (axes::Press, the same profile) in step with machine time and reads the die's
// height there, exactly, between the trace's tenth-of-a-degree crank signal; the feeder's X is
// the table's real position from on_motion. The one thing the control does to the press, the
// feeder's interlock holding it (press.feeder_hold_lag_in), the proof takes from the machine:
// its copy is held and let go at the instants the cabinet's signal
// press.feeder_interlock.hold says, so it never decides a hold of its own.
//
//   clearance (in) = max(die height - safe height, zone edge - feeder X)   (< 0: collision)
//   time margin (s) = the die going below safe height - the feeder's last exit from the zone,
//                     or the feeder's entry - the die's last rise above safe height
//                     (negative when they overlap)
#pragma once

#include "axes/press.hpp"
#include "decks/press_feeder_job.hpp"
#include "decks/template_job.hpp"
#include "relaylogic/control_cabinet.hpp"
#include "relaylogic/machine_observer.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

class PressProof : public relaylogic::MachineObserver {
public:
    PressProof(const axes::PressProfile& press, double zone_edge_x_in, double safe_height_in,
               int cycle_card);

    struct Instant {
        std::int64_t cycle = 0; // the pass of the loop (1 = the first)
        double t = 0;           // machine seconds
        double crank_deg = 0;
        double feeder_x_in = 0;
        double die_height_in = 0;
        double clearance_in = 0;
    };

    // The clearance at one instant (exposed for the tests' hand calculation).
    static double clearance(double die_height_in, double safe_height_in, double zone_edge_x_in,
                            double feeder_x_in);

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_signal(double t, relaylogic::SignalId id, std::uint32_t, std::uint32_t value) override;
    void on_motion(double t, const std::array<double, 5>& real) override;
    void on_card(double t, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_finish(double t) override { advance(t); }

    std::int64_t cycles() const { return cycle_; }
    const Instant& closest() const { return closest_; }                    // the smallest clearance
    const std::optional<Instant>& collision() const { return collision_; } // the first
    std::optional<double> min_margin_s() const { return min_margin_s_; }
    // The smallest clearance of each cycle (index 0 = cycle 1; the home card counts to it).
    const std::vector<double>& cycle_clearance_in() const { return per_cycle_; }
    // The times the feeder entered the zone (insert, take-out, insert, ...).
    const std::vector<double>& entries_s() const { return entries_; }
    const axes::Press& press() const { return press_; }

private:
    void advance(double t);
    void check(double t);
    void margin(double m);
    double crossing_time(double t, double a_deg) const; // the die passing a_deg since last

    axes::Press press_;
    std::optional<relaylogic::SignalId> interlock_; // the cabinet's press.feeder_interlock.hold
    double edge_;
    double safe_;
    int cycle_card_;
    std::pair<double, double> low_angles_; // the die below safe height between these angles
    std::int64_t cycle_ = 0;
    double x_ = 0;
    bool started_ = false;
    bool inside_ = false;
    bool low_ = false;
    double last_t_ = 0;
    double last_theta_ = 0;
    double last_exit_ = -std::numeric_limits<double>::infinity();
    double last_up_ = -std::numeric_limits<double>::infinity();
    std::optional<double> down_inside_; // the die went low with the feeder inside, at
    std::optional<double> enter_low_;   // the feeder entered with the die low, at
    Instant closest_{0, 0, 0, 0, 0, std::numeric_limits<double>::infinity()};
    std::optional<Instant> collision_;
    std::optional<double> min_margin_s_;
    std::vector<double> per_cycle_;
    std::vector<double> entries_;
};

// The report's press block (RunResult.press and the proof) and the summary's lines.
nlohmann::json press_block(const relaylogic::RunResult& result, const PressProof& proof,
                           const decks::PressFeederJob& job);
std::string press_summary(const relaylogic::RunResult& result, const PressProof& proof);
// "collision in cycle 3 at 151.20 s: crank 140.3 deg, feeder X 0.712 in, die 0.21 in above
// bottom dead centre (safe height 0.25 in)"
std::string collision_message(const PressProof& proof, double safe_height_in,
                              double zone_edge_x_in);

} // namespace parsons::cli
