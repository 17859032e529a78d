#include "cardreader/five_card_format.hpp"

#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::cardreader {
namespace {

struct Span {
    int first = kColumns + 1;
    int last = 0;
};

// Where the layout keeps each axis (its fields and its sequence columns), the spindle column
// and the card-number columns.
struct Plan {
    std::array<Span, kAxisCount> axis{};
    Span spindle;
    Span number;
};

void widen(Span& s, int first, int last) {
    s.first = std::min(s.first, first);
    s.last = std::max(s.last, last);
}

Plan plan_of(const CardLayout& layout) {
    Plan p;
    for (const LayoutField& f : layout.fields) {
        if (f.axis) {
            widen(p.axis.at(static_cast<std::size_t>(*f.axis)), f.first_column, f.last_column());
        } else if (f.kind == FieldKind::spindle) {
            widen(p.spindle, f.first_column, f.last_column());
        } else if (f.kind == FieldKind::card_number) {
            widen(p.number, f.first_column, f.last_column());
        }
    }
    for (std::size_t a = 0; a < p.axis.size(); ++a) {
        const int s = layout.sequence_first_column.at(a);
        widen(p.axis.at(a), s, s + 4);
    }
    return p;
}

bool inside(const Span& s, int column) {
    return column >= s.first && column <= s.last;
}

// Column `column` of the one card, on the axis card of axis a (0 when it is not there).
int axis_card_column(const Plan& p, std::size_t a, int column) {
    if (inside(p.spindle, column) || inside(p.number, column)) {
        return column;
    }
    if (inside(p.axis.at(a), column)) {
        return column - p.axis.at(a).first + p.spindle.last + 1;
    }
    return 0;
}

ColumnWord mark_of(std::size_t a) {
    return row_bit(digit_row(static_cast<int>(a) + 1));
}

class FiveCardSource : public CardSource {
public:
    FiveCardSource(std::istream& in, std::string file, const CardLayout& layout)
        : cbn_(make_cbn_source(in, file)), file_(std::move(file)), plan_(plan_of(layout)) {}

    std::optional<Card> next() override {
        std::array<std::optional<Card>, kAxisCount> step{};
        std::array<std::int64_t, kAxisCount> where{};
        std::int64_t first_card = physical_ + 1;
        for (int i = 0; i < kAxisCount; ++i) {
            auto card = cbn_->next();
            if (!card) {
                if (i == 0) {
                    return std::nullopt;
                }
                throw DeckError::in_file(
                    file_, fmt::format("the deck ends after {} of the five cards of step {} "
                                       "(cards {}-{}): five cards a step, one per lead screw",
                                       i, step_ + 1, first_card, physical_));
            }
            ++physical_;
            const std::size_t a = axis_of(*card);
            if (step.at(a)) {
                throw DeckError::at_card_column(
                    file_, physical_, kAxisMarkColumn,
                    fmt::format("a second {} card in step {} (the first is card {}): each step "
                                "has one card per lead screw",
                                axis_name(kAxes.at(a)), step_ + 1, where.at(a)));
            }
            step.at(a) = *card;
            where.at(a) = physical_;
        }
        ++step_;
        return assemble(step, where);
    }

    int cards_a_step() const override { return kAxisCount; }

private:
    std::size_t axis_of(const Card& card) const {
        const ColumnWord m = card.column(kAxisMarkColumn);
        for (std::size_t a = 0; a < kAxisCount; ++a) {
            if (m == mark_of(a)) {
                return a;
            }
        }
        throw DeckError::at_card_column(
            file_, physical_, kAxisMarkColumn,
            fmt::format("axis mark {:#05x} is not one punch in rows 1-5 (1 table, 2 cross, 3 "
                        "vertical, 4 swivel, 5 tilt)",
                        m));
    }

    Card assemble(const std::array<std::optional<Card>, kAxisCount>& step,
                  const std::array<std::int64_t, kAxisCount>& where) const {
        Card out;
        const Card& table = *step.front();
        for (int col = 1; col <= kColumns; ++col) {
            if (inside(plan_.spindle, col) || inside(plan_.number, col)) {
                for (std::size_t a = 1; a < kAxisCount; ++a) {
                    if (step.at(a)->column(col) != table.column(col)) {
                        throw DeckError::at_card_column(
                            file_, where.at(a), col,
                            fmt::format("differs from the table card (card {}) of the same "
                                        "step: the five cards carry one {}",
                                        where.front(),
                                        inside(plan_.spindle, col) ? "spindle direction"
                                                                   : "card number"));
                    }
                }
                out.set_column(col, table.column(col));
            }
        }
        for (std::size_t a = 0; a < kAxisCount; ++a) {
            const Card& card = *step.at(a);
            std::array<bool, kColumns + 1> used{};
            used.at(kAxisMarkColumn) = true;
            for (int col = 1; col <= kColumns; ++col) {
                const int on_axis_card = axis_card_column(plan_, a, col);
                if (on_axis_card != 0) {
                    used.at(static_cast<std::size_t>(on_axis_card)) = true;
                    if (inside(plan_.axis.at(a), col)) {
                        out.set_column(col, card.column(on_axis_card));
                    }
                }
            }
            for (int col = 1; col <= kColumns; ++col) {
                if (!used.at(static_cast<std::size_t>(col)) && card.column(col) != 0) {
                    throw DeckError::at_card_column(
                        file_, where.at(a), col,
                        fmt::format("punched, but the {} card has no field here",
                                    axis_name(kAxes.at(a))));
                }
            }
        }
        return out;
    }

    std::unique_ptr<CardSource> cbn_;
    std::string file_;
    Plan plan_;
    std::int64_t physical_ = 0;
    std::int64_t step_ = 0;
};

class FiveCardSink : public CardSink {
public:
    FiveCardSink(std::ostream& out, std::string file, const CardLayout& layout)
        : cbn_(make_cbn_sink(out, file)), file_(std::move(file)), layout_(layout) {}

    void write(const Card& card) override {
        ++step_;
        FiveCards five = split_into_five(card, layout_);
        if (five.error) {
            throw DeckError::in_file(file_, fmt::format("card {}: {}", step_, *five.error));
        }
        for (const Card& c : five.cards) {
            cbn_->write(c);
        }
    }

private:
    std::unique_ptr<CardSink> cbn_;
    std::string file_;
    const CardLayout& layout_;
    std::int64_t step_ = 0;
};

} // namespace

FiveCards split_into_five(const Card& card, const CardLayout& layout) {
    const Plan plan = plan_of(layout);
    FiveCards five;
    for (int col = 1; col <= kColumns; ++col) {
        bool placed = false;
        for (std::size_t a = 0; a < kAxisCount; ++a) {
            const int to = axis_card_column(plan, a, col);
            if (to != 0) {
                five.cards.at(a).set_column(to, card.column(col));
                placed = true;
            }
        }
        if (!placed && card.column(col) != 0) {
            five.error = fmt::format("column {} is punched, but the five-card layout carries no "
                                     "field of that column (column {} holds the axis mark)",
                                     col, kAxisMarkColumn);
            return five;
        }
    }
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        five.cards.at(a).set_column(kAxisMarkColumn, mark_of(a));
    }
    return five;
}

std::unique_ptr<CardSource> make_five_card_source(std::istream& in, std::string file,
                                                  const CardLayout& layout) {
    return std::make_unique<FiveCardSource>(in, std::move(file), layout);
}

std::unique_ptr<CardSink> make_five_card_sink(std::ostream& out, std::string file,
                                              const CardLayout& layout) {
    return std::make_unique<FiveCardSink>(out, std::move(file), layout);
}

} // namespace parsons::cardreader
