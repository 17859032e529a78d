// The press-feeder proof (outputs/proofs/press_proof.hpp says what it checks and how).
#include "outputs/proofs/press_proof.hpp"

#include "outputs/report/figures.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parsons::cli {
using cardreader::DeckError;

PressProof::PressProof(const axes::PressProfile& press, double zone_edge_x_in,
                       double safe_height_in, int cycle_card)
    : press_(press), edge_(zone_edge_x_in), safe_(safe_height_in), cycle_card_(cycle_card) {
    low_angles_ = press_.angles_at_height(safe_height_in).value_or(std::pair{360.0, 360.0});
}

double PressProof::clearance(double die_height_in, double safe_height_in, double zone_edge_x_in,
                             double feeder_x_in) {
    return std::max(die_height_in - safe_height_in, zone_edge_x_in - feeder_x_in);
}

void PressProof::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
    if (info.scope == "press" && info.name == "feeder_interlock.hold") {
        interlock_ = info.id;
        if (initial != 0) {
            press_.hold(press_.time_s()); // a resumed run that was held when saved
        }
    }
}

void PressProof::on_signal(double t, relaylogic::SignalId id, std::uint32_t /*old_value*/,
                           std::uint32_t value) {
    advance(t);
    if (interlock_ && id == *interlock_) {
        // The cabinet held or let go of its press at t, every edge due by then taken: so is
        // this copy.
        if (value != 0) {
            press_.hold(t);
        } else {
            press_.release(t);
        }
    }
}

void PressProof::on_motion(double t, const std::array<double, 5>& real) {
    advance(t);
    x_ = real[0];
    check(t);
}

void PressProof::on_card(double t, std::int64_t /*index*/, const cardreader::CardOrders& orders) {
    advance(t);
    // The cycle's first card (a sync card since every move of the cycle is synchronised).
    if (orders.number == cycle_card_) {
        ++cycle_;
    }
}

void PressProof::advance(double t) {
    // Every event of the press up to t: each detector edge and each change of its speed.
    while (press_.next_event_time() <= t) {
        const double te = press_.next_event_time();
        press_.advance_to(te);
        check(te);
    }
    if (t > press_.time_s()) {
        press_.advance_to(t);
        check(t);
    }
}

double PressProof::crossing_time(double t, double a_deg) const {
    // The press turned at one speed since the last check (every speed change is an event that
    // was checked): the crossing is where the unwrapped angle passes a_deg.
    const double theta = press_.theta_deg();
    if (theta == last_theta_) {
        return t;
    }
    double c = std::floor(last_theta_ / 360.0) * 360.0 + a_deg;
    while (c <= last_theta_) {
        c += 360.0;
    }
    return last_t_ +
           (t - last_t_) * std::clamp((c - last_theta_) / (theta - last_theta_), 0.0, 1.0);
}

void PressProof::margin(double m) {
    if (!min_margin_s_ || m < *min_margin_s_) {
        min_margin_s_ = m;
    }
}

void PressProof::check(double t) {
    const double a = press_.angle_deg();
    const double h = press_.die_height_in_at_angle(a);
    const bool inside = x_ > edge_ + 1e-9;
    const bool low = h < safe_;
    if (!started_) {
        started_ = true;
        inside_ = inside;
        low_ = low;
        last_t_ = t;
        last_theta_ = press_.theta_deg();
    }
    const std::int64_t cycle = std::max(cycle_, std::int64_t{1});
    const double c = clearance(h, safe_, edge_, x_);
    if (static_cast<std::size_t>(cycle) > per_cycle_.size()) {
        per_cycle_.resize(static_cast<std::size_t>(cycle), std::numeric_limits<double>::infinity());
    }
    double& mine = per_cycle_.at(static_cast<std::size_t>(cycle) - 1);
    mine = std::min(mine, c);
    const Instant now{cycle, t, a, x_, h, c};
    if (c < closest_.clearance_in) {
        closest_ = now;
    }
    if (c < 0 && !collision_) {
        collision_ = now;
    }
    // The time margins: the die passing the safe height, the feeder passing the zone edge.
    if (low != low_) {
        const double tc = crossing_time(t, low ? low_angles_.first : low_angles_.second);
        if (low) {
            if (inside_) {
                down_inside_ = tc;
            } else if (std::isfinite(last_exit_)) {
                margin(tc - last_exit_);
            }
        } else {
            last_up_ = tc;
            if (enter_low_) {
                margin(*enter_low_ - tc);
                enter_low_.reset();
            }
        }
    }
    if (inside != inside_) {
        if (inside) {
            entries_.push_back(t);
            if (low) {
                enter_low_ = t;
            } else if (std::isfinite(last_up_)) {
                margin(t - last_up_);
            }
        } else {
            last_exit_ = t;
            if (down_inside_) {
                margin(*down_inside_ - t);
                down_inside_.reset();
            }
        }
    }
    inside_ = inside;
    low_ = low;
    last_t_ = t;
    last_theta_ = press_.theta_deg();
}

nlohmann::json press_block(const relaylogic::RunResult& /*result*/, const PressProof& proof,
                           const decks::PressFeederJob& job) {
    nlohmann::json j;
    j["proof_cycles"] = proof.cycles();
    j["variant"] = job.variant;
    j["zone_edge_x_in"] = job.options.zone_edge_x_in;
    j["safe_height_in"] = job.options.safe_height_in;
    j["min_clearance_in"] = fine_length(proof.closest().clearance_in);
    j["min_clearance_cycle"] = proof.closest().cycle;
    j["min_time_margin_s"] =
        proof.min_margin_s() ? nlohmann::json(decimals(*proof.min_margin_s(), 4)) : nullptr;
    nlohmann::json per_cycle = nlohmann::json::array();
    for (double c : proof.cycle_clearance_in()) {
        per_cycle.push_back(fine_length(c));
    }
    j["cycle_clearance_in"] = per_cycle;
    j["collision"] = nullptr;
    if (const auto& c = proof.collision()) {
        j["collision"] = {{"cycle", c->cycle},
                          {"machine_seconds", time_s(c->t)},
                          {"crank_angle_deg", angle_deg(c->crank_deg)},
                          {"feeder_x_in", fine_length(c->feeder_x_in)},
                          {"die_height_in", fine_length(c->die_height_in)}};
    }
    return j;
}

std::string collision_message(const PressProof& proof, double safe_height_in,
                              double zone_edge_x_in) {
    const auto& c = *proof.collision();
    return fmt::format("collision in cycle {} at {:.2f} s: crank {:.1f} deg, feeder X {:.3f} in "
                       "(inside the die zone past {:.3f} in), die {:.3f} in above bottom dead "
                       "centre (safe height {:.3f} in)",
                       c.cycle, c.t, c.crank_deg, c.feeder_x_in, zone_edge_x_in, c.die_height_in,
                       safe_height_in);
}

std::string press_summary(const relaylogic::RunResult& result, const PressProof& proof) {
    std::string mean = "-";
    if (result.press && result.press->mean_cycle_s) {
        mean = fmt::format("{:.2f} s", *result.press->mean_cycle_s);
    }
    std::string margin = "-";
    if (proof.min_margin_s()) {
        margin = fmt::format("{:.2f} s", *proof.min_margin_s());
    }
    return fmt::format("  press proof    {} cycle{}, mean cycle {}; smallest clearance {:.4f} in "
                       "(cycle {}), least time margin {}; {}\n",
                       proof.cycles(), proof.cycles() == 1 ? "" : "s", mean,
                       proof.closest().clearance_in, proof.closest().cycle, margin,
                       proof.collision() ? "COLLISION" : "no collision");
}

} // namespace parsons::cli
