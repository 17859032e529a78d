#include "cli/support/sweep_grid.hpp"

#include "cli/support/deck_files.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>

namespace parsons::cli {

namespace {

using cardreader::DeckError;

bool key_character(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
}

// KEY=REST, the key checked.
std::pair<std::string, std::string> split_key(const std::string& spec, const std::string& option,
                                              const char* form) {
    const auto eq = spec.find('=');
    if (eq == std::string::npos || eq == 0) {
        throw DeckError(fmt::format("{} '{}': not {}", option, spec, form));
    }
    std::string key = spec.substr(0, eq);
    for (const char c : key) {
        if (!key_character(c)) {
            throw DeckError(fmt::format("{} '{}': the key '{}' has a character '{}' that no key "
                                        "has (keys are gen's options without the dashes, or "
                                        "profile.SECTION.KEY)",
                                        option, spec, key, c));
        }
    }
    return {key, spec.substr(eq + 1)};
}

// A whole number of the text, or nothing.
bool read_number(const std::string& text, double& value) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) != 0) {
        return false;
    }
    char* end = nullptr;
    errno = 0;
    value = std::strtod(text.c_str(), &end);
    return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
}

// A value of A:B:N, printed to 12 significant digits (0.1:0.3:3 gives 0.2 and 0.3, not
// 0.30000000000000004).
std::string grid_value(double v) {
    double shortened = std::strtod(fmt::format("{:.12g}", v).c_str(), nullptr);
    if (shortened == 0) {
        shortened = 0; // never "-0"
    }
    return fmt::format("{}", shortened);
}

std::vector<std::string> range_values(const std::string& option, const std::string& spec,
                                      const std::string& range) {
    const auto c1 = range.find(':');
    const auto c2 = range.find(':', c1 + 1);
    double a = 0;
    double b = 0;
    double n = 0;
    if (c2 == std::string::npos || range.find(':', c2 + 1) != std::string::npos ||
        !read_number(range.substr(0, c1), a) ||
        !read_number(range.substr(c1 + 1, c2 - c1 - 1), b) ||
        !read_number(range.substr(c2 + 1), n)) {
        throw DeckError(fmt::format("{} '{}': a range is A:B:N, three numbers (N values from A "
                                    "to B)",
                                    option, spec));
    }
    if (n != std::floor(n) || n < 2 || n > static_cast<double>(kMaxSweepCases)) {
        throw DeckError(fmt::format("{} '{}': N must be a whole number from 2 to {}", option, spec,
                                    kMaxSweepCases));
    }
    const auto count = static_cast<long>(n);
    std::vector<std::string> values;
    values.reserve(static_cast<std::size_t>(count));
    for (long i = 0; i < count; ++i) {
        const double v =
            i == count - 1 ? b
                           : a + (b - a) * static_cast<double>(i) / static_cast<double>(count - 1);
        values.push_back(grid_value(v));
    }
    return values;
}

} // namespace

SweepKey parse_set(const std::string& spec) {
    auto [key, value] = split_key(spec, "--set", "KEY=VALUE");
    return {key, {value}, "--set " + spec};
}

SweepKey parse_vary(const std::string& spec) {
    auto [key, rest] = split_key(spec, "--vary", "KEY=V1,V2,... or KEY=A:B:N");
    SweepKey k{key, {}, "--vary " + spec};
    if (rest.find(',') == std::string::npos && rest.find(':') != std::string::npos) {
        k.values = range_values("--vary", spec, rest);
        return k;
    }
    std::size_t start = 0;
    while (true) {
        const auto comma = rest.find(',', start);
        k.values.push_back(rest.substr(start, comma - start));
        if (comma == std::string::npos) {
            break;
        }
        start = comma + 1;
    }
    for (const std::string& v : k.values) {
        if (v.empty()) {
            throw DeckError(fmt::format("--vary '{}': an empty value in the list", spec));
        }
    }
    return k;
}

SweepGrid expand_grid(const std::string& family, const std::vector<SweepKey>& keys) {
    SweepGrid grid;
    std::size_t total = 1;
    std::set<std::string> seen;
    for (const SweepKey& k : keys) {
        if (!seen.insert(k.key).second) {
            throw DeckError(fmt::format("{}: the key '{}' is given twice", k.given, k.key));
        }
        grid.keys.push_back(k.key);
        total *= k.values.size();
        if (total > kMaxSweepCases) {
            throw DeckError(
                fmt::format("{}: the grid would have more than {} cases", k.given, kMaxSweepCases));
        }
    }
    grid.cases.reserve(total);
    std::vector<std::size_t> at(keys.size(), 0);
    for (std::size_t n = 0; n < total; ++n) {
        SweepCase c{static_cast<long>(n + 1), family, {}};
        for (std::size_t i = 0; i < keys.size(); ++i) {
            c.values.push_back(keys[i].values[at[i]]);
        }
        grid.cases.push_back(std::move(c));
        for (std::size_t i = keys.size(); i-- > 0;) { // the last key varies fastest
            if (++at[i] < keys[i].values.size()) {
                break;
            }
            at[i] = 0;
        }
    }
    return grid;
}

std::string csv_field(const std::string& text) {
    const bool quote = text.find_first_of(",\"\r\n") != std::string::npos ||
                       (!text.empty() && (text.front() == ' ' || text.back() == ' '));
    if (!quote) {
        return text;
    }
    std::string out = "\"";
    for (const char c : text) {
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    }
    return out + "\"";
}

std::string grid_csv(const SweepGrid& grid) {
    std::string out = "case,family";
    for (const std::string& k : grid.keys) {
        out += ',';
        out += csv_field(k);
    }
    out += "\n";
    for (const SweepCase& c : grid.cases) {
        out += fmt::format("{},{}", c.number, csv_field(c.family));
        for (const std::string& v : c.values) {
            out += ',';
            out += csv_field(v);
        }
        out += "\n";
    }
    return out;
}

namespace {

// One line of a cases file split into its fields (RFC 4180 quotes within the line).
std::vector<std::string> split_row(const std::string& line, const std::string& where) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                fields.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                fields.back() += c;
            }
        } else if (c == '"' && fields.back().empty()) {
            quoted = true;
        } else if (c == ',') {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    if (quoted) {
        throw DeckError(where + ": a quoted field has no closing quote");
    }
    return fields;
}

} // namespace

SweepGrid read_cases(const std::string& path) {
    const std::string text = read_text_file(path, "cannot open the cases file");
    SweepGrid grid;
    std::set<long> numbers;
    std::size_t line_no = 0;
    std::size_t start = 0;
    bool header = true;
    while (start < text.size()) {
        auto end = text.find('\n', start);
        if (end == std::string::npos) {
            end = text.size();
        }
        std::string line = text.substr(start, end - start);
        start = end + 1;
        ++line_no;
        if (!line.empty() && line.back() == '\r') {
            line.pop_back();
        }
        const std::string where = fmt::format("{}:{}", path, line_no);
        if (line.empty()) {
            continue;
        }
        const auto fields = split_row(line, where);
        if (header) {
            if (fields.size() < 2 || fields[0] != "case" || fields[1] != "family") {
                throw DeckError(where + ": not a cases file (its first line must begin "
                                        "\"case,family\", as sweep --cases-out writes it)");
            }
            grid.keys.assign(fields.begin() + 2, fields.end());
            for (std::size_t k = 0; k < grid.keys.size(); ++k) {
                if (std::count(grid.keys.begin(), grid.keys.begin() + static_cast<long>(k),
                               grid.keys[k]) != 0) {
                    throw DeckError(
                        fmt::format("{}: the key '{}' is there twice", where, grid.keys[k]));
                }
            }
            header = false;
            continue;
        }
        if (fields.size() != grid.keys.size() + 2) {
            throw DeckError(fmt::format("{}: {} fields where the header has {}", where,
                                        fields.size(), grid.keys.size() + 2));
        }
        double number = 0;
        if (!read_number(fields[0], number) || number != std::floor(number) || number < 1 ||
            number > 1e9) {
            throw DeckError(
                fmt::format("{}: case '{}' is not a case number (1, 2, ...)", where, fields[0]));
        }
        if (!numbers.insert(static_cast<long>(number)).second) {
            throw DeckError(fmt::format("{}: case {} is there twice", where, fields[0]));
        }
        if (fields[1].empty()) {
            throw DeckError(where + ": the case has no family");
        }
        if (grid.cases.size() >= kMaxSweepCases) {
            throw DeckError(fmt::format("{}: more than {} cases", where, kMaxSweepCases));
        }
        grid.cases.push_back(
            {static_cast<long>(number), fields[1], {fields.begin() + 2, fields.end()}});
    }
    if (header) {
        throw DeckError(path + ": empty file: no cases");
    }
    return grid;
}

} // namespace parsons::cli
