#include "outputs/replay/run_timeline.hpp"

#include "axes/json_text.hpp"
#include "axes/lead_screw_axis.hpp"
#include "cardreader/layout.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/card_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <iterator>
#include <map>
#include <stdexcept>

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

// The record's header is written as text while the run goes, not built as a tree of JSON
// objects: a tree of maps for every signal and card cost more than the run they record (the
// demo deck: 14 million instructions of 23, most of the WebAssembly page's recording time).
// The text is nlohmann's own, value for value: strings escaped as its dump escapes them,
// numbers in its number text.
void put_string(std::string& out, std::string_view text) {
    out += '"';
    const auto plain = [](char c) {
        return c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20;
    };
    if (std::all_of(text.begin(), text.end(), plain)) { // every name the machine gives
        out += text;
        out += '"';
        return;
    }
    for (const char c : text) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\b':
            out += "\\b";
            break;
        case '\f':
            out += "\\f";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (plain(c)) {
                out += c;
            } else {
                out += fmt::format("\\u{:04x}", static_cast<unsigned>(c));
            }
        }
    }
    out += '"';
}

// A finite double as nlohmann writes it: the shortest text that reads back to it (fmt's, where
// nlohmann's Grisu2 now and then writes 17 digits: json_text shortens those anyway), and ".0"
// after a whole number, still a fraction to a reader that keeps integers apart.
void put_number(std::string& out, double value) {
    const std::size_t from = out.size();
    fmt::format_to(std::back_inserter(out), "{}", value);
    if (out.find_first_of(".e", from) == std::string::npos) {
        out += ".0";
    }
}

// A card's number in thousandths as inches: the shortest text of n / 1000.0 is the decimal
// itself (four digits or fewer always read back to their double), so no float formatting.
void put_inches(std::string& out, std::int64_t thousandths) {
    if (thousandths < 0) {
        out += '-';
        thousandths = -thousandths;
    }
    out += std::to_string(thousandths / 1000);
    out += '.';
    int rest = static_cast<int>(thousandths % 1000);
    if (rest == 0) {
        out += '0';
        return;
    }
    for (int place = 100; rest != 0; place /= 10) {
        out += static_cast<char>('0' + rest / place);
        rest %= place;
    }
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

RunTimeline::RunTimeline(std::size_t max_changes) {
    log_.limit = max_changes;
    // A short deck's record without a reallocation (the demo deck's is 66 000 changes).
    const std::size_t expected = std::min<std::size_t>(max_changes, 1 << 17);
    log_.t.reserve(expected);
    log_.id.reserve(expected);
    log_.value.reserve(expected);
    motion_.reserve(expected / 4 * kMotionRecord);
}

void RunTimeline::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
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
    // The tracer defines its signals in id order, once each (Tracer::attach); a record attached
    // again starts its signals again.
    if (info.id == 0) {
        signals_text_.clear();
        initial_values_.clear();
    }
    if (info.id != initial_values_.size()) {
        throw std::logic_error(
            fmt::format("signal {} defined after {} others", info.id, initial_values_.size()));
    }
    initial_values_.push_back(initial);
    // Keys in the order nlohmann's objects keep them (sorted), as the record has always had.
    std::string& out = signals_text_;
    out += signals_text_.empty() ? "[" : ",";
    out += "{\"component\":";
    put_string(out, info.component);
    out += fmt::format(",\"initial\":{},\"name\":", initial);
    put_string(out, info.name);
    out += ",\"numeral\":";
    put_string(out, info.numeral);
    out += ",\"scope\":";
    put_string(out, info.scope);
    out += fmt::format(",\"width\":{}}}", info.width);
}

// Only when the tracer does not append to change_log() itself (a fan-out of observers).
void RunTimeline::on_signal(double t, relaylogic::SignalId id, std::uint32_t /*old_value*/,
                            std::uint32_t new_value) {
    log_.append(t, id, new_value);
}

void RunTimeline::on_motion(double t, const std::array<double, 5>& real_in) {
    if (full()) {
        full_ = true;
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
    // {"axes":{...},"index":..,"kind":..,"number":..,"spindle":..,"t":..}: nlohmann's sorted
    // keys; the axes by name, so cross, swivel, table, tilt, vertical.
    std::string& out = cards_text_;
    out += cards_text_.empty() ? "[" : ",";
    out += '{';
    const char* kind = "motion";
    switch (orders.kind) {
    case cardreader::CardKind::condition:
        kind = "condition";
        break;
    case cardreader::CardKind::sync:
        kind = "sync";
        break;
    case cardreader::CardKind::tap:
        kind = "tap";
        break;
    case cardreader::CardKind::segment:
        kind = "segment";
        break;
    case cardreader::CardKind::motion: {
        // The axes in their names' order, worked out once.
        static const std::array<std::size_t, cardreader::kAxisCount> by_name = [] {
            std::array<std::size_t, cardreader::kAxisCount> order{};
            for (std::size_t i = 0; i < order.size(); ++i) {
                order[i] = i;
            }
            std::sort(order.begin(), order.end(), [](std::size_t a, std::size_t b) {
                return cardreader::axis_name(static_cast<cardreader::Axis>(a)) <
                       cardreader::axis_name(static_cast<cardreader::Axis>(b));
            });
            return order;
        }();
        out += "\"axes\":{";
        for (const std::size_t i : by_name) {
            const auto& a = orders.axes[i];
            if (i != by_name.front()) {
                out += ',';
            }
            put_string(out, cardreader::axis_name(static_cast<cardreader::Axis>(i)));
            out += ":{\"check_in\":";
            put_inches(out, a.check);
            // The numbers the card gives the absolute storage: its slow-downs, then its stop.
            out += ",\"held_in\":[";
            for (const auto& sd : a.slow_down) {
                if (sd) {
                    put_inches(out, *sd);
                    out += ',';
                }
            }
            put_inches(out, a.stop);
            out += a.motion == cardreader::Motion::forward ? "],\"motion\":\"+\",\"speed\":"
                                                           : "],\"motion\":\"-\",\"speed\":";
            out += std::to_string(a.start_speed);
            out += ",\"stop_in\":";
            put_inches(out, a.stop);
            out += '}';
        }
        out += "},";
        break;
    }
    }
    out += fmt::format("\"index\":{},\"kind\":\"{}\",\"number\":{},", index, kind, orders.number);
    if (orders.kind == cardreader::CardKind::motion) {
        out += "\"spindle\":";
        put_string(out, cardreader::spindle_name(orders.spindle));
        out += ',';
    }
    out += "\"t\":";
    put_number(out, t);
    out += '}';
}

void RunTimeline::on_brushes(double t, std::int64_t index, const cardreader::Card& card,
                             const cardreader::CardLayout& layout) {
    if (brush_wiring_text_.empty()) {
        // The same for every run on a layout: written once a layout (a thread's own, for a
        // process that runs decks on several).
        thread_local std::map<std::string, std::string> written;
        auto [at, is_new] = written.try_emplace(layout.name);
        if (is_new) {
            nlohmann::json wires = nlohmann::json::array();
            for (const relaylogic::BrushWire& w : relaylogic::brush_wiring(layout)) {
                wires.push_back({{"column", w.column},
                                 {"rows", w.rows},
                                 {"field", w.field},
                                 {"picks", w.picks}});
            }
            at->second = wires.dump();
        }
        brush_wiring_text_ = at->second;
    }
    // The holes: three hex digits a column, column 1 first, the column's Hollerith word (row 12
    // in bit 11 .. row 9 in bit 0, cardreader/card.hpp).
    std::string& out = brushes_text_;
    out += brushes_text_.empty() ? "[" : ",";
    out += "{\"holes\":\"";
    static constexpr char kHex[] = "0123456789abcdef";
    for (const cardreader::ColumnWord word : card.columns()) {
        out += kHex[(word >> 8) & 0xf];
        out += kHex[(word >> 4) & 0xf];
        out += kHex[word & 0xf];
    }
    out += fmt::format("\",\"index\":{},\"t\":", index);
    put_number(out, t);
    out += '}';
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

std::vector<std::uint32_t> RunTimeline::final_values() const {
    std::vector<std::uint32_t> values = initial_values_;
    for (std::size_t i = 0; i < log_.id.size(); ++i) {
        values.at(log_.id[i]) = log_.value[i]; // every signal is defined before any change
    }
    return values;
}

nlohmann::json RunTimeline::header() const {
    return nlohmann::json::parse(header_text());
}

std::string RunTimeline::signals_text() const {
    return signals_text_.empty() ? "[]" : signals_text_ + "]";
}

std::string RunTimeline::cards_text() const {
    return cards_text_.empty() ? "[]" : cards_text_ + "]";
}

std::string RunTimeline::record_texts() const {
    return "\"cards\":" + cards_text() +
           ",\"brushes\":" + (brushes_text_.empty() ? "[]" : brushes_text_ + "]") +
           ",\"brush_wiring\":" + (brush_wiring_text_.empty() ? "[]" : brush_wiring_text_) + ",";
}

nlohmann::json RunTimeline::header_fields() const {
    nlohmann::json axes = nlohmann::json::array();
    for (std::size_t i = 0; i < cardreader::kAxisCount; ++i) {
        axes.push_back(cardreader::axis_name(static_cast<cardreader::Axis>(i)));
    }
    nlohmann::json rest = {{"axes", std::move(axes)},
                           {"signals_signature", fmt::format("{:016x}", signals_hash_)},
                           {"conditions", conditions_},
                           {"stop", stop_},
                           {"design", design_},
                           {"finish", finish_},
                           {"final_values", final_values()},
                           {"changes", log_.t.size()},
                           {"motion_records", motion_.size() / kMotionRecord},
                           {"truncated", full_ || log_.truncated}};
    return rest;
}

std::string RunTimeline::page_header_text() const {
    std::string text =
        header_fields().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    text.replace(0, 1, "{" + record_texts());
    return text;
}

std::string RunTimeline::header_text(bool with_signals) const {
    // {"signals":[...],"cards":[...], then the rest's keys (the cards' numbers are already
    // nlohmann's; json_text shortens them as it shortens the rest's).
    std::string text = axes::json_text(header_fields());
    text.replace(0, 1,
                 (with_signals ? "{\"signals\":" + signals_text() + "," : std::string("{")) +
                     axes::shortest_numbers(record_texts()));
    return text;
}

std::string RunTimeline::embedded_json() const {
    const std::string packed = packed_record(log_.t, log_.id, log_.value, motion_);
    const nlohmann::json arrays = {
        {"encoding", "xor1"},
        {"packed", base64(reinterpret_cast<const unsigned char*>(packed.data()), packed.size())}};
    std::string text = header_text();
    text.replace(text.size() - 1, 1, ",\"arrays\":" + arrays.dump() + "}");
    return text;
}

} // namespace parsons::cli
