#include "cli/support/deck_files.hpp"

#include "cli/support/number_rule.hpp"
#include "cli/support/value_names.hpp"

#include "cardreader/layout.hpp"
#include "cli/support/applied_profile.hpp"
#include "outputs/output_file.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <memory>
#include <set>
#include <sstream>

namespace parsons::cli {

using cardreader::DeckError;

namespace {

// Where --format auto (the default) finds no extension it knows: the first bytes decide.
constexpr auto kFormatFromBytes = static_cast<cardreader::DeckFormat>(0xFF);
constexpr std::size_t kHeadBytes = cardreader::kDeckHeadBytes;

} // namespace

void add_input_flags(CLI::App& cmd, DeckFlags& flags) {
    cmd.add_option(
           "--format", flags.format,
           "Input deck format: auto, cbn, bin, text, listing, tape or five (auto, the default: "
           "from "
           "the extension .cbn .bin .txt/.crd/.card/.cards .csv/.lst .tape/.ptp .five, else from "
           "the first bytes as SIMH tells them; - reads standard input)")
        ->type_name(deck_formats({"auto"}));
    cmd.add_option("--code", flags.code, "Keypunch code of text card images: 029 or 026")
        ->type_name(code_names())
        ->capture_default_str();
    cmd.add_option("--layout", flags.layout, "Card layout (the reader's plugboard)")
        ->type_name(layout_names())
        ->capture_default_str();
}

cardreader::DeckOptions deck_options(const std::string& path, const std::string& format_flag,
                                     const DeckFlags& flags, const std::string& option) {
    cardreader::DeckOptions options;
    options.file_name = path;
    const bool output = option != "--format";
    if (!format_flag.empty() && format_flag != "auto") {
        auto f = cardreader::format_named(format_flag);
        if (!f) {
            throw DeckError::in_file(path,
                                     fmt::format("unknown format '{}' for {} (cbn, bin, "
                                                 "text, listing, tape or five{})",
                                                 format_flag, option, output ? "" : ", or auto"));
        }
        options.format = *f;
    } else if (auto f = cardreader::format_for_path(path); f && path != "-") {
        options.format = *f;
    } else if (output && null_device(path)) {
        options.format = cardreader::DeckFormat::cbn; // nothing reads it: any format discards
    } else if (output) {
        throw DeckError::in_file(
            path == "-" ? "standard output" : path,
            path == "-" ? fmt::format("a deck written to standard output needs {} cbn, bin, "
                                      "text, listing, tape or five",
                                      option)
                        : fmt::format("cannot tell the deck format from the extension; give {} "
                                      "cbn, bin, text, listing, tape or five",
                                      option));
    } else {
        options.format = kFormatFromBytes;
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

void apply_feed(axes::MachineProfile& profile, const std::string& feed,
                const cardreader::DeckOptions& deck) {
    if (cardreader::format_is_continuous(deck.format)) {
        if (feed == "cards") {
            throw DeckError::in_file(deck.file_name,
                                     fmt::format("--feed cards: a {} deck has no separate cards "
                                                 "to feed (it always feeds as a ribbon)",
                                                 cardreader::format_name(deck.format)));
        }
        profile.ribbon_feed = true;
    } else if (!feed.empty()) {
        profile.ribbon_feed = feed == "ribbon";
    }
}

InputDeck::InputDeck(const std::string& path, const DeckFlags& flags)
    : options_(deck_options(path, flags.format, flags)) {
    const bool from_bytes = options_.format == kFormatFromBytes;
    std::string head;
    if (path == "-") {
        // Standard input, read whole: its format may have to be told from its first bytes.
        std::string bytes{std::istreambuf_iterator<char>(std::cin),
                          std::istreambuf_iterator<char>()};
        if (std::cin.bad()) {
            throw DeckError::in_file("standard input", "read error");
        }
        options_.file_name = "standard input";
        head = bytes.substr(0, kHeadBytes);
        size_bytes_ = static_cast<double>(bytes.size());
        in_ = std::make_unique<std::istringstream>(std::move(bytes));
    } else {
        if (std::filesystem::is_directory(path)) {
            throw DeckError::in_file(path, "is a directory, not a deck");
        }
        auto file = std::make_unique<std::ifstream>(path, std::ios::binary);
        if (!*file) {
            throw DeckError::in_file(path, std::string("cannot open: ") + std::strerror(errno));
        }
        if (!std::filesystem::is_regular_file(path)) {
            // A FIFO or a device: read whole, so that the deck can be read twice (rewind).
            std::string bytes{std::istreambuf_iterator<char>(*file),
                              std::istreambuf_iterator<char>()};
            if (file->bad()) {
                throw DeckError::in_file(path, "read error");
            }
            head = bytes.substr(0, kHeadBytes);
            size_bytes_ = static_cast<double>(bytes.size());
            in_ = std::make_unique<std::istringstream>(std::move(bytes));
        } else {
            head.resize(kHeadBytes);
            file->read(head.data(), static_cast<std::streamsize>(head.size()));
            head.resize(static_cast<std::size_t>(file->gcount()));
            file->clear();
            file->seekg(0);
            in_ = std::move(file);
            std::error_code ec;
            size_bytes_ = static_cast<double>(std::filesystem::file_size(path, ec));
        }
    }
    if (auto kind = cardreader::non_deck_kind(head)) {
        throw DeckError::in_file(options_.file_name, "this is " + *kind + ", not a deck of cards");
    }
    if (!from_bytes && path != "-" && (flags.format.empty() || flags.format == "auto")) {
        content_outranks_extension(head);
    }
    if (from_bytes) {
        const auto sniffed = cardreader::sniff_format(head);
        if (!sniffed) {
            throw DeckError::in_file(options_.file_name,
                                     head.empty()
                                         ? std::string("empty file: no cards")
                                         : fmt::format("cannot tell the deck format from {}its "
                                                       "first bytes; give --format cbn, bin, "
                                                       "text, listing, tape or five",
                                                       path == "-" ? "" : "the extension or "));
        }
        options_.format = *sniffed;
    }
    // A warning about the deck goes to standard error once, however often the deck is read
    // (run reads it through before the run when it holds condition, sync or tap cards).
    options_.warn = [said = std::make_shared<std::set<std::string>>()](const std::string& what) {
        if (said->insert(what).second) {
            say(stderr, "parsons: warning: " + what + "\n");
        }
    };
    source_ = cardreader::open_card_source(*in_, options_);
}

// The format the extension gave yields to what the bytes plainly are
// (cardreader::content_outranks), with one warning a file however often the command opens it
// (run opens a deck again to check a job file's fingerprint).
void InputDeck::content_outranks_extension(const std::string& head) {
    const auto found = cardreader::content_outranks(options_.format, head);
    if (!found) {
        return;
    }
    static std::set<std::string> said;
    if (said.insert(options_.file_name).second) {
        say(stderr, fmt::format("parsons: warning: {}: the extension says {}, but the content is "
                                "{}: {}; read as {} (--format {} reads it as the extension "
                                "says)\n",
                                options_.file_name, cardreader::format_name(options_.format),
                                cardreader::format_name(found->format), found->why,
                                cardreader::format_name(found->format),
                                cardreader::format_name(options_.format)));
    }
    options_.format = found->format;
}

void InputDeck::rewind() {
    in_->clear();
    in_->seekg(0);
    source_ = cardreader::open_card_source(*in_, options_);
}

std::vector<int> tool_numbers(const axes::MachineProfile& profile) {
    std::vector<int> numbers;
    for (const axes::Tool& t : profile.tools) {
        numbers.push_back(t.number);
    }
    return numbers;
}

cardreader::PressLimits press_limits(const axes::MachineProfile& profile) {
    cardreader::PressLimits limits;
    limits.strokes_per_min = profile.press.strokes_per_min;
    limits.pulses_per_degree = profile.press.pulses_per_degree;
    limits.fastest_factor =
        (1.0 + std::max(0.0, profile.press.variation)) * std::max(1.0, profile.press.change_factor);
    limits.drive_max_in_per_min = profile.sync_drive.max_in_per_min;
    return limits;
}

cardreader::SpindleLimits spindle_limits(const axes::MachineProfile& profile) {
    cardreader::SpindleLimits limits;
    limits.heads.clear();
    for (const axes::SpindleHead& h : profile.spindle.heads) {
        limits.heads.push_back({h.tool, h.ratio, h.pitch_in.has_value()});
    }
    limits.max_rpm = profile.spindle.max_rpm;
    limits.drive_max_in_per_min = profile.sync_drive.max_in_per_min;
    return limits;
}

cardreader::DeckReviewer deck_reviewer(const axes::MachineProfile& profile) {
    cardreader::DeckReviewer reviewer;
    reviewer.allow_conditions(profile.condition_cards, profile.name, tool_numbers(profile));
    reviewer.allow_sync(profile.press_sync, profile.name, press_limits(profile));
    reviewer.allow_tap(profile.spindle_sync, profile.name, spindle_limits(profile));
    return reviewer;
}

void refuse_deck_errors(InputDeck& deck, const axes::MachineProfile& profile) {
    // The review `check` makes; only its deck errors matter here.
    cardreader::DeckReviewer review = deck_reviewer(profile);
    const cardreader::CardLayout& layout = *deck.options().layout;
    const std::string& file = deck.options().file_name;
    auto refuse = [&](const std::vector<cardreader::ReviewNote>& notes) {
        for (const auto& n : notes) {
            if (n.deck_error) {
                throw DeckError::at_card_column(
                    file, n.card, n.column,
                    n.message + " (refused before any motion; parsons check lists every one)");
            }
        }
    };
    while (auto card = deck.cards().next()) {
        const cardreader::DecodeResult decoded = cardreader::decode(*card, layout);
        if (!decoded) {
            review.skip(); // the reader stops the machine there: its own business (exit 3)
            continue;
        }
        refuse(review.review(decoded.orders));
    }
    refuse(review.finish());
    deck.rewind();
}

double InputDeck::fraction_read() {
    if (size_bytes_ <= 0) {
        return 0;
    }
    const auto pos = in_->tellg();
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
    return AppliedProfile::load(file).profile();
}

} // namespace parsons::cli

namespace parsons::cli {

std::vector<cardreader::Axis> apply_limits(axes::MachineProfile& profile,
                                           const std::vector<std::string>& limits) {
    std::vector<cardreader::Axis> set;
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
            if (const auto problem = number_problem(text, NumberKind::real)) {
                throw bad(*problem);
            }
            return std::strtod(text.c_str(), nullptr);
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
        set.push_back(*axis);
    }
    return set;
}

cardreader::DeckFingerprint fingerprint_deck(const std::string& path, const DeckFlags& flags,
                                             std::int64_t max_cards) {
    InputDeck deck(path, flags);
    cardreader::DeckFingerprint fingerprint;
    while (max_cards < 0 || fingerprint.cards() < max_cards) {
        auto card = deck.cards().next();
        if (!card) {
            break;
        }
        fingerprint.add(*card);
    }
    return fingerprint;
}

} // namespace parsons::cli
