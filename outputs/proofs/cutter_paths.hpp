// Observers that record where the cutter centre really went, for the proof of the cut.
#pragma once

#include "axes/machine_profile.hpp"
#include "decks/wing_job.hpp"
#include "relaylogic/machine_observer.hpp"

#include <Eigen/Core>

#include <vector>

namespace parsons::cli {

// The template job: the table and cross-slide positions at every impulse (its two moving axes).
class CutterPath : public relaylogic::MachineObserver {
public:
    void on_motion(double /*t*/, const std::array<double, 5>& real) override {
        const Eigen::Vector2d p(real[0], real[1]);
        if (path.empty() || p != path.back()) {
            path.push_back(p);
        }
    }
    std::vector<Eigen::Vector2d> path;
};

// The wing job: the cutter centre relative to the wing (the work frame), turning the five real
// positions back through the fixture's real angles.
class WingPath : public relaylogic::MachineObserver {
public:
    WingPath(const Eigen::Vector3d& zero, const axes::MachineProfile& profile)
        : zero_(zero), profile_(profile) {}
    void on_motion(double /*t*/, const std::array<double, 5>& real) override {
        path.push_back(decks::work_point(real, zero_, profile_));
    }
    std::vector<Eigen::Vector3d> path;

private:
    Eigen::Vector3d zero_;
    const axes::MachineProfile& profile_;
};

} // namespace parsons::cli
