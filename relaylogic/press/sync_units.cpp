#include "relaylogic/press/sync_units.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

void SyncUnits::install(Tracer& tracer, const axes::MachineProfile& profile) {
    if (!profile.press_sync) {
        return;
    }
    tracer_ = &tracer;
    press_ = std::make_unique<axes::Press>(profile.press);
    // Every signal starts where the press stands when the run starts.
    crank_21_ = tracer.define("press", "crank_21.angle",
                              "crank 21 of the press: angle from top dead centre, tenths of a "
                              "degree (EP 0436887 Fig. 2A)",
                              "21", 12, crank_tenths());
    die_20_ = tracer.define("press", "die_20.height",
                            "die 20: height above bottom dead centre, thousandths of an inch "
                            "(Fig. 2B)",
                            "20", 16, die_thousandths());
    motor_22_ = tracer.define("press", "motor_22.running",
                              "motor 22 turns the crank (the control does not drive it)", "22", 1,
                              press_->stopped() ? 0U : 1U);
    device_13_ = std::make_unique<DirectionJudgingDevice>(tracer, press_->count());
    // Lined up with top dead centre before the run (switch 16A at the top, then the crank
    // turned to its start): the register reads the crank's angle.
    const std::int64_t d16 = std::int64_t{360} * profile.press.pulses_per_degree;
    register_14_ = std::make_unique<PositionRegister>(
        tracer, static_cast<int>(d16), static_cast<int>(((press_->count() % d16) + d16) % d16));
    register_11_ = std::make_unique<SpeedRegister>(tracer);
    speed_11_ = tracer.define("press", "speed_register_11.speed",
                              "speed register 11: the crank's speed it reads at each reference "
                              "block, its pulses timed edge to edge, hundredths of a pulse a "
                              "second",
                              "11", 20);
    scp_ = std::make_unique<SynchronisationProcessor>(tracer, profile);
    if (profile.press.feeder_hold_lag_in > 0) {
        interlock_ = std::make_unique<FeederInterlock>(tracer, profile.press.feeder_hold_lag_in);
    }
}

std::uint32_t SyncUnits::crank_tenths() const {
    return static_cast<std::uint32_t>(std::lround(press_->angle_deg() * 10)) % 3600U;
}

std::uint32_t SyncUnits::die_thousandths() const {
    return static_cast<std::uint32_t>(std::lround(press_->die_height_in() * 1000));
}

bool SyncUnits::on_edge(const axes::DetectorEdge& edge, double t) {
    last_edge_s_ = t;
    const int sense = device_13_->judge(edge);
    register_14_->count(sense);
    if (sense != 0) {
        register_11_->pulse();
        if (first_edge_s_ < 0) {
            first_edge_s_ = t;
        }
    }
    if (tracer_->observer() != nullptr) {
        show_press();
    }
    return scp_->detector_61(register_14_->value());
}

void SyncUnits::on_edges(std::int64_t n, const axes::DetectorEdge& last, double first_t, double t) {
    if (n <= 0) {
        return;
    }
    last_edge_s_ = t;
    if (first_edge_s_ < 0) {
        first_edge_s_ = first_t;
    }
    const int sense = press_->speed_deg_per_s() < 0 ? -1 : +1;
    device_13_->jump_to(last.count, sense);
    register_14_->count_many(n, sense);
    register_11_->count_many(n);
    if (tracer_->observer() != nullptr) {
        show_press();
    }
}

double SyncUnits::sample_speed(double t) {
    register_14_->release_16A();
    register_11_->sample();
    const int n = register_11_->stored();
    if (n > 0) {
        if (sampled_edge_s_ >= 0 && last_edge_s_ > sampled_edge_s_) {
            rate_ = n / (last_edge_s_ - sampled_edge_s_);
            turning_ = true;
        } else if (n >= 2 && last_edge_s_ > first_edge_s_) {
            rate_ = (n - 1) / (last_edge_s_ - first_edge_s_); // the first pulses ever timed
            turning_ = true;
        }
        sampled_edge_s_ = last_edge_s_;
    } else if (sampled_edge_s_ >= 0 && t > last_edge_s_ && rate_ > 1.0 / (t - last_edge_s_)) {
        rate_ = 1.0 / (t - last_edge_s_); // slower than one pulse since the last
        turning_ = false;
    }
    tracer_->set(speed_11_, static_cast<std::uint32_t>(std::lround(rate_ * 100.0)));
    return rate_;
}

std::int64_t SyncUnits::quiet_edges(std::int64_t limit) const {
    if (!scp_->holding()) {
        return limit;
    }
    // The edge that brings register 14 onto R makes 61 conduct: every edge before it is quiet.
    const std::int64_t d = register_14_->device_16();
    const std::int64_t v = register_14_->value();
    const std::int64_t target = scp_->target_pulses();
    const std::int64_t ahead =
        press_->speed_deg_per_s() < 0 ? ((v - target) % d + d) % d : ((target - v) % d + d) % d;
    const std::int64_t to_target = ahead == 0 ? d : ahead;
    return std::min(limit, to_target - 1);
}

void SyncUnits::show_press() {
    tracer_->set(crank_21_, crank_tenths());
    tracer_->set(die_20_, die_thousandths());
    tracer_->set(motor_22_, press_->stopped() ? 0U : 1U);
}

nlohmann::json SyncUnits::save() const {
    nlohmann::json j = {{"press", press_->save()},
                        {"direction_judging_13", device_13_->save()},
                        {"position_register_14", register_14_->save()},
                        {"speed_register_11", register_11_->save()},
                        {"synchronisation_processor_17", scp_->save()},
                        {"last_edge_s", axes::exact(last_edge_s_)},
                        {"speed_timer",
                         {{"first_edge_s", axes::exact(first_edge_s_)},
                          {"sampled_edge_s", axes::exact(sampled_edge_s_)},
                          {"rate", axes::exact(rate_)},
                          {"turning", turning_}}}};
    if (interlock_) {
        j["feeder_interlock"] = interlock_->save();
    }
    return j;
}

void SyncUnits::load(const nlohmann::json& j) {
    press_->load(axes::member(j, "press"));
    device_13_->load(axes::member(j, "direction_judging_13"));
    register_14_->load(axes::member(j, "position_register_14"));
    register_11_->load(axes::member(j, "speed_register_11"));
    scp_->load(axes::member(j, "synchronisation_processor_17"));
    last_edge_s_ = axes::exact(axes::member(j, "last_edge_s"));
    const nlohmann::json& timer = axes::member(j, "speed_timer");
    first_edge_s_ = axes::exact(axes::member(timer, "first_edge_s"));
    sampled_edge_s_ = axes::exact(axes::member(timer, "sampled_edge_s"));
    rate_ = axes::exact(axes::member(timer, "rate"));
    turning_ = axes::read<bool>(timer, "turning");
    if (interlock_) {
        interlock_->load(axes::member(j, "feeder_interlock"));
    } else if (j.contains("feeder_interlock")) {
        throw axes::StateError("the saved press has a feeder interlock; this profile has none "
                               "(press.feeder_hold_lag_in 0)");
    }
}

} // namespace parsons::relaylogic
