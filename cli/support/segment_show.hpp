// `parsons show` for a segment card (an addition after EP 0636958, Black & Decker;
// cardreader/segment_card.hpp): field by field, and as JSON.
#pragma once

#include "cardreader/layout.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>

namespace parsons::cli {

void print_segment_card(std::int64_t index, const cardreader::CardOrders& o,
                        const cardreader::CardLayout& layout);
nlohmann::json segment_card_json(std::int64_t index, const cardreader::CardOrders& o);

} // namespace parsons::cli
