// `parsons run --html FILE`: one self-contained HTML page of a finished run. It is the exhibit
// page's viewer (web/viewer.js, web/exhibit.css, the viewer's part of web/index.html, built
// into parsons) in replay mode, with the run's timeline and report embedded: it opens from
// disk with no server and no WebAssembly, and plays the recorded run on machine time.
#pragma once

#include "outputs/replay/run_timeline.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::cli {

// `deck_path` as the visitor typed it; the page carries its file name only.
std::string replay_page(const RunTimeline& timeline, const nlohmann::json& report,
                        const std::string& deck_path);

} // namespace parsons::cli
