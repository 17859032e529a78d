// Opening deck files for the subcommands: format from the extension or a flag, clear errors.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "cli/support/cli11_fwd.hpp"

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace parsons::cli {

// The flags every command that reads a deck shares.
struct DeckFlags {
    std::string format; // empty: from the extension
    std::string code = "029";
    std::string layout = "fig8";
    // No option sets it: `parsons bench` alone raises it (cardreader::DeckOptions::max_cards).
    std::int64_t max_cards = cardreader::kMaxDeckCards;
};

void add_input_flags(CLI::App& cmd, DeckFlags& flags);

// Resolves format (flag or extension), keypunch code and layout; throws DeckError. The
// message for a missing format names `option` (--format for an input, --to for an output).
cardreader::DeckOptions deck_options(const std::string& path, const std::string& format_flag,
                                     const DeckFlags& flags,
                                     const std::string& option = "--format");

// The whole of a text file (never more than 64 MiB); throws DeckError naming the file when it
// cannot be opened, with `missing` as the reason, or the system's reason when `missing` is empty.
std::string read_text_file(const std::string& file, const std::string& missing = {});
// The same, with "-" read as standard input (a command whose --help promises it). Either
// refuses a folder and reads at most 64 MiB (a device such as /dev/zero never ends).
std::string read_text_input(const std::string& file);

// The built-in machine profile FILE names, or the profile file FILE applied over the built-in
// profile its "name" names (else the default); throws DeckError naming the file and the key on
// a bad profile. AppliedProfile (applied_profile.hpp) keeps where each value came from.
axes::MachineProfile load_profile(const std::string& file);
// --limit AXIS=MIN:MAX (repeatable): the soft limits of the job, over the profile's. Returns
// the axis of each spec, in order.
std::vector<cardreader::Axis> apply_limits(axes::MachineProfile& profile,
                                           const std::vector<std::string>& limits);

// --feed cards|ribbon over the profile's ribbon_feed; a continuous format (tape) always feeds as
// a ribbon, and --feed cards on one is refused (DeckError).
void apply_feed(axes::MachineProfile& profile, const std::string& feed,
                const cardreader::DeckOptions& deck);

// An open input deck: the file and its card reader. The name "-" is standard input, its
// format given by --format or told from its first bytes.
class PipedInput;

class InputDeck {
public:
    InputDeck(const std::string& path, const DeckFlags& flags);
    ~InputDeck();
    InputDeck(const InputDeck&) = delete;
    InputDeck& operator=(const InputDeck&) = delete;
    cardreader::CardSource& cards() { return *source_; }
    const cardreader::DeckOptions& options() const { return options_; }
    // How far through the file the reader is, 0..1 (for a progress bar).
    double fraction_read();
    // Back to the first card (a deck read through once before the run, as run's check of
    // condition cards does). A FIFO or device is read whole at opening so that this works.
    void rewind();

private:
    void content_outranks_extension(const std::string& head);
    void open_source();

    std::unique_ptr<std::istream> in_;
    PipedInput* piped_ = nullptr; // standard input, a FIFO or a device: in_'s buffer
    double size_bytes_ = 0;
    cardreader::DeckOptions options_;
    std::unique_ptr<cardreader::CardSource> source_;
};

// Condition, sync and tap cards (additions): the deck's first deck error (relaylogic cannot take
// it: a condition, sync or tap card the profile does not allow, a duplicate event, a condition
// on an axis its motion card does not move, a condition or sync card with no motion card after
// it, speed sync on an axis that does not move or faster than the sync drive follows, a loop to
// a card the deck does not hold, a tap with a tool no spindle head holds, a speed above motor
// 27's fastest or a feed the follower drive cannot follow) as a DeckError naming file, card and
// column, read before any card runs; the deck is rewound after.
void refuse_deck_errors(InputDeck& deck, const axes::MachineProfile& profile);
// The name run_command.cpp calls: the same as refuse_deck_errors (condition, sync and tap
// cards).
inline void refuse_condition_errors(InputDeck& deck, const axes::MachineProfile& profile) {
    refuse_deck_errors(deck, profile);
}
// The review's view of the profile's press and sync drive (sync cards).
cardreader::PressLimits press_limits(const axes::MachineProfile& profile);
// The review's view of the profile's spindle heads, motor 27 and follower drive (tap cards).
cardreader::SpindleLimits spindle_limits(const axes::MachineProfile& profile);
// A DeckReviewer for `profile`: its condition units, press sync and spindle sync.
cardreader::DeckReviewer deck_reviewer(const axes::MachineProfile& profile);
// The numbers of the tools the profile's changer holds (for the condition cards' review).
std::vector<int> tool_numbers(const axes::MachineProfile& profile);

// The fingerprint of the first `max_cards` cards of a deck (all of them when negative).
cardreader::DeckFingerprint fingerprint_deck(const std::string& path, const DeckFlags& flags,
                                             std::int64_t max_cards = -1);

} // namespace parsons::cli
