// The media of Fig. 9 and col. 6: a ribbon of cards (no feed gap), five separate cards a step (one
// per lead screw) and perforated tape. Each feeds the same orders (docs/design-rules.md rule 13).
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/five_card_format.hpp"
#include "cardreader/tape_format.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <bit>
#include <fstream>
#include <random>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::read_error;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::vector<Card> random_cards(std::mt19937& rng, int n) {
    std::vector<Card> cards;
    for (int i = 0; i < n; ++i) {
        cards.push_back(encode(test::random_orders(rng, fig8_layout()), fig8_layout()).card);
    }
    return cards;
}

std::string write_deck(const std::vector<Card>& cards, DeckFormat format) {
    return test::deck_bytes(cards, format);
}

std::vector<Card> read_deck(const std::string& bytes, DeckFormat format) {
    std::istringstream in(bytes);
    DeckOptions options;
    options.format = format;
    auto source = open_card_source(in, options);
    std::vector<Card> cards;
    while (auto c = source->next()) {
        cards.push_back(*c);
    }
    return cards;
}

std::string tape_of(const Card& card) {
    const auto frames = tape_encode(card);
    return {frames.begin(), frames.end()};
}

relaylogic::RunResult run_sample(axes::MachineProfile profile, relaylogic::Pace pace) {
    std::ifstream in(source_path("decks/samples/patent-example.csv"));
    DeckOptions options;
    options.format = DeckFormat::listing;
    auto deck = open_card_source(in, options);
    relaylogic::ControlCabinet cabinet(std::move(profile), fig8_layout());
    cabinet.set_pace(pace);
    cabinet.record_card_times(true);
    return cabinet.run(*deck);
}

// The same sample, punched on cards (.cbn) or five cards a step (.five), from the file's bytes.
relaylogic::RunResult run_sample_on(DeckFormat format, axes::MachineProfile profile,
                                    relaylogic::Pace pace) {
    const auto cards =
        read_deck(read_bytes(source_path("decks/samples/patent-example.csv")), DeckFormat::listing);
    std::istringstream in(write_deck(cards, format));
    DeckOptions options;
    options.format = format;
    auto deck = open_card_source(in, options);
    relaylogic::ControlCabinet cabinet(std::move(profile), fig8_layout());
    cabinet.set_pace(pace);
    cabinet.record_card_times(true);
    return cabinet.run(*deck);
}

void check_same_end(const relaylogic::RunResult& a, const relaylogic::RunResult& b) {
    for (std::size_t i = 0; i < 5; ++i) {
        INFO(axis_name(kAxes.at(i)));
        CHECK(a.axes.at(i).counter_in == b.axes.at(i).counter_in);
        CHECK(a.axes.at(i).real_in == Approx(b.axes.at(i).real_in).margin(1e-12));
        CHECK(a.axes.at(i).impulses == b.axes.at(i).impulses);
    }
}

} // namespace

TEST_CASE("Tape: a column is two frames, rows 12-3 then 4-9 in channels 6..1, odd parity in "
          "channel 7, channel 8 ends the card",
          "[tape][media]") {
    Card card;
    card.set_column(1, 0x801); // rows 12 and 9
    card.set_column(2, 0x0C0); // rows 2 and 3: two holes, check channel punched
    card.set_column(80, 0xFFF);
    const auto frames = tape_encode(card);
    REQUIRE(frames.size() == 161);
    CHECK(frames.at(0) == 0x20);   // row 12 in channel 6
    CHECK(frames.at(1) == 0x01);   // row 9 in channel 1
    CHECK(frames.at(2) == 0x43);   // rows 2, 3 in channels 2, 1, and the check hole
    CHECK(frames.at(3) == 0x40);   // a blank half column still has a hole (channel 7)
    CHECK(frames.at(158) == 0x7F); // six holes: check channel punched
    CHECK(frames.at(159) == 0x7F);
    CHECK(frames.at(160) == 0x80);
    for (std::size_t i = 0; i < 160; ++i) {
        INFO("frame " << i + 1);
        CHECK(std::popcount(static_cast<unsigned>(frames.at(i))) % 2 == 1);
        CHECK((frames.at(i) & 0x80) == 0);
    }
}

TEST_CASE("Tape: a deck reads back card for card, leader and trailer between cards ignored",
          "[tape][media]") {
    std::mt19937 rng(1952);
    const auto cards = random_cards(rng, 12);
    std::string bytes(20, '\0'); // leader
    for (const Card& c : cards) {
        bytes += tape_of(c) + std::string(3, '\0');
    }
    CHECK(read_deck(bytes, DeckFormat::tape) == cards);
    CHECK(read_deck(write_deck(cards, DeckFormat::tape), DeckFormat::tape) == cards);
}

TEST_CASE("Tape: bad frames are refused naming the frame and the channel",
          "[tape][media][bad-input]") {
    Card card;
    card.set_column(3, 0x400); // row 11
    const std::string good = tape_of(card);
    auto error_of = [](const std::string& bytes) {
        return read_error(bytes, DeckFormat::tape, "deck.tape");
    };
    std::string parity = std::string(2, '\0') + good + good;
    parity.at(2 + 161 + 4) = 0x03; // card 2, column 3, rows 12-3: two holes, no check hole
    CHECK(error_of(parity) ==
          "deck.tape: frame 168, channel 7 (card 2, column 3, rows 12-3): check channel wrong: "
          "frame 0x03 has an even number of holes in channels 1-7 (odd parity)");
    std::string blank = good;
    blank.at(9) = '\0';
    CHECK(error_of(blank) == "deck.tape: frame 10, channel 7 (card 1, column 5, rows 4-9): check "
                             "channel wrong: frame 0x00 has an even number of holes in channels "
                             "1-7 (odd parity); blank tape inside a card");
    std::string early_end = good;
    early_end.at(40) = static_cast<char>(0x80);
    CHECK(error_of(early_end) ==
          "deck.tape: frame 41, channel 8 (card 1, column 21, rows 12-3): end of card (channel "
          "8) after only 40 of the card's 160 data frames: a frame is missing");
    std::string marked = good;
    marked.at(7) = static_cast<char>(0xC0); // a data frame with channel 8 too
    CHECK(error_of(marked).find("deck.tape: frame 8, channel 8 (card 1, column 4, rows 4-9)") == 0);
    std::string no_end = good;
    no_end.at(160) = 0x40;
    CHECK(error_of(no_end) == "deck.tape: frame 161, channel 8: card 1 has 160 data frames but "
                              "frame 0x40 is not the end of card (channel 8 alone)");
    CHECK(error_of(good.substr(0, 160)) == "deck.tape: frame 161: the tape ends where card 1's "
                                           "end-of-card frame (channel 8) should be");
    CHECK(error_of(good + good.substr(0, 50)) ==
          "deck.tape: frame 212: the tape ends inside card 2 after 50 of its 160 data frames");
    CHECK(error_of(std::string(5, '\0') + "\x80") ==
          "deck.tape: frame 6, channel 8: end of card where no card has begun");
    CHECK(error_of(std::string(30, '\0')) == "deck.tape: no cards: the file holds nothing but a "
                                             "header, comments, blank lines or blank tape");
}

TEST_CASE("Five cards: one card per lead screw, marked in column 76, the axis's columns from 2",
          "[five][media]") {
    std::mt19937 rng(70);
    const Card card = random_cards(rng, 1).front();
    const FiveCards five = split_into_five(card, fig8_layout());
    REQUIRE_FALSE(five.error);
    // fig8: table 2-19, cross 20-33, vertical 34-47, swivel 48-61, tilt 62-75.
    const std::array<int, 5> first = {2, 20, 34, 48, 62};
    const std::array<int, 5> width = {18, 14, 14, 14, 14};
    for (std::size_t a = 0; a < 5; ++a) {
        INFO(axis_name(kAxes.at(a)));
        const Card& c = five.cards.at(a);
        CHECK(c.column(76) == row_bit(digit_row(static_cast<int>(a) + 1)));
        CHECK(c.column(1) == card.column(1));
        for (int col = 77; col <= 80; ++col) {
            CHECK(c.column(col) == card.column(col));
        }
        for (int i = 0; i < width.at(a); ++i) {
            CHECK(c.column(2 + i) == card.column(first.at(a) + i));
        }
        for (int col = 2 + width.at(a); col < 76; ++col) {
            CHECK(c.column(col) == 0);
        }
    }
    Card with_76 = card;
    with_76.set_column(76, row_bit(Row::r3));
    CHECK(split_into_five(with_76, fig8_layout()).error ==
          "column 76 is punched, but the five-card layout carries no field of that column "
          "(column 76 holds the axis mark)");
}

TEST_CASE("Five cards: the reader reassembles each step, in any order within it", "[five][media]") {
    std::mt19937 rng(71);
    const auto cards = random_cards(rng, 6);
    const std::string bytes = write_deck(cards, DeckFormat::five);
    REQUIRE(bytes.size() == cards.size() * 5 * 160);
    CHECK(read_deck(bytes, DeckFormat::five) == cards);
    // Step 2 (cards 6-10) shuffled: tilt first, table last.
    std::string shuffled = bytes;
    for (int k = 0; k < 5; ++k) {
        shuffled.replace(static_cast<std::size_t>((5 + k) * 160), 160,
                         bytes.substr(static_cast<std::size_t>((9 - k) * 160), 160));
    }
    CHECK(read_deck(shuffled, DeckFormat::five) == cards);
}

TEST_CASE("Five cards: a missing, doubled or disagreeing card is refused by card and column",
          "[five][media][bad-input]") {
    std::mt19937 rng(72);
    const auto cards = random_cards(rng, 2);
    auto physical = [&](std::size_t step) {
        return split_into_five(cards.at(step), fig8_layout()).cards;
    };
    auto deck_of = [](const std::vector<Card>& cs) { return write_deck(cs, DeckFormat::cbn); };
    auto error_of = [](const std::string& bytes) {
        return read_error(bytes, DeckFormat::five, "deck.five");
    };
    auto s1 = physical(0);
    auto s2 = physical(1);
    std::vector<Card> deck(s1.begin(), s1.end());
    deck.insert(deck.end(), s2.begin(), s2.end());

    auto doubled = deck;
    doubled.at(7) = doubled.at(6); // card 8 is a second cross card
    CHECK(error_of(deck_of(doubled)) ==
          "deck.five: card 8, column 76: a second cross card in step 2 "
          "(the first is card 7): each step has one card per lead "
          "screw");
    auto unmarked = deck;
    unmarked.at(2).set_column(76, 0);
    CHECK(error_of(deck_of(unmarked)) == "deck.five: card 3, column 76: axis mark 0x000 is not one "
                                         "punch in rows 1-5 (1 table, 2 cross, 3 vertical, 4 "
                                         "swivel, 5 tilt)");
    auto two_marks = deck;
    two_marks.at(2).set_column(76, row_bit(Row::r1) | row_bit(Row::r2));
    CHECK(error_of(deck_of(two_marks)).find("deck.five: card 3, column 76: axis mark") == 0);
    auto number = deck;
    number.at(8).set_column(80, number.at(8).column(80) ^ row_bit(Row::r12));
    CHECK(error_of(deck_of(number)) == "deck.five: card 9, column 80: differs from the table card "
                                       "(card 6) of the same step: the five cards carry one card "
                                       "number");
    auto spindle = deck;
    spindle.at(1).set_column(1, spindle.at(1).column(1) ^ row_bit(Row::r5));
    CHECK(error_of(deck_of(spindle))
              .find("deck.five: card 2, column 1: differs from the table "
                    "card (card 1)") == 0);
    auto stray = deck;
    stray.at(1).set_column(20, row_bit(Row::r4)); // the cross card ends at column 15
    CHECK(error_of(deck_of(stray)) == "deck.five: card 2, column 20: punched, but the cross card "
                                      "has no field here");
    auto short_deck = deck;
    short_deck.pop_back();
    CHECK(error_of(deck_of(short_deck)) == "deck.five: the deck ends after 4 of the five cards of "
                                           "step 2 (cards 6-9): five cards a step, one per lead "
                                           "screw");
}

TEST_CASE("Media: card -> five-card -> tape -> card gives identical cards (parsons convert)",
          "[media][cli]") {
    TempDir dir;
    REQUIRE(run_parsons("punch " + q(source_path("decks/samples/patent-example.csv")) + " -o " +
                        q(dir.str("deck.cbn")))
                .exit_code == 0);
    auto step = [&](const std::string& from, const std::string& to) {
        auto r = run_parsons("convert " + q(dir.str(from)) + " -o " + q(dir.str(to)));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
    };
    step("deck.cbn", "deck.five");
    step("deck.five", "deck.tape");
    step("deck.tape", "back.cbn");
    CHECK(read_bytes(dir.path("deck.five")).size() == 4 * 5 * 160);
    CHECK(read_bytes(dir.path("deck.tape")).size() == 4 * 161);
    CHECK(read_bytes(dir.path("back.cbn")) == read_bytes(dir.path("deck.cbn")));
    // and the other way round
    step("deck.cbn", "deck2.tape");
    step("deck2.tape", "deck2.five");
    step("deck2.five", "back2.cbn");
    CHECK(read_bytes(dir.path("back2.cbn")) == read_bytes(dir.path("deck.cbn")));
}

TEST_CASE("Media: a bad tape is refused with exit 2 and a message naming the frame",
          "[media][cli][bad-input]") {
    TempDir dir;
    std::mt19937 rng(73);
    std::string bytes = write_deck(random_cards(rng, 2), DeckFormat::tape);
    bytes.at(9) = static_cast<char>(bytes.at(9) ^ 0x04); // card 1, frame 10
    write_bytes(dir.path("bad.tape"), bytes);
    for (const char* cmd : {"convert", "run", "check", "show"}) {
        INFO(cmd);
        const std::string extra = std::string(cmd) == "convert" ? " -o " + q(dir.str("x.cbn")) : "";
        auto r = run_parsons(std::string(cmd) + " " + q(dir.str("bad.tape")) + extra);
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("bad.tape: frame 10, channel 7 (card 1, column 5, rows 4-9): check "
                            "channel wrong") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn")));
}

TEST_CASE("Ribbon: a deck fed as a ribbon (Fig. 9) takes exactly the feed gaps less machine "
          "time, and ends the same",
          "[media][ribbon][cabinet]") {
    auto profile = axes::default_profile();
    profile.feed_gap_s = GENERATE(0.10, 0.037);
    const auto pace = GENERATE(relaylogic::Pace::fast_forward, relaylogic::Pace::impulse_level);
    const auto cards = run_sample(profile, pace);
    profile.ribbon_feed = true;
    const auto ribbon = run_sample(profile, pace);
    REQUIRE(cards.completed);
    REQUIRE(ribbon.completed);
    REQUIRE(ribbon.cards_read == cards.cards_read);
    const double gaps = static_cast<double>(cards.cards_read - 1) * profile.feed_gap_s;
    CHECK(cards.machine_seconds - ribbon.machine_seconds == Approx(gaps).margin(1e-9));
    REQUIRE(ribbon.cards.size() == cards.cards.size());
    for (std::size_t i = 0; i < cards.cards.size(); ++i) {
        INFO("card " << i + 1);
        const double long_card = cards.cards.at(i).end_s - cards.cards.at(i).start_s;
        const double short_card = ribbon.cards.at(i).end_s - ribbon.cards.at(i).start_s;
        CHECK(long_card - short_card == Approx(i == 0 ? 0.0 : profile.feed_gap_s).margin(1e-9));
    }
    for (std::size_t a = 0; a < 5; ++a) {
        CHECK(ribbon.axes.at(a).counter_in == cards.axes.at(a).counter_in);
        CHECK(ribbon.axes.at(a).real_in == Approx(cards.axes.at(a).real_in).margin(1e-12));
        CHECK(ribbon.axes.at(a).impulses == cards.axes.at(a).impulses);
    }
}

TEST_CASE("Ribbon: run --feed ribbon and a tape deck save the feed gaps, a .five deck takes four "
          "card cycles more a step, --feed cards on tape is refused",
          "[media][ribbon][cli]") {
    TempDir dir;
    REQUIRE(run_parsons("punch " + q(source_path("decks/samples/patent-example.csv")) + " -o " +
                        q(dir.str("deck.cbn")))
                .exit_code == 0);
    REQUIRE(run_parsons("convert " + q(dir.str("deck.cbn")) + " -o " + q(dir.str("deck.tape")))
                .exit_code == 0);
    REQUIRE(run_parsons("convert " + q(dir.str("deck.cbn")) + " -o " + q(dir.str("deck.five")))
                .exit_code == 0);
    auto seconds = [&](const std::string& args) {
        auto r = run_parsons("run -q " + args + " --report " + q(dir.str("r.json")));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const std::string report = read_bytes(dir.path("r.json"));
        const auto key = report.rfind("\"machine_seconds\""); // the deck's, after the cards'
        REQUIRE(key != std::string::npos);
        return std::stod(report.substr(report.find(':', key) + 1));
    };
    const double cards = seconds(q(dir.str("deck.cbn")));
    const double ribbon = seconds(q(dir.str("deck.cbn")) + " --feed ribbon");
    const double tape = seconds(q(dir.str("deck.tape")));
    const double gap = axes::default_profile().feed_gap_s;
    CHECK(cards - ribbon == Approx(3 * gap).margin(1e-6));
    CHECK(tape == Approx(ribbon).margin(1e-9));
    CHECK(seconds(q(dir.str("deck.cbn")) + " --feed cards") == Approx(cards).margin(1e-9));
    // Five cards a step (col. 6): four more card cycles a step; on a ribbon 19 gaps fewer (4 in
    // the first step, 5 in each of the 3 others).
    const double cycle = axes::default_profile().reader_cycle_s;
    const double five = seconds(q(dir.str("deck.five")));
    CHECK(five - cards == Approx(4 * 4 * cycle).margin(2e-6));
    CHECK(five - seconds(q(dir.str("deck.five")) + " --feed ribbon") ==
          Approx(19 * gap).margin(2e-6));
    auto refused = run_parsons("run " + q(dir.str("deck.tape")) + " --feed cards");
    CHECK(refused.exit_code == 2);
    CHECK(refused.output.find("deck.tape: --feed cards: a tape deck has no separate cards") !=
          std::string::npos);
}

TEST_CASE("Five cards: each card of a step takes a card cycle of the reader and the motors start "
          "after the fifth (col. 6: one card a step is preferred 'from the standpoint of economy "
          "and speed'), and on a ribbon each card saves its gap",
          "[five][media][ribbon][cabinet]") {
    auto profile = axes::default_profile();
    profile.ribbon_feed = GENERATE(false, true);
    const double cycle = profile.reader_cycle_s;
    const double gap = profile.feed_gap_s;
    const auto one = run_sample_on(DeckFormat::cbn, profile, relaylogic::Pace::fast_forward);
    const auto five = run_sample_on(DeckFormat::five, profile, relaylogic::Pace::fast_forward);
    REQUIRE(one.completed);
    REQUIRE(five.completed);
    REQUIRE(one.cards_read == 4);
    REQUIRE(five.cards_read == 4);
    REQUIRE(five.cards.size() == one.cards.size());
    // Four more cards pass the brushes each step; on a ribbon none of them has a gap.
    const double longer = 4 * (cycle - (profile.ribbon_feed ? gap : 0.0));
    CHECK(five.cards.at(0).end_s - one.cards.at(0).end_s == Approx(longer).margin(1e-9));
    for (std::size_t i = 0; i < one.cards.size(); ++i) {
        INFO("card " << i + 1);
        const double one_card = one.cards.at(i).end_s - one.cards.at(i).start_s;
        const double five_cards = five.cards.at(i).end_s - five.cards.at(i).start_s;
        CHECK(five_cards - one_card == Approx(longer).margin(1e-9));
    }
    CHECK(five.machine_seconds - one.machine_seconds == Approx(4 * longer).margin(1e-9));
    if (!profile.ribbon_feed) {
        CHECK(five.cards.at(0).end_s - one.cards.at(0).end_s == Approx(2.4).margin(1e-9));
        CHECK(five.machine_seconds - one.machine_seconds == Approx(9.6).margin(1e-9));
    }
    check_same_end(five, one);
    // Impulse level agrees with fast-forward to the last bit.
    const auto slow = run_sample_on(DeckFormat::five, profile, relaylogic::Pace::impulse_level);
    REQUIRE(slow.completed);
    CHECK(slow.machine_seconds == five.machine_seconds);
    for (std::size_t i = 0; i < 5; ++i) {
        CHECK(slow.axes.at(i).real_in == five.axes.at(i).real_in);
        CHECK(slow.axes.at(i).impulses == five.axes.at(i).impulses);
    }
}

TEST_CASE("Five cards: on a ribbon the first step saves four feed gaps, every later step five",
          "[five][media][ribbon][cabinet]") {
    auto profile = axes::default_profile();
    profile.feed_gap_s = GENERATE(0.10, 0.037);
    const auto cards = run_sample_on(DeckFormat::five, profile, relaylogic::Pace::fast_forward);
    profile.ribbon_feed = true;
    const auto ribbon = run_sample_on(DeckFormat::five, profile, relaylogic::Pace::fast_forward);
    REQUIRE(cards.completed);
    REQUIRE(ribbon.completed);
    REQUIRE(ribbon.cards.size() == 4);
    REQUIRE(cards.cards.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
        INFO("step " << i + 1);
        const double long_step = cards.cards.at(i).end_s - cards.cards.at(i).start_s;
        const double short_step = ribbon.cards.at(i).end_s - ribbon.cards.at(i).start_s;
        CHECK(long_step - short_step == Approx((i == 0 ? 4 : 5) * profile.feed_gap_s).margin(1e-9));
    }
    CHECK(cards.machine_seconds - ribbon.machine_seconds ==
          Approx(19 * profile.feed_gap_s).margin(1e-9));
    check_same_end(ribbon, cards);
}

TEST_CASE("Five cards: every axis card's card number and spindle columns are compared with the "
          "table card's, the tilt card's (the fifth) too",
          "[five][media][bad-input][mutation]") {
    std::mt19937 rng(73);
    const auto cards = random_cards(rng, 1);
    const auto step = split_into_five(cards.front(), fig8_layout()).cards;
    auto error_of = [](const std::vector<Card>& cs) {
        return read_error(write_deck(cs, DeckFormat::cbn), DeckFormat::five, "deck.five");
    };
    for (std::size_t a = 1; a < 5; ++a) {
        INFO(axis_name(kAxes.at(a)));
        const std::string card = std::to_string(a + 1);
        for (int col : {77, 78, 79, 80}) {
            std::vector<Card> deck(step.begin(), step.end());
            deck.at(a).set_column(col, deck.at(a).column(col) ^ row_bit(Row::r11));
            CHECK(error_of(deck) == "deck.five: card " + card + ", column " + std::to_string(col) +
                                        ": differs from the table card (card 1) of the same step: "
                                        "the five cards carry one card number");
        }
        std::vector<Card> deck(step.begin(), step.end());
        deck.at(a).set_column(1, deck.at(a).column(1) ^ row_bit(Row::r7));
        CHECK(error_of(deck) == "deck.five: card " + card +
                                    ", column 1: differs from the table card (card 1) of the "
                                    "same step: the five cards carry one spindle direction");
    }
    // The table card itself in a later place of its step: its own columns are the reference.
    std::vector<Card> tilt_first = {step.at(4), step.at(1), step.at(2), step.at(3), step.at(0)};
    tilt_first.at(0).set_column(80, tilt_first.at(0).column(80) ^ row_bit(Row::r11));
    CHECK(error_of(tilt_first) == "deck.five: card 1, column 80: differs from the table card "
                                  "(card 5) of the same step: the five cards carry one card "
                                  "number");
}

TEST_CASE("Tape: an end-of-card frame with other holes besides channel 8 is a bad frame",
          "[tape][media][bad-input][mutation]") {
    Card card;
    card.set_column(3, 0x400); // row 11
    const std::string good = tape_of(card);
    REQUIRE(good.size() == 161);
    REQUIRE(static_cast<unsigned char>(good.at(160)) == 0x80);
    for (unsigned frame : {0x81U, 0xC0U, 0x83U, 0xFFU}) {
        INFO(fmt::format("{:#04x}", frame));
        std::string bad = good + good;
        bad.at(160) = static_cast<char>(frame);
        CHECK(read_error(bad, DeckFormat::tape, "deck.tape") ==
              fmt::format("deck.tape: frame 161, channel 8: card 1 has 160 data frames but frame "
                          "{:#04x} is not the end of card (channel 8 alone)",
                          frame));
    }
    CHECK(read_deck(good + good, DeckFormat::tape).size() == 2);
}
