#include "cli/deck_files.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace parsons::cli {

using cardreader::DeckError;

void add_input_flags(CLI::App& cmd, DeckFlags& flags) {
    cmd.add_option("--format", flags.format,
                   "Input deck format: cbn, bin, text or listing (default: from the extension: "
                   ".cbn .bin .txt/.crd/.card/.cards .csv/.lst)");
    cmd.add_option("--code", flags.code, "Keypunch code of text card images: 029 or 026")
        ->capture_default_str();
    cmd.add_option("--layout", flags.layout, "Card layout (the reader's plugboard)")
        ->capture_default_str();
}

cardreader::DeckOptions deck_options(const std::string& path, const std::string& format_flag,
                                     const DeckFlags& flags) {
    cardreader::DeckOptions options;
    options.file_name = path;
    if (!format_flag.empty()) {
        auto f = cardreader::format_named(format_flag);
        if (!f) {
            throw DeckError::in_file(path, fmt::format("unknown format '{}' (cbn, bin, text or "
                                                       "listing)",
                                                       format_flag));
        }
        options.format = *f;
    } else {
        auto f = cardreader::format_for_path(path);
        if (!f) {
            throw DeckError::in_file(path, "cannot tell the deck format from the extension; "
                                           "give --format cbn, bin, text or listing");
        }
        options.format = *f;
    }
    auto code = cardreader::code_named(flags.code);
    if (!code) {
        throw DeckError::in_file(
            path, fmt::format("unknown keypunch code '{}' (029 or 026)", flags.code));
    }
    options.code = *code;
    options.layout = cardreader::layout_named(flags.layout);
    if (!options.layout) {
        throw DeckError::in_file(path,
                                 fmt::format("unknown card layout '{}' (fig8)", flags.layout));
    }
    return options;
}

InputDeck::InputDeck(const std::string& path, const DeckFlags& flags)
    : options_(deck_options(path, flags.format, flags)) {
    if (std::filesystem::is_directory(path)) {
        throw DeckError::in_file(path, "is a directory, not a deck");
    }
    in_.open(path, std::ios::binary);
    if (!in_) {
        throw DeckError::in_file(path, std::string("cannot open: ") + std::strerror(errno));
    }
    std::error_code ec;
    size_bytes_ = static_cast<double>(std::filesystem::file_size(path, ec));
    source_ = cardreader::open_card_source(in_, options_);
}

double InputDeck::fraction_read() {
    if (size_bytes_ <= 0) {
        return 0;
    }
    const auto pos = in_.tellg();
    return pos < 0 ? 1.0 : std::min(1.0, static_cast<double>(pos) / size_bytes_);
}

std::string read_text_file(const std::string& file, const std::string& missing) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw DeckError::in_file(
            file, missing.empty() ? std::string("cannot open: ") + std::strerror(errno) : missing);
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

axes::MachineProfile load_profile(const std::string& file) {
    if (file.empty()) {
        return axes::default_profile();
    }
    // A built-in profile by name (parsons-1952, parsons-safe), unless a file of that name exists.
    if (auto builtin = axes::builtin_profile(file); builtin && !std::filesystem::exists(file)) {
        return *builtin;
    }
    const std::string text = read_text_file(file);
    try {
        return axes::profile_from_json(text, axes::default_profile());
    } catch (const axes::ProfileError& e) {
        throw DeckError::in_file(file, e.what());
    }
}

} // namespace parsons::cli

namespace parsons::cli {

void apply_limits(axes::MachineProfile& profile, const std::vector<std::string>& limits) {
    for (const std::string& spec : limits) {
        const auto eq = spec.find('=');
        const auto colon = spec.find(':', eq == std::string::npos ? 0 : eq);
        auto bad = [&spec](const std::string& why) {
            return DeckError(fmt::format("--limit '{}': {} (expected AXIS=MIN:MAX in inches, e.g. "
                                         "table=0:9.5)",
                                         spec, why));
        };
        if (eq == std::string::npos || colon == std::string::npos) {
            throw bad("not AXIS=MIN:MAX");
        }
        const auto axis = cardreader::axis_named(spec.substr(0, eq));
        if (!axis) {
            throw bad("unknown axis '" + spec.substr(0, eq) +
                      "' (table, cross, vertical, swivel or tilt)");
        }
        auto number = [&](const std::string& text) {
            std::size_t used = 0;
            double v = 0;
            try {
                v = std::stod(text, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used == 0 || used != text.size() || !std::isfinite(v)) {
                throw bad("'" + text + "' is not a number of inches");
            }
            return v;
        };
        const double lo = number(spec.substr(eq + 1, colon - eq - 1));
        const double hi = number(spec.substr(colon + 1));
        if (!(lo < hi)) {
            throw bad("the minimum must be below the maximum");
        }
        auto& a = profile.axes.at(cardreader::axis_index(*axis));
        a.soft_limits = true;
        a.soft_min_in = lo;
        a.soft_max_in = hi;
    }
}

} // namespace parsons::cli
