// Drawing a property case, shrinking a failing one, and telling it (tests/property_test.cpp).
#include "tests/property/property_case.hpp"

#include "tests/property/key_ranges.hpp"
#include "tests/test_support.hpp"

#include "axes/profile_json.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>

namespace parsons::test {
namespace {

using nlohmann::json;

// SplitMix64: each case's generators seeded from its own seed, well apart.
std::uint32_t property_seed_mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<std::uint32_t>(x ^ (x >> 31));
}

// The value at a dotted key ("axes.table.speed_in_per_min[1]"), or null where the file has none.
json* find_profile_key(json& j, const std::string& key) {
    json* at = &j;
    std::size_t from = 0;
    while (from <= key.size()) {
        const std::size_t dot = std::min(key.find('.', from), key.size());
        std::string part = key.substr(from, dot - from);
        int index = -1;
        if (const auto bracket = part.find('['); bracket != std::string::npos) {
            index = std::stoi(part.substr(bracket + 1));
            part = part.substr(0, bracket);
        }
        if (!at->is_object() || !at->contains(part)) {
            return nullptr;
        }
        at = &(*at)[part];
        if (index >= 0) {
            if (!at->is_array() || static_cast<int>(at->size()) <= index) {
                return nullptr;
            }
            at = &(*at)[static_cast<std::size_t>(index)];
        }
        from = dot + 1;
    }
    return at;
}

// The keys of `full` whose values differ from `base`'s; objects compared key by key, arrays whole.
json differences_from_named(const json& full, const json& base) {
    json out = json::object();
    for (const auto& [key, value] : full.items()) {
        if (!base.contains(key)) {
            out[key] = value;
            continue;
        }
        const json& named = base.at(key);
        if (value.is_object() && named.is_object()) {
            json d = differences_from_named(value, named);
            if (!d.empty()) {
                out[key] = d;
            }
        } else if (value != named) {
            out[key] = value;
        }
    }
    return out;
}

// The lowest and highest values in range (an exclusive bound stepped inside).
std::pair<double, double> inside_range(const KeyRange& r) {
    const double lo = r.min_exclusive ? r.min + std::max(1e-6, std::abs(r.min) * 1e-6) : r.min;
    const double hi = r.max_exclusive ? r.max - std::max(1e-6, std::abs(r.max) * 1e-6) : r.max;
    if (r.kind == KeyRange::Kind::integer) {
        return {std::ceil(lo), std::floor(hi)};
    }
    return {lo, hi};
}

// A new value for the key, within its range: near the value it had, anywhere, spread over the
// decades, or at either end. False when it leaves the value as it was.
bool redraw_key(json& value, const KeyRange& r, std::mt19937& rng) {
    auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    auto real = [&rng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    if (r.kind == KeyRange::Kind::boolean) {
        value = !(value.is_boolean() && value.get<bool>());
        return true;
    }
    if (r.kind == KeyRange::Kind::choice) {
        value =
            r.choices.at(static_cast<std::size_t>(pick(0, static_cast<int>(r.choices.size()) - 1)));
        return true;
    }
    const auto [lo, hi] = inside_range(r);
    const double was = value.is_number() ? value.get<double>() : (lo + hi) / 2;
    double x = was;
    switch (pick(0, 9)) {
    case 0:
    case 1:
    case 2:
    case 3:
        x = was != 0 ? was * std::exp(real(std::log(0.5), std::log(2.0))) : real(lo, hi);
        break;
    case 4:
    case 5:
        x = real(lo, hi);
        break;
    case 6:
        x = lo > 0 ? std::exp(real(std::log(lo), std::log(hi))) : real(lo, hi);
        break;
    case 7:
        x = lo;
        break;
    case 8:
        x = hi;
        break;
    default:
        return false;
    }
    x = std::clamp(x, lo, hi);
    if (r.kind == KeyRange::Kind::integer) {
        value = static_cast<std::int64_t>(std::llround(x));
    } else {
        value = x;
    }
    return true;
}

// A value just past one end of the key's range.
void past_range(json& value, const KeyRange& r, std::mt19937& rng) {
    const bool below = std::bernoulli_distribution(0.5)(rng);
    if (r.kind == KeyRange::Kind::integer) {
        value = static_cast<std::int64_t>(below ? r.min - 1 : r.max + 1);
        return;
    }
    const double step = std::max(1e-3, std::abs(below ? r.min : r.max) * 0.01);
    if (below) {
        value = r.min_exclusive ? r.min : r.min - step;
    } else {
        value = r.max_exclusive ? r.max : r.max + step;
    }
}

void collect_leaf_keys(const json& j, const std::string& prefix, std::vector<std::string>& out) {
    for (const auto& [key, value] : j.items()) {
        const std::string path = prefix.empty() ? key : prefix + "." + key;
        if (value.is_object()) {
            collect_leaf_keys(value, path, out);
        } else if (path != "name") {
            out.push_back(path);
        }
    }
}

// Removes a dotted leaf key, and any object it leaves empty.
void erase_profile_key(json& j, const std::string& key) {
    const auto dot = key.find('.');
    if (dot == std::string::npos) {
        j.erase(key);
        return;
    }
    const std::string head = key.substr(0, dot);
    if (j.contains(head) && j.at(head).is_object()) {
        erase_profile_key(j.at(head), key.substr(dot + 1));
        if (j.at(head).empty()) {
            j.erase(head);
        }
    }
}

std::string deck_extension_of(cardreader::DeckFormat f) {
    return std::string(".") + std::string(cardreader::format_name(f));
}

} // namespace

std::vector<std::string> profile_keys(const json& profile) {
    std::vector<std::string> keys;
    collect_leaf_keys(profile, "", keys);
    return keys;
}

PropertyCase draw_case(std::uint64_t seed, int deep_every) {
    PropertyCase c;
    c.seed = seed;
    std::mt19937 rng(property_seed_mix(seed * 8 + 0));
    std::mt19937 crng(property_seed_mix(seed * 8 + 1));
    std::mt19937 srng(property_seed_mix(seed * 8 + 2));
    std::mt19937 trng(property_seed_mix(seed * 8 + 3));
    std::mt19937 prng(property_seed_mix(seed * 8 + 4));
    auto pick = [&prng](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(prng);
    };
    c.deck = random_case(rng, crng, srng, trng);
    const std::array<const char*, 3> bases = {"parsons-1952", "parsons-safe", "parsons-extended"};
    const std::string base = bases.at(static_cast<std::size_t>(pick(0, 2)));
    json full = json::parse(axes::profile_to_json(c.deck.profile));
    const std::vector<KeyRange>& ranges = key_ranges();
    const int redrawn = pick(0, 4) == 0 ? 0 : pick(1, 4);
    for (int i = 0; i < redrawn; ++i) {
        const KeyRange& r =
            ranges.at(static_cast<std::size_t>(pick(0, static_cast<int>(ranges.size()) - 1)));
        json* value = find_profile_key(full, r.key);
        if (value != nullptr && redraw_key(*value, r, prng)) {
            c.drawn.push_back(loader_key(r.key));
        }
    }
    if (pick(0, 99) < 6) {
        std::vector<const KeyRange*> ranged;
        for (const KeyRange& r : ranges) {
            if ((r.kind == KeyRange::Kind::number || r.kind == KeyRange::Kind::integer) &&
                r.max_documented) {
                ranged.push_back(&r);
            }
        }
        const KeyRange& r =
            *ranged.at(static_cast<std::size_t>(pick(0, static_cast<int>(ranged.size()) - 1)));
        if (json* value = find_profile_key(full, r.key)) {
            past_range(*value, r, prng);
            c.out_of_range = loader_key(r.key);
        }
    }
    const json named = json::parse(axes::profile_to_json(*axes::builtin_profile(base)));
    c.profile = differences_from_named(full, named);
    c.profile.erase("name");
    json file = json{{"name", base}};
    file.update(c.profile);
    c.profile = file;
    c.deep = deep_every > 0 && pick(1, deep_every) == 1;
    c.interrupt_card = pick(1, std::max(1, static_cast<int>(c.deck.cards.size())));
    return c;
}

PropertyCase shrink(const PropertyCase& c, const Violation& v, int budget) {
    PropertyCase best = c;
    auto still_fails = [&](const PropertyCase& trial) {
        if (budget-- <= 0) {
            return false;
        }
        const auto w = check_case(trial);
        return w && w->invariant == v.invariant;
    };
    bool progress = true;
    while (progress && budget > 0) {
        progress = false;
        for (std::size_t i = best.deck.faults.size(); i-- > 0;) {
            PropertyCase trial = best;
            trial.deck.faults.erase(trial.deck.faults.begin() + static_cast<long>(i));
            if (still_fails(trial)) {
                best = trial;
                progress = true;
            }
        }
        if (!best.deck.extra_punches.empty()) {
            PropertyCase trial = best;
            trial.deck.extra_punches.clear();
            if (still_fails(trial)) {
                best = trial;
                progress = true;
            }
        }
        for (std::size_t i = best.deck.cards.size(); i-- > 0 && best.deck.cards.size() > 1;) {
            PropertyCase trial = best;
            trial.deck.cards.erase(trial.deck.cards.begin() + static_cast<long>(i));
            auto& punches = trial.deck.extra_punches;
            punches.erase(std::remove_if(punches.begin(), punches.end(),
                                         [i](const auto& p) { return std::get<0>(p) == i; }),
                          punches.end());
            for (auto& p : punches) {
                std::get<0>(p) -= std::get<0>(p) > i ? 1 : 0;
            }
            trial.interrupt_card = std::min<std::int64_t>(
                trial.interrupt_card, static_cast<std::int64_t>(trial.deck.cards.size()));
            if (still_fails(trial)) {
                best = trial;
                progress = true;
            }
        }
        for (const std::string& key : profile_keys(best.profile)) {
            PropertyCase trial = best;
            erase_profile_key(trial.profile, key);
            if (still_fails(trial)) {
                best = trial;
                progress = true;
            }
        }
    }
    return best;
}

std::string describe(const PropertyCase& c) {
    std::string text =
        fmt::format("seed {} (PARSONS_PROPERTY_REPLAY={} replays it)\n", c.seed, c.seed);
    text += "profile.json: " + c.profile.dump() + "\n";
    if (!c.out_of_range.empty()) {
        text += "drawn past its range: " + c.out_of_range + "\n";
    }
    for (const auto& f : c.deck.faults) {
        text += "--fault " + f.spec + "\n";
    }
    if (c.deep) {
        text += fmt::format("deep: impulse level, and a run cut as card {} is fed, resumed\n",
                            c.interrupt_card);
    }
    text +=
        fmt::format("deck{} ({} cards{}):\n", deck_extension_of(c.deck.medium), c.deck.cards.size(),
                    c.deck.extra_punches.empty() ? "" : ", double punches made");
    try {
        text += deck_bytes(punched_cards(c.deck), cardreader::DeckFormat::listing);
    } catch (const std::exception& e) {
        text += std::string("(no listing: ") + e.what() + ")\n";
    }
    return text;
}

void write_case(const PropertyCase& c, const std::string& dir) {
    std::filesystem::create_directories(dir);
    const std::filesystem::path d(dir);
    write_bytes(d / "profile.json", c.profile.dump(2) + "\n");
    const auto punched = punched_cards(c.deck);
    write_bytes(d / ("deck" + deck_extension_of(c.deck.medium)),
                deck_bytes(punched, c.deck.medium));
    std::string faults;
    for (const auto& f : c.deck.faults) {
        faults += f.spec + "\n";
    }
    write_bytes(d / "faults.txt", faults);
    write_bytes(d / "case.txt", describe(c));
}

} // namespace parsons::test
