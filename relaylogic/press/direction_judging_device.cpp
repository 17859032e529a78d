#include "relaylogic/press/direction_judging_device.hpp"

#include "axes/state_json.hpp"

namespace parsons::relaylogic {
namespace {

// The ring 00 -> 10 -> 11 -> 01 as a two-bit number a + 2b: 0, 1, 3, 2.
int ring_index(int a, int b) {
    static constexpr int kIndex[4] = {0, 1, 3, 2}; // by a + 2b
    return kIndex[a + 2 * b];
}

} // namespace

DirectionJudgingDevice::DirectionJudgingDevice(Tracer& tracer, std::int64_t count,
                                               PulseSource source)
    : tracer_(tracer), a_(axes::phases_at(count).phase_a), b_(axes::phases_at(count).phase_b) {
    if (source == PulseSource::spindle_encoder_32) {
        relay_a_ = tracer.define("spindle", "encoder_32.phase_a",
                                 "encoder 32 on motor 27, phase A (relay following it in "
                                 "interface 33; EP 0360190)",
                                 "32", 1, static_cast<std::uint32_t>(a_));
        relay_b_ = tracer.define("spindle", "encoder_32.phase_b",
                                 "encoder 32 phase B, a quarter behind A (EP 0360190)", "32", 1,
                                 static_cast<std::uint32_t>(b_));
        sense_relay_ = tracer.define("spindle", "interface_33.forward",
                                     "spindle encoder interface 33: the last edge counted up (1, "
                                     "motor forward) or down (0); device 13 of EP 0436887 reused",
                                     "33", 1, 1);
        return;
    }
    relay_a_ = tracer.define("press", "detector_10.phase_a",
                             "detector 10 phase A (relay following it; EP 0436887)", "10", 1,
                             static_cast<std::uint32_t>(a_));
    relay_b_ = tracer.define("press", "detector_10.phase_b",
                             "detector 10 phase B, a quarter behind A (EP 0436887)", "10", 1,
                             static_cast<std::uint32_t>(b_));
    sense_relay_ = tracer.define("press", "direction_judging_13.forward",
                                 "direction judging device 13: the last edge counted up "
                                 "(1) or down (0) (EP 0436887 claim 3)",
                                 "13", 1, 1);
}

void DirectionJudgingDevice::stand_at(std::int64_t count) {
    const axes::DetectorEdge e = axes::phases_at(count);
    a_ = e.phase_a;
    b_ = e.phase_b;
    tracer_.set(relay_a_, static_cast<std::uint32_t>(a_));
    tracer_.set(relay_b_, static_cast<std::uint32_t>(b_));
}

int DirectionJudgingDevice::judge(const axes::DetectorEdge& edge) {
    const int before = ring_index(a_, b_);
    const int after = ring_index(edge.phase_a, edge.phase_b);
    a_ = edge.phase_a;
    b_ = edge.phase_b;
    tracer_.set(relay_a_, static_cast<std::uint32_t>(a_));
    tracer_.set(relay_b_, static_cast<std::uint32_t>(b_));
    int sense = 0;
    if (after == (before + 1) % 4) {
        sense = +1;
    } else if (before == (after + 1) % 4) {
        sense = -1;
    }
    if (sense != 0) {
        sense_ = sense;
        tracer_.set(sense_relay_, sense > 0 ? 1U : 0U);
    }
    return sense;
}

void DirectionJudgingDevice::jump_to(std::int64_t count, int sense) {
    stand_at(count);
    sense_ = sense;
    tracer_.set(sense_relay_, sense > 0 ? 1U : 0U);
}

nlohmann::json DirectionJudgingDevice::save() const {
    return {{"a", a_}, {"b", b_}, {"sense", sense_}};
}

void DirectionJudgingDevice::load(const nlohmann::json& j) {
    a_ = axes::read<int>(j, "a") != 0 ? 1 : 0;
    b_ = axes::read<int>(j, "b") != 0 ? 1 : 0;
    sense_ = axes::read<int>(j, "sense") >= 0 ? +1 : -1;
}

} // namespace parsons::relaylogic
