#include "cli/demo_index.hpp"

#include "cardreader/card_svg.hpp"

#include <fmt/format.h>

namespace parsons::cli {
namespace {

using cardreader::xml_escape;

constexpr const char* kStyle =
    R"(body{font:16px/1.5 system-ui,sans-serif;max-width:70rem;margin:0 auto;padding:1rem;color:#1b1b1b;background:#fff}
h1{font-size:1.6rem;margin:.5rem 0}h2{font-size:1.3rem;margin-top:2.5rem;border-bottom:1px solid #999}
h3{font-size:1.05rem;margin:1.5rem 0 .25rem}nav a{margin-right:1rem}
figure{margin:.5rem 0 1rem}figure img{max-width:100%;border:1px solid #ccc;background:#fff}
figcaption{font-size:.9rem;color:#444}ul.files{padding-left:1.2rem;margin:.25rem 0}
a{color:#0645ad}a:focus{outline:3px solid #f90}
@media (prefers-color-scheme: dark){body{background:#111;color:#eee}a{color:#8ab4f8}figcaption{color:#bbb}})";

std::string run_html(const DemoRun& run) {
    std::string out =
        fmt::format("<h3>{}</h3>\n<p>{}</p>\n", xml_escape(run.title), xml_escape(run.sentence));
    if (!run.links.empty()) {
        out += "<ul class=\"files\">\n";
        for (const auto& [label, path] : run.links) {
            out += fmt::format("<li><a href=\"{}\">{}</a></li>\n", xml_escape(path),
                               xml_escape(label));
        }
        out += "</ul>\n";
    }
    for (const auto& [caption, path] : run.pictures) {
        out += fmt::format("<figure><a href=\"{0}\"><img src=\"{0}\" alt=\"{1}\" "
                           "loading=\"lazy\"></a><figcaption>{1}</figcaption></figure>\n",
                           xml_escape(path), xml_escape(caption));
    }
    return out;
}

} // namespace

std::string demo_index_html(const std::vector<DemoSection>& sections) {
    std::string out = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
        "<title>parsons demo</title>\n<style>\n{}\n</style>\n</head>\n<body>\n"
        "<h1>parsons demo: the first numerically controlled milling machine, and three "
        "later systems</h1>\n"
        "<p>Everything on this page was written by one run of <code>parsons demo</code> on the "
        "emulated machine: the relay cabinet of John Parsons and Frank Stulen's patent (US "
        "2,820,187, 1952) reading punched cards, then three later patents' ideas carried as "
        "additions. Each run's replay page plays the run relay by relay in the browser; the "
        "trace opens in GTKWave.</p>\n<nav>",
        kStyle);
    for (const DemoSection& s : sections) {
        out += fmt::format("<a href=\"#{0}\">{1}</a>", xml_escape(s.folder), xml_escape(s.title));
    }
    out += "</nav>\n";
    for (const DemoSection& s : sections) {
        out += fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n<p>{}</p>\n", xml_escape(s.folder),
                           xml_escape(s.title), xml_escape(s.story));
        for (const DemoRun& run : s.runs) {
            out += run_html(run);
        }
        out += "</section>\n";
    }
    out += "<p>Every claim of the five patents, with a command that shows it at work: "
           "docs/claims.md (installed under share/doc/parsons/docs/).</p>\n</body>\n</html>\n";
    return out;
}

} // namespace parsons::cli
