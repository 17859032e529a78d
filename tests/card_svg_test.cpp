#include "cardreader/card_svg.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <regex>

using namespace parsons::cardreader;
using parsons::test::count;

namespace {

Card sample_card() {
    Card card;
    card.set_column(1, row_bit(Row::r0));
    card.set_column(2, row_bit(Row::r0) | row_bit(Row::r12));
    card.set_column(12, row_bit(Row::r8));
    card.set_column(80, row_bit(Row::r1));
    card.set_column(40, row_bit(Row::r12) | row_bit(Row::r8) | row_bit(Row::r4)); // '<'
    return card;
}

} // namespace

TEST_CASE("Card picture: one rectangular hole per punch, the digits 0-9 printed in every column",
          "[svg]") {
    const Card card = sample_card();
    const std::string svg = card_svg(card, fig8_layout(), {"test card", std::nullopt});
    int holes = 0;
    for (int c = 1; c <= 80; ++c) {
        holes += hole_count(card.column(c));
    }
    CHECK(count(svg, "<rect x=") == static_cast<std::size_t>(holes));
    // 800 printed digits plus the interpretation characters and labels.
    const std::regex digit(R"(<text x="[0-9.]+" y="[0-9.]+">[0-9]</text>)");
    const auto printed =
        std::distance(std::sregex_iterator(svg.begin(), svg.end(), digit), std::sregex_iterator());
    CHECK(printed >= 800);
    CHECK(count(svg, "<svg") == 1);
    CHECK(count(svg, "</svg>") == 1);
    CHECK(count(svg, "<g") == count(svg, "</g>"));
}

TEST_CASE("Card picture: the keypunch interpretation along the top is escaped XML", "[svg]") {
    const std::string svg = card_svg(sample_card(), fig8_layout(), {"a < b & c", std::nullopt});
    CHECK(svg.find("y=\"11\">&lt;</text>") != std::string::npos); // column 40 prints '<'
    CHECK(svg.find("a &lt; b &amp; c") != std::string::npos);
    CHECK(svg.find("a < b") == std::string::npos);
}

TEST_CASE("Card picture: field names, axis sections and the clipped corner are drawn", "[svg]") {
    const std::string svg = card_svg(Card{}, fig8_layout(), {"blank", std::nullopt});
    for (const char* label : {"TABLE", "CROSS", "VERTICAL", "SWIVEL", "TILT", "SLOW 1", "SLOW 2",
                              "STOP", "CHECK", "CARD NO.", "SPINDLE", "MOTION", "SPEED"}) {
        INFO(label);
        CHECK(svg.find(std::string(">") + label + "<") != std::string::npos);
    }
    CHECK(svg.find("M 25 0 H 737.5 V 325 H 0 V 43 Z") != std::string::npos);
    CHECK(count(svg, "&#215;") == 25); // five cross marks for each of five axes
}

TEST_CASE("Card picture: a bad punch is outlined and named under the card", "[svg]") {
    const std::string svg =
        card_svg(sample_card(), fig8_layout(), {"bad", BadPunch{12, "double punch"}});
    CHECK(count(svg, "stroke=\"#d01c1c\"") == 1);
    CHECK(svg.find("bad punch, column 12: double punch") != std::string::npos);
}
