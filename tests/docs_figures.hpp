// Figures the docs quote from a run, checked against the run (tests/docs_commands_test.cpp;
// docs/testing.md, "The docs are tested too"). A page declares how to get one, once, on a line
// of its own:
//   <!-- figure NAME: COMMAND => FILE SELECTOR FORMAT -->
// COMMAND runs in the page's scratch folder after the page's commands. SELECTOR is a JSON
// pointer into FILE; `rows`, the data rows of a CSV (lines not blank, not `#`, less the header);
// `lines`; `bytes`; or `event:SIGNAL=NEW#N` in an events stream, the time of the Nth change of
// SIGNAL to NEW (`...#N.old`: the value it changed from). FORMAT is `int`, `.Nf`, `±.Nf`
// (signed, with the typographic minus), `min` (seconds as whole minutes) or `MB` (bytes as whole
// megabytes), a trailing `,` grouping thousands. The page quotes it as
// `<!--f:NAME-->3,958<!--/f-->`, which Markdown shows as the bare figure.
#pragma once

#include "tests/test_support.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace parsons::test {

// Checks (or, when `updating`, rewrites) every quoted figure of a page's `lines`: each
// declaration's COMMAND goes to `run` (in `folder`, where FILE is then read); the count of
// quoted figures is added to `figures`, and `changed` is set when a figure was rewritten.
void check_figures(std::vector<std::string>& lines, const std::string& relative,
                   const std::function<ProcessResult(const std::string&)>& run,
                   const std::filesystem::path& folder, bool updating, bool& changed, int& figures);

} // namespace parsons::test
