#include "cardreader/deck_error.hpp"
#include "cardreader/deck_io.hpp"

#include "cardreader/orders.hpp"
#include "tests/test_support.hpp"

#include <sys/stat.h>

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace parsons::cardreader;

TEST_CASE("Deck files: the format follows the extension", "[deck-io]") {
    CHECK(format_for_path("a/b/deck.cbn") == DeckFormat::cbn);
    CHECK(format_for_path("DECK.BIN") == DeckFormat::bin);
    CHECK(format_for_path("cards.txt") == DeckFormat::text);
    CHECK(format_for_path("cards.crd") == DeckFormat::text);
    CHECK(format_for_path("job.csv") == DeckFormat::listing);
    CHECK(format_for_path("job.lst") == DeckFormat::listing);
    CHECK_FALSE(format_for_path("dir.cbn/deck"));
    CHECK_FALSE(format_for_path("deck"));
    CHECK(format_named("listing") == DeckFormat::listing);
    CHECK_FALSE(format_named("csv"));
}

TEST_CASE("Deck files: every reader is total: random bytes give cards or a DeckError",
          "[deck-io][bad-input]") {
    std::mt19937 rng(80);
    const std::string alphabet = "0123456789,.+-\n\r\t #ABCtablecrossverticalswiveltilt";
    for (DeckFormat format :
         {DeckFormat::cbn, DeckFormat::bin, DeckFormat::text, DeckFormat::listing}) {
        for (int trial = 0; trial < 300; ++trial) {
            std::string bytes(rng() % 700, '\0');
            for (char& b : bytes) {
                b = trial % 2 == 0 ? static_cast<char>(rng()) : alphabet[rng() % alphabet.size()];
            }
            if (trial % 3 == 0 && format == DeckFormat::cbn) {
                for (std::size_t i = 0; i < bytes.size(); ++i) { // mostly well-formed
                    bytes[i] = static_cast<char>(i % 160 == 0 ? 0xC0 : 0x40);
                }
                if (!bytes.empty()) {
                    bytes[rng() % bytes.size()] = static_cast<char>(rng());
                }
            }
            std::istringstream in(bytes);
            DeckOptions options;
            options.format = format;
            options.file_name = "random";
            auto source = open_card_source(in, options);
            int cards = 0;
            try {
                while (source->next() && cards < 1000) {
                    ++cards;
                }
            } catch (const DeckError& e) {
                CHECK(std::string(e.what()).rfind("random", 0) == 0);
            }
            CHECK(cards <= 700);
        }
    }
}

TEST_CASE("Deck files: auto tells cbn, bin, text and listing from the first bytes as SIMH does",
          "[deck-io][simh]") {
    std::string cbn(160, '\x40');
    cbn[0] = static_cast<char>(0xC0);            // card-start mark, odd parity
    CHECK(sniff_format(cbn) == DeckFormat::cbn); // a blank card: .bin words too, but parity says
    cbn[5] = 0x00;                               // a parity fault: then its .bin words win
    CHECK(sniff_format(cbn) == DeckFormat::bin);
    cbn[5] = 0x01; // neither: the card-start mark still says column binary
    CHECK(sniff_format(cbn) == DeckFormat::cbn);
    std::string bin(160, '\0');
    bin[1] = static_cast<char>(0x80); // row 12 of column 1
    bin[2] = static_cast<char>(0x10); // row 9 of column 2: the low four bits stay clear
    CHECK(sniff_format(bin) == DeckFormat::bin);
    bin[2] = static_cast<char>(0x11); // a low bit set: not .bin, and not printable either
    CHECK_FALSE(sniff_format(bin));
    CHECK(sniff_format("HELLO 1952\n~raw0007\n") == DeckFormat::text);
    CHECK(sniff_format("card,spindle,axis\n") == DeckFormat::listing);
    CHECK(sniff_format("CARD,spindle,axis\n") == DeckFormat::listing);
    CHECK(sniff_format("# a listing\ncard,") == DeckFormat::listing);
    CHECK(sniff_format("\xEF\xBB\xBF"
                       "card,spindle") == DeckFormat::listing);
    // A whole first card of .bin words wins over text, as in sim_card.c (a blank card).
    CHECK(sniff_format(std::string(160, '\0')) == DeckFormat::bin);
    CHECK_FALSE(sniff_format(""));
}

TEST_CASE("Deck files: a common file that is no deck is named by its magic number",
          "[deck-io][bad-input]") {
    CHECK(non_deck_kind("\x89PNG\r\n\x1a\n....") == "a PNG image");
    CHECK(non_deck_kind("%PDF-1.7") == "a PDF document");
    CHECK(non_deck_kind(std::string("PK\x03\x04", 4)) == "a ZIP archive (an office document?)");
    CHECK(non_deck_kind("\x1f\x8b\x08") == "a gzip-compressed file (gunzip it first)");
    CHECK(non_deck_kind("<svg xmlns") == "an SVG picture");
    CHECK(non_deck_kind("$date\n  today\n$end") == "a VCD trace");
    CHECK(non_deck_kind("{\n  \"status\"") == "a JSON file (a report, a job or a state?)");
    CHECK_FALSE(non_deck_kind("card,spindle,axis"));
    CHECK_FALSE(non_deck_kind("HELLO"));
    std::string cbn(160, '\x40');
    cbn[0] = static_cast<char>(0xC0);
    CHECK_FALSE(non_deck_kind(cbn));
}

namespace {

// Two cards (one with holes in every row, one blank) written in `format` (for five cards a
// step, whose column 76 stays blank, two blank cards).
std::string two_cards_as(DeckFormat format) {
    Card full;
    for (int c = 1; c <= kColumns && format != DeckFormat::five; ++c) {
        full.set_column(c, static_cast<ColumnWord>((c * 0x111) & 0xFFF));
    }
    std::ostringstream out;
    DeckOptions options;
    options.format = format;
    options.file_name = "deck";
    auto sink = open_card_sink(out, options);
    sink->write(full);
    sink->write(Card{});
    return out.str();
}

const std::string kListingText = "# a listing\ncard,spindle,axis,motion,speed,slow1,slow2,stop,"
                                 "check,seq\n1,0,table,+,1,8.785,8.885,8.985,8.985,12\n";

} // namespace

TEST_CASE("Deck files: content outranks the extension when it plainly is another format",
          "[deck-io]") {
    struct Case {
        DeckFormat extension;
        std::string bytes;
        DeckFormat found;
        std::string why;
    };
    const std::string cbn = two_cards_as(DeckFormat::cbn);
    const std::string bin = two_cards_as(DeckFormat::bin);
    const std::string text = two_cards_as(DeckFormat::text);
    const std::string tape = std::string(5, '\0') + two_cards_as(DeckFormat::tape);
    const std::vector<Case> cases = {
        {DeckFormat::cbn, text, DeckFormat::text,
         "printable ASCII in lines of a card each, with no card-start"},
        {DeckFormat::cbn, bin, DeckFormat::bin, "320 bytes are 2 whole IBM 1130 binary cards"},
        {DeckFormat::cbn, tape, DeckFormat::tape, "after 5 blank leader frames, 160 frames"},
        {DeckFormat::cbn, kListingText, DeckFormat::listing, "line 2 is the listing's header"},
        {DeckFormat::five, text, DeckFormat::text, "printable ASCII"},
        {DeckFormat::bin, cbn, DeckFormat::cbn, "320 bytes are 2 whole column-binary cards"},
        {DeckFormat::bin, text, DeckFormat::text, "printable ASCII"},
        {DeckFormat::text, cbn, DeckFormat::cbn, "card-start mark (bit 7) on each card's first"},
        {DeckFormat::text, bin, DeckFormat::bin, "bits 3..0 of every column's first byte clear"},
        {DeckFormat::text, kListingText, DeckFormat::listing, "header 'card,spindle,axis,"},
        {DeckFormat::text, tape, DeckFormat::tape, "end-of-card frame (channel 8 alone)"},
        {DeckFormat::listing, text, DeckFormat::text, "none holds a comma, as every listing row"},
        {DeckFormat::listing, cbn, DeckFormat::cbn, "column-binary"},
        {DeckFormat::tape, cbn, DeckFormat::cbn, "column-binary"},
        {DeckFormat::tape, "HELLO 1952\n", DeckFormat::text, "first 11 bytes are printable"},
    };
    for (const Case& c : cases) {
        INFO(format_name(c.extension) << " holding " << format_name(c.found));
        const auto found = content_outranks(c.extension, c.bytes);
        REQUIRE(found);
        CHECK(found->format == c.found);
        CHECK_THAT(found->why, Catch::Matchers::Contains(c.why));
    }
}

TEST_CASE("Deck files: content that fits its extension, or no format or several, keeps the "
          "extension",
          "[deck-io]") {
    const std::string cbn = two_cards_as(DeckFormat::cbn);
    SECTION("each format under its own extension") {
        for (DeckFormat f :
             {DeckFormat::cbn, DeckFormat::bin, DeckFormat::text, DeckFormat::tape}) {
            INFO(format_name(f));
            CHECK_FALSE(content_outranks(f, two_cards_as(f)));
        }
        CHECK_FALSE(content_outranks(DeckFormat::listing, kListingText));
        CHECK_FALSE(content_outranks(DeckFormat::five, cbn)); // the same bytes as .cbn
        CHECK_FALSE(content_outranks(DeckFormat::cbn, two_cards_as(DeckFormat::five)));
    }
    SECTION("no format, or more than one") {
        // A listing whose header is mistyped still has commas: the listing reader names it.
        CHECK_FALSE(content_outranks(DeckFormat::listing, "card,spindel,axis\n1,0,table\n"));
        CHECK_FALSE(content_outranks(DeckFormat::listing, "HELLO, 1952\n"));
        // Column binary with its marks lost is of odd parity: no .bin; nor text ('@' a byte),
        // whose lines hold 80 columns at most: its reader names it.
        CHECK_FALSE(content_outranks(DeckFormat::cbn, std::string(160, '\x40')));
        CHECK_FALSE(content_outranks(DeckFormat::cbn, std::string(81, 'A') + "\n"));
        CHECK(content_outranks(DeckFormat::cbn,
                               std::string(80, 'A') + "\n~raw" + std::string(320, '0') + "\n"));
        // Too short to hold one whole card of any binary format.
        CHECK_FALSE(content_outranks(DeckFormat::text, cbn.substr(0, 100)));
        CHECK_FALSE(content_outranks(DeckFormat::cbn, std::string("\xC0\x40\x40", 3)));
        CHECK_FALSE(content_outranks(DeckFormat::cbn, ""));
        // A .cbn card with a parity error is no format at all.
        std::string damaged = cbn;
        damaged[7] = '\x41';
        CHECK_FALSE(content_outranks(DeckFormat::text, damaged));
        CHECK_FALSE(content_outranks(DeckFormat::bin, damaged));
        // Bytes that are .bin cards and a tape card at once: several, so the extension reads.
        std::string both(161, '\x01');
        for (std::size_t i = 0; i < 160; i += 2) {
            both[i] = '\x70'; // low four bits clear (.bin), odd parity (tape)
        }
        both[160] = '\x80';
        both += std::string(159, '\0');
        CHECK_FALSE(content_outranks(DeckFormat::cbn, both));
        std::string only_bin = both;
        only_bin[160] = '\0'; // no end-of-card frame: no tape
        const auto found = content_outranks(DeckFormat::cbn, only_bin);
        REQUIRE(found);
        CHECK(found->format == DeckFormat::bin);
    }
}

// A deck holds at most 9,999 cards (docs/deck-formats.md, "How long a deck may be").
namespace parsons_limit {
using namespace parsons;
using Catch::Matchers::Contains;
namespace {

std::vector<Card> limit_cards(std::int64_t n) {
    std::mt19937 rng(53);
    const Card card = encode(test::random_orders(rng, fig8_layout()), fig8_layout()).card;
    return std::vector<Card>(static_cast<std::size_t>(n), card);
}

// How many cards the reader gives from `bytes`, or its DeckError.
std::string limit_read_all(const std::string& bytes, DeckFormat format) {
    std::istringstream in(bytes);
    DeckOptions options;
    options.format = format;
    options.file_name = "d";
    auto source = open_card_source(in, options);
    std::int64_t n = 0;
    try {
        while (source->next()) {
            ++n;
        }
    } catch (const DeckError& e) {
        return e.what();
    }
    return std::to_string(n) + " cards";
}

} // namespace

TEST_CASE("Deck limit: 9,999 cards are read and card 10,000 is refused by name, in every format",
          "[deck-io][deck-limit]") {
    for (const DeckFormat f : {DeckFormat::cbn, DeckFormat::bin, DeckFormat::text,
                               DeckFormat::listing, DeckFormat::tape}) {
        INFO(format_name(f));
        CHECK(limit_read_all(test::deck_bytes(limit_cards(9999), f), f) == "9999 cards");
        CHECK_THAT(limit_read_all(test::deck_bytes(limit_cards(10000), f), f),
                   Contains("d: card 10000: a deck holds at most 9,999 cards"));
    }
    SECTION(".five: five cards a step share one number: 9,999 steps, step 10,000 refused") {
        const DeckFormat f = DeckFormat::five;
        CHECK(limit_read_all(test::deck_bytes(limit_cards(9999), f), f) == "9999 cards");
        CHECK_THAT(limit_read_all(test::deck_bytes(limit_cards(10000), f), f),
                   Contains("d: step 10000 (cards 49996-50000): a deck holds at most 9,999 steps"));
    }
}

TEST_CASE("Deck limit: a text line with no end is refused at its line, in bounded memory",
          "[deck-io][deck-limit]") {
    CHECK(limit_read_all(std::string(4096, 'A') + "\n", DeckFormat::text) == "1 cards");
    CHECK_THAT(limit_read_all(std::string(4097, 'A'), DeckFormat::text),
               Contains("d:1: line is longer than 4096 bytes"));
}

TEST_CASE("Deck limit: standard input, a FIFO and a device are judged at card 10,000 in bounded "
          "memory and time",
          "[deck-io][deck-limit][cli]") {
    test::TempDir dir;
    // Under a memory limit of 300 MB: once, all of /dev/zero was kept (3.3 GB after 8 s). Not
    // under the sanitizers, whose shadow memory is a reservation of terabytes: there a program
    // under the limit cannot start (the regular build holds the memory bound).
#ifdef PARSONS_SANITIZE
    const std::string limit;
#else
    const std::string limit = "ulimit -v 300000; ";
#endif
    SECTION("an endless text deck on standard input") {
        const auto r = test::run_shell(limit + "yes X | timeout 60 PARSONS run - -q");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("standard input: card 10000: a deck holds at most 9,999"));
    }
    SECTION("an endless listing on standard input") {
        const auto r = test::run_shell(
            limit + "(echo card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq; n=0; "
                    "while :; do for a in table cross vertical swivel tilt; do "
                    "echo \"$((n % 10000)),,$a,+,3,,,0.001,0.001,5\" || exit 0; done; n=$((n+1)); "
                    "done) | timeout 120 PARSONS check -");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("standard input: card 10000: a deck holds at most 9,999"));
    }
    SECTION("/dev/zero (blank .bin cards for ever), read, never written") {
        for (const std::string command : {"show", "run", "check"}) {
            const auto r = test::run_shell(limit + "timeout 60 PARSONS " + command + " /dev/zero" +
                                           (command == "run" ? " -q" : ""));
            INFO(command << ": " << r.output);
            CHECK(r.exit_code == 2);
            CHECK_THAT(r.output, Contains("/dev/zero: card 10000: a deck holds at most 9,999"));
        }
    }
    SECTION("endless comments: refused past 64 MiB, in bounded memory") {
        const auto r = test::run_shell(limit + "yes '# x' | timeout 60 PARSONS run - --format "
                                               "listing -q");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("standard input: more than 64 MiB read and still no end"));
    }
    SECTION("an endless line on a FIFO the test makes") {
        const std::string fifo = dir.str("deck.txt");
        REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
        // The writer opens the FIFO under a timeout of its own, its output and errors away from
        // the test's pipe: had parsons never opened the FIFO (once, under the sanitizers, it
        // could not start), a writer blocked in open() held the pipe and the test waited for ever.
        const auto r = test::run_shell(
            limit + "(timeout 90 sh -c \"tr '\\\\0' A < /dev/zero > " + test::q(fifo) +
            "\" >/dev/null 2>&1 &) ; timeout 60 PARSONS show " + test::q(fifo));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("deck.txt:1: line is longer than 4096 bytes"));
    }
    SECTION("9,999 cards from a pipe are a deck: run reads it whole") {
        test::write_bytes(dir.path("d.txt"), test::deck_bytes(limit_cards(9999), DeckFormat::text));
        const auto r =
            test::run_shell(limit + "cat " + test::q(dir.str("d.txt")) + " | PARSONS show -");
        CHECK(r.exit_code != 2);
        CHECK_THAT(r.output, !Contains("at most 9,999"));
    }
}

} // namespace parsons_limit
