// Gear ratio data memory 12a of EP 0360190 (Mitsubishi) and the NC's operation I
// (Fig. 4, right column). An addition (docs/design-rules.md rule 14), after Mitsubishi's patent.
//
// The NC takes one step a scan, after PC 130's scan in the same instant, so it reads the bus as
// the PC just left it. Its step (traced as nc10.operation_i):
//
//   step  entered when                          does
//   0     idle, or the PC dropped its request   ready and received drop, buffer 9 empties,
//                                               request_since -1
//   11    a request is on the bus (S11)         request_since = this scan's time
//   12    the scan after S11 (S12)              "ready to receive?" (always yes here)
//   13    the scan after S12 (S13)              nc_ready up
//   14    data_valid on the bus (S14)           the data lines' ratio into interface 9's buffer
//   15    the scan after S14 (S15)              nc_received up
//   16    the scan after S15 (S16)              buffer -> 12a, ++received, request_since -1
//
// At steps 11-15 a request that has gone sends the NC idle (the data, if any, is dropped: the
// PC withdrew). Step 16 is entered whatever the bus shows (the PC drops its request at the scan
// it sees received, the same instant as S16); the next scan the NC sees the request gone and
// goes idle. Hence the NC's ready and received stand a scan after the PC's tool ready, which is
// why PC 130's busy() counts them.
//
// Second embodiment: select(T) is the NC's S31-S33 (Fig. 7): the ratio stored for T (the
// profile's heads, memory 12a's parameters of Fig. 6) into use.
//
// Emulation note: the NC is a computer; it is built here as the cabinet builds everything, the
// memory a bank of holding relays for the ratio's digits (traced in millionths), the steps a
// stepping switch.
#include "relaylogic/tapping/gear_ratio_memory.hpp"

#include "axes/state_json.hpp"

#include <cmath>

namespace parsons::relaylogic {
namespace {

bool valid_step(int step) {
    return step == 0 || (step >= 11 && step <= 16);
}

} // namespace

GearRatioMemory::GearRatioMemory(Tracer& tracer, const axes::SpindleSyncProfile& profile)
    : tracer_(tracer), profile_(profile) {
    const axes::SpindleHead* first = profile_.head(profile_.first_tool);
    ratio_ = first != nullptr ? first->ratio : 0.0;
    ratio_signal_ = tracer.define("spindle", "memory_12a.ratio",
                                  "gear ratio data memory 12a: the ratio A the NC computes the "
                                  "tool's speed with (S x A), millionths",
                                  "12a", 24, ratio_millionths(ratio_));
    buffer_signal_ = tracer.define("spindle", "interface_9.buffer",
                                   "interface 9's buffer memory: the ratio read from bus 35 "
                                   "(S14), millionths (0 = empty)",
                                   "9", 24);
    ready_signal_ = tracer.define("spindle", "bus35.nc_ready",
                                  "bus 35: the NC's preparation completion (S13)", "35", 1);
    received_signal_ = tracer.define("spindle", "bus35.nc_received",
                                     "bus 35: the NC's data reception completion (S15)", "35", 1);
    step_signal_ =
        tracer.define("spindle", "nc10.operation_i",
                      "NC 10: the step of operation I it stands at (S11-S16; 0 idle)", "10", 5);
}

void GearRatioMemory::idle() {
    step_ = 0;
    buffer_.reset();
    request_since_s_ = -1;
}

void GearRatioMemory::scan(double t, Bus35& bus) {
    switch (step_) {
    case 0:
        if (bus.transfer_request) {
            step_ = 11; // S11
            request_since_s_ = t;
        }
        break;
    case 11:
        if (!bus.transfer_request) {
            idle();
        } else {
            step_ = 12; // S12: ready to receive
        }
        break;
    case 12:
        if (!bus.transfer_request) {
            idle();
        } else {
            step_ = 13; // S13
            bus.nc_ready = true;
        }
        break;
    case 13:
        if (!bus.transfer_request) {
            idle();
        } else if (bus.data_valid) {
            step_ = 14; // S14
            buffer_ = bus.data_ratio;
        }
        break;
    case 14:
        if (!bus.transfer_request) {
            idle();
        } else {
            step_ = 15; // S15
            bus.nc_received = true;
        }
        break;
    case 15:
        step_ = 16; // S16
        ratio_ = buffer_.value_or(ratio_);
        ++received_;
        request_since_s_ = -1;
        break;
    default: // 16
        if (!bus.transfer_request) {
            idle();
        }
        break;
    }
    if (step_ == 0) {
        bus.nc_ready = false;
        bus.nc_received = false;
    }
    tracer_.set(step_signal_, static_cast<std::uint32_t>(step_));
    tracer_.set(ready_signal_, bus.nc_ready ? 1U : 0U);
    tracer_.set(received_signal_, bus.nc_received ? 1U : 0U);
    tracer_.set(buffer_signal_, ratio_millionths(buffer_.value_or(0.0)));
    tracer_.set(ratio_signal_, ratio_millionths(ratio_));
}

bool GearRatioMemory::select(int tool) {
    const axes::SpindleHead* h = profile_.head(tool);
    if (h == nullptr) {
        return false;
    }
    ratio_ = h->ratio;
    tracer_.set(ratio_signal_, ratio_millionths(ratio_));
    return true;
}

nlohmann::json GearRatioMemory::save() const {
    return {{"ratio", axes::exact(ratio_)},
            {"buffer", buffer_ ? axes::exact(*buffer_) : nlohmann::json(nullptr)},
            {"request_since_s", axes::exact(request_since_s_)},
            {"received", received_},
            {"step", step_}};
}

void GearRatioMemory::load(const nlohmann::json& j) {
    const int step = axes::read<int>(j, "step");
    if (!valid_step(step)) {
        throw axes::StateError("memory_12a: step is not 0 or 11 .. 16");
    }
    const nlohmann::json& buffer = axes::member(j, "buffer");
    if (buffer.is_null() == (step >= 14)) {
        throw axes::StateError("memory_12a: the buffer is full exactly from S14 on");
    }
    ratio_ = axes::exact(axes::member(j, "ratio"));
    buffer_.reset();
    if (!buffer.is_null()) {
        buffer_ = axes::exact(buffer);
    }
    request_since_s_ = axes::exact(axes::member(j, "request_since_s"));
    received_ = axes::read<std::int64_t>(j, "received");
    step_ = step;
}

} // namespace parsons::relaylogic
