// The press's profile keys (axes/profile_json.hpp: press, sync_drive, speed_sample_s): read
// back, refused out of range with the key named, and the press refused when its pulses outrun
// registers 14 and 11. Moved from press_test.cpp, which keeps the plant itself.
#include "axes/press.hpp"
#include "axes/profile_json.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace parsons::axes;

TEST_CASE("Press profile: every press key reads back from the profile's JSON", "[press]") {
    MachineProfile p = extended_profile();
    CHECK(p.press_sync);
    CHECK_FALSE(default_profile().press_sync);
    PressProfile& press = p.press;
    press.strokes_per_min = 7.5;
    press.start_angle_deg = 12.5;
    press.pulses_per_degree = 9;
    press.reverse = true;
    press.stroke_in = 3.5;
    press.rod_in = 9.25;
    press.pressing_from_deg = 100;
    press.pressing_to_deg = 250;
    press.pressing_slowdown = 0.125;
    press.drift_per_cycle = -0.03;
    press.variation = 0.25;
    press.seed = 4242;
    press.change_cycle = 3;
    press.change_angle_deg = 33.5;
    press.change_factor = 0.75;
    press.stop_cycle = 5;
    press.stop_angle_deg = 270.5;
    p.sync_drive = SyncDrive{3.25, 0.125};
    p.speed_sample_s = 0.25;
    p.sync_timeout_s = 600;
    p.max_stepping_rate_per_s = 600; // switches that follow its 506 pulses a second
    const MachineProfile q = profile_from_json(profile_to_json(p), default_profile());
    CHECK(q.press_sync);
    CHECK(q.press.strokes_per_min == 7.5);
    CHECK(q.press.start_angle_deg == 12.5);
    CHECK(q.press.pulses_per_degree == 9);
    CHECK(q.press.reverse);
    CHECK(q.press.stroke_in == 3.5);
    CHECK(q.press.rod_in == 9.25);
    CHECK(q.press.pressing_from_deg == 100);
    CHECK(q.press.pressing_to_deg == 250);
    CHECK(q.press.pressing_slowdown == 0.125);
    CHECK(q.press.drift_per_cycle == -0.03);
    CHECK(q.press.variation == 0.25);
    CHECK(q.press.seed == 4242);
    CHECK(q.press.change_cycle == 3);
    CHECK(q.press.change_angle_deg == 33.5);
    CHECK(q.press.change_factor == 0.75);
    CHECK(q.press.stop_cycle == 5);
    CHECK(q.press.stop_angle_deg == 270.5);
    CHECK(q.sync_drive.max_in_per_min == 3.25);
    CHECK(q.sync_drive.acceleration_in_per_s2 == 0.125);
    CHECK(q.speed_sample_s == 0.25);
    CHECK(q.sync_timeout_s == 600);
    CHECK(profile_to_json(q) == profile_to_json(p));
    // A partial press object changes only its keys.
    const MachineProfile r =
        profile_from_json(R"({"press": {"seed": 9}, "press_sync": true})", default_profile());
    CHECK(r.press.seed == 9);
    CHECK(r.press.strokes_per_min == 2.0);
    CHECK(r.press_sync);
    // The limits themselves are accepted.
    for (const char* ok :
         {R"({"press": {"strokes_per_min": 0.1, "pulses_per_degree": 27}})",
          R"({"press": {"strokes_per_min": 120, "pulses_per_degree": 1}})",
          R"({"press": {"pressing_slowdown": 0.9, "drift_per_cycle": -0.1, "variation": 0.5}})",
          R"({"press": {"drift_per_cycle": 0.1, "change_factor": 4, "start_angle_deg": 359.5}})",
          R"({"press": {"pressing_from_deg": 0, "pressing_to_deg": 360, "stop_cycle": 0}})",
          R"({"press": {"stroke_in": 4, "rod_in": 2.001}, "sync_timeout_s": 3600})"}) {
        INFO(ok);
        CHECK_NOTHROW(profile_from_json(ok, default_profile()));
    }
}

TEST_CASE("Press profile: a value out of range is an error naming its key", "[press]") {
    struct Bad {
        const char* json;
        const char* key;
    };
    const Bad bad = GENERATE(values<Bad>({
        {R"({"press_sync": 1})", "press_sync:"},
        {R"({"press": 3})", "press:"},
        {R"({"press": {"spm": 3}})", "press.spm: unknown key"},
        {R"({"press": {"strokes_per_min": 0.09}})", "press.strokes_per_min:"},
        {R"({"press": {"strokes_per_min": 121}})", "press.strokes_per_min:"},
        {R"({"press": {"strokes_per_min": "2"}})", "press.strokes_per_min:"},
        {R"({"press": {"start_angle_deg": 360}})", "press.start_angle_deg:"},
        {R"({"press": {"start_angle_deg": -1}})", "press.start_angle_deg:"},
        {R"({"press": {"pulses_per_degree": 0}})", "press.pulses_per_degree:"},
        {R"({"press": {"pulses_per_degree": 28}})", "press.pulses_per_degree:"},
        {R"({"press": {"pulses_per_degree": 4.5}})", "press.pulses_per_degree:"},
        {R"({"press": {"reverse": 1}})", "press.reverse:"},
        {R"({"press": {"stroke_in": 0}})", "press.stroke_in:"},
        {R"({"press": {"rod_in": -8}})", "press.rod_in:"},
        {R"({"press": {"stroke_in": 4, "rod_in": 2}})", "press.rod_in:"},
        {R"({"press": {"stroke_in": 20}})", "press.rod_in:"},
        {R"({"press": {"pressing_from_deg": -1}})", "press.pressing_from_deg:"},
        {R"({"press": {"pressing_to_deg": 361}})", "press.pressing_to_deg:"},
        {R"({"press": {"pressing_from_deg": 210, "pressing_to_deg": 150}})",
         "press.pressing_from_deg:"},
        {R"({"press": {"pressing_from_deg": 150, "pressing_to_deg": 150}})",
         "press.pressing_from_deg:"},
        {R"({"press": {"pressing_slowdown": 0.91}})", "press.pressing_slowdown:"},
        {R"({"press": {"pressing_slowdown": -0.1}})", "press.pressing_slowdown:"},
        {R"({"press": {"drift_per_cycle": 0.11}})", "press.drift_per_cycle:"},
        {R"({"press": {"drift_per_cycle": -0.11}})", "press.drift_per_cycle:"},
        {R"({"press": {"variation": 0.51}})", "press.variation:"},
        {R"({"press": {"variation": -0.01}})", "press.variation:"},
        {R"({"press": {"seed": -1}})", "press.seed:"},
        {R"({"press": {"seed": 4294967296}})", "press.seed:"},
        {R"({"press": {"change_cycle": -1}})", "press.change_cycle:"},
        {R"({"press": {"change_cycle": 1.5}})", "press.change_cycle:"},
        {R"({"press": {"change_angle_deg": 360}})", "press.change_angle_deg:"},
        {R"({"press": {"change_factor": 0}})", "press.change_factor:"},
        {R"({"press": {"change_factor": 4.01}})", "press.change_factor:"},
        {R"({"press": {"stop_cycle": -2}})", "press.stop_cycle:"},
        {R"({"press": {"stop_angle_deg": 360}})", "press.stop_angle_deg:"},
        {R"({"press": {"stop_angle_deg": -0.5}})", "press.stop_angle_deg:"},
        {R"({"sync_drive": 5})", "sync_drive:"},
        {R"({"sync_drive": {"max_in_per_min": 0}})", "sync_drive.max_in_per_min:"},
        {R"({"sync_drive": {"max_in_per_min": 1001}})", "sync_drive.max_in_per_min:"},
        {R"({"sync_drive": {"acceleration_in_per_s2": 0}})", "sync_drive.acceleration_in_per_s2:"},
        {R"({"sync_drive": {"jerk": 1}})", "sync_drive.jerk: unknown key"},
        {R"({"speed_sample_s": 0})", "speed_sample_s:"},
        {R"({"speed_sample_s": 61})", "speed_sample_s:"},
        {R"({"sync_timeout_s": 0})", "sync_timeout_s:"},
        {R"({"sync_timeout_s": 3601})", "sync_timeout_s:"},
    }));
    INFO(bad.json);
    CHECK_THROWS_WITH(profile_from_json(bad.json, default_profile()), Catch::StartsWith(bad.key));
}

TEST_CASE("Press profile: a press whose pulses come faster than registers 14 and 11 step is "
          "refused, naming strokes_per_min and what they can follow",
          "[press]") {
    const MachineProfile extended = extended_profile(); // 100 steps a second, 4 pulses a degree
    // 4 strokes a minute: 96 pulses a second, within; 5: 120, beyond.
    CHECK_NOTHROW(profile_from_json(R"({"press": {"strokes_per_min": 4}})", extended));
    CHECK_THROWS_WITH(profile_from_json(R"({"press": {"strokes_per_min": 5}})", extended),
                      Catch::StartsWith("press.strokes_per_min:") &&
                          Catch::Contains("120 detector pulses a second") &&
                          Catch::Contains("at most 4.17 strokes a minute"));
    // Variation and a lasting change count at their fastest.
    CHECK_THROWS_WITH(
        profile_from_json(R"({"press": {"strokes_per_min": 4, "variation": 0.1}})", extended),
        Catch::StartsWith("press.strokes_per_min:"));
    CHECK_THROWS_WITH(
        profile_from_json(R"({"press": {"strokes_per_min": 4, "change_factor": 1.1}})", extended),
        Catch::StartsWith("press.strokes_per_min:"));
    // Faster switches follow a faster press; without press synchronisation nothing is judged.
    CHECK_NOTHROW(profile_from_json(
        R"({"press": {"strokes_per_min": 5}, "max_stepping_rate_per_s": 130})", extended));
    CHECK_NOTHROW(profile_from_json(R"({"press": {"strokes_per_min": 5}})", default_profile()));
}
