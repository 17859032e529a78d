// out/demo/index.html: the page that shows what `parsons demo` ran, one section a system (the
// patent's own deck, the airfoil template, two tools, the press feeder, tapping), each run with
// a sentence, its figures, its pictures (plot, cut) and links to its replay page, report, deck
// and trace. Every path in it is relative to the demo's folder, so it opens from disk.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace parsons::cli {

// One run: what to look at, and its files (label, path relative to the demo's folder).
struct DemoRun {
    std::string title;
    std::string sentence;
    std::vector<std::pair<std::string, std::string>> pictures; // shown in the page
    std::vector<std::pair<std::string, std::string>> links;    // opened from it
};

// One system: its folder, its title (with the patent), what it shows, and its runs.
struct DemoSection {
    std::string folder;
    std::string title;
    std::string story;
    std::vector<DemoRun> runs;
};

// The page, self-contained (its style inline; pictures and links are the demo's own files).
std::string demo_index_html(const std::vector<DemoSection>& sections);

} // namespace parsons::cli
