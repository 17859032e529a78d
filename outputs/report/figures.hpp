// Figures as the JSON outputs write them (docs/report.md, "Figures are rounded to what they
// resolve"): each kind rounded to what it resolves, and held as the nearest double to that
// decimal, so that the JSON carries the shortest text that reads back to it (0.00146, never
// 0.0014600000000000001; 88.194111, never 88.19411099999999). What is read back (saved states,
// profiles, job files) keeps every bit instead.
#pragma once

namespace parsons::cli {

// v to `places` decimals (0..15), as the nearest double to that decimal; never -0; a NaN or an
// infinity as it is.
double decimals(double v, int places);

// Counter readings: the machine's resolution, 0.001 in.
double counter_reading(double inches);
// Lengths the emulator knows beyond the counters (real position, error, slip, screw turns, the
// cut proof, generated work zeros and scallops): 0.00001 in.
double fine_length(double inches);
// Times: the microsecond.
double time_s(double seconds);
// Angles: 0.0001 degree.
double angle_deg(double degrees);

} // namespace parsons::cli
