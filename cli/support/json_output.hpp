// --json on show, check, gen and punch: one JSON document on standard output, for scripts
// (docs/json-output.md). The commands build their documents; this is what they share: the
// flag, the document's head, inches as numbers, the refusal of a second output on standard
// output, and the printing (through the one output writer, so a failed write is exit 2).
#pragma once

#include "cardreader/orders.hpp"
#include "cli/support/cli11_fwd.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cli {

// The version of the documents' fields; raised when a field changes meaning or goes away
// (new fields may be added without raising it).
inline constexpr int kJsonSchemaVersion = 1;

// The documents keep their keys in the order written ("command" and "schema_version" first).
using Json = nlohmann::ordered_json;

// Registers --json on a command, with the one wording of its help.
void add_json_flag(CLI::App& cmd, bool& json);

// {"command": COMMAND, "schema_version": 1}: the head of every document.
Json json_document(std::string_view command);

// A file's name, or null when none was written.
Json file_or_null(const std::string& name);
// A card's four digits as inches (8785 -> 8.785), or null for a blank field.
Json inches_json(std::optional<cardreader::Thousandths> value);

// Throws DeckError (exit 2) when --json is asked for and the output named by `flag` is "-":
// the document and that output would both go to standard output. Call it before anything
// is written.
void refuse_json_beside_standard_output(std::string_view command, bool json, std::string_view flag,
                                        const std::string& output);

// Prints the document on standard output, pretty-printed with a 2-space indent and a newline;
// throws DeckError ("standard output: cannot write: ...") when it cannot be written.
void print_json_document(const Json& document);

} // namespace parsons::cli
