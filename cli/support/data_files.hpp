// The data parsons ships: the bundled airfoil coordinate files and the sample decks. They live
// in share/parsons beside the executable's folder: PREFIX/share/parsons when installed
// (PREFIX/bin/parsons), build/share/parsons in a build tree (build/cli/parsons; the build
// copies decks/airfoils and decks/samples there). PARSONS_DATA_DIR overrides both.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

// The folder holding airfoils/ and samples/, or nothing when none is found.
std::optional<std::filesystem::path> data_dir();

// The bundled airfoil files, by file name ("clarky.dat"), sorted; empty without a data folder.
std::vector<std::string> bundled_airfoils();

// What --dat NAME opens: NAME itself when it names a file; else, for a bare name with no
// folder in it, the bundled file of that name (with or without ".dat"); else NAME unchanged
// (opening it then fails with the file named).
std::string resolve_airfoil_file(const std::string& name);

// The coordinate file an airfoil source names ("dat PATH": PATH), or "" ("naca 2412").
std::string airfoil_file_read(const std::string& airfoil_source);

// " (bundled: clarky.dat, e387.dat, ...)" for a message about an airfoil file that could not
// be opened, or "" when nothing is bundled.
std::string bundled_airfoils_hint();

} // namespace parsons::cli
