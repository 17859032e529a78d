#include "cardreader/deck_io.hpp"
#include "cardreader/hollerith.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <sstream>

using namespace parsons::cardreader;

namespace {
ColumnWord rows(std::initializer_list<int> names) {
    ColumnWord w = 0;
    for (int n : names) {
        w = static_cast<ColumnWord>(w | row_bit(row_named(n)));
    }
    return w;
}
} // namespace

TEST_CASE("Hollerith: a text card image of 'HELLO, 1952' decodes to the IBM 029 chart's punches",
          "[hollerith][text]") {
    std::istringstream in("HELLO, 1952 &-/.$\n");
    DeckOptions options;
    options.format = DeckFormat::text;
    options.file_name = "known.txt";
    auto source = open_card_source(in, options);
    auto card = source->next();
    REQUIRE(card);
    // Chart: H = 12-8, E = 12-5, L = 11-3, O = 11-6, ',' = 0-8-3, digits single punches,
    // '&' = 12, '-' = 11, '/' = 0-1, '.' = 12-8-3, '$' = 11-8-3.
    const std::vector<ColumnWord> expected = {rows({12, 8}),
                                              rows({12, 5}),
                                              rows({11, 3}),
                                              rows({11, 3}),
                                              rows({11, 6}),
                                              rows({0, 8, 3}),
                                              0,
                                              rows({1}),
                                              rows({9}),
                                              rows({5}),
                                              rows({2}),
                                              0,
                                              rows({12}),
                                              rows({11}),
                                              rows({0, 1}),
                                              rows({12, 8, 3}),
                                              rows({11, 8, 3})};
    for (std::size_t i = 0; i < expected.size(); ++i) {
        INFO("column " << i + 1);
        CHECK(card->column(static_cast<int>(i) + 1) == expected[i]);
    }
    for (int c = static_cast<int>(expected.size()) + 1; c <= kColumns; ++c) {
        CHECK(card->column(c) == 0);
    }
    CHECK_FALSE(source->next());
}

TEST_CASE("Hollerith: every key of the 029 and 026 punches a different hole pattern",
          "[hollerith]") {
    for (KeypunchCode code : {KeypunchCode::ibm029, KeypunchCode::ibm026}) {
        std::set<ColumnWord> patterns;
        std::set<char> keys;
        for (const CodeEntry& e : code_table(code)) {
            patterns.insert(e.punches);
            keys.insert(e.ascii);
            CHECK(punches_for(e.ascii, code) == e.punches);
            CHECK(entry_for_punches(e.punches, code)->ascii == e.ascii);
        }
        CHECK(patterns.size() == code_table(code).size());
        CHECK(keys.size() == code_table(code).size());
    }
    CHECK(code_table(KeypunchCode::ibm029).size() == 63);
    CHECK(code_table(KeypunchCode::ibm026).size() == 48);
}

TEST_CASE("Hollerith: the 029 and 026 differ where the charts differ", "[hollerith]") {
    CHECK(punches_for('&', KeypunchCode::ibm029) == rows({12}));
    CHECK(punches_for('+', KeypunchCode::ibm026) == rows({12}));
    CHECK(punches_for('+', KeypunchCode::ibm029) == rows({12, 8, 6}));
    CHECK(punches_for('(', KeypunchCode::ibm029) == rows({12, 8, 5}));
    CHECK(punches_for('(', KeypunchCode::ibm026) == rows({0, 8, 4}));
    CHECK(punches_for('=', KeypunchCode::ibm029) == rows({8, 6}));
    CHECK(punches_for('=', KeypunchCode::ibm026) == rows({8, 3}));
    CHECK_FALSE(punches_for('a', KeypunchCode::ibm029)); // the reader folds case, not the table
    CHECK_FALSE(punches_for('~', KeypunchCode::ibm029));
    CHECK(entry_for_punches(rows({12, 0}), KeypunchCode::ibm029) == nullptr);
    CHECK(std::string(entry_for_punches(rows({12, 8, 2}), KeypunchCode::ibm029)->printed) ==
          "\u00a2");
}

TEST_CASE("Card: punches are named as a keypunch operator says them", "[card]") {
    CHECK(punches_text(rows({12, 8, 3})) == "12-8-3");
    CHECK(punches_text(rows({0, 1, 2})) == "0-1-2");
    CHECK(punches_text(0) == "blank");
    CHECK(hole_count(rows({11, 0, 9})) == 3);
}
