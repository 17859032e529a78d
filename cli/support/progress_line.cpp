#include "cli/support/progress_line.hpp"

#include "outputs/output_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace parsons::cli {

// The exhibit page's stderr (web/parsons_web.cpp) is emscripten's terminal emulation, which says
// it is a terminal; its lines go into the page, where a carriage return cannot redraw a line and
// the bar would pile up in front of the next message. So no progress line there.
#ifdef __EMSCRIPTEN__
ProgressLine::ProgressLine(bool /*wanted*/) : enabled_(false) {}
#else
ProgressLine::ProgressLine(bool wanted) : enabled_(wanted && isatty(fileno(stderr)) != 0) {}
#endif

ProgressLine::~ProgressLine() {
    clear();
}

void ProgressLine::show(double fraction, const std::string& text, bool force) {
    if (!enabled_) {
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && !force && now - last_ < std::chrono::milliseconds(100)) {
        return;
    }
    last_ = now;
    const double f = std::clamp(fraction, 0.0, 1.0);
    constexpr int kWidth = 30;
    const auto filled = static_cast<std::size_t>(f * kWidth);
    std::string line =
        fmt::format("[{:<{}}] {:3.0f}%  {}", std::string(filled, '#'), kWidth, 100 * f, text);
    if (line.size() > 79) {
        line.resize(79);
    }
    fmt::print(stderr, "\r{:<79}", line);
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressLine::clear() {
    if (drawn_) {
        say(stderr, fmt::format("\r{:<79}\r", "")); // never throws: the destructor clears too
        drawn_ = false;
    }
}

} // namespace parsons::cli
