// A progress line on standard error, for the commands that take a while (run, bench and its
// --scaling sweep, gen of a long deck): redrawn in place with a carriage return, at most ten
// times a second, and wiped when the work is done. Shown only when standard error is a
// terminal, so that a log, a pipe or a test sees none of it.
#pragma once

#include <chrono>
#include <string>

namespace parsons::cli {

class ProgressLine {
public:
    // `wanted`: false under -q; the line shows only when wanted and stderr is a terminal.
    explicit ProgressLine(bool wanted = true);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    bool shown() const { return enabled_; }
    // A bar for `fraction` (0..1) and the text beside it; `force` draws even within the tenth
    // of a second since the last drawing (a new stage).
    void show(double fraction, const std::string& text, bool force = false);
    // Wipes the line (the destructor does too).
    void clear();

private:
    bool enabled_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point last_{};
};

} // namespace parsons::cli
