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
#include <array>
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

// The most a deck read from a pipe or device may hold before its card past 9,999: 9,999
// cards of any format take far less (a listing row a card and axis, 4,096 bytes a line at
// most, is the longest); only endless comments or blank lines come here.
constexpr std::size_t kMostPipedBytes = std::size_t{64} << 20;

// The whole of `in`, at most kMostPipedBytes (a device such as /dev/zero never ends).
std::string read_bounded(std::istream& in, const std::string& name) {
    std::string text;
    std::array<char, 65536> chunk{};
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
        if (text.size() > kMostPipedBytes) {
            throw DeckError::in_file(name, fmt::format("more than {} MiB: no program, profile or "
                                                       "job parsons reads is that long",
                                                       kMostPipedBytes >> 20));
        }
    }
    if (in.bad()) {
        throw DeckError::in_file(name, "read error");
    }
    return text;
}

} // namespace

// Standard input, a FIFO or a device, kept as it is read so that it can be read again from
// the start; it reads nothing more than its readers ask, and at most kMostPipedBytes.
class PipedInput : public std::streambuf {
public:
    PipedInput(std::istream* source, std::unique_ptr<std::istream> owned)
        : source_(source), owned_(std::move(owned)) {
        setg(data_.data(), data_.data(), data_.data());
    }
    bool over() const { return over_; }
    bool failed() const { return source_->bad(); }

protected:
    int_type underflow() override {
        if (gptr() < egptr()) {
            return traits_type::to_int_type(*gptr());
        }
        const auto pos = static_cast<std::size_t>(gptr() - eback());
        if (pos >= data_.size() && !done_) {
            if (data_.size() >= kMostPipedBytes) {
                over_ = true;
                done_ = true;
            } else {
                std::array<char, 4096> chunk{};
                source_->read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
                const auto n = static_cast<std::size_t>(source_->gcount());
                done_ = n == 0;
                data_.append(chunk.data(), n);
            }
        }
        setg(data_.data(), data_.data() + pos, data_.data() + data_.size());
        return gptr() < egptr() ? traits_type::to_int_type(*gptr()) : traits_type::eof();
    }
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        if (dir == std::ios_base::cur) {
            return seekpos(gptr() - eback() + off, std::ios_base::in);
        }
        return dir == std::ios_base::beg ? seekpos(off, std::ios_base::in) : pos_type(-1);
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode) override {
        if (pos < 0 || static_cast<std::size_t>(pos) > data_.size()) {
            return pos_type(-1);
        }
        setg(data_.data(), data_.data() + static_cast<std::size_t>(pos),
             data_.data() + data_.size());
        return pos;
    }

private:
    std::istream* source_;
    std::unique_ptr<std::istream> owned_;
    std::string data_;
    bool done_ = false;
    bool over_ = false;
};

// An istream over a PipedInput it owns.
class PipedStream : public std::istream {
public:
    explicit PipedStream(std::unique_ptr<PipedInput> buf)
        : std::istream(buf.get()), buf_(std::move(buf)) {}

private:
    std::unique_ptr<PipedInput> buf_;
};

// The readers' cards from a PipedInput: past kMostPipedBytes, the deck is refused.
class PipedSource : public cardreader::CardSource {
public:
    PipedSource(std::unique_ptr<cardreader::CardSource> inner, const PipedInput& piped,
                std::string file)
        : inner_(std::move(inner)), piped_(piped), file_(std::move(file)) {}
    std::optional<cardreader::Card> next() override {
        std::optional<cardreader::Card> card;
        try {
            card = inner_->next();
        } catch (const DeckError&) {
            refuse_if_over();
            throw;
        }
        if (!card) {
            refuse_if_over();
        }
        return card;
    }
    int cards_a_step() const override { return inner_->cards_a_step(); }

private:
    void refuse_if_over() const {
        if (piped_.over()) {
            throw DeckError::in_file(
                file_, fmt::format("more than {} MiB read and still no end of the deck: no deck "
                                   "of 9,999 cards is that long (endless comments or blank "
                                   "lines?)",
                                   kMostPipedBytes >> 20));
        }
    }

    std::unique_ptr<cardreader::CardSource> inner_;
    const PipedInput& piped_;
    std::string file_;
};

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
    options.max_cards = flags.max_cards;
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
    std::unique_ptr<std::istream> file_stream;
    std::istream* source = &std::cin;
    if (path == "-") {
        options_.file_name = "standard input";
    } else {
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec)) {
            throw DeckError::in_file(path, "is a directory, not a deck");
        }
        file_stream = std::make_unique<std::ifstream>(path, std::ios::binary);
        if (!*file_stream) {
            throw DeckError::in_file(path, std::string("cannot open: ") + std::strerror(errno));
        }
        source = file_stream.get();
    }
    std::error_code regular_ec;
    if (path != "-" && std::filesystem::is_regular_file(path, regular_ec)) {
        head.resize(kHeadBytes);
        source->read(head.data(), static_cast<std::streamsize>(head.size()));
        head.resize(static_cast<std::size_t>(source->gcount()));
        source->clear();
        source->seekg(0);
        std::error_code ec;
        size_bytes_ = static_cast<double>(std::filesystem::file_size(path, ec));
        in_ = std::move(file_stream);
    } else {
        // Standard input, a FIFO or a device: kept as it is read (so that the deck can be read
        // twice, rewind), never more than the readers take: they stop at the card past 9,999,
        // and at kMostPipedBytes of lines that hold no card.
        auto piped = std::make_unique<PipedInput>(source, std::move(file_stream));
        head.resize(kHeadBytes);
        head.resize(static_cast<std::size_t>(
            piped->sgetn(head.data(), static_cast<std::streamsize>(head.size()))));
        piped->pubseekpos(0);
        if (piped->failed()) {
            throw DeckError::in_file(options_.file_name, "read error");
        }
        piped_ = piped.get();
        in_ = std::make_unique<PipedStream>(std::move(piped));
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
            say(stderr, "parsons: warning: " + cardreader::visible_text(what) + "\n");
        }
    };
    open_source();
}

// The readers' cards; from a pipe, a deck that goes on past kMostPipedBytes without reaching
// its card past 9,999 is refused there (the pipe's end is not the deck's).
void InputDeck::open_source() {
    source_ = cardreader::open_card_source(*in_, options_);
    if (piped_ != nullptr) {
        source_ = std::make_unique<PipedSource>(std::move(source_), *piped_, options_.file_name);
    }
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
    open_source();
}

InputDeck::~InputDeck() = default;

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
    reviewer.allow_segments(profile.contouring, profile.name);
    return reviewer;
}

namespace {

// Whether any card of the deck is an addition's (column 76's mark), read through, not decoded.
bool has_extension_card(InputDeck& deck, const cardreader::CardLayout& layout) {
    while (const auto card = deck.cards().next()) {
        if (cardreader::is_extension_card(*card, layout)) {
            return true;
        }
    }
    return false;
}

} // namespace

void refuse_deck_errors(InputDeck& deck, const axes::MachineProfile& profile) {
    const cardreader::CardLayout& layout = *deck.options().layout;
    // The review finds deck errors only on the additions' cards (condition, sync and tap cards,
    // marked in the extension column) and on the motion cards that follow one. A deck with none
    // is read through (a card that cannot be read is refused here as before) and not decoded:
    // the run decodes each card once (issue 51).
    const bool extension = has_extension_card(deck, layout);
    deck.rewind();
    if (!extension) {
        return;
    }
    // The review `check` makes; only its deck errors matter here.
    cardreader::DeckReviewer review = deck_reviewer(profile);
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
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        throw DeckError::in_file(file, "is a directory, not a file");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw DeckError::in_file(
            file, missing.empty() ? std::string("cannot open: ") + std::strerror(errno) : missing);
    }
    return read_bounded(in, file);
}

std::string read_text_input(const std::string& file) {
    return file == "-" ? read_bounded(std::cin, "standard input") : read_text_file(file);
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
