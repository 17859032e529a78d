// The machine's path as G-code (RS-274), for the tools CNC people already use: CAMotics,
// LinuxCNC's previewers, any G-code viewer (`parsons convert DECK -o path.ngc`; docs/gcode.md).
//
// An observer of the run: it takes the real positions of the table (X), cross slide (Y) and
// vertical slide (Z) at every commutator impulse, cuts them into pieces at each card read and
// at each step of a speed switch 236, and writes each piece as the fewest G1 lines that stay
// within kGcodePathToleranceIn of every position the machine passed through
// (Douglas-Peucker). Each line's F is the speed the machine moved along it, inches a minute:
// what the speed switches set, with the run-up and coast. Each card's lines follow a comment
// naming the card; the end is a comment before M2. A run cut short (a machine stop, the
// operator's Ctrl-C) ends with the stop and an INCOMPLETE comment instead, and no M2: the
// program must not look whole to a controller.
#pragma once

#include "relaylogic/machine_observer.hpp"

#include <array>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cli {

// No position the machine passed through is further than this from the lines written, inches.
inline constexpr double kGcodePathToleranceIn = 0.0001;

class GcodePathWriter : public relaylogic::MachineObserver {
public:
    // deck: named in the header comment.
    GcodePathWriter(std::ostream& out, std::string deck = {});
    ~GcodePathWriter() override;
    GcodePathWriter(const GcodePathWriter&) = delete;
    GcodePathWriter& operator=(const GcodePathWriter&) = delete;

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_start() override;
    void on_signal(double seconds, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_motion(double seconds, const std::array<double, 5>& real_in) override;
    void on_card(double seconds, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double seconds, const relaylogic::StopInfo& stop) override;
    void on_finish(double seconds) override;

    std::int64_t lines_written() const { return moves_; }

private:
    struct Point {
        double t;
        std::array<double, 3> at; // table, cross, vertical
    };
    void flush_piece();
    void write_move(const Point& from, const Point& to);

    std::ostream& out_;
    std::string deck_;
    std::vector<relaylogic::SignalId> speed_switches_;
    std::vector<relaylogic::SignalId> motors_; // the five lead-screw motors
    std::vector<Point> piece_;        // since the last break, the first point the break itself
    std::array<double, 2> fixture_{}; // swivel and tilt screws now
    std::string pending_;             // comments to write before the next move
    std::string stop_;
    std::int64_t moves_ = 0;
    bool finished_ = false;
};

} // namespace parsons::cli
