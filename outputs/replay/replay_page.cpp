#include "outputs/replay/replay_page.hpp"

#include "axes/json_text.hpp"
#include "outputs/web_assets.hpp" // generated: cmake/embed_web.cmake

#include "cardreader/card_svg.hpp"

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace parsons::cli {

namespace {

// JSON inside <script type="application/json">: "</script" would end the element early and
// "<!--" change how the browser reads it, so every '<' is written \u003c, which JSON reads as
// the same character.
std::string script_safe(const std::string& json) {
    std::string out;
    out.reserve(json.size());
    for (const char c : json) {
        if (c == '<') {
            out += "\\u003c";
        } else {
            out += c;
        }
    }
    return out;
}

// The text between two markers of a built-in asset (the viewer's part of index.html).
std::string_view between(std::string_view text, std::string_view begin, std::string_view end) {
    const auto from = text.find(begin);
    const auto to = text.find(end);
    if (from == std::string_view::npos || to == std::string_view::npos || to < from) {
        throw std::logic_error("the built-in web/index.html lost its viewer markers");
    }
    return text.substr(from + begin.size(), to - from - begin.size());
}

// A path's last part: the page names a deck by its file name only.
std::string file_name(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

void fill(std::string& page, std::string_view slot, std::string_view text) {
    const auto at = page.find(slot);
    if (at == std::string::npos) {
        throw std::logic_error("the built-in web/replay.html lost a slot");
    }
    page.replace(at, slot.size(), text);
}

} // namespace

std::string replay_page(const RunTimeline& timeline, const nlohmann::json& report,
                        const std::string& deck_path) {
    // The deck's file name only: the page is made to be passed on, and the folders it was run
    // from (a home directory, a build tree) are nobody's business (issue 31, item 4).
    const std::string deck_name = file_name(deck_path);
    std::string page(web_assets::replay_html);
    // The slots are filled last to first in the template, so no filled text is searched.
    nlohmann::json run = {{"deck", deck_name}, {"report", report}};
    auto& embedded = run["report"];
    if (const auto deck = embedded.find("deck"); // the report names it as typed
        embedded.is_object() && deck != embedded.end() && deck->is_string()) {
        *deck = file_name(deck->get<std::string>());
    }
    fill(page, "/*sound-js*/", web_assets::sound_js);
    fill(page, "<!--run-json-->", script_safe(axes::json_text(run)));
    fill(page, "<!--timeline-json-->", script_safe(timeline.embedded_json()));
    fill(page, "/*tour-js*/", web_assets::tour_js);
    fill(page, "/*viewer-js*/", web_assets::viewer_js);
    fill(page, "/*mill-js*/", web_assets::mill_js);
    fill(page, "/*reader-js*/", web_assets::reader_js);
    fill(page, "/*circuit-js*/", web_assets::circuit_js);
    fill(page, "/*cabinet-js*/", web_assets::cabinet_js);
    fill(page, "/*parts-js*/", web_assets::parts_js);
    fill(page, "<!--viewer-->",
         between(web_assets::index_html, "<!--viewer:begin-->", "<!--viewer:end-->"));
    fill(page, "/*exhibit-css*/", web_assets::exhibit_css);
    // The deck's name, in the title and the heading.
    const std::string title = cardreader::xml_escape(deck_name);
    for (std::size_t at = page.find("<!--title-->"); at != std::string::npos;
         at = page.find("<!--title-->", at + title.size())) {
        page.replace(at, std::string_view("<!--title-->").size(), title);
    }
    return page;
}

} // namespace parsons::cli
