// The exhibit page's door into the emulator (docs/web.md): the page gives parsons a command
// line, exactly as a user types one, and parsons runs it on the page's in-memory files. So the
// page decodes, punches, draws, generates and runs with the program's own code, and its errors
// are worded as the program words them. A run is also recorded for the viewer, whose arrays
// the page reads in place: the page's timeline (outputs/replay/run_timeline.hpp) is handed to
// the command line, and run attaches it as it attaches --html's (the replay output of run's
// table of outputs, cli/run_outputs.cpp; outputs/replay/replay_output.hpp).
#include "cli/command_line.hpp"
#include "outputs/replay/run_timeline.hpp"

#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

std::unique_ptr<parsons::cli::RunTimeline> g_timeline;

// `parsons ARGS...` with ARGS a JSON array of strings; the exit code. Standard output and error
// reach the page line by line (Module.print, Module.printErr). With `record`, a run's timeline
// is kept for timeline_header() and the arrays.
int call(const std::string& args_json, bool record) {
    // The bundled airfoils and sample decks are embedded at /share/parsons (web/CMakeLists.txt).
    setenv("PARSONS_DATA_DIR", "/share/parsons", 1);
    std::vector<std::string> args{"parsons"};
    for (const auto& a : nlohmann::json::parse(args_json)) {
        args.push_back(a.get<std::string>());
    }
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    g_timeline = record ? std::make_unique<parsons::cli::RunTimeline>() : nullptr;
    const int code = parsons::cli::command_line_main(static_cast<int>(args.size()), argv.data(),
                                                     "parsons " PARSONS_VERSION " (WebAssembly)",
                                                     g_timeline.get());
    std::fflush(stdout);
    std::fflush(stderr);
    return code;
}

// The run's header without its signals, and the signals alone: the page asks for them only
// when the header's signals_signature is new to it (a new machine profile).
std::string timeline_header() {
    return g_timeline ? g_timeline->page_header_text() : "null";
}
std::string timeline_signals() {
    return g_timeline ? g_timeline->signals_text() : "null";
}

template <typename T>
emscripten::val view(const std::vector<T>& v) {
    return emscripten::val(emscripten::typed_memory_view(v.size(), v.data()));
}

emscripten::val change_times() {
    return view(g_timeline->change_times());
}
emscripten::val change_ids() {
    return view(g_timeline->change_ids());
}
emscripten::val change_values() {
    return view(g_timeline->change_values());
}
emscripten::val motion() {
    return view(g_timeline->motion());
}

} // namespace

EMSCRIPTEN_BINDINGS(parsons_web) {
    emscripten::function("call", &call);
    emscripten::function("timelineHeader", &timeline_header);
    emscripten::function("timelineSignals", &timeline_signals);
    emscripten::function("changeTimes", &change_times);
    emscripten::function("changeIds", &change_ids);
    emscripten::function("changeValues", &change_values);
    emscripten::function("motion", &motion);
}
