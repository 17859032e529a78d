#include "cardreader/card_svg.hpp"

#include <fmt/format.h>

#include <iterator>
#include <vector>

namespace parsons::cardreader {
namespace {

// Real card dimensions, in hundredths of an inch.
constexpr double kCardWidth = 737.5;
constexpr double kCardHeight = 325.0;
constexpr double kFirstColumnX = 25.1; // centre of column 1
constexpr double kColumnPitch = 8.7;
constexpr double kFirstRowY = 25.0; // centre of row 12
constexpr double kRowPitch = 25.0;
constexpr double kHoleWidth = 5.5;
constexpr double kHoleHeight = 12.5;
constexpr double kMargin = 12.0;  // around the card, in the picture
constexpr double kCaption = 34.0; // room for the caption under the card

constexpr const char* kStock = "#f4e9c8";
constexpr const char* kInk = "#5b4630";
constexpr const char* kHole = "#22201c";

double column_x(int col) {
    return kFirstColumnX + (col - 1) * kColumnPitch;
}
double row_y(int row_index) {
    return kFirstRowY + row_index * kRowPitch;
} // 0 = row 12

void draw_stock(std::string& svg) {
    // Clipped upper-left corner, as on the real card.
    fmt::format_to(std::back_inserter(svg),
                   R"(<path d="M 25 0 H {w} V {h} H 0 V 43 Z" fill="{stock}" stroke="#b9a67a" )"
                   R"(stroke-width="0.8"/>)"
                   "\n",
                   fmt::arg("w", kCardWidth), fmt::arg("h", kCardHeight),
                   fmt::arg("stock", kStock));
}

void draw_printing(std::string& svg) {
    // Digits 0-9 in every column, and column numbers under rows 0 and 9.
    svg += fmt::format(R"(<g font-family="DejaVu Sans Mono, Courier New, monospace" )"
                       R"(font-size="7" fill="{}" text-anchor="middle">)"
                       "\n",
                       kInk);
    for (int col = 1; col <= kColumns; ++col) {
        const double x = column_x(col);
        for (int d = 0; d <= 9; ++d) {
            fmt::format_to(std::back_inserter(svg), R"(<text x="{:.2f}" y="{:.2f}">{}</text>)", x,
                           row_y(2 + d) + 2.5, d);
        }
        svg += '\n';
    }
    svg += "</g>\n";
    svg += fmt::format(R"(<g font-family="DejaVu Sans, Arial, sans-serif" font-size="3.6" )"
                       R"(fill="{}" text-anchor="middle">)",
                       kInk);
    for (int col = 1; col <= kColumns; ++col) {
        fmt::format_to(std::back_inserter(svg),
                       R"(<text x="{0:.2f}" y="{1:.2f}">{2}</text><text x="{0:.2f}" )"
                       R"(y="{3:.2f}">{2}</text>)",
                       column_x(col), row_y(2) + 11.0, col, row_y(11) + 12.0);
    }
    svg += "</g>\n";
}

bool starts_section(const LayoutField& f) {
    return f.kind == FieldKind::spindle || f.kind == FieldKind::motion ||
           f.kind == FieldKind::card_number || f.kind == FieldKind::event ||
           f.kind == FieldKind::extension || f.kind == FieldKind::position_sync ||
           f.kind == FieldKind::loop_mark || f.kind == FieldKind::register_reset ||
           f.kind == FieldKind::travel_per_pulse || f.kind == FieldKind::tap_tool;
}

// A section name in bold over columns first..last.
void section_name(std::string& svg, std::string name, int first, int last) {
    for (char& c : name) {
        c = static_cast<char>(c - ('a' - 'A') * (c >= 'a' && c <= 'z'));
    }
    fmt::format_to(std::back_inserter(svg),
                   R"(<text font-size="6.4" font-weight="bold" letter-spacing="1" )"
                   R"(x="{:.2f}" y="46">{}</text>)"
                   "\n",
                   (column_x(first + 2) + column_x(last)) / 2, name);
}

// Field names and rules over the columns: the layout's motion-card fields, or on a condition
// card (an addition after EP 0640901) its five condition slots, or on a sync card (an addition
// after EP 0436887) its position sync, loop and travel-per-pulse fields, or on a tap card (an
// addition after EP 0360190) its tool, feed axis, sense, depth, pitch and speed; on each of
// them the extension mark in column 76 and the card number.
void draw_fields(std::string& svg, const CardLayout& layout, CardKind kind) {
    const bool condition_card = kind == CardKind::condition;
    svg += fmt::format(R"(<g font-family="DejaVu Sans, Arial, sans-serif" fill="{}" )"
                       R"(text-anchor="middle">)"
                       "\n",
                       kInk);
    std::vector<LayoutField> fields = layout.fields;
    if (kind != CardKind::motion) {
        fields = condition_card           ? layout.condition_fields
                 : kind == CardKind::sync ? layout.sync_fields
                                          : layout.tap_fields;
        fields.push_back({FieldKind::extension, std::nullopt, layout.extension_column, 1});
        if (const LayoutField* number = layout.find(FieldKind::card_number)) {
            fields.push_back(*number);
        }
    }
    for (const LayoutField& f : fields) {
        // Rule at the left edge of the field: heavy (164) between sections, thin within.
        const double left = column_x(f.first_column) - kColumnPitch / 2;
        const bool heavy = starts_section(f);
        fmt::format_to(std::back_inserter(svg),
                       R"(<line x1="{0:.2f}" y1="{4}" x2="{0:.2f}" y2="{1}" stroke="{2}" )"
                       R"(stroke-width="{3}"/>)",
                       left, kCardHeight - 4, kInk, heavy ? 1.6 : 0.4, heavy ? 34 : 52);
        const double centre = (column_x(f.first_column) + column_x(f.last_column())) / 2;
        const std::string_view label = field_short_label(f.kind);
        if (f.width == 1) {
            fmt::format_to(
                std::back_inserter(svg),
                R"~(<text font-size="4.4" transform="translate({:.2f} 66) rotate(-90)" )~"
                R"(text-anchor="start">{}</text>)",
                centre + 1.5, xml_escape(label));
        } else {
            fmt::format_to(std::back_inserter(svg),
                           R"(<text font-size="5.2" x="{:.2f}" y="63">{}</text>)", centre,
                           xml_escape(label));
        }
        svg += '\n';
    }
    if (condition_card) {
        for (int slot = 0; slot < kConditionsPerCard; ++slot) {
            const int first = 1 + slot * 15;
            section_name(svg, fmt::format("condition {}", slot + 1), first, first + 12);
        }
        svg += "\n</g>\n";
        return;
    }
    if (kind == CardKind::sync) {
        for (const LayoutField& f : layout.sync_fields) {
            if (f.kind == FieldKind::position_sync) {
                section_name(svg, "position sync", f.first_column - 1, f.first_column + 3);
            } else if (f.kind == FieldKind::loop_mark) {
                section_name(svg, "loop", f.first_column, f.first_column + 8);
            } else if (f.kind == FieldKind::travel_per_pulse) {
                section_name(svg, std::string(axis_name(f.axis.value_or(Axis::table))),
                             f.first_column - 2, f.last_column());
            }
        }
        svg += "\n</g>\n";
        return;
    }
    if (kind == CardKind::tap) {
        if (!layout.tap_fields.empty()) {
            section_name(svg, "tap (EP 0360190)", layout.tap_fields.front().first_column,
                         layout.tap_fields.back().last_column() - 2);
        }
        svg += "\n</g>\n";
        return;
    }
    // Axis section names over each section.
    for (Axis a : kAxes) {
        int first = 0;
        int last = 0;
        for (const LayoutField& f : layout.fields) {
            if (f.axis == a) {
                first = first == 0 ? f.first_column : std::min(first, f.first_column);
                last = std::max(last, f.last_column());
            }
        }
        if (first == 0) {
            continue;
        }
        section_name(svg, std::string(axis_name(a)), first, last);
    }
    // The row of cross marks of each sequence pattern 222, in row 12.
    for (Axis a : kAxes) {
        const int first = layout.sequence_first_column.at(axis_index(a));
        for (int k = 0; k < kSequencePositions; ++k) {
            fmt::format_to(std::back_inserter(svg),
                           R"(<text font-size="6" x="{:.2f}" y="{:.2f}">&#215;</text>)",
                           column_x(first + k), row_y(0) + 2.2);
        }
    }
    svg += "\n</g>\n";
}

void draw_interpretation(std::string& svg, const Card& card, KeypunchCode code) {
    svg += R"(<g font-family="DejaVu Sans Mono, Courier New, monospace" font-size="8.5" )"
           R"(fill="#1d1a16" text-anchor="middle">)";
    for (int col = 1; col <= kColumns; ++col) {
        const CodeEntry* e = entry_for_punches(card.column(col), code);
        if (e && e->ascii != ' ') {
            fmt::format_to(std::back_inserter(svg), R"(<text x="{:.2f}" y="11">{}</text>)",
                           column_x(col), xml_escape(e->printed));
        }
    }
    svg += "</g>\n";
}

void draw_holes(std::string& svg, const Card& card, const std::optional<BadPunch>& bad) {
    svg += fmt::format(R"(<g fill="{}">)", kHole);
    for (int col = 1; col <= kColumns; ++col) {
        for (int r = 0; r < kRows; ++r) {
            if (!card.punched(col, kRowsTopToBottom.at(static_cast<std::size_t>(r)))) {
                continue;
            }
            const bool flagged = bad && bad->column == col;
            fmt::format_to(std::back_inserter(svg),
                           R"(<rect x="{:.2f}" y="{:.2f}" width="{}" height="{}"{}/>)",
                           column_x(col) - kHoleWidth / 2, row_y(r) - kHoleHeight / 2, kHoleWidth,
                           kHoleHeight, flagged ? R"( stroke="#d01c1c" stroke-width="1.4")" : "");
        }
    }
    svg += "</g>\n";
}

} // namespace

std::string xml_escape(std::string_view text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '&':
            out += "&amp;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

std::string card_svg(const Card& card, const CardLayout& layout, const CardPictureNotes& notes,
                     KeypunchCode code) {
    std::string svg;
    const double width = kCardWidth + 2 * kMargin;
    const double height = kCardHeight + 2 * kMargin + kCaption;
    svg += fmt::format(
        R"(<?xml version="1.0" encoding="UTF-8"?>)"
        "\n"
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0:.0f}mm" height="{1:.0f}mm" )"
        R"(viewBox="0 0 {2} {3}">)"
        "\n<title>{4}</title>\n"
        R"(<rect width="{2}" height="{3}" fill="#ffffff"/>)"
        "\n"
        R"~(<g transform="translate({5} {5})">)~"
        "\n",
        width * 0.254 * 1.4, height * 0.254 * 1.4, width, height, xml_escape(notes.caption),
        kMargin);
    draw_stock(svg);
    draw_printing(svg);
    draw_fields(svg, layout,
                is_condition_card(card, layout) ? CardKind::condition
                : is_sync_card(card, layout)    ? CardKind::sync
                : is_tap_card(card, layout)     ? CardKind::tap
                                                : CardKind::motion);
    draw_interpretation(svg, card, code);
    draw_holes(svg, card, notes.bad_punch);
    svg += "</g>\n";
    fmt::format_to(std::back_inserter(svg),
                   R"(<text x="{}" y="{:.1f}" font-family="DejaVu Sans, Arial, sans-serif" )"
                   R"(font-size="9" fill="#333">{}</text>)"
                   "\n",
                   kMargin, kMargin + kCardHeight + 14, xml_escape(notes.caption));
    if (notes.bad_punch) {
        fmt::format_to(std::back_inserter(svg),
                       R"(<text x="{}" y="{:.1f}" font-family="DejaVu Sans, Arial, sans-serif" )"
                       R"(font-size="9" fill="#d01c1c">bad punch, column {}: {}</text>)"
                       "\n",
                       kMargin, kMargin + kCardHeight + 27, notes.bad_punch->column,
                       xml_escape(notes.bad_punch->what));
    }
    svg += "</svg>\n";
    return svg;
}

} // namespace parsons::cardreader
