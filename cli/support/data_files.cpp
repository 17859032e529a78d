// Finding the data parsons ships (cli/support/data_files.hpp).
#include "cli/support/data_files.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace parsons::cli {
namespace fs = std::filesystem;

namespace {

bool is_data_dir(const fs::path& dir) {
    std::error_code ec;
    return fs::is_directory(dir / "airfoils", ec);
}

} // namespace

std::optional<fs::path> data_dir() {
    if (const char* env = std::getenv("PARSONS_DATA_DIR"); env != nullptr && *env != '\0') {
        return is_data_dir(env) ? std::optional<fs::path>(env) : std::nullopt;
    }
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
        return std::nullopt;
    }
    const fs::path dir = exe.parent_path().parent_path() / "share" / "parsons";
    if (is_data_dir(dir)) {
        return dir;
    }
    return std::nullopt;
}

std::vector<std::string> bundled_airfoils() {
    std::vector<std::string> names;
    const auto dir = data_dir();
    if (!dir) {
        return names;
    }
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(*dir / "airfoils", ec)) {
        if (entry.path().extension() == ".dat") {
            names.push_back(entry.path().filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

std::string resolve_airfoil_file(const std::string& name) {
    std::error_code ec;
    if (name.empty() || fs::exists(name, ec) || name.find('/') != std::string::npos) {
        return name;
    }
    const auto dir = data_dir();
    if (!dir) {
        return name;
    }
    for (const fs::path& candidate :
         {*dir / "airfoils" / name, *dir / "airfoils" / (name + ".dat")}) {
        if (fs::is_regular_file(candidate, ec)) {
            return candidate.string();
        }
    }
    return name;
}

std::string bundled_airfoils_hint() {
    const auto names = bundled_airfoils();
    if (names.empty()) {
        return "";
    }
    return fmt::format(" (bundled, by name: {})", fmt::join(names, ", "));
}

std::string airfoil_file_read(const std::string& airfoil_source) {
    const std::string dat = "dat ";
    return airfoil_source.rfind(dat, 0) == 0 ? airfoil_source.substr(dat.size()) : std::string();
}

} // namespace parsons::cli
