#include "tests/docs_figures.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>

namespace parsons::test {
namespace fs = std::filesystem;

namespace {

struct FigureSource {
    std::string command;
    std::string file;
    std::string selector;
    std::string format;
};

std::string format_figure(double value, std::string format) {
    const bool grouped = !format.empty() && format.back() == ',';
    if (grouped) {
        format.pop_back();
    }
    if (format == "min") { // seconds, as whole minutes
        value /= 60;
        format = "int";
    } else if (format == "MB") { // bytes, as whole megabytes
        value /= 1e6;
        format = "int";
    }
    // "±.2f": always signed, the minus as the typographic one the pages use (−0.83).
    const bool signed_figure = format.rfind("±", 0) == 0;
    if (signed_figure) {
        format = "+" + format.substr(std::string("±").size());
    }
    std::string text = format == "int" ? std::to_string(std::llround(value))
                                       : fmt::format(fmt::runtime("{:" + format + "}"), value);
    if (signed_figure && text.front() == '-') {
        text = "−" + text.substr(1);
    }
    if (grouped) {
        const auto point = text.find('.');
        auto digits_end = point == std::string::npos ? text.size() : point;
        const std::size_t first = text.front() == '-' ? 1 : 0;
        for (auto at = digits_end; at > first + 3; at -= 3) {
            text.insert(at - 3, ",");
        }
    }
    return text;
}

double select_figure(const fs::path& file, const std::string& selector) {
    const std::string bytes = read_bytes(file);
    if (selector == "bytes") {
        return static_cast<double>(bytes.size());
    }
    if (selector == "lines") {
        return static_cast<double>(
            std::count_if(bytes.begin(), bytes.end(), [](char c) { return c == '\n'; }));
    }
    if (selector == "rows") {
        long rows = -1; // the header
        for (const std::string& l : lines_of(bytes)) {
            rows += l.find_first_not_of(" \t") != std::string::npos && l.front() != '#' ? 1 : 0;
        }
        return static_cast<double>(rows);
    }
    // "event:SIGNAL=NEW#N": the time of the Nth change of SIGNAL to NEW in an events stream;
    // "...#N.old": the value it changed from.
    static const std::regex event(R"(^event:([^=]+)=(-?\d+)#(\d+)(\.old)?$)");
    std::smatch m;
    if (std::regex_match(selector, m, event)) {
        int seen = 0;
        for (const std::string& l : lines_of(bytes)) {
            const auto e = nlohmann::json::parse(l);
            if (e.value("signal", "") == std::string(m[1]) && e.contains("new") &&
                e.at("new") == std::stol(m[2]) && ++seen == std::stoi(m[3])) {
                return m[4].matched ? e.at("old").get<double>() : e.at("t").get<double>();
            }
        }
        FAIL("no such event in " << file.string() << ": " << selector);
    }
    return nlohmann::json::parse(bytes).at(nlohmann::json::json_pointer(selector)).get<double>();
}

} // namespace

void check_figures(std::vector<std::string>& lines, const std::string& relative,
                   const std::function<ProcessResult(const std::string&)>& run,
                   const std::filesystem::path& folder, bool updating, bool& changed,
                   int& figures) {
    static const std::regex declared(
        R"(^<!-- figure ([a-z0-9_-]+): (.+) => (\S+) (\S+) (\S+) -->$)");
    static const std::regex quoted(R"(<!--f:([a-z0-9_-]+)-->([^<]*)<!--/f-->)");
    std::map<std::string, FigureSource> sources;
    for (const std::string& l : lines) {
        std::smatch m;
        if (std::regex_match(l, m, declared)) {
            sources[m[1]] = {m[2], m[3], m[4], m[5]};
        }
    }
    std::map<std::string, std::string> values;
    std::set<std::string> ran; // a command several figures share runs once
    for (const auto& [name, src] : sources) {
        if (ran.insert(src.command).second) {
            const ProcessResult r = run(src.command);
            INFO(relative << ": figure " << name << ": " << src.command << "\n" << r.output);
            REQUIRE(r.exit_code == 0);
        }
        values[name] = format_figure(select_figure(folder / src.file, src.selector), src.format);
    }
    std::set<std::string> used;
    for (std::string& l : lines) {
        std::string out;
        auto from = l.cbegin();
        for (std::sregex_iterator it(l.cbegin(), l.cend(), quoted), end; it != end; ++it) {
            const std::string name = (*it)[1];
            INFO(relative << ": figure " << name << " in: " << l);
            REQUIRE(values.count(name) == 1); // every quoted figure is declared
            used.insert(name);
            ++figures;
            std::string text = (*it)[2];
            if (updating) {
                changed = changed || text != values[name];
                text = values[name];
            } else {
                CHECK(text == values[name]);
            }
            out.append(from, (*it)[0].first);
            out += "<!--f:" + name + "-->" + text + "<!--/f-->";
            from = (*it)[0].second;
        }
        out.append(from, l.cend());
        l = out;
    }
    for (const auto& [name, src] : sources) {
        INFO(relative << ": figure " << name << " is declared and never quoted");
        CHECK(used.count(name) == 1);
    }
}

} // namespace parsons::test
