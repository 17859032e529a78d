#include "outputs/traces/trace_outputs.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <ostream>
#include <set>

namespace parsons::cli {

using relaylogic::SignalId;
using relaylogic::SignalInfo;

// ---------------------------------------------------------------------------------------------
// OutputBuffer

OutputBuffer::OutputBuffer(std::ostream& out, std::size_t capacity)
    : out_(out), data_(std::max<std::size_t>(capacity, 256)) {}

OutputBuffer::~OutputBuffer() {
    try {
        flush();
    } catch (...) { // NOLINT(bugprone-empty-catch): a destructor must not throw
    }
}

void OutputBuffer::drain(std::size_t need) {
    out_.write(data_.data(), static_cast<std::streamsize>(size_));
    size_ = 0;
    if (need > data_.size()) {
        data_.resize(need);
    }
}

void OutputBuffer::put(std::string_view s) {
    char* p = claim(s.size());
    std::memcpy(p, s.data(), s.size());
    size_ += s.size();
}

void OutputBuffer::put_uint(std::uint64_t v) {
    constexpr std::size_t kMax = 24;
    char* p = claim(kMax);
    commit(std::to_chars(p, p + kMax, v).ptr);
}

void OutputBuffer::put_int(std::int64_t v) {
    constexpr std::size_t kMax = 24;
    char* p = claim(kMax);
    commit(std::to_chars(p, p + kMax, v).ptr);
}

void OutputBuffer::put_fixed(double v, int decimals) {
    static constexpr std::array<double, 10> kHalfUnit = {0.5,  0.05, 0.005, 5e-4, 5e-5,
                                                         5e-6, 5e-7, 5e-8,  5e-9, 5e-10};
    if (decimals >= 0 && decimals < 10 && std::fabs(v) < kHalfUnit.at(decimals)) {
        v = 0.0; // never "-0.00000"
    }
    constexpr std::size_t kMax = 64;
    char* p = claim(kMax);
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    auto r = std::to_chars(p, p + kMax, v, std::chars_format::fixed, decimals);
    if (r.ec != std::errc{}) {
        r = std::to_chars(p, p + kMax, v, std::chars_format::general, 17);
    }
    commit(r.ptr);
#else
    // No floating-point to_chars (the WebAssembly build's libc++): fmt rounds the same, exactly.
    auto r = fmt::format_to_n(p, kMax, "{:.{}f}", v, decimals);
    if (r.size > kMax) {
        r = fmt::format_to_n(p, kMax, "{:.17g}", v);
    }
    commit(r.out);
#endif
}

void OutputBuffer::flush() {
    drain(0);
    out_.flush();
}

// ---------------------------------------------------------------------------------------------
// Names

std::string vcd_reference_name(std::string_view name) {
    std::string out(name);
    for (char& c : out) {
        const bool ok =
            (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
        if (!ok) {
            c = '_';
        }
    }
    if (out.empty()) {
        out = "_";
    }
    return out;
}

std::string vcd_identifier_code(std::size_t n) {
    constexpr std::size_t kFirst = 33; // '!'
    constexpr std::size_t kRadix = 94; // '!' .. '~'
    std::string code;
    while (true) {
        code.push_back(static_cast<char>(kFirst + n % kRadix));
        n /= kRadix;
        if (n == 0) {
            break;
        }
        --n; // bijective: "!!" follows "~"
    }
    return code;
}

namespace {

std::string json_string(std::string_view s) {
    return nlohmann::json(std::string(s))
        .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// The $date text, as reproducible builds ask (reproducible-builds.org/specs/source-date-epoch):
// the instant SOURCE_DATE_EPOCH gives, in seconds since 1970 UTC; without it, or when it is not
// such a count, none, so that two runs of one deck write the same trace byte for byte (a run's
// machine time starts at 0 whenever it is run; the wall clock says nothing of it).
std::string source_date() {
    const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
    if (epoch == nullptr || *epoch == '\0' || std::strlen(epoch) > 15) {
        return {};
    }
    std::time_t seconds = 0;
    for (const char* c = epoch; *c != '\0'; ++c) {
        if (*c < '0' || *c > '9') {
            return {};
        }
        seconds = seconds * 10 + (*c - '0');
    }
    std::tm tm{};
    if (gmtime_r(&seconds, &tm) == nullptr) {
        return {};
    }
    std::array<char, 64> text{};
    const std::size_t n = std::strftime(text.data(), text.size(), "%Y-%m-%d %H:%M:%S UTC", &tm);
    return std::string(text.data(), n);
}

// A position in whole thousandths of an inch, to the nearest (a NaN or an infinity as 0: the
// axes never report one).
long long thousandths_of(double inches) {
    const double t = std::round(inches * 1000.0);
    return std::isfinite(t) && std::fabs(t) < 1e15 ? static_cast<long long>(t) : 0;
}

// VCD comment text may hold neither "$end" nor a line break.
std::string comment_text(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        out.push_back(c == '$' ? 'S' : (c == '\n' || c == '\r') ? ' ' : c);
    }
    return out;
}

// Axis scopes first, in card order, then the others (the cabinet) as they first appeared.
int scope_rank(const std::string& scope, const std::vector<std::string>& appearance) {
    if (auto axis = cardreader::axis_named(scope)) {
        return static_cast<int>(cardreader::axis_index(*axis));
    }
    const auto at = std::find(appearance.begin(), appearance.end(), scope);
    return cardreader::kAxisCount + static_cast<int>(at - appearance.begin());
}

} // namespace

// ---------------------------------------------------------------------------------------------
// VcdWriter

VcdWriter::VcdWriter(std::ostream& out, std::string date, const std::array<double, 5>& initial_in)
    : buf_(out), date_(std::move(date)) {
    for (std::size_t k = 0; k < initial_in.size(); ++k) {
        position_thousandths_.at(k) = thousandths_of(initial_in.at(k));
    }
}

void VcdWriter::on_signal_defined(const SignalInfo& info, std::uint32_t initial) {
    if (header_written_) {
        return; // a VCD cannot declare a signal after its definitions end
    }
    if (vars_.size() <= info.id) {
        vars_.resize(info.id + std::size_t{1});
        hot_.resize(info.id + std::size_t{1});
    }
    Var& v = vars_.at(info.id);
    v.scope = vcd_reference_name(info.scope);
    v.reference = vcd_reference_name(info.name);
    v.width = std::clamp(info.width, 1, 32);
    v.initial = initial;
    v.defined = true;
}

void VcdWriter::on_start() {
    if (!header_written_) {
        write_header();
    }
}

void VcdWriter::write_header() {
    header_written_ = true;
    std::vector<std::string> appearance;
    for (const Var& v : vars_) {
        if (v.defined &&
            std::find(appearance.begin(), appearance.end(), v.scope) == appearance.end()) {
            appearance.push_back(v.scope);
        }
    }
    for (cardreader::Axis a : cardreader::kAxes) { // each axis scope holds its position
        const std::string axis(cardreader::axis_name(a));
        if (std::find(appearance.begin(), appearance.end(), axis) == appearance.end()) {
            appearance.push_back(axis);
        }
    }
    std::vector<std::string> scopes = appearance;
    std::stable_sort(scopes.begin(), scopes.end(), [&](const auto& a, const auto& b) {
        return scope_rank(a, appearance) < scope_rank(b, appearance);
    });

    const std::string date = date_.empty() ? source_date() : date_;
    if (!date.empty()) {
        buf_.put("$date\n    ");
        buf_.put(date);
        buf_.put("\n$end\n");
    }
    buf_.put("$version parsons $end\n");
    buf_.put("$comment\n    Parsons-Stulen punched-card control (US 2,820,187), relay level.\n"
             "    One scope per lead-screw axis and one for the cabinet; each name ends in the\n"
             "    patent's reference numeral. Machine time, 1 us per tick.\n$end\n");
    buf_.put("$timescale 1 us $end\n");
    // Identifier codes in the order a reader scans the signals: "!", "\"", ...; then the five
    // positions.
    std::size_t codes = 0;
    for (const std::string& scope : scopes) {
        for (std::size_t id = 0; id < vars_.size(); ++id) {
            if (vars_[id].defined && vars_[id].scope == scope) {
                vars_[id].code = vcd_identifier_code(codes++);
            }
        }
    }
    for (std::string& code : position_code_) {
        code = vcd_identifier_code(codes++);
    }
    declared_.clear();
    for (const std::string& scope : scopes) {
        buf_.put("$scope module ");
        buf_.put(scope);
        buf_.put(" $end\n");
        std::set<std::string> taken;
        if (auto axis = cardreader::axis_named(scope)) {
            const std::string& code = position_code_.at(cardreader::axis_index(*axis));
            buf_.put("$var real 64 ");
            buf_.put(code);
            buf_.put(' ');
            buf_.put(kPositionReference);
            buf_.put(" $end\n");
            taken.emplace(kPositionReference);
            declared_.push_back({scope, std::string(kPositionReference), "real", 64});
        }
        for (std::size_t id = 0; id < vars_.size(); ++id) {
            Var& v = vars_[id];
            if (!v.defined || v.scope != scope) {
                continue;
            }
            Hot& h = hot_[id];
            std::copy(v.code.begin(), v.code.end(), h.tail.begin());
            h.tail.at(v.code.size()) = '\n';
            h.code_len = static_cast<std::uint8_t>(v.code.size());
            h.width = static_cast<std::uint8_t>(v.width);
            if (!taken.insert(v.reference).second) {
                v.reference = fmt::format("{}_{}", v.reference, id); // names that differ in '.'
                taken.insert(v.reference);
            }
            declared_.push_back({scope, v.reference, "wire", v.width});
            buf_.put("$var wire ");
            buf_.put_uint(static_cast<std::uint64_t>(v.width));
            buf_.put(' ');
            buf_.put(v.code);
            buf_.put(' ');
            buf_.put(v.reference);
            if (v.width > 1) {
                buf_.put(" [");
                buf_.put_uint(static_cast<std::uint64_t>(v.width - 1));
                buf_.put(":0]");
            }
            buf_.put(" $end\n");
        }
        buf_.put("$upscope $end\n");
    }
    buf_.put("$enddefinitions $end\n#0\n$dumpvars\n");
    for (std::size_t id = 0; id < vars_.size(); ++id) {
        if (vars_[id].defined) {
            put_value(hot_[id], vars_[id].initial);
        }
    }
    for (std::size_t k = 0; k < position_code_.size(); ++k) {
        put_position(k);
    }
    buf_.put("$end\n");
    last_us_ = 0;
    last_seconds_ = -1;
}

void VcdWriter::advance_time(double seconds) {
    if (seconds == last_seconds_) {
        return;
    }
    last_seconds_ = seconds;
    const double us = std::round(seconds * 1e6);
    if (!(us > static_cast<double>(last_us_))) {
        return; // same microsecond (or NaN): one timestamp for all its changes
    }
    last_us_ = static_cast<std::int64_t>(us);
    char* p = buf_.claim(24);
    *p++ = '#';
    p = std::to_chars(p, p + 22, last_us_).ptr;
    *p++ = '\n';
    buf_.commit(p);
}

void VcdWriter::put_value(const Hot& h, std::uint32_t value) {
    char* p = buf_.claim(48);
    if (h.width == 1) {
        *p++ = (value & 1u) != 0 ? '1' : '0';
    } else {
        *p++ = 'b';
        for (int bit = h.width - 1; bit >= 0; --bit) {
            *p++ = ((value >> bit) & 1u) != 0 ? '1' : '0';
        }
        *p++ = ' ';
    }
    std::memcpy(p, h.tail.data(), h.tail.size()); // claimed room for it: 48 >= 1 + 34 + 8
    buf_.commit(p + h.code_len + 1);
}

void VcdWriter::on_signal(double seconds, SignalId id, std::uint32_t /*old_value*/,
                          std::uint32_t new_value) {
    if (!header_written_) {
        write_header();
    }
    if (id >= hot_.size() || hot_[id].code_len == 0) {
        return; // never declared
    }
    advance_time(seconds);
    put_value(hot_[id], new_value);
}

// "r8.985 CODE": the thousandths as a decimal, from the integer itself, so that the text is the
// value compared (never "-0.000").
void VcdWriter::put_position(std::size_t axis) {
    const long long q = position_thousandths_.at(axis);
    const unsigned long long magnitude =
        q < 0 ? 0ULL - static_cast<unsigned long long>(q) : static_cast<unsigned long long>(q);
    char* p = buf_.claim(48);
    *p++ = 'r';
    if (q < 0) {
        *p++ = '-';
    }
    p = std::to_chars(p, p + 24, magnitude / 1000).ptr;
    *p++ = '.';
    const unsigned long long fraction = magnitude % 1000;
    *p++ = static_cast<char>('0' + fraction / 100);
    *p++ = static_cast<char>('0' + fraction / 10 % 10);
    *p++ = static_cast<char>('0' + fraction % 10);
    *p++ = ' ';
    buf_.commit(p);
    buf_.put(position_code_.at(axis));
    buf_.put('\n');
}

void VcdWriter::on_motion(double seconds, const std::array<double, 5>& real_in) {
    if (!header_written_) {
        write_header();
    }
    bool timed = false;
    for (std::size_t k = 0; k < real_in.size(); ++k) {
        const long long q = thousandths_of(real_in[k]);
        if (q == position_thousandths_[k]) {
            continue; // the same to the thousandth: nothing to write
        }
        if (!timed) {
            advance_time(seconds);
            timed = true;
        }
        position_thousandths_[k] = q;
        put_position(k);
    }
}

void VcdWriter::put_comment(std::string_view text) {
    buf_.put("$comment ");
    buf_.put(comment_text(text));
    buf_.put(" $end\n");
}

void VcdWriter::on_card(double seconds, std::int64_t index, const cardreader::CardOrders& orders) {
    if (!header_written_) {
        write_header();
    }
    advance_time(seconds);
    put_comment("card " + std::to_string(index) + " read, number " + std::to_string(orders.number));
}

void VcdWriter::on_stop(double seconds, const relaylogic::StopInfo& stop) {
    if (!header_written_) {
        write_header();
    }
    advance_time(seconds);
    put_comment("machine stop: " + std::string(relaylogic::stop_reason_name(stop.reason)) + ": " +
                stop.message);
}

void VcdWriter::on_condition(double seconds, const relaylogic::ConditionEvent& e) {
    if (!header_written_) {
        write_header();
    }
    advance_time(seconds);
    put_comment(fmt::format("{}: event {} ({} {}, {})", relaylogic::condition_event_name(e.kind),
                            e.event, cardreader::axis_name(e.axis),
                            cardreader::format_inches(e.position),
                            cardreader::action_text(e.action, e.parameter)));
}

void VcdWriter::on_finish(double seconds) {
    if (!header_written_) {
        write_header();
    }
    advance_time(seconds);
    buf_.flush();
}

// ---------------------------------------------------------------------------------------------
// EventsJsonlWriter

EventsJsonlWriter::EventsJsonlWriter(std::ostream& out) : buf_(out) {}

void EventsJsonlWriter::on_signal_defined(const SignalInfo& info, std::uint32_t /*initial*/) {
    if (middle_.size() <= info.id) {
        middle_.resize(info.id + std::size_t{1});
    }
    middle_.at(info.id) = ",\"component\":" + json_string(info.component) +
                          ",\"numeral\":" + json_string(info.numeral) +
                          ",\"signal\":" + json_string(info.scope + "." + info.name) + ",\"old\":";
}

void EventsJsonlWriter::on_signal(double seconds, SignalId id, std::uint32_t old_value,
                                  std::uint32_t new_value) {
    if (id >= middle_.size() || middle_[id].empty()) {
        return;
    }
    buf_.put("{\"t\":");
    buf_.put_fixed(seconds, 6);
    buf_.put(middle_[id]);
    buf_.put_uint(old_value);
    buf_.put(",\"new\":");
    buf_.put_uint(new_value);
    buf_.put("}\n");
}

void EventsJsonlWriter::on_card(double seconds, std::int64_t index,
                                const cardreader::CardOrders& orders) {
    buf_.put("{\"t\":");
    buf_.put_fixed(seconds, 6);
    buf_.put(",\"event\":\"card\",\"index\":");
    buf_.put_int(index);
    buf_.put(",\"number\":");
    buf_.put_int(orders.number);
    buf_.put("}\n");
}

void EventsJsonlWriter::on_stop(double seconds, const relaylogic::StopInfo& stop) {
    buf_.put("{\"t\":");
    buf_.put_fixed(seconds, 6);
    buf_.put(",\"event\":\"stop\",\"reason\":");
    buf_.put(json_string(relaylogic::stop_reason_name(stop.reason)));
    buf_.put(",\"card\":");
    buf_.put_int(stop.card);
    buf_.put(",\"card_number\":");
    if (stop.card_number >= 0) {
        buf_.put_int(stop.card_number);
    } else {
        buf_.put("null");
    }
    buf_.put(",\"axis\":");
    buf_.put(stop.axis ? json_string(cardreader::axis_name(*stop.axis)) : std::string("null"));
    buf_.put(",\"message\":");
    buf_.put(json_string(stop.message));
    buf_.put(",\"lamps\":[");
    for (std::size_t i = 0; i < stop.lamps.size(); ++i) {
        if (i > 0) {
            buf_.put(',');
        }
        buf_.put(json_string(stop.lamps[i]));
    }
    buf_.put("]}\n");
}

// {"t":..,"event":"condition_met","id":7,"card":2,"card_number":2,"condition_card":1,
//  "axis":"table","position":"5.000","sense":"forward","action":"lamp","parameter":3,
//  "tool_in_spindle":1}, and for an every-condition "mode":"every","firing":2 at the end
void EventsJsonlWriter::on_condition(double seconds, const relaylogic::ConditionEvent& e) {
    buf_.put("{\"t\":");
    buf_.put_fixed(seconds, 6);
    buf_.put(",\"event\":");
    buf_.put(json_string(relaylogic::condition_event_name(e.kind)));
    buf_.put(",\"id\":");
    buf_.put_int(e.event);
    buf_.put(",\"card\":");
    buf_.put_int(e.card);
    buf_.put(",\"card_number\":");
    buf_.put_int(e.card_number);
    buf_.put(",\"condition_card\":");
    buf_.put_int(e.condition_card);
    buf_.put(",\"axis\":");
    buf_.put(json_string(cardreader::axis_name(e.axis)));
    buf_.put(",\"position\":");
    buf_.put(json_string(cardreader::format_inches(e.position)));
    buf_.put(",\"sense\":");
    buf_.put(json_string(cardreader::sense_name(e.sense)));
    buf_.put(",\"action\":");
    buf_.put(json_string(cardreader::action_name(e.action)));
    buf_.put(",\"parameter\":");
    buf_.put_int(e.parameter);
    buf_.put(",\"tool_in_spindle\":");
    buf_.put_int(e.tool_in_spindle);
    if (e.firing > 0) { // an every-condition (an addition): which firing
        buf_.put(",\"mode\":\"every\",\"firing\":");
        buf_.put_int(e.firing);
    }
    buf_.put("}\n");
}

void EventsJsonlWriter::on_finish(double seconds) {
    buf_.put("{\"t\":");
    buf_.put_fixed(seconds, 6);
    buf_.put(",\"event\":\"finish\"}\n");
    buf_.flush();
}

// ---------------------------------------------------------------------------------------------
// PathCsvWriter

PathCsvWriter::PathCsvWriter(std::ostream& out) : buf_(out) {
    buf_.put("t,table,cross,vertical,swivel,tilt\n");
}

void PathCsvWriter::on_motion(double seconds, const std::array<double, 5>& real_in) {
    std::array<long long, 6> row{std::llround(seconds * 1e6)};
    for (std::size_t i = 0; i < real_in.size(); ++i) {
        row.at(i + 1) = std::llround(real_in.at(i) * 1e5);
    }
    if (any_ && row == last_) {
        return; // the same instant and places as the row before (a slow-down, a stop)
    }
    last_ = row;
    any_ = true;
    buf_.put_fixed(seconds, 6);
    for (double x : real_in) {
        buf_.put(',');
        buf_.put_fixed(x, 5);
    }
    buf_.put('\n');
}

void PathCsvWriter::on_finish(double /*seconds*/) {
    buf_.flush();
}

} // namespace parsons::cli
