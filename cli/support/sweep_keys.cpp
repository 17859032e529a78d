#include "cli/support/sweep_keys.hpp"

#include "cli/command_line.hpp"
#include "cli/support/deck_files.hpp"
#include "outputs/output_file.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <sstream>

namespace parsons::cli {

namespace {

using cardreader::DeckError;
using nlohmann::json;
namespace fs = std::filesystem;

// gen's options a sweep sets itself, for every case.
const std::set<std::string> kOwnKeys = {"output",  "o",    "to",   "job-out",
                                        "centres", "json", "help", "h"};

std::string json_pointer_of(const std::string& dotted) {
    std::string pointer;
    std::size_t start = 0;
    while (start <= dotted.size()) {
        const auto dot = std::min(dotted.find('.', start), dotted.size());
        pointer += "/" + dotted.substr(start, dot - start);
        start = dot + 1;
    }
    return pointer;
}

std::size_t index_of(const std::vector<KeyUse>& uses, const std::string& key) {
    for (std::size_t i = 0; i < uses.size(); ++i) {
        if (uses[i].key == key) {
            return i;
        }
    }
    return uses.size();
}

} // namespace

GenCommandLine::GenCommandLine() : app_(std::make_unique<CLI::App>()) {
    build_command_line(*app_, selected_, "sweep");
}

GenCommandLine::~GenCommandLine() = default;

CLI::App* GenCommandLine::family(const std::string& name) {
    CLI::App* gen = app_->get_subcommand("gen");
    std::string names;
    for (CLI::App* sub : gen->get_subcommands({})) {
        if (sub->get_name() == name) {
            return sub;
        }
        names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    throw DeckError(fmt::format("sweep: unknown family '{}' (one of: {}, the generators of "
                                "parsons gen)",
                                name, names));
}

std::optional<std::string> GenCommandLine::refusal(const std::vector<std::string>& args) {
    std::vector<std::string> all = {"parsons", "gen"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) {
        argv.push_back(a.data());
    }
    app_->clear(); // the one command line, parsed anew for each case asked about
    try {
        app_->parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError& e) {
        return std::string(e.what());
    }
    return std::nullopt;
}

KeyUse key_use(CLI::App& family, const std::string& key) {
    KeyUse use;
    use.key = key;
    if (key.rfind("profile.", 0) == 0) {
        use.profile_value = true;
        use.pointer = json_pointer_of(key.substr(8));
        return use;
    }
    if (kOwnKeys.count(key) != 0) {
        throw DeckError(fmt::format("sweep: the key '{}' is the sweep's own (it writes each "
                                    "case's deck and job description itself)",
                                    key));
    }
    if (const CLI::Option* opt = family.get_option_no_throw("--" + key)) {
        use.several = opt->get_items_expected_max() > 1;
        return use;
    }
    std::string upper = key;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    for (const CLI::Option* opt : family.get_options()) {
        if (!opt->nonpositional() && opt->get_name(true) == upper) {
            use.positional = true;
            return use;
        }
    }
    std::string names;
    for (const CLI::Option* opt : family.get_options()) {
        const std::string name = opt->nonpositional() ? opt->get_name() : "";
        if (name.rfind("--", 0) == 0 && kOwnKeys.count(name.substr(2)) == 0) {
            names += (names.empty() ? "" : ", ") + name.substr(2);
        }
    }
    throw DeckError(fmt::format("sweep: gen {} has no option '--{}' (its keys: {}; or "
                                "profile.SECTION.KEY for a profile value)",
                                family.get_name(), key, names));
}

// The arguments of `parsons gen FAMILY` for one case's gen options (profile values aside).
std::vector<std::string> gen_args(const std::string& family, const std::vector<KeyUse>& uses,
                                  const std::vector<std::string>& values) {
    std::vector<std::string> args = {family};
    for (std::size_t i = 0; i < uses.size(); ++i) {
        const KeyUse& u = uses[i];
        if (u.profile_value) {
            continue;
        }
        if (u.positional) {
            args.push_back(values[i]);
        } else if (u.several) {
            args.push_back("--" + u.key);
            std::istringstream words(values[i]);
            for (std::string w; words >> w;) {
                args.push_back(w);
            }
        } else {
            args.push_back(fmt::format("--{}={}", u.key, values[i]));
        }
    }
    return args;
}

// The profile a case's profile values start from: its "profile" key, else gen FAMILY's own
// default (parsons-extended for the additions' jobs), else the 1952 machine.
std::string base_profile(CLI::App& family, const std::vector<KeyUse>& uses,
                         const std::vector<std::string>& values) {
    const std::size_t p = index_of(uses, "profile");
    if (p < uses.size()) {
        return values[p];
    }
    const CLI::Option* opt = family.get_option_no_throw("--profile");
    return opt != nullptr ? opt->get_default_str() : std::string();
}

// The case's profile as JSON text: the base with each profile value set. Throws DeckError
// naming the key when the profile has no such key or the value is not of its kind.
std::string case_profile(const std::string& base, const std::vector<KeyUse>& uses,
                         const std::vector<std::string>& values) {
    json profile = json::parse(axes::profile_to_json(load_profile(base)));
    for (std::size_t i = 0; i < uses.size(); ++i) {
        if (!uses[i].profile_value) {
            continue;
        }
        const std::string& key = uses[i].key;
        json::json_pointer pointer;
        try {
            pointer = json::json_pointer(uses[i].pointer);
        } catch (const json::exception&) {
            throw DeckError(fmt::format("sweep: '{}' is no profile key", key));
        }
        if (!profile.contains(pointer)) {
            throw DeckError(fmt::format("sweep: the profile {} has no key '{}' (see parsons "
                                        "profile for its keys)",
                                        base.empty() ? "parsons-1952" : base, key.substr(8)));
        }
        json& at = profile[pointer];
        const std::string& v = values[i];
        if (at.is_number()) {
            json number;
            try {
                number = json::parse(v);
            } catch (const json::exception&) {
            }
            if (!number.is_number()) {
                throw DeckError(
                    fmt::format("sweep: {}={}: the profile's value is a number", key, v));
            }
            at = number;
        } else if (at.is_boolean()) {
            if (v != "true" && v != "false") {
                throw DeckError(fmt::format("sweep: {}={}: the value is true or false", key, v));
            }
            at = v == "true";
        } else if (at.is_string()) {
            at = v;
        } else {
            throw DeckError(fmt::format("sweep: {}: not a single value of the profile (a section "
                                        "or a list; name one of its keys, e.g. {}.0)",
                                        key, key));
        }
    }
    return profile.dump(2) + "\n";
}

// Checks every key and value of the grid before a case runs (exit 2 naming the first refused).
std::vector<KeyUse> check_grid(GenCommandLine& gen, const SweepGrid& grid,
                               const std::string& scratch) {
    if (grid.cases.empty()) {
        throw DeckError("sweep: no cases");
    }
    const std::string family_name = grid.cases.front().family;
    CLI::App& family = *gen.family(family_name);
    std::vector<KeyUse> uses;
    bool profile_values = false;
    for (const std::string& key : grid.keys) {
        uses.push_back(key_use(family, key));
        profile_values = profile_values || uses.back().profile_value;
    }
    for (const SweepCase& c : grid.cases) {
        if (c.family != family_name) {
            throw DeckError(fmt::format("sweep: case {} is of the family '{}' where case {} is "
                                        "'{}' (a sweep is one family)",
                                        c.number, c.family, grid.cases.front().number,
                                        family_name));
        }
    }
    const std::vector<std::string>& first = grid.cases.front().values;
    const std::string probe = (fs::path(scratch) / "probe.profile.json").string();
    auto check = [&](const std::vector<std::string>& values, const std::string& what) {
        auto args = gen_args(family_name, uses, values);
        args.insert(args.end(), {"-o", "/dev/null"});
        if (const auto why = gen.refusal(args)) {
            throw DeckError(fmt::format("sweep: {}: {}", what, *why));
        }
        if (profile_values) {
            write_file(probe, case_profile(base_profile(family, uses, values), uses, values));
            try {
                load_profile(probe);
            } catch (const DeckError& e) {
                std::string why = e.what();
                if (why.rfind(probe, 0) == 0) {
                    why = why.substr(probe.size() + 2);
                }
                throw DeckError(fmt::format("sweep: {}: the profile refuses it: {}", what, why));
            }
        }
    };
    check(first, "the first case");
    for (std::size_t k = 0; k < grid.keys.size(); ++k) {
        std::set<std::string> tried = {first[k]};
        for (const SweepCase& c : grid.cases) {
            if (tried.insert(c.values[k]).second) {
                std::vector<std::string> values = first;
                values[k] = c.values[k];
                check(values, fmt::format("{}={}", grid.keys[k], c.values[k]));
            }
        }
    }
    return uses;
}

} // namespace parsons::cli
