#include "cardreader/deck_error.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/text_format.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <sstream>
#include <vector>

using namespace parsons::cardreader;

namespace {

// The cards of `text`; each warning the reader gives goes into `warnings` when one is given.
std::vector<Card> read_text(const std::string& text, KeypunchCode code = KeypunchCode::ibm029,
                            std::vector<std::string>* warnings = nullptr) {
    std::istringstream in(text);
    DeckOptions options;
    options.format = DeckFormat::text;
    options.file_name = "deck.txt";
    options.code = code;
    if (warnings != nullptr) {
        options.warn = [warnings](const std::string& w) { warnings->push_back(w); };
    }
    auto source = open_card_source(in, options);
    std::vector<Card> cards;
    while (auto c = source->next()) {
        cards.push_back(*c);
    }
    return cards;
}

std::string text_error(const std::string& text) {
    return parsons::test::read_error(text, DeckFormat::text, "deck.txt");
}

ColumnWord ch(char c) {
    return *punches_for(c, KeypunchCode::ibm029);
}

} // namespace

TEST_CASE("Text cards: a short line is padded with blanks, a blank line is a blank card",
          "[text]") {
    auto cards = read_text("AB\n\nC");
    REQUIRE(cards.size() == 3);
    CHECK(cards[0].column(1) == ch('A'));
    CHECK(cards[0].column(2) == ch('B'));
    CHECK(cards[0].column(3) == 0);
    CHECK(cards[1].blank());
    CHECK(cards[2].column(1) == ch('C'));
}

TEST_CASE("Text cards: a tab moves to the next multiple of 8 columns, as SIMH does", "[text]") {
    auto cards = read_text("A\tB\t\tC\n");
    REQUIRE(cards.size() == 1);
    CHECK(cards[0].column(1) == ch('A'));
    CHECK(cards[0].column(9) == ch('B'));
    CHECK(cards[0].column(25) == ch('C'));
    for (int c : {2, 8, 10, 24}) {
        CHECK(cards[0].column(c) == 0);
    }
}

TEST_CASE("Text cards: lower case is folded to upper case", "[text]") {
    auto cards = read_text("parsons\n");
    REQUIRE(cards.size() == 1);
    CHECK(cards[0] == read_text("PARSONS\n")[0]);
}

TEST_CASE("Text cards: CRLF line ends read the same as LF", "[text]") {
    CHECK(read_text("AB\r\nCD\r\n") == read_text("AB\nCD\n"));
    CHECK(text_error("AB\rCD\n") == "deck.txt:1:3: carriage return inside a line");
}

TEST_CASE("Text cards: text past column 80 is dropped as SIMH drops it, with one warning naming "
          "the line",
          "[text][bad-input]") {
    const std::string eighty(80, 'X');
    std::vector<std::string> warnings;
    const auto cards = read_text("OK\n" + eighty + "\n" + eighty + "{}~ seq 0010\n" +
                                     std::string(79, ' ') + "\tX\n" + eighty + "Y\n",
                                 KeypunchCode::ibm029, &warnings);
    REQUIRE(cards.size() == 5);
    CHECK(cards[2] == cards[1]); // the 80 columns, the rest dropped unread ('{' and '~' too)
    CHECK(cards[3].column(80) == 0);
    CHECK(cards[3].column(79) == 0);
    CHECK(cards[4] == cards[1]);
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0] == "deck.txt:3: text past column 80 dropped, as SIMH drops it (a card has 80 "
                         "columns); the same on any later line, not told again");
    warnings.clear();
    read_text(eighty + "\n", KeypunchCode::ibm029, &warnings);
    CHECK(warnings.empty()); // exactly 80 columns is a whole card
    SECTION("a line of more than 4,096 bytes is no card image") {
        CHECK(text_error(std::string(4096, 'A') + "\n") == "no error");
        CHECK(text_error("A\n" + std::string(4097, 'A')) ==
              "deck.txt:2: line is longer than 4096 bytes: no card image is (an endless line or "
              "not a text deck)");
    }
}

TEST_CASE("Text cards: a UTF-8 byte-order mark at the start is read past, as in a listing",
          "[text]") {
    CHECK(read_text("\xEF\xBB\xBF"
                    "AB\nC\n") == read_text("AB\nC\n"));
    CHECK(read_text("\xEF\xBB\xBF") == read_text("\n")); // the mark alone: one blank line
    // Only at the start: elsewhere its first byte is no keypunch character.
    CHECK(text_error("A\n\xEF\xBB\xBF\n") ==
          "deck.txt:2:1: byte 0xef is not a character of the IBM 029 keypunch");
    CHECK(text_error("\xEF\xBB"
                     "A\n") ==
          "deck.txt:1:1: bytes 0xef 0xbb begin a byte-order mark that does not end (0xef 0xbb "
          "0xbf)");
}

TEST_CASE("Deck errors: control bytes a file holds are written visibly as \\xNN, never raw",
          "[text][deck-io][bad-input]") {
    CHECK(text_error("~\x1b[2J\n") ==
          "deck.txt:1:1: '~\\x1b[2J' is no SIMH control line (~raw followed by octal column "
          "words, ~eor, ~eof, ~eoi, or a lone ~); '~' is no keypunch character");
    CHECK(parsons::test::listing_error("1,0,t\x1b]0;x\x07\x7f\xff\xc2\x9b,+,3,,,1.000,1.000,1\n")
              .find("unknown axis 't\\x1b]0;x\\x07\\x7f\\xff\\xc2\\x9b'") != std::string::npos);
    // Text that is UTF-8 stays as it is, and so do tabs and line ends.
    CHECK(visible_text("caf\xC3\xA9 \xE2\x80\x94\t\n") == "caf\xC3\xA9 \xE2\x80\x94\t\n");
    CHECK(visible_text("\r\x01") == "\\x0d\\x01");
}

TEST_CASE("Text cards: a character outside the 029 set names line and column",
          "[text][bad-input]") {
    CHECK(text_error("ABC~\n") == "deck.txt:1:4: '~' is not a character of the IBM 029 keypunch");
    CHECK(text_error("A\nB\xC3\xA9\n") ==
          "deck.txt:2:2: byte 0xc3 is not a character of the IBM 029 keypunch");
    CHECK(text_error(std::string("A\0B", 3)) ==
          "deck.txt:1:2: byte 0x00 is not a character of the IBM 029 keypunch");
}

TEST_CASE("Text cards: the 026 code reads its own characters", "[text]") {
    auto cards = read_text("+(\n", KeypunchCode::ibm026);
    REQUIRE(cards.size() == 1);
    CHECK(cards[0].column(1) == row_bit(Row::r12));
    CHECK(cards[0].column(2) == (row_bit(Row::r0) | row_bit(Row::r8) | row_bit(Row::r4)));
}

TEST_CASE("Text cards: a card no keys make is written as SIMH's ~raw and read back the same",
          "[text][simh]") {
    Card card;
    card.set_column(1, ch('A'));
    card.set_column(7, row_bit(Row::r12) | row_bit(Row::r0)); // 12-0: no 029 key
    card.set_column(80, kAllRowsMask);                        // every row: a lace punch
    std::ostringstream out;
    auto sink = make_text_sink(out, "out.txt", KeypunchCode::ibm029);
    sink->write(card);
    // 80 column words of four octal digits, rows 12 .. 9: 'A' is 12-1 = 4400 octal.
    std::string expected =
        "~raw4400" + std::string(5 * 4, '0') + "5000" + std::string(72 * 4, '0') + "7777\n";
    CHECK(out.str() == expected);
    const auto back = read_text(out.str());
    REQUIRE(back.size() == 1);
    CHECK(back[0] == card);
}

TEST_CASE("Text cards: ~raw with fewer words leaves the rest blank, any case", "[text][simh]") {
    const auto cards = read_text("~RAW00070001\n~raw\n");
    REQUIRE(cards.size() == 2);
    CHECK(cards[0].column(1) == 07);
    CHECK(cards[0].column(2) == row_bit(Row::r9));
    for (int c = 3; c <= kColumns; ++c) {
        CHECK(cards[0].column(c) == 0);
    }
    CHECK(cards[1].blank());
}

TEST_CASE("Text cards: a bad ~raw line is named by line and column", "[text][simh][bad-input]") {
    CHECK(text_error("~raw0008\n") == "deck.txt:1:8: '8' in a ~raw card: each column is four "
                                      "octal digits 0-7 (rows 12-11-0 .. 7-8-9)");
    CHECK(text_error("A\n~raw00 7\n") == "deck.txt:2:7: byte 0x20 in a ~raw card: each column "
                                         "is four octal digits 0-7 (rows 12-11-0 .. 7-8-9)");
    CHECK(text_error("~raw000\n") ==
          "deck.txt:1:7: a ~raw card ends inside a column word (3 of its 4 octal digits)");
    CHECK(text_error("~raw" + std::string(320, '0') + "0\n") ==
          "deck.txt:1:325: a ~raw card has more than 80 columns (320 octal digits)");
    CHECK(read_text("~raw" + std::string(320, '1') + "\n").size() == 1);
    CHECK(text_error("~frob\n") ==
          "deck.txt:1:1: '~frob' is no SIMH control line (~raw followed by octal column words, "
          "~eor, ~eof, ~eoi, or a lone ~); '~' is no keypunch character");
}

TEST_CASE("Text cards: ~eor is the 7-8-9 card, written back as ~eor", "[text][simh]") {
    const auto cards = read_text("A\n~eor\nB\n");
    REQUIRE(cards.size() == 3);
    CHECK(cards[1].column(1) == (row_bit(Row::r7) | row_bit(Row::r8) | row_bit(Row::r9)));
    for (int c = 2; c <= kColumns; ++c) {
        CHECK(cards[1].column(c) == 0);
    }
    std::ostringstream out;
    auto sink = make_text_sink(out, "out.txt", KeypunchCode::ibm029);
    for (const Card& c : cards) {
        sink->write(c);
    }
    CHECK(out.str() == "A\n~eor\nB\n");
}

TEST_CASE("Text cards: ~eof, ~eoi and a lone ~ are passed over and the cards after them read, "
          "as SIMH reads on, with a warning naming the line only when cards follow",
          "[text][simh]") {
    auto read_warned = [](const std::string& text, std::vector<std::string>& warnings) {
        return read_text(text, KeypunchCode::ibm029, &warnings);
    };
    for (const char* mark : {"~eof", "~EOI", "~", "~  \t"}) {
        INFO(mark);
        std::vector<std::string> warnings;
        const auto cards = read_warned(std::string("A\nB\n") + mark + "\nC\nD\n", warnings);
        REQUIRE(cards.size() == 4); // the mark is no card; C and D are read
        CHECK(cards[1].column(1) == ch('B'));
        CHECK(cards[2].column(1) == ch('C'));
        CHECK(cards[3].column(1) == ch('D'));
        REQUIRE(warnings.size() == 1);
        CHECK_THAT(warnings[0], Catch::StartsWith("deck.txt:3: "));
        CHECK_THAT(warnings[0], Catch::Contains("passed over and the cards after it are read"));
        // At the end of the deck a mark only closes it, as the hopper's end: nothing to say.
        warnings.clear();
        CHECK(read_warned(std::string("A\nB\n") + mark + "\n", warnings).size() == 2);
        CHECK(warnings.empty());
    }
    std::vector<std::string> warnings;
    read_warned("A\n~eof\n~eoi\nB\n~\nC\n", warnings);
    REQUIRE(warnings.size() == 2); // one a run of marks, at its first
    CHECK_THAT(warnings[0], Catch::StartsWith("deck.txt:2: '~eof' is SIMH's end-of-file card"));
    CHECK_THAT(warnings[1], Catch::StartsWith("deck.txt:5: a lone '~' is SIMH's end-of-file"));
    // Without a listener the reader reads on all the same.
    CHECK(read_text("A\n~eof\nB\n").size() == 2);
}

TEST_CASE("Text cards: an end-of-file card of holes is written as ~raw, so that it reads back "
          "as the card and is not passed over",
          "[text][simh]") {
    Card eof_card;
    eof_card.set_column(1, 015);
    std::ostringstream out;
    auto sink = make_text_sink(out, "out.txt", KeypunchCode::ibm029);
    sink->write(eof_card);
    CHECK(out.str().starts_with("~raw0015"));
    CHECK(read_text(out.str()) == std::vector<Card>{eof_card});
}

TEST_CASE("Text cards: writing then reading gives the same cards, trailing blanks trimmed",
          "[text]") {
    std::ostringstream out;
    auto sink = make_text_sink(out, "out.txt", KeypunchCode::ibm029);
    auto cards = read_text("HELLO, 1952\n\n  X  \n");
    for (const Card& c : cards) {
        sink->write(c);
    }
    CHECK(out.str() == "HELLO, 1952\n\n  X\n");
    CHECK(read_text(out.str()) == cards);
}
