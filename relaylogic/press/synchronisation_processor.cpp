#include "relaylogic/press/synchronisation_processor.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

using cardreader::axis_name;

SynchronisationProcessor::SynchronisationProcessor(Tracer& tracer, int pulses_per_degree,
                                                   double block_s)
    : tracer_(tracer), ppd_(pulses_per_degree), block_s_(block_s) {
    sync_card_ =
        tracer.define("press", "synchronisation_processor_17.sync_card",
                      "a sync card's orders wait for their motion card (EP 0436887)", "17", 1);
    angle_60_ = tracer.define("press", "position_reader_60.angle",
                              "programmed position reader 60: the angle R in detector pulses "
                              "(0 = no position synchronisation)",
                              "60", 14);
    hold_60_ = tracer.define("press", "position_reader_60.hold",
                             "programmed position reader 60's hold relay: the card's motion "
                             "waits for the crank",
                             "60", 1);
    detector_61_ = tracer.define("press", "sync_position_detector_61",
                                 "synchronisation position detector 61: register 14 stands "
                                 "on R",
                                 "61", 1);
    for (cardreader::Axis a : cardreader::kAxes) {
        const std::string axis(axis_name(a));
        feed_62_.at(cardreader::axis_index(a)) =
            tracer.define("press", "feed_speed_reader_62." + axis,
                          "programmed feed speed reader 62: the " + axis +
                              " travel per pulse F, 0.00001 in (0 = not speed-synchronised)",
                          "62", 17);
        output_63_.at(cardreader::axis_index(a)) =
            tracer.define("press", "processor_63." + axis,
                          "processor 63: the " + axis +
                              " speed sent to the drive, thousandths of an inch a minute",
                          "63", 20);
    }
}

void SynchronisationProcessor::take(const cardreader::SyncOrder& order, std::int64_t card,
                                    int number) {
    pending_ = order;
    pending_card_ = card;
    pending_number_ = number;
    tracer_.set(sync_card_, 1);
}

void SynchronisationProcessor::arm() {
    if (!pending_) {
        return;
    }
    if (pending_->position_sync) {
        target_ = pending_->angle_deg * ppd_;
    }
    feed_ = pending_->travel_per_pulse;
    pending_.reset();
    tracer_.set(sync_card_, 0);
    show();
}

void SynchronisationProcessor::clear() {
    target_.reset();
    holding_ = false;
    feed_ = {};
    next_ = {};
    output_ = {};
    tracer_.set(detector_61_, 0);
    show();
}

bool SynchronisationProcessor::any_speed_synced() const {
    return std::any_of(feed_.begin(), feed_.end(), [](const auto& f) { return f.has_value(); });
}

bool SynchronisationProcessor::hold_unless_at(int register_value, double t) {
    if (!target_) {
        return false;
    }
    if (register_value == *target_) {
        tracer_.set(detector_61_, 1);
        return false;
    }
    holding_ = true;
    hold_since_ = t;
    tracer_.set(hold_60_, 1);
    return true;
}

bool SynchronisationProcessor::detector_61(int register_value) {
    if (!holding_ || register_value != *target_) {
        return false;
    }
    tracer_.set(detector_61_, 1);
    return true;
}

void SynchronisationProcessor::release() {
    holding_ = false;
    tracer_.set(hold_60_, 0);
}

bool SynchronisationProcessor::reference_block(int pulses, double max_in_per_s) {
    bool changed = false;
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        if (output_.at(i) != next_.at(i)) {
            output_.at(i) = next_.at(i);
            changed = true;
        }
        // F (1e-5 in a pulse) x pulses in the interval / the interval, at most the drive's.
        next_.at(i) = feed_.at(i)
                          ? std::min(max_in_per_s,
                                     *feed_.at(i) * 1e-5 * static_cast<double>(pulses) / block_s_)
                          : 0.0;
    }
    show();
    return changed;
}

void SynchronisationProcessor::show() {
    if (tracer_.observer() == nullptr) {
        return; // nobody watches: the values need not be worked out (they change at every edge)
    }
    tracer_.set(angle_60_, static_cast<std::uint32_t>(target_.value_or(0)));
    tracer_.set(hold_60_, holding_ ? 1U : 0U);
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        tracer_.set(feed_62_.at(i), static_cast<std::uint32_t>(feed_.at(i).value_or(0)));
        tracer_.set(output_63_.at(i),
                    static_cast<std::uint32_t>(std::lround(output_.at(i) * 60000.0)));
    }
}

namespace {

nlohmann::json optional_int(const std::optional<int>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

std::optional<int> read_optional(const nlohmann::json& j) {
    if (j.is_null()) {
        return std::nullopt;
    }
    if (!j.is_number_integer()) {
        throw axes::StateError("synchronisation_processor_17: expected an integer or null");
    }
    return j.get<int>();
}

} // namespace

nlohmann::json SynchronisationProcessor::save() const {
    nlohmann::json feeds = nlohmann::json::array();
    nlohmann::json next = nlohmann::json::array();
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        feeds.push_back(optional_int(feed_.at(i)));
        next.push_back(axes::exact(next_.at(i)));
        out.push_back(axes::exact(output_.at(i)));
    }
    nlohmann::json pending = nullptr;
    if (pending_) {
        nlohmann::json f = nlohmann::json::array();
        for (const auto& v : pending_->travel_per_pulse) {
            f.push_back(optional_int(v));
        }
        pending = {{"position_sync", pending_->position_sync},
                   {"angle_deg", pending_->angle_deg},
                   {"travel_per_pulse", f},
                   {"card", pending_card_},
                   {"number", pending_number_}};
    }
    return {{"pending", pending},  {"target", optional_int(target_)},
            {"holding", holding_}, {"hold_since", axes::exact(hold_since_)},
            {"feed", feeds},       {"next", next},
            {"output", out}};
}

void SynchronisationProcessor::load(const nlohmann::json& j) {
    const nlohmann::json& p = axes::member(j, "pending");
    pending_.reset();
    if (!p.is_null()) {
        cardreader::SyncOrder o;
        o.position_sync = axes::read<bool>(p, "position_sync");
        o.angle_deg = axes::read<int>(p, "angle_deg");
        const auto& f = axes::member(p, "travel_per_pulse");
        for (std::size_t i = 0; i < o.travel_per_pulse.size() && i < f.size(); ++i) {
            o.travel_per_pulse.at(i) = read_optional(f.at(i));
        }
        pending_ = o;
        pending_card_ = axes::read<std::int64_t>(p, "card");
        pending_number_ = axes::read<int>(p, "number");
    }
    target_ = read_optional(axes::member(j, "target"));
    holding_ = axes::read<bool>(j, "holding");
    hold_since_ = axes::exact(axes::member(j, "hold_since"));
    const auto& feeds = axes::member(j, "feed");
    const auto& next = axes::member(j, "next");
    const auto& out = axes::member(j, "output");
    if (!feeds.is_array() || feeds.size() != feed_.size() || !next.is_array() ||
        next.size() != feed_.size() || !out.is_array() || out.size() != feed_.size()) {
        throw axes::StateError("synchronisation_processor_17: five feeds, next and output");
    }
    for (std::size_t i = 0; i < feed_.size(); ++i) {
        feed_.at(i) = read_optional(feeds.at(i));
        next_.at(i) = axes::exact(next.at(i));
        output_.at(i) = axes::exact(out.at(i));
    }
}

} // namespace parsons::relaylogic
