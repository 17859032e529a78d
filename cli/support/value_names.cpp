#include "cli/support/value_names.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/hollerith.hpp"
#include "cardreader/layout.hpp"

#include <algorithm>

namespace parsons::cli {
namespace {

std::vector<std::string> split(const std::string& text, char by) {
    std::vector<std::string> parts;
    std::string part;
    for (const char c : text) {
        if (c == by) {
            parts.push_back(part);
            part.clear();
        } else {
            part += c;
        }
    }
    parts.push_back(part);
    return parts;
}

void add_unique(std::vector<std::string>& to, const std::string& word) {
    if (!word.empty() && std::find(to.begin(), to.end(), word) == to.end()) {
        to.push_back(word);
    }
}

// One alternative of a type name ("FILE.json", ".nc", "DECK", "{a,b}") into `choices`.
void read_alternative(const std::string& alt, ValueChoices& choices) {
    if (alt.size() >= 2 && alt.front() == '{' && alt.back() == '}') {
        for (const std::string& w : split(alt.substr(1, alt.size() - 2), ',')) {
            add_unique(choices.words, w);
        }
    } else if (alt == kDeckValue) {
        for (cardreader::DeckFormat f : cardreader::kDeckFormats) {
            for (std::string_view e : cardreader::format_extensions(f)) {
                add_unique(choices.extensions, std::string(e));
            }
        }
    } else if (alt == kProfileValue) {
        for (const char* name : axes::kBuiltinProfiles) {
            add_unique(choices.words, name);
        }
        add_unique(choices.extensions, "json");
    } else if (alt == kAirfoilValue) {
        for (std::string_view name : kBundledAirfoils) {
            add_unique(choices.words, std::string(name));
        }
    } else if (alt == kDirValue) {
        choices.folders = true;
    } else if (alt == "FILE") {
        choices.any_file = true;
    } else if (alt.rfind("FILE.", 0) == 0) {
        add_unique(choices.extensions, alt.substr(5));
    } else if (alt.size() > 1 && alt.front() == '.') {
        add_unique(choices.extensions, alt.substr(1)); // FILE.ngc|.nc: the kinds after the first
    }
}

} // namespace

std::string file_value(std::span<const std::string_view> extensions) {
    std::string s = "FILE";
    for (std::string_view e : extensions) {
        s += (s == "FILE" ? "." : "|.") + std::string(e);
    }
    return s;
}

std::string file_value(std::initializer_list<std::string_view> extensions) {
    return file_value(std::span<const std::string_view>(extensions.begin(), extensions.size()));
}

std::string one_of(const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) {
        s += (s.empty() ? "" : ",") + w;
    }
    return "{" + s + "}";
}

std::string deck_formats(const std::vector<std::string>& more) {
    std::vector<std::string> words;
    for (cardreader::DeckFormat f : cardreader::kDeckFormats) {
        words.emplace_back(cardreader::format_name(f));
    }
    words.insert(words.end(), more.begin(), more.end());
    return one_of(words);
}

std::string code_names() {
    std::vector<std::string> words;
    for (cardreader::KeypunchCode c : cardreader::kKeypunchCodes) {
        words.emplace_back(cardreader::code_name(c));
    }
    return one_of(words);
}

std::string layout_names() {
    return one_of(
        std::vector<std::string>(cardreader::kLayoutNames.begin(), cardreader::kLayoutNames.end()));
}

ValueChoices value_choices(const std::string& type_name) {
    ValueChoices choices;
    // CLI11 joins each validator's description after a ':' ("TEXT:{cards,ribbon}",
    // "INT:INT in [1 - 101]"); a set of words is one of them.
    for (const std::string& piece : split(type_name, ':')) {
        for (const std::string& alt : split(piece, '|')) {
            read_alternative(alt, choices);
        }
    }
    return choices;
}

} // namespace parsons::cli
