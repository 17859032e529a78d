// The contouring attachment's part of the run report and the summary (an addition after
// EP 0636958, Black & Decker; docs/contouring.md, docs/report.md): its junctions, the steps its
// stepper motors lost and how far the path as cut left the programmed path.
#pragma once

#include "relaylogic/contouring/contouring_result.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace parsons::cli {

nlohmann::json contouring_json(const relaylogic::ContouringResult& c);
// The summary's lines, each without a newline.
std::vector<std::string> contouring_lines(const relaylogic::ContouringResult& c);

} // namespace parsons::cli
