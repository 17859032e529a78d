// Observers that write a run to files as it happens: the relay-level VCD trace (--trace), one
// JSON object per signal change (--events) and the real tool path as CSV (--path).
//
// They are the 1952 machine's oscillograph and recorder pen: every relay of the storage banks
// (350-356, 318-324), every stepping switch of the counters (104-110, 310-316), the speed
// switches 236, stepping shaft 280, the master switch 204 and lamps 270/272, as the cabinet
// reports them through relaylogic::Tracer. Each writer takes the stream it writes to (the CLI
// opens the file and commits it whole); none prints anything else.
//
// Speed: a long deck makes tens of millions of signal changes, so the hot path (on_signal,
// on_motion) formats numbers by hand into one reused buffer and never allocates; what each
// signal's line needs besides its value (VCD identifier code, the JSON text naming the
// signal) is worked out once, when the signal is defined.
#pragma once

#include "relaylogic/machine_observer.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cli {

// A large character buffer in front of a std::ostream: appends are a bounds test and a copy;
// the stream sees one write per megabyte. flush() hands everything to the stream and flushes
// it; the destructor flushes what is left (and never throws).
class OutputBuffer {
public:
    explicit OutputBuffer(std::ostream& out, std::size_t capacity = std::size_t{1} << 20);
    ~OutputBuffer();
    OutputBuffer(const OutputBuffer&) = delete;
    OutputBuffer& operator=(const OutputBuffer&) = delete;

    void put(char c) {
        if (size_ == data_.size()) {
            drain(1);
        }
        data_[size_++] = c;
    }
    void put(std::string_view s);
    void put_uint(std::uint64_t v);
    void put_int(std::int64_t v);
    // Fixed-point with the given number of decimals; a value that rounds to zero prints as
    // zero, never "-0.000".
    void put_fixed(double v, int decimals);
    // Room for n characters written straight into the buffer: write them at the pointer
    // returned, then hand back the end with commit().
    char* claim(std::size_t n) {
        if (data_.size() - size_ < n) {
            drain(n);
        }
        return data_.data() + size_;
    }
    void commit(const char* end) { size_ = static_cast<std::size_t>(end - data_.data()); }
    void flush();

private:
    void drain(std::size_t need);

    std::ostream& out_;
    std::vector<char> data_;
    std::size_t size_ = 0;
};

// The VCD reference of a signal: the tracer's name with every character that is not a letter,
// digit or '_' replaced by '_' ("absolute_storage_352.relay_7" -> "absolute_storage_352_relay_7").
// GTKWave reads '.' as a hierarchy separator, so dots do not stay.
std::string vcd_reference_name(std::string_view name);

// The compact VCD identifier code of the n-th signal: "!" .. "~", then "!!", "\"!", ...
// (printable ASCII 33-126, bijective base 94).
std::string vcd_identifier_code(std::size_t n);

// A variable as the VCD declares it: its scope, its reference ("absolute_counter_110",
// "position_in"), "wire" or "real", and its width in bits (64 for a real). The GTKWave save file
// beside the trace is made from this list (outputs/traces/gtkwave_save.hpp).
struct VcdVariable {
    std::string scope;
    std::string reference;
    std::string kind; // "wire" or "real"
    int width = 1;
};

// An IEEE 1364 value change dump: one `$scope module` per axis (table, cross, vertical, swivel,
// tilt) and one for the cabinet's shared parts, every signal a `$var wire`, time in integer
// microseconds. Card feeds and a machine stop are written as `$comment`s where they happen.
//
// Each axis scope also holds the axis's real position, `$var real 64 CODE position_in`, in
// inches (the positions the path CSV has, on_motion): written `rVALUE CODE` with three decimals,
// and only when the position to the nearest thousandth changes. A thousandth is the machine's
// own unit (the cards, the counters and the commutator's impulses count it); five decimals would
// write almost every motion report of every moving axis (55,032 changes on the sample deck
// against 31,705, beside the signals' 142,587), and --path has them. The positions take the
// identifier codes after the signals', so a signal's code is the same as in a trace without them.
class VcdWriter : public relaylogic::MachineObserver {
public:
    // The reference of each axis scope's position.
    static constexpr std::string_view kPositionReference = "position_in";

    // date: the $date text; empty = SOURCE_DATE_EPOCH's instant (UTC), or no $date without it.
    // initial_in: the five axes' real positions when the run starts (a resumed run's are where
    // the saved state left them), for $dumpvars.
    explicit VcdWriter(std::ostream& out, std::string date = {},
                       const std::array<double, 5>& initial_in = {});

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_start() override;
    void on_signal(double seconds, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_card(double seconds, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double seconds, const relaylogic::StopInfo& stop) override;
    void on_condition(double seconds, const relaylogic::ConditionEvent& event) override;
    void on_motion(double seconds, const std::array<double, 5>& real_in) override;
    void on_finish(double seconds) override;

    // Every variable the header declared, in the order it declared them (empty before the
    // header is written, at the start of the run).
    const std::vector<VcdVariable>& declared() const { return declared_; }

private:
    struct Var {
        std::string scope;
        std::string reference;
        std::string code;
        int width = 1;
        std::uint32_t initial = 0;
        bool defined = false;
    };
    // What on_signal needs, packed: the end of a value line, the identifier code (at most 4
    // characters for 94^4 signals) and its newline, copied as 8 bytes at once; and the width.
    struct Hot {
        std::array<char, 8> tail{};
        std::uint8_t code_len = 0; // 0: never declared
        std::uint8_t width = 1;
    };

    void write_header();
    void advance_time(double seconds);
    void put_value(const Hot& h, std::uint32_t value);
    void put_comment(std::string_view text);
    void put_position(std::size_t axis);

    OutputBuffer buf_;
    std::string date_;
    std::vector<Var> vars_;
    std::vector<Hot> hot_;
    std::vector<VcdVariable> declared_;
    // Per axis: its identifier code and the position last written, in thousandths of an inch.
    std::array<std::string, 5> position_code_;
    std::array<long long, 5> position_thousandths_{};
    bool header_written_ = false;
    std::int64_t last_us_ = 0;
    double last_seconds_ = -1; // the time last advanced to: most events share an instant
};

// One JSON object per line:
//   {"t":12.345678,"component":"speed switch
//   ...","numeral":"236","signal":"table.speed_switch_236","old":3,"new":0}
//   {"t":0.150000,"event":"card","index":1,"number":1}
//   {"t":30.2,"event":"stop","reason":"check_mismatch","card":3,"card_number":3,"axis":"table",
//    "message":"...","lamps":["indicator 268","lamp 270 (...)"]}
//   {"t":31.0,"event":"finish"}
// "t" is machine time in seconds (6 decimals); "axis" is null when no axis stopped the machine.
class EventsJsonlWriter : public relaylogic::MachineObserver {
public:
    explicit EventsJsonlWriter(std::ostream& out);

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_signal(double seconds, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_card(double seconds, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double seconds, const relaylogic::StopInfo& stop) override;
    void on_condition(double seconds, const relaylogic::ConditionEvent& event) override;
    void on_finish(double seconds) override;
    bool follows_motion() const override { return false; }

private:
    OutputBuffer buf_;
    // Per signal: `,"component":"...","numeral":"...","signal":"scope.name","old":`
    std::vector<std::string> middle_;
};

// The real positions of the five axes, one row per change (every commutator impulse and every
// axis coming to rest): `t,table,cross,vertical,swivel,tilt`, machine seconds with 6 decimals,
// inches with 5.
class PathCsvWriter : public relaylogic::MachineObserver {
public:
    explicit PathCsvWriter(std::ostream& out);

    void on_motion(double seconds, const std::array<double, 5>& real_in) override;
    void on_finish(double seconds) override;

private:
    OutputBuffer buf_;
    // The last row as written (microseconds, hundred-thousandths of an inch): a row that would
    // print the same is not written again.
    std::array<long long, 6> last_{};
    bool any_ = false;
};

} // namespace parsons::cli
