#include "relaylogic/conditions/monitoring_unit.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

using cardreader::PassingSense;

MonitoringUnit::MonitoringUnit(Tracer& tracer) : tracer_(tracer) {
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        std::array<std::unique_ptr<HoldingRelayBank>, 4> banks;
        for (std::size_t i = 0; i < 4; ++i) {
            static constexpr std::array<const char*, 4> kDigits = {"inches", "tenths", "hundredths",
                                                                   "thousandths"};
            banks.at(i) = std::make_unique<HoldingRelayBank>(
                tracer, "conditions", "PRG", fmt::format("monitoring_prg_{}_{}", k, kDigits.at(i)));
        }
        banks_.push_back(std::move(banks));
        sense_signal_.at(static_cast<std::size_t>(k)) = tracer.define(
            "conditions", fmt::format("monitoring_prg.channel_{}.sense", k),
            fmt::format("monitoring unit PRG, channel {}: sense relay (1 forward, 2 reverse, 3 "
                        "either)",
                        k),
            "PRG", 2);
    }
    status_ = tracer.define("conditions", "monitoring_prg.status",
                            "monitoring unit PRG: status signal to ALE, the identifier of the "
                            "condition last met (EP 0640901 claim 3)",
                            "PRG", 7);
}

void MonitoringUnit::arm(int k, const ConditionEntry& condition) {
    const auto i = static_cast<std::size_t>(k);
    const Digits d = value_digits(condition.position);
    for (std::size_t b = 0; b < 4; ++b) {
        banks_.at(i).at(b)->release_all();
        banks_.at(i).at(b)->pick(d.at(b));
    }
    sense_.at(i) = condition.sense;
    positions_.at(i) = condition.position;
    axis_.at(i) = condition.axis;
    tracer_.set(sense_signal_.at(i), condition.sense == PassingSense::forward   ? 1U
                                     : condition.sense == PassingSense::reverse ? 2U
                                                                                : 3U);
    watch_.at(cardreader::axis_index(condition.axis)) |= 1U << k;
}

void MonitoringUnit::disarm(int k) {
    const auto i = static_cast<std::size_t>(k);
    for (auto& w : watch_) {
        w &= ~(1U << k);
    }
    for (auto& bank : banks_.at(i)) {
        bank->release_all();
    }
    tracer_.set(sense_signal_.at(i), 0);
}

void MonitoringUnit::clear() {
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        disarm(k);
    }
    tracer_.set(status_, 0);
}

bool MonitoringUnit::senses(int k, int direction) const {
    const PassingSense s = sense_.at(static_cast<std::size_t>(k));
    return s == PassingSense::either || (s == PassingSense::forward) == (direction > 0);
}

unsigned MonitoringUnit::on_counter_step(cardreader::Axis axis, const Digits& counter,
                                         int direction) {
    const unsigned mask = watch_.at(cardreader::axis_index(axis));
    unsigned met = 0;
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        if ((mask >> k & 1U) == 0 || !senses(k, direction)) {
            continue;
        }
        const auto& banks = banks_.at(static_cast<std::size_t>(k));
        if (banks[0]->closed(counter[0]) && banks[1]->closed(counter[1]) &&
            banks[2]->closed(counter[2]) && banks[3]->closed(counter[3])) {
            met |= 1U << k;
        }
    }
    return met;
}

void MonitoringUnit::report(int event) {
    tracer_.set(status_, static_cast<std::uint32_t>(event));
}

nlohmann::json MonitoringUnit::save() const {
    nlohmann::json j = nlohmann::json::object();
    j["watch"] = watch_;
    nlohmann::json channels = nlohmann::json::array();
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        const auto i = static_cast<std::size_t>(k);
        channels.push_back({{"position", positions_.at(i)},
                            {"sense", static_cast<int>(sense_.at(i))},
                            {"axis", static_cast<int>(axis_.at(i))}});
    }
    j["channels"] = channels;
    return j;
}

void MonitoringUnit::load(const nlohmann::json& j) {
    using axes::member;
    using axes::read;
    clear();
    const auto watch = read<std::array<unsigned, cardreader::kAxisCount>>(j, "watch");
    const auto& channels = member(j, "channels");
    if (!channels.is_array() ||
        channels.size() != static_cast<std::size_t>(InternalBuffer::kChannels)) {
        throw axes::StateError("monitoring_prg.channels: wrong length");
    }
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        const auto& c = channels.at(static_cast<std::size_t>(k));
        const int position = read<int>(c, "position");
        const int sense = read<int>(c, "sense");
        const int axis = read<int>(c, "axis");
        if (position < 0 || position > 9999 || sense < 0 || sense > 2 || axis < 0 ||
            axis >= cardreader::kAxisCount) {
            throw axes::StateError(fmt::format("monitoring_prg.channels[{}]: out of range", k));
        }
        bool armed = false;
        for (std::size_t a = 0; a < watch.size(); ++a) {
            armed = armed || (watch.at(a) >> k & 1U) != 0;
        }
        if (armed) {
            arm(k, ConditionEntry{0, static_cast<cardreader::Axis>(axis),
                                  static_cast<cardreader::Thousandths>(position),
                                  static_cast<PassingSense>(sense)});
        }
    }
    if (watch != watch_) {
        throw axes::StateError("monitoring_prg.watch does not match its channels");
    }
}

} // namespace parsons::relaylogic
