#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/listing_format.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using namespace parsons::cardreader;

namespace {

const std::string kHeader = "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n";

// A valid card 1, one row per axis, with `replace` substituted for the row of `axis`.
std::string card_rows(int number, const std::string& axis = "", const std::string& replace = "") {
    std::string rows;
    for (Axis a : kAxes) {
        if (axis_name(a) == axis) {
            rows += replace;
            continue;
        }
        rows +=
            std::to_string(number) + ",0," + std::string(axis_name(a)) + ",+,3,,,1.000,1.000,1\n";
    }
    return rows;
}

std::string listing_read_error(const std::string& bytes) {
    return parsons::test::read_error(bytes, DeckFormat::listing, "deck.csv");
}

// Listing -> cards (.cbn bytes) -> listing text.
std::string round_trip(const std::string& listing) {
    std::istringstream in(listing);
    DeckOptions in_options;
    in_options.format = DeckFormat::listing;
    in_options.file_name = "in.csv";
    auto source = open_card_source(in, in_options);
    std::ostringstream cbn;
    auto cbn_sink = make_cbn_sink(cbn, "deck.cbn");
    while (auto card = source->next()) {
        cbn_sink->write(*card);
    }
    std::istringstream cbn_in(cbn.str());
    auto cbn_source = make_cbn_source(cbn_in, "deck.cbn");
    std::ostringstream out;
    auto listing_sink = make_listing_sink(out, "out.csv", fig8_layout());
    while (auto card = cbn_source->next()) {
        listing_sink->write(*card);
    }
    return out.str();
}

} // namespace

TEST_CASE("Listing: a valid listing reads, comments, blank lines and CRLF are allowed",
          "[listing]") {
    const std::string text =
        "# a comment\n" + kHeader + "\r\n" + card_rows(1) + "  # indented comment\n" + card_rows(2);
    CHECK(listing_read_error(text) == "no error");
}

TEST_CASE("Listing: random valid listings survive listing -> .cbn -> listing unchanged",
          "[listing][cbn]") {
    std::mt19937 rng(1949);
    for (int deck = 0; deck < 40; ++deck) {
        std::string listing = std::string(kListingHeader) + "\n";
        const int cards = 1 + static_cast<int>(rng() % 12);
        for (int i = 0; i < cards; ++i) {
            CardOrders orders = parsons::test::random_orders(rng, fig8_layout());
            for (Axis a : kAxes) {
                listing += listing_row(orders, a) + "\n";
            }
        }
        INFO(listing);
        CHECK(round_trip(listing) == listing);
    }
}

TEST_CASE("Listing: a row with an unknown axis names file and line", "[listing][bad-input]") {
    CHECK(listing_read_error(kHeader + card_rows(1, "cross", "1,0,crosss,+,3,,,1.000,1.000,1\n")) ==
          "deck.csv:3: unknown axis 'crosss' (table, cross, vertical, swivel or tilt)");
}

TEST_CASE("Listing: a value over 9.999 is refused", "[listing][bad-input]") {
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,+,3,,,10.000,1.000,1\n")) ==
          "deck.csv:2: stop '10.000': over 9.999 inches (the four-digit counters and storage "
          "banks hold 0.000 .. 9.999)");
}

TEST_CASE("Listing: a value without three decimals is refused", "[listing][bad-input]") {
    CHECK(
        listing_read_error(kHeader + card_rows(1, "tilt", "1,0,tilt,+,2,8.78,,9.000,1.000,5\n")) ==
        "deck.csv:6: slow1 '8.78': needs exactly three decimals, d.ddd (the card holds "
        "thousandths)");
    CHECK(listing_read_error(kHeader + card_rows(1, "tilt", "1,0,tilt,+,3,,,1,1.000,5\n")) ==
          "deck.csv:6: stop '1': needs exactly three decimals, d.ddd (the card holds thousandths)");
    CHECK(listing_read_error(kHeader + card_rows(1, "tilt", "1,0,tilt,+,3,,,1.0x0,1.000,5\n")) ==
          "deck.csv:6: stop '1.0x0': not a number of inches (write d.ddd, e.g. 8.785)");
}

TEST_CASE("Listing: a card with an axis row missing names the card and the axis",
          "[listing][bad-input]") {
    CHECK(listing_read_error(kHeader + card_rows(1, "vertical", "") + card_rows(2)) ==
          "deck.csv:6: card 2 begins, but card 1 (from line 2) has no row for the vertical axis");
    CHECK(listing_read_error(kHeader + card_rows(1, "tilt", "")) ==
          "deck.csv:5: card 1 (from line 2) ends without a row for the tilt axis");
}

TEST_CASE("Listing: a card with an axis row repeated names both lines", "[listing][bad-input]") {
    CHECK(listing_read_error(kHeader + card_rows(1, "swivel", "1,0,table,+,3,,,1.000,1.000,1\n")) ==
          "deck.csv:5: card 1 has a second row for the table axis (first on line 2)");
}

TEST_CASE("Listing: a second slow-down where the layout has none names the row",
          "[listing][bad-input]") {
    CHECK(listing_read_error(kHeader +
                             card_rows(1, "cross", "1,0,cross,+,1,0.800,0.900,1.000,1.000,1\n")) ==
          "deck.csv:3: layout fig8 has no second slow-down field for the cross axis (only the "
          "table has two)");
}

TEST_CASE("Listing: other malformed rows are named by line", "[listing][bad-input]") {
    CHECK(listing_read_error("card,axis\n") ==
          "deck.csv:1: expected the header line "
          "'card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq' first: its field 2 is "
          "'axis', not 'spindle'");
    CHECK(listing_read_error(kHeader + "1,0,table,+,3\n") ==
          "deck.csv:2: expected 10 comma-separated fields "
          "(card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq), found 5");
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,*,3,,,1.000,1.000,1\n")) ==
          "deck.csv:2: motion '*' is not + (forward) or - (reverse)");
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,+,4,,,1.000,1.000,1\n")) ==
          "deck.csv:2: speed '4' is not 1, 2 or 3");
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,+,3,,,1.000,1.000,16\n")) ==
          "deck.csv:2: sequence position '6' is not 1..5");
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,+,3,,,1.000,,1\n")) ==
          "deck.csv:2: check is blank (stop and check are always punched)");
    CHECK(listing_read_error(kHeader + card_rows(1, "cross", "1,1,cross,+,3,,,1.000,1.000,1\n")) ==
          "deck.csv:3: card 1: spindle reverse here but forward on line 2 (one spindle column a "
          "card)");
    CHECK(listing_read_error(kHeader +
                             card_rows(1, "table", "12345,0,table,+,3,,,1.000,1.000,1\n")) ==
          "deck.csv:2: card number '12345' is not 0..9999");
    CHECK(listing_read_error(kHeader + card_rows(1, "table", "1,0,table,+,3,,,-1.000,1.000,1\n")) ==
          "deck.csv:2: stop '-1.000': inches are never negative (the motion column gives the "
          "direction)");
}

TEST_CASE("Listing: an empty file, or a header alone, is an error", "[listing][bad-input]") {
    CHECK(listing_read_error("") == "deck.csv: empty file: the deck has no cards");
    CHECK(listing_read_error(kHeader) == "deck.csv: no cards: the file holds nothing but a header, "
                                         "comments, blank lines or blank tape");
}

TEST_CASE("Listing: a spreadsheet's UTF-8 byte-order mark is read past", "[listing]") {
    const std::string listing = kHeader + card_rows(1);
    CHECK(round_trip("\xEF\xBB\xBF" + listing) == round_trip(listing));
    // Only at the very start: anywhere else it is a bad field.
    CHECK(listing_read_error(kHeader + "\xEF\xBB\xBF" + card_rows(1)) != "no error");
}

TEST_CASE("Listing: a header with a typo names the wrong word", "[listing][bad-input]") {
    CHECK(listing_read_error("card,spindle,axsi,motion,speed,slow1,slow2,stop,check,seq\n") ==
          "deck.csv:1: expected the header line "
          "'card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq' first: its field 3 is "
          "'axsi', not 'axis'");
    CHECK(listing_read_error("card,spindle,axis,motion,speed,slow1,slow2,stop,check\n") ==
          "deck.csv:1: expected the header line "
          "'card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq' first: it has 9 fields, "
          "not 10");
}
