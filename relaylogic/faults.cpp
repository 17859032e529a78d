#include "relaylogic/faults.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {
namespace {

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const auto colon = s.find(':', start);
        parts.push_back(s.substr(start, colon - start));
        if (colon == std::string::npos) {
            return parts;
        }
        start = colon + 1;
    }
}

std::int64_t count_from_1(const std::string& spec, const std::string& text, const char* what) {
    if (text.empty() || text.size() > 9 ||
        text.find_first_not_of("0123456789") != std::string::npos || std::stol(text) < 1) {
        throw FaultSpecError(
            fmt::format("--fault '{}': {} must be a count from 1 to 999999999", spec, what));
    }
    return std::stol(text);
}

cardreader::Axis axis_of(const std::string& spec, const std::string& text) {
    auto a = cardreader::axis_named(text);
    if (!a) {
        throw FaultSpecError(fmt::format("--fault '{}': unknown axis '{}' (table, cross, vertical, "
                                         "swivel or tilt)",
                                         spec, text));
    }
    return *a;
}

constexpr const char* kForms =
    "drop-impulse:AXIS:N, stuck-relay:AXIS:BANK:DIGIT, dead-relay:AXIS:BANK:DIGIT, "
    "skip-step:AXIS:SWITCH:N, feed-twice:N, swap-cards:N, short-card:N, slip:AXIS:N:M, "
    "stale-ratio:N or transfer-hang:N";

} // namespace

Fault drop_impulse(cardreader::Axis axis, std::int64_t impulse) {
    Fault f;
    f.kind = FaultKind::drop_impulse;
    f.axis = axis;
    f.n = impulse;
    f.spec = fmt::format("drop-impulse:{}:{}", cardreader::axis_name(axis), impulse);
    return f;
}

Fault parse_fault(const std::string& spec) {
    const std::vector<std::string> p = split(spec);
    auto expect = [&](std::size_t parts, const char* form) {
        if (p.size() != parts) {
            throw FaultSpecError(fmt::format("--fault '{}': expected {}", spec, form));
        }
    };
    Fault f;
    f.spec = spec;
    const std::string& kind = p.at(0);
    if (kind == "drop-impulse") {
        expect(3, "drop-impulse:AXIS:N (e.g. drop-impulse:table:120)");
        f.kind = FaultKind::drop_impulse;
        f.axis = axis_of(spec, p[1]);
        f.n = count_from_1(spec, p[2], "N");
    } else if (kind == "stuck-relay" || kind == "dead-relay") {
        expect(4, "stuck-relay:AXIS:BANK:DIGIT or dead-relay:AXIS:BANK:DIGIT (e.g. "
                  "stuck-relay:table:354:7)");
        f.kind = kind == "stuck-relay" ? FaultKind::stuck_relay : FaultKind::dead_relay;
        f.axis = axis_of(spec, p[1]);
        const std::vector<std::string> banks = {"350", "352", "354", "356",
                                                "318", "320", "322", "324"};
        if (std::find(banks.begin(), banks.end(), p[2]) == banks.end()) {
            throw FaultSpecError(fmt::format("--fault '{}': BANK is one of 350, 352, 354, 356 "
                                             "(absolute storage) or 318, 320, 322, 324 "
                                             "(incremental storage)",
                                             spec));
        }
        f.numeral = std::stoi(p[2]);
        if (p[3].size() != 1 || p[3][0] < '0' || p[3][0] > '9') {
            throw FaultSpecError(fmt::format("--fault '{}': DIGIT is a relay 0-9", spec));
        }
        f.digit = p[3][0] - '0';
    } else if (kind == "skip-step") {
        expect(4, "skip-step:AXIS:SWITCH:N (e.g. skip-step:table:110:300)");
        f.kind = FaultKind::skip_step;
        f.axis = axis_of(spec, p[1]);
        const std::vector<std::string> switches = {"104", "106", "108", "110",
                                                   "310", "312", "314", "316"};
        if (std::find(switches.begin(), switches.end(), p[2]) == switches.end()) {
            throw FaultSpecError(fmt::format("--fault '{}': SWITCH is one of 104, 106, 108, 110 "
                                             "(absolute counter) or 310, 312, 314, 316 "
                                             "(increment counter)",
                                             spec));
        }
        f.numeral = std::stoi(p[2]);
        f.n = count_from_1(spec, p[3], "N");
    } else if (kind == "feed-twice" || kind == "swap-cards" || kind == "short-card") {
        expect(2, "feed-twice:N, swap-cards:N or short-card:N (N: the card's place in the deck)");
        f.kind = kind == "feed-twice"   ? FaultKind::feed_twice
                 : kind == "swap-cards" ? FaultKind::swap_cards
                                        : FaultKind::short_card;
        f.n = count_from_1(spec, p[1], "N");
    } else if (kind == "stale-ratio" || kind == "transfer-hang") {
        expect(2, "stale-ratio:N (N: the head exchange, from 1) or transfer-hang:N (N: the gear "
                  "ratio transfer, from 1)");
        f.kind = kind == "stale-ratio" ? FaultKind::stale_ratio : FaultKind::transfer_hang;
        f.n = count_from_1(spec, p[1], "N");
    } else if (kind == "slip") {
        expect(4, "slip:AXIS:N:M (e.g. slip:table:2000:25, 0.025 in of screw travel from the "
                  "2000th impulse)");
        f.kind = FaultKind::slip;
        f.axis = axis_of(spec, p[1]);
        f.n = count_from_1(spec, p[2], "N");
        f.count = count_from_1(spec, p[3], "M");
        if (f.count > 10000) {
            throw FaultSpecError(fmt::format("--fault '{}': M is at most 10000 (thousandths of "
                                             "screw travel: the counters' whole 10 inches)",
                                             spec));
        }
    } else {
        throw FaultSpecError(fmt::format("--fault '{}': unknown fault (one of {})", spec, kForms));
    }
    return f;
}

FaultyFeed::FaultyFeed(cardreader::CardSource& deck, std::vector<Fault> faults,
                       std::vector<FaultEffect*> effects)
    : deck_(deck), faults_(std::move(faults)), effects_(std::move(effects)) {}

std::optional<cardreader::Card> FaultyFeed::pull() {
    auto card = deck_.next();
    if (!card) {
        return card;
    }
    ++pulled_;
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        if (f.kind == FaultKind::short_card && f.n == pulled_) {
            for (int c = 61; c <= cardreader::kColumns; ++c) {
                card->set_column(c, 0);
            }
            effects_[i]->acted = true;
            effects_[i]->effect = fmt::format("card {} of the deck was short: columns 61-80 never "
                                              "reached the brushes",
                                              pulled_);
        }
    }
    return card;
}

std::optional<cardreader::Card> FaultyFeed::next() {
    if (again_) {
        auto card = again_;
        again_.reset();
        return card;
    }
    const std::int64_t position = pulled_ + 1;
    auto card = pull();
    if (!card) {
        return card;
    }
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        if (f.kind == FaultKind::feed_twice && f.n == position) {
            again_ = card;
            effects_[i]->acted = true;
            effects_[i]->effect = fmt::format("card {} of the deck was fed twice", position);
        } else if (f.kind == FaultKind::swap_cards && f.n == position) {
            auto following = pull();
            if (following) {
                again_ = card;
                card = following;
                effects_[i]->acted = true;
                effects_[i]->effect = fmt::format("cards {} and {} of the deck were fed in the "
                                                  "other order",
                                                  position, position + 1);
            }
        }
    }
    return card;
}

} // namespace parsons::relaylogic
