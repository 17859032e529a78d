// What an option's value is, in the one place both sides read it: the commands give each value a
// type name (CLI11's `type_name`, which --help shows), and the manual pages and the shell
// completion (cli/support/manual.cpp) read the same name back to offer the values a user may
// type. A type name is alternatives joined by '|':
//   FILE.json      a file of that kind; FILE.ngc|.nc|.gcode one of several kinds; FILE any file
//   DIR            a folder
//   DECK           a deck in any format parsons reads (the extensions of cardreader/deck_io)
//   PROFILE        a built-in machine profile's name, or a JSON file
//   AIRFOIL        a bundled airfoil's name (kBundledAirfoils; --dat takes FILE.dat|AIRFOIL)
//   {a,b,c}        one of these words (CLI::IsMember shows its set the same way, after a ':')
// Anything else (INT, FLOAT, TEXT, AXIS=MIN:MAX, ...) is typed, not chosen: nothing is offered.
// docs/install.md ("Shell completion").
#pragma once

#include <array>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cli {

inline constexpr std::string_view kDeckValue = "DECK";
inline constexpr std::string_view kProfileValue = "PROFILE";
inline constexpr std::string_view kDirValue = "DIR";
inline constexpr std::string_view kAirfoilValue = "AIRFOIL";
// The airfoils parsons ships (decks/airfoils/NAME.dat, installed in share/parsons/airfoils),
// which --dat takes by name; tests/manual_test.cpp holds this list to the folder.
inline constexpr std::array<std::string_view, 6> kBundledAirfoils = {
    "clarky", "e387", "n63412", "naca0012", "naca2412", "naca63412_lednicer"};
// The names a G-code program goes by (convert writes G-code to a file of one of them).
inline constexpr std::array<std::string_view, 3> kGcodeExtensions = {"ngc", "nc", "gcode"};

// "FILE.csv|.lst" for {"csv", "lst"} (extensions without their dot).
std::string file_value(std::span<const std::string_view> extensions);
std::string file_value(std::initializer_list<std::string_view> extensions);
// "{cbn,bin,text}".
std::string one_of(const std::vector<std::string>& words);
// The deck formats' names ("{cbn,bin,text,listing,tape,five}"), with `more` after them.
std::string deck_formats(const std::vector<std::string>& more = {});
// The keypunch codes ("{029,026}") and the card layouts ("{fig8}") the deck options take.
std::string code_names();
std::string layout_names();

// What may be offered for a value of this type name (CLI11's full type name, "TEXT:{a,b}"
// included).
struct ValueChoices {
    std::vector<std::string> words;      // to offer as they are
    std::vector<std::string> extensions; // files of these kinds ("json"), and folders to reach them
    bool any_file = false;               // any file, and folders
    bool folders = false;                // folders only
    bool empty() const { return words.empty() && extensions.empty() && !any_file && !folders; }
};
ValueChoices value_choices(const std::string& type_name);

} // namespace parsons::cli
