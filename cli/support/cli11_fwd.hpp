// CLI11's two classes by name only. The headers of cli/ take a `CLI::App&` and include this; a
// file that builds options includes <CLI/CLI.hpp> itself. CLI11 is header-only and costs some
// 8 s of compiling a file (15 s under the sanitizers), so the dozen files that never call it are
// spared it (docs/testing.md, "How long the suite takes").
#pragma once

namespace CLI {
class App;
class Option;
} // namespace CLI
