#include "cli/support/json_output.hpp"

#include "axes/json_text.hpp"
#include "outputs/output_file.hpp"
#include "outputs/report/figures.hpp"

#include "cardreader/deck_error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>

namespace parsons::cli {

void add_json_flag(CLI::App& cmd, bool& json) {
    cmd.add_flag("--json", json,
                 "Print one JSON document on standard output instead of the text, for scripts "
                 "(docs/json-output.md); errors stay on standard error");
}

Json json_document(std::string_view command) {
    return Json{{"command", std::string(command)}, {"schema_version", kJsonSchemaVersion}};
}

Json file_or_null(const std::string& name) {
    return name.empty() ? Json(nullptr) : Json(name);
}

Json inches_json(std::optional<cardreader::Thousandths> value) {
    if (!value) {
        return nullptr;
    }
    return counter_reading(*value / 1000.0);
}

void refuse_json_beside_standard_output(std::string_view command, bool json, std::string_view flag,
                                        const std::string& output) {
    if (json && output == "-") {
        throw cardreader::DeckError(
            fmt::format("{}: --json and {} - cannot both go to standard output; write the "
                        "deck to a file (or leave out --json)",
                        command, flag));
    }
}

void print_json_document(const Json& document) {
    // Names and messages come from the user's files: a byte that is not UTF-8 is replaced
    // (U+FFFD) rather than refused.
    OutputFile out("-");
    out.stream() << axes::json_text(document, 2) << '\n';
    out.commit();
}

} // namespace parsons::cli
