#include "relaylogic/card_reader.hpp"
#include "relaylogic/sequence_control.hpp"
#include "relaylogic/storage.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace parsons::relaylogic {

namespace {

using cardreader::ColumnWord;
using cardreader::FieldKind;

int field_slot(FieldKind kind) {
    switch (kind) {
    case FieldKind::slow_down_1:
        return 0;
    case FieldKind::slow_down_2:
        return 1;
    case FieldKind::stop:
        return 2;
    case FieldKind::check:
        return 3;
    default:
        return -1;
    }
}

std::uint16_t digit_mask(ColumnWord word) {
    std::uint16_t mask = 0;
    for (int d = 0; d < 10; ++d) {
        if ((word & cardreader::row_bit(cardreader::digit_row(d))) != 0) {
            mask = static_cast<std::uint16_t>(mask | (1U << d));
        }
    }
    return mask;
}

} // namespace

SensedCard sense_card(const cardreader::Card& card, const cardreader::CardLayout& layout,
                      bool refuse_double_punch) {
    SensedCard sensed;
    sensed.decoded = cardreader::decode(card, layout);
    // Condition, sync and tap cards are additions: their double punches (and any other fault
    // of their holes, a tap of depth 0 among them) are bad punches in every profile.
    if (sensed.decoded || refuse_double_punch || cardreader::is_extension_card(card, layout)) {
        return sensed;
    }
    // As a 1952 reader: every punched row of a digit column picks its relay. The orders are
    // read from a copy that keeps only each column's lowest punched row.
    cardreader::Card lowest = card;
    for (const cardreader::LayoutField& f : layout.fields) {
        const int slot = field_slot(f.kind);
        if (slot < 0 || !f.axis || f.width != 4) {
            continue;
        }
        for (int i = 0; i < 4; ++i) {
            const int c = f.first_column + i;
            const std::uint16_t mask = digit_mask(card.column(c));
            if (mask == 0 || (mask & (mask - 1)) == 0) {
                continue; // blank or a single digit
            }
            const int low = __builtin_ctz(mask);
            ColumnWord word = card.column(c);
            for (int d = low + 1; d < 10; ++d) {
                word =
                    static_cast<ColumnWord>(word & ~cardreader::row_bit(cardreader::digit_row(d)));
            }
            lowest.set_column(c, word);
            sensed.extra.at(cardreader::axis_index(*f.axis))
                .at(static_cast<std::size_t>(slot))
                .at(static_cast<std::size_t>(i)) =
                static_cast<std::uint16_t>(mask & ~(1U << static_cast<unsigned>(low)));
            sensed.double_columns.push_back(c);
        }
    }
    if (sensed.double_columns.empty()) {
        return sensed; // a bad punch of another kind
    }
    cardreader::DecodeResult clean = cardreader::decode(lowest, layout);
    if (!clean) {
        sensed.decoded = std::move(clean); // another problem besides the double punches
        sensed.extra = {};
        sensed.double_columns.clear();
        return sensed;
    }
    sensed.decoded = std::move(clean);
    return sensed;
}

std::vector<BrushWire> brush_wiring(const cardreader::CardLayout& layout) {
    static constexpr std::array<const char*, 4> kPlaces = {"inches", "tenths", "hundredths",
                                                           "thousandths"};
    const std::vector<int> digits = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    std::vector<BrushWire> wires;
    for (const cardreader::LayoutField& f : layout.fields) {
        const std::string scope =
            f.axis ? std::string(cardreader::axis_name(*f.axis)) : std::string("cabinet");
        const std::string label = cardreader::field_label(f);
        for (int k = 0; k < f.width; ++k) {
            const int column = f.first_column + k;
            const int place = 4 - f.width + k; // a number's last column is its thousandths
            switch (f.kind) {
            case FieldKind::slow_down_1:
            case FieldKind::slow_down_2:
            case FieldKind::stop:
                wires.push_back({column, digits, label + ", " + kPlaces.at(place),
                                 fmt::format("{}.{}_{}.relay_#", scope, kAbsoluteStorageName,
                                             kAbsoluteBanks.at(place))});
                break;
            case FieldKind::check:
                wires.push_back({column, digits, label + ", " + kPlaces.at(place),
                                 fmt::format("{}.{}_{}.relay_#", scope, kIncrementalStorageName,
                                             kIncrementalBanks.at(place))});
                break;
            case FieldKind::card_number:
                wires.push_back({column, digits, label, "cabinet.card_number_check"});
                break;
            case FieldKind::start_speed:
                wires.push_back({column, {0, 1, 2}, label, scope + ".speed_switch_236"});
                break;
            case FieldKind::motion:
                wires.push_back({column, {0, 1}, label, scope + ".reversing_control_214"});
                break;
            case FieldKind::spindle:
                wires.push_back({column, {0, 1}, label, "cabinet.spindle_control_165"});
                break;
            default:
                break; // the extension mark and the later cards' fields: their attachments'
            }
        }
    }
    for (std::size_t a = 0; a < cardreader::kAxisCount; ++a) {
        const std::string axis(cardreader::axis_name(static_cast<cardreader::Axis>(a)));
        for (int p = 0; p < 5; ++p) {
            wires.push_back({layout.sequence_first_column.at(a) + p,
                             {12},
                             fmt::format("{} sequence position {}", axis, p + 1),
                             fmt::format("{}.sequence_switch_224.contact_{}", axis,
                                         kSequenceContacts.at(static_cast<std::size_t>(p)))});
        }
    }
    std::sort(wires.begin(), wires.end(),
              [](const BrushWire& x, const BrushWire& y) { return x.column < y.column; });
    return wires;
}

} // namespace parsons::relaylogic
