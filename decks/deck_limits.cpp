// The refusals of decks/deck_limits.hpp, their wording in one place.
#include "decks/deck_limits.hpp"

#include "decks/template_job.hpp"

#include <fmt/format.h>

#include <cmath>

namespace parsons::decks {

static_assert(kLeastShapeIn == 0.1 && kLeastCutterRadiusIn == 0.001,
              "a user's 0.1 and 0.001 are at the limits, not under them");

std::string count_text(std::int64_t count) {
    const std::string digits = std::to_string(count < 0 ? -count : count);
    std::string text;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) {
            text += ',';
        }
        text += digits[i];
    }
    return count < 0 ? "-" + text : text;
}

void refuse_past_deck_limit(std::int64_t cards, const std::string& what, bool at_least,
                            const std::string& detail) {
    if (cards <= kMaxDeckCards) {
        return;
    }
    throw JobError(fmt::format("{}: the deck would need {}{} cards{}, more than the {} a deck can "
                               "number (card numbers are four digits, columns 77-80)",
                               what, at_least ? "at least " : "", count_text(cards),
                               detail.empty() ? "" : " (" + detail + ")",
                               count_text(kMaxDeckCards)));
}

void refuse_unless_finite(const std::string& option, double value) {
    if (!std::isfinite(value)) {
        throw JobError(fmt::format("{} {}: give a finite number", option, value));
    }
}

void refuse_unless_shape(const std::string& option, double value_in, const std::string& what) {
    refuse_unless_finite(option, value_in);
    if (!(value_in >= kLeastShapeIn)) {
        throw JobError(fmt::format("{} {}: a {} under {:.3f} in is no shape to the machine, which "
                                   "moves in impulses of {:.3f} in: give at least {:.3f} in, a "
                                   "hundred impulses",
                                   option, value_in, what, kLeastShapeIn, kImpulseIn,
                                   kLeastShapeIn));
    }
}

void refuse_unless_cutter(const std::string& option, double radius_in) {
    refuse_unless_finite(option, radius_in);
    if (!(radius_in >= kLeastCutterRadiusIn)) {
        throw JobError(fmt::format("{} {}: a cutter radius under {:.3f} in is less than one "
                                   "impulse, the smallest move the machine makes, so the path "
                                   "could not be offset by it: give at least {:.3f} in",
                                   option, radius_in, kLeastCutterRadiusIn, kLeastCutterRadiusIn));
    }
}

} // namespace parsons::decks
