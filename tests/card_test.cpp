#include "cardreader/card.hpp"

#include <catch2/catch.hpp>

using namespace parsons::cardreader;

TEST_CASE("Card: rows 12, 11, 0..9 sit in bits 11..0 of the column word", "[card]") {
    CHECK(row_bit(Row::r12) == 0x800);
    CHECK(row_bit(Row::r11) == 0x400);
    CHECK(row_bit(Row::r0) == 0x200);
    CHECK(row_bit(Row::r9) == 0x001);
    CHECK(row_bit(digit_row(5)) == 0x010);
}
