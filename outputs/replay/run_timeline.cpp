#include "outputs/replay/run_timeline.hpp"

#include "axes/json_text.hpp"
#include "axes/lead_screw_axis.hpp"
#include "cardreader/orders.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace parsons::cli {

namespace {

// The packed record (`run --html`): the arrays written exactly, a few bytes a number, so the
// demo deck's page stays under 1 MB (raw typed arrays made it 2.3 MB). The viewer's unpack()
// (web/viewer.js) reads it back bit for bit. Layout, in order:
//   signal ids: zigzag varint of the difference from the previous id (ids cluster by axis);
//   new values: varint;
//   times, then each of the motion record's eight columns: the number's bits XORed with the
//   previous number's of the same column (0 before the first), written as its low nonzero
//   bytes, little-endian; how many (0..8) is a nibble, two a byte, all nibbles before the bytes.
// A repeated number (most times repeat: several relays move at one instant; the angles and
// idle axes rarely change) costs half a byte; a changed one its differing low bytes.
void put_varint(std::string& out, std::uint64_t n) {
    while (n >= 0x80) {
        out += static_cast<char>((n & 0x7f) | 0x80);
        n >>= 7;
    }
    out += static_cast<char>(n);
}

// `count` doubles, from `values` every `stride`th from `first`.
void put_xor_column(std::string& out, const std::vector<double>& values, std::size_t first,
                    std::size_t stride, std::size_t count) {
    std::string nibbles((count + 1) / 2, '\0');
    std::string bytes;
    std::uint64_t previous = 0;
    for (std::size_t i = 0; i < count; ++i) {
        // memcpy, not std::bit_cast: the WebAssembly build's libc++ (emscripten 3.1.6) has none.
        std::uint64_t bits = 0;
        std::memcpy(&bits, &values[first + i * stride], sizeof bits);
        std::uint64_t x = bits ^ previous;
        previous = bits;
        unsigned n = 0;
        for (; x != 0; x >>= 8, ++n) {
            bytes += static_cast<char>(x & 0xff);
        }
        nibbles[i / 2] =
            static_cast<char>(static_cast<unsigned char>(nibbles[i / 2]) | (n << ((i % 2) * 4)));
    }
    out += nibbles;
    out += bytes;
}

} // namespace

std::string packed_record(const std::vector<double>& change_t,
                          const std::vector<std::uint32_t>& change_id,
                          const std::vector<std::uint32_t>& change_v,
                          const std::vector<double>& motion) {
    std::string out;
    std::int64_t previous_id = 0;
    for (const std::uint32_t id : change_id) {
        const std::int64_t d = static_cast<std::int64_t>(id) - previous_id;
        previous_id = id;
        put_varint(out, d >= 0 ? static_cast<std::uint64_t>(d) << 1
                               : (static_cast<std::uint64_t>(-d) << 1) - 1);
    }
    for (const std::uint32_t v : change_v) {
        put_varint(out, v);
    }
    put_xor_column(out, change_t, 0, 1, change_t.size());
    const std::size_t records = motion.size() / RunTimeline::kMotionRecord;
    for (std::size_t c = 0; c < RunTimeline::kMotionRecord; ++c) {
        put_xor_column(out, motion, c, RunTimeline::kMotionRecord, records);
    }
    return out;
}

std::string base64(const unsigned char* data, std::size_t size) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 3 <= size; i += 3) {
        const std::uint32_t n =
            (std::uint32_t{data[i]} << 16) | (std::uint32_t{data[i + 1]} << 8) | data[i + 2];
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += kDigits[(n >> 6) & 63];
        out += kDigits[n & 63];
    }
    if (const std::size_t rest = size - i; rest > 0) {
        std::uint32_t n = std::uint32_t{data[i]} << 16;
        if (rest == 2) {
            n |= std::uint32_t{data[i + 1]} << 8;
        }
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += rest == 2 ? kDigits[(n >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

RunTimeline::RunTimeline(std::size_t max_changes) : max_changes_(max_changes) {
    // A short deck's record without a reallocation (the demo deck's is 66 000 changes).
    const std::size_t expected = std::min<std::size_t>(max_changes, 1 << 17);
    change_t_.reserve(expected);
    change_id_.reserve(expected);
    change_v_.reserve(expected);
    motion_.reserve(expected / 4 * kMotionRecord);
}

void RunTimeline::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
    signals_text_.clear();
    const auto mix = [this](std::string_view text) {
        for (const char c : text) {
            signals_hash_ = (signals_hash_ ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
        }
        signals_hash_ = (signals_hash_ ^ 0xffU) * 0x100000001b3ULL; // a separator
    };
    mix(std::to_string(info.id));
    mix(info.scope);
    mix(info.name);
    mix(info.component);
    mix(info.numeral);
    mix(std::to_string(info.width));
    mix(std::to_string(initial));
    if (signals_.size() <= info.id) {
        signals_.get_ref<nlohmann::json::array_t&>().resize(info.id + 1);
        last_values_.resize(info.id + 1);
    }
    last_values_[info.id] = initial;
    signals_[info.id] = {{"scope", info.scope},         {"name", info.name},
                         {"component", info.component}, {"numeral", info.numeral},
                         {"width", info.width},         {"initial", initial}};
}

void RunTimeline::on_signal(double t, relaylogic::SignalId id, std::uint32_t /*old_value*/,
                            std::uint32_t new_value) {
    if (full()) {
        truncated_ = true;
        return;
    }
    change_t_.push_back(t);
    change_id_.push_back(id);
    change_v_.push_back(new_value);
    last_values_[id] = new_value; // defined before any change
}

void RunTimeline::on_motion(double t, const std::array<double, 5>& real_in) {
    if (full()) {
        truncated_ = true;
        return;
    }
    motion_.push_back(t);
    motion_.insert(motion_.end(), real_in.begin(), real_in.end());
    // The angles again only when their screw has moved: most impulses are the other axes'.
    const auto swivel = cardreader::axis_index(cardreader::Axis::swivel);
    const auto tilt = cardreader::axis_index(cardreader::Axis::tilt);
    if (!angles_known_ || real_in[swivel] != angle_screws_[0]) {
        angles_[0] = axes::fixture_angle_deg(profile_.axes[swivel], real_in[swivel], false);
        angle_screws_[0] = real_in[swivel];
    }
    if (!angles_known_ || real_in[tilt] != angle_screws_[1]) {
        angles_[1] = axes::fixture_angle_deg(profile_.axes[tilt], real_in[tilt], true);
        angle_screws_[1] = real_in[tilt];
    }
    angles_known_ = true;
    motion_.insert(motion_.end(), angles_.begin(), angles_.end());
}

void RunTimeline::on_run_start(double t, const std::array<double, 5>& real_in) {
    on_motion(t, real_in); // every instant of the replay then has a motion record at or before it
}

void RunTimeline::on_card(double t, std::int64_t index, const cardreader::CardOrders& orders) {
    nlohmann::json card = {{"t", t}, {"index", index}, {"number", orders.number}};
    switch (orders.kind) {
    case cardreader::CardKind::condition:
        card["kind"] = "condition";
        break;
    case cardreader::CardKind::sync:
        card["kind"] = "sync";
        break;
    case cardreader::CardKind::tap:
        card["kind"] = "tap";
        break;
    case cardreader::CardKind::motion: {
        card["kind"] = "motion";
        card["spindle"] = cardreader::spindle_name(orders.spindle);
        nlohmann::json axes = nlohmann::json::object();
        for (std::size_t i = 0; i < cardreader::kAxisCount; ++i) {
            const auto& a = orders.axes[i];
            // The numbers the card gives the absolute storage: its slow-downs, then its stop.
            nlohmann::json held = nlohmann::json::array();
            for (const auto& sd : a.slow_down) {
                if (sd) {
                    held.push_back(static_cast<double>(*sd) / 1000.0);
                }
            }
            held.push_back(static_cast<double>(a.stop) / 1000.0);
            axes[std::string(cardreader::axis_name(static_cast<cardreader::Axis>(i)))] = {
                {"motion", a.motion == cardreader::Motion::forward ? "+" : "-"},
                {"speed", a.start_speed},
                {"stop_in", static_cast<double>(a.stop) / 1000.0},
                {"held_in", std::move(held)},
                {"check_in", static_cast<double>(a.check) / 1000.0}};
        }
        card["axes"] = std::move(axes);
        break;
    }
    }
    cards_.push_back(std::move(card));
}

void RunTimeline::on_stop(double t, const relaylogic::StopInfo& stop) {
    stop_ = {{"t", t},
             {"reason", relaylogic::stop_reason_name(stop.reason)},
             {"card", stop.card},
             {"card_number", stop.card_number},
             {"message", stop.message},
             {"lamps", stop.lamps}};
    if (stop.axis) {
        stop_["axis"] = cardreader::axis_name(*stop.axis);
    }
}

void RunTimeline::on_condition(double t, const relaylogic::ConditionEvent& event) {
    conditions_.push_back({{"t", t},
                           {"kind", relaylogic::condition_event_name(event.kind)},
                           {"event", event.event},
                           {"card", event.card},
                           {"axis", cardreader::axis_name(event.axis)}});
}

void RunTimeline::on_finish(double t) {
    finish_ = t;
}

nlohmann::json RunTimeline::header() const {
    return nlohmann::json::parse(header_text());
}

std::string RunTimeline::signals_text() const {
    if (signals_text_.empty()) {
        signals_text_ = axes::json_text(signals_);
    }
    return signals_text_;
}

nlohmann::json RunTimeline::header_fields() const {
    nlohmann::json axes = nlohmann::json::array();
    for (std::size_t i = 0; i < cardreader::kAxisCount; ++i) {
        axes.push_back(cardreader::axis_name(static_cast<cardreader::Axis>(i)));
    }
    nlohmann::json rest = {{"axes", std::move(axes)},
                           {"signals_signature", fmt::format("{:016x}", signals_hash_)},
                           {"cards", cards_},
                           {"conditions", conditions_},
                           {"stop", stop_},
                           {"design", design_},
                           {"finish", finish_},
                           {"final_values", last_values_},
                           {"changes", change_t_.size()},
                           {"motion_records", motion_.size() / kMotionRecord},
                           {"truncated", truncated_}};
    return rest;
}

std::string RunTimeline::page_header_text() const {
    return header_fields().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string RunTimeline::header_text(bool with_signals) const {
    std::string text = axes::json_text(header_fields());
    if (with_signals) { // {"signals":[...], then the rest's keys
        text.replace(0, 1, "{\"signals\":" + signals_text() + ",");
    }
    return text;
}

std::string RunTimeline::embedded_json() const {
    const std::string packed = packed_record(change_t_, change_id_, change_v_, motion_);
    const nlohmann::json arrays = {
        {"encoding", "xor1"},
        {"packed", base64(reinterpret_cast<const unsigned char*>(packed.data()), packed.size())}};
    std::string text = header_text();
    text.replace(text.size() - 1, 1, ",\"arrays\":" + arrays.dump() + "}");
    return text;
}

} // namespace parsons::cli
