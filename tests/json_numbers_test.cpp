// Numbers as people write them (docs/report.md, "Figures are rounded to what they resolve"):
// a figure rounded to its places is the nearest double to that decimal
// (outputs/report/figures.hpp), and every JSON file is written with each number in the shortest
// text that reads back to the same double (axes/json_text.hpp), where nlohmann's Grisu2 writes
// 17 digits for about one double in a thousand.
#include "axes/json_text.hpp"
#include "outputs/report/figures.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>

using parsons::axes::json_text;
using parsons::axes::shortest_numbers;
using parsons::cli::angle_deg;
using parsons::cli::counter_reading;
using parsons::cli::decimals;
using parsons::cli::fine_length;
using parsons::cli::time_s;

namespace {

// Under the sanitizers (some ten times slower) a tenth of the random sample.
#ifdef PARSONS_SANITIZE
constexpr int kSamples = 20000;
#else
constexpr int kSamples = 200000;
#endif

// Digits after the point of a number's text, its exponent counted in ("6e-05": 5).
int places_of(const std::string& text) {
    const auto e = text.find_first_of("eE");
    const std::string mantissa = text.substr(0, e);
    const int exponent = e == std::string::npos ? 0 : std::stoi(text.substr(e + 1));
    const auto point = mantissa.find('.');
    int digits = point == std::string::npos ? 0 : static_cast<int>(mantissa.size() - point - 1);
    if (point != std::string::npos) {
        while (digits > 0 && mantissa[point + static_cast<std::size_t>(digits)] == '0') {
            --digits; // "1.50" has one decimal that counts
        }
    }
    return std::max(0, digits - exponent);
}

} // namespace

TEST_CASE("JSON numbers: a figure rounded to its places is written in no more than those places, "
          "and reads back to the rounded value",
          "[json][report]") {
    // The report's own example: 88.194111 s, which a product by 1e-6 held as 88.19411099999999.
    CHECK(json_text(nlohmann::json(time_s(88.19411099999999))) == "88.194111");
    CHECK(json_text(nlohmann::json(fine_length(0.0014600000000000001))) == "0.00146");
    CHECK(json_text(nlohmann::json(counter_reading(8.384999999999998))) == "8.385");
    CHECK(json_text(nlohmann::json(angle_deg(-14.036200000000001))) == "-14.0362");
    CHECK(json_text(nlohmann::json(time_s(0.09999999999999999))) == "0.1");
    // Rounding, not cutting: half a unit goes up, and -0 is never written.
    CHECK(counter_reading(1.0005000001) == 1.001);
    CHECK(counter_reading(1.0004999) == 1.0);
    CHECK(json_text(nlohmann::json(counter_reading(-0.0004))) == "0.0");
    CHECK(std::isnan(decimals(std::numeric_limits<double>::quiet_NaN(), 3)));
    CHECK(decimals(std::numeric_limits<double>::infinity(), 3) ==
          std::numeric_limits<double>::infinity());
    // A value past what its places can change is left as it is.
    CHECK(decimals(1e300, 6) == 1e300);

    std::mt19937_64 rng(1952);
    std::uniform_real_distribution<double> seconds(0.0, 50000.0);
    std::uniform_real_distribution<double> inches(-40.0, 40.0);
    for (int i = 0; i < kSamples; ++i) {
        INFO("sample " << i);
        const double t = time_s(seconds(rng));
        const std::string ts = json_text(nlohmann::json(t));
        REQUIRE(places_of(ts) <= 6);
        REQUIRE(std::strtod(ts.c_str(), nullptr) == t);
        const double x = fine_length(inches(rng));
        const std::string xs = json_text(nlohmann::json(x));
        REQUIRE(places_of(xs) <= 5);
        REQUIRE(std::strtod(xs.c_str(), nullptr) == x);
    }
}

TEST_CASE("JSON numbers: every number is written in its shortest text that reads back to the same "
          "double, and only numbers change",
          "[json]") {
    // The case that needs it: nlohmann writes 17 digits for 336.915222 (this checks that it
    // still does, so that the next line tests something).
    const double t = 336915222 / 1e6;
    CHECK(nlohmann::json(t).dump() == "336.91522200000003");
    CHECK(json_text(nlohmann::json(t)) == "336.915222");
    // Inside a document, at every depth, and in the indented form.
    const nlohmann::json doc = {{"cards", {{{"start_seconds", t}}, {{"start_seconds", 1.5}}}},
                                {"n", 12345678901234567LL},
                                {"name", "336.91522200000003 \"0.30000000000000004\""},
                                {"x", -0.0}};
    CHECK(json_text(doc) == "{\"cards\":[{\"start_seconds\":336.915222},{\"start_seconds\":1.5}],"
                            "\"n\":12345678901234567,"
                            "\"name\":\"336.91522200000003 \\\"0.30000000000000004\\\"\","
                            "\"x\":-0.0}");
    CHECK(json_text(doc, 2).find("\"start_seconds\": 336.915222\n") != std::string::npos);
    // A number that needs all its digits keeps them: a different double is never written.
    CHECK(shortest_numbers("[0.30000000000000004,6.000000000000001e-05,1e+300]") ==
          "[0.30000000000000004,6.000000000000001e-05,1e+300]");
    CHECK(shortest_numbers("[0.10000000000000001, 2.0000000000000000]") == "[0.1, 2.0]");

    // Every bit kept, never longer than nlohmann's text: random doubles of every size.
    std::mt19937_64 rng(436887);
    int shortened = 0;
    for (int i = 0; i < kSamples; ++i) {
        INFO("sample " << i);
        double v = 0;
        if (i % 2 == 0) {
            const std::uint64_t bits = rng();
            std::memcpy(&v, &bits, sizeof v);
            if (!std::isfinite(v)) {
                continue;
            }
        } else {
            v = static_cast<double>(rng() % 100000000000ULL) / 1e6; // a microsecond figure
        }
        const std::string theirs = nlohmann::json(v).dump();
        const std::string ours = json_text(nlohmann::json(v));
        REQUIRE(std::strtod(ours.c_str(), nullptr) == v);
        REQUIRE(ours.size() <= theirs.size());
        shortened += ours.size() < theirs.size() ? 1 : 0;
        if (i % 2 == 1) {
            REQUIRE(places_of(ours) <= 6);
        }
    }
    CHECK(shortened > 20); // Grisu2's misses are there to be mended (about 0.1 %)
}
