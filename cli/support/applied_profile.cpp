#include "cli/support/applied_profile.hpp"

#include "cli/support/deck_files.hpp"

#include "axes/profile_json.hpp"
#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/layout.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <system_error>

namespace parsons::cli {
namespace {

using nlohmann::json;

json as_json(const axes::MachineProfile& p) {
    return json::parse(axes::profile_to_json(p));
}

void differences(const json& applied, const json& named, const std::string& key, json& out) {
    if (applied.is_object() && named.is_object()) {
        for (const auto& [k, v] : applied.items()) {
            const std::string sub = key.empty() ? k : key + "." + k;
            differences(v, named.contains(k) ? named.at(k) : json(nullptr), sub, out);
        }
        return;
    }
    if (applied != named) {
        out.push_back(json{{"key", key}, {"value", applied}, {"named_value", named}});
    }
}

// The named profile a profile file is applied over: the built-in one its "name" names, else
// the default.
axes::MachineProfile named_base(const std::string& text) {
    try {
        const json j = json::parse(text);
        if (j.is_object() && j.contains("name") && j.at("name").is_string()) {
            if (auto builtin = axes::builtin_profile(j.at("name").get<std::string>())) {
                return *builtin;
            }
        }
    } catch (const json::exception&) {
        // not JSON, or a number too large: profile_from_json names the byte
    }
    return axes::default_profile();
}

std::string range_text(double lo, double hi) {
    return fmt::format("{:.3f} .. {:.3f} in", lo, hi);
}

} // namespace

json profile_differences(const axes::MachineProfile& applied, const axes::MachineProfile& named) {
    json out = json::array();
    differences(as_json(applied), as_json(named), "", out);
    return out;
}

namespace {

// What a --profile that names no file is told: the built-in names, since a mistyped name is
// the likelier slip (or "" when the file exists and read_text_file is to say why it cannot
// be opened).
std::string not_a_profile(const std::string& file) {
    std::error_code ec;
    if (std::filesystem::exists(file, ec)) {
        return "";
    }
    std::string names;
    for (std::size_t i = 0; i < axes::kBuiltinProfiles.size(); ++i) {
        names += (i == 0                                   ? ""
                  : i + 1 == axes::kBuiltinProfiles.size() ? " or "
                                                           : ", ") +
                 std::string(axes::kBuiltinProfiles.at(i));
    }
    return fmt::format("no such profile: neither a built-in profile ({}) nor a file", names);
}

} // namespace

std::string AppliedProfile::file_read(const std::string& name) {
    // A built-in profile by name (parsons-1952, parsons-safe), unless a file of that name exists.
    std::error_code ec;
    if (name.empty() || (axes::builtin_profile(name) && !std::filesystem::exists(name, ec))) {
        return "";
    }
    return name;
}

AppliedProfile AppliedProfile::load(const std::string& file) {
    AppliedProfile a;
    auto builtin =
        file.empty() ? std::optional(axes::default_profile()) : axes::builtin_profile(file);
    if (file_read(file).empty()) {
        a.profile_ = *builtin;
        a.named_ = a.profile_;
    } else {
        const std::string text = read_text_file(file, not_a_profile(file));
        a.named_ = named_base(text);
        try {
            a.profile_ = axes::profile_from_json(text, a.named_);
        } catch (const axes::ProfileError& e) {
            throw cardreader::DeckError::in_file(file, e.what());
        }
        a.file_ = file;
    }
    for (std::size_t i = 0; i < a.profile_.axes.size(); ++i) {
        const auto& x = a.profile_.axes.at(i);
        const auto& n = a.named_.axes.at(i);
        const bool soft_same =
            x.soft_limits == n.soft_limits &&
            (!x.soft_limits || (x.soft_min_in == n.soft_min_in && x.soft_max_in == n.soft_max_in));
        const bool travel_same =
            x.travel_min_in == n.travel_min_in && x.travel_max_in == n.travel_max_in;
        const std::string named = "profile " + a.named_.name;
        const std::string from_file = "profile file " + a.file_;
        a.soft_from_.at(i) = soft_same ? named : from_file;
        a.travel_from_.at(i) = travel_same ? named : from_file;
    }
    return a;
}

AppliedProfile AppliedProfile::from_state(const json& saved, const std::string& state_file) {
    AppliedProfile a;
    const json& profile = axes::member(saved, "profile");
    a.named_ = named_base(profile.dump());
    a.profile_ = axes::profile_from_json(profile.dump(), a.named_);
    // The state remembers where its limits came from; older states do not.
    const json* origins = nullptr;
    if (saved.contains("profile_applied") && saved.at("profile_applied").is_object() &&
        saved.at("profile_applied").contains("limits")) {
        origins = &saved.at("profile_applied").at("limits");
        if (saved.at("profile_applied").contains("file") &&
            saved.at("profile_applied").at("file").is_string()) {
            a.file_ = saved.at("profile_applied").at("file").get<std::string>();
        }
    }
    for (std::size_t i = 0; i < a.profile_.axes.size(); ++i) {
        const std::string& axis = a.profile_.axes.at(i).name;
        auto earlier = [&](const char* which) -> std::string {
            if (origins == nullptr || !origins->contains(axis) ||
                !origins->at(axis).contains(which) ||
                !origins->at(axis).at(which).contains("from") ||
                !origins->at(axis).at(which).at("from").is_string()) {
                return "";
            }
            return ", " + origins->at(axis).at(which).at("from").get<std::string>() +
                   " in the stopped run";
        };
        a.soft_from_.at(i) = "saved state " + state_file + earlier("movement_range");
        a.travel_from_.at(i) = "saved state " + state_file + earlier("limit_switches");
    }
    return a;
}

void AppliedProfile::apply_limits(const std::vector<std::string>& limits) {
    const std::vector<cardreader::Axis> axes = cli::apply_limits(profile_, limits);
    for (std::size_t i = 0; i < axes.size(); ++i) {
        soft_from_.at(cardreader::axis_index(axes.at(i))) = "--limit " + limits.at(i);
    }
}

json AppliedProfile::describe() const {
    nlohmann::json limits = nlohmann::json::object();
    for (std::size_t i = 0; i < profile_.axes.size(); ++i) {
        const auto& x = profile_.axes.at(i);
        limits[x.name] = {
            {"movement_range",
             {{"in", x.soft_limits ? nlohmann::json{x.soft_min_in, x.soft_max_in}
                                   : nlohmann::json(nullptr)},
              {"from", soft_from_.at(i)}}},
            {"limit_switches",
             {{"in", {x.travel_min_in, x.travel_max_in}}, {"from", travel_from_.at(i)}}}};
    }
    return nlohmann::json{{"name", profile_.name},
                          {"file", file_.empty() ? nlohmann::json(nullptr) : nlohmann::json(file_)},
                          {"named_profile", named_.name},
                          {"differs_from_named", profile_differences(profile_, named_)},
                          {"limits", limits}};
}

std::vector<std::string> AppliedProfile::limit_lines() const {
    std::vector<std::string> lines;
    for (std::size_t i = 0; i < profile_.axes.size(); ++i) {
        const auto& x = profile_.axes.at(i);
        const std::string range =
            x.soft_limits ? fmt::format("movement range {} ({})",
                                        range_text(x.soft_min_in, x.soft_max_in), soft_from_.at(i))
                          : fmt::format("no movement range ({})", soft_from_.at(i));
        lines.push_back(fmt::format("{:<8} {}; limit switches {} ({})", x.name, range,
                                    range_text(x.travel_min_in, x.travel_max_in),
                                    travel_from_.at(i)));
    }
    return lines;
}

} // namespace parsons::cli
