#include "cli/support/manual.hpp"

#include "cli/support/value_names.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <sstream>

namespace parsons::cli {
namespace {

// roff text: backslashes and hyphens escaped, a line that would start with a control character
// protected.
std::string roff(const std::string& text) {
    std::string out;
    bool line_start = true;
    for (const char c : text) {
        if (line_start && (c == '.' || c == '\'')) {
            out += "\\&";
        }
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else {
            out += c;
        }
        line_start = c == '\n';
    }
    return out;
}

// Single-quoted for a shell: ' becomes '\''.
std::string shell_quoted(const std::string& text) {
    std::string out = "'";
    for (const char c : text) {
        out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
}

// A flag expects no value (CLI11's add_flag: expected(0)); every other option one or more.
bool takes_value(const CLI::Option& o) {
    return o.get_items_expected_max() > 0;
}

// An option in no group (group("")) is internal (bench's --child-*): CLI11's --help leaves it
// out, and so do the manual pages and the completion.
bool hidden(const CLI::Option& o) {
    return o.get_group().empty();
}

std::vector<const CLI::App*> subcommands_of(const CLI::App& app) {
    return app.get_subcommands([](const CLI::App*) { return true; });
}

std::vector<const CLI::Option*> named_options(const CLI::App& app) {
    return app.get_options(
        [](const CLI::Option* o) { return !o->get_positional() && !hidden(*o); });
}

std::vector<const CLI::Option*> positional_options(const CLI::App& app) {
    return app.get_options([](const CLI::Option* o) { return o->get_positional(); });
}

std::string page_name(const std::string& path) {
    std::string name = "parsons";
    std::istringstream words(path);
    std::string w;
    while (words >> w) {
        name += "-" + w;
    }
    return name;
}

// The footer of a command's --help in sections: the text before the first heading, then each
// heading ("Exit codes:", "Examples:") with its lines.
struct FooterSection {
    std::string heading; // empty: the text before any heading
    std::vector<std::string> lines;
};
std::vector<FooterSection> footer_sections(const std::string& footer) {
    std::vector<FooterSection> sections(1);
    std::istringstream in(footer);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.front() != ' ' && line.back() == ':') {
            sections.push_back({line.substr(0, line.size() - 1), {}});
        } else {
            sections.back().lines.push_back(line);
        }
    }
    for (FooterSection& s : sections) {
        while (!s.lines.empty() && s.lines.back().empty()) {
            s.lines.pop_back();
        }
    }
    return sections;
}

std::string section_title(const std::string& heading) {
    if (heading == "Exit codes") {
        return "EXIT STATUS";
    }
    return upper(heading);
}

std::string option_item(const CLI::Option& o) {
    std::string names;
    for (const std::string& n : option_names(o)) {
        names += fmt::format("{}\\fB{}\\fR", names.empty() ? "" : ", ", roff(n));
    }
    if (takes_value(o)) {
        names += fmt::format(" \\fI{}\\fR", roff(o.get_type_name()));
    }
    std::string text = o.get_description();
    std::vector<std::string> notes;
    if (!o.get_default_str().empty()) {
        notes.push_back("default: " + o.get_default_str());
    }
    if (o.get_required()) {
        notes.push_back("required");
    }
    if (!notes.empty()) {
        std::string joined;
        for (const std::string& n : notes) {
            joined += (joined.empty() ? "" : "; ") + n;
        }
        text += " (" + joined + ")";
    }
    return fmt::format(".TP\n{}\n{}\n", names, roff(text));
}

ManPage page_of(const std::string& path, const CLI::App& app, const std::string& version) {
    ManPage page;
    page.name = page_name(path);
    const std::string command = path.empty() ? "parsons" : "parsons " + path;
    std::string& t = page.text;
    t += fmt::format(".\\\" Written from parsons' command line by parsons_manual; do not edit.\n");
    t += fmt::format(".TH {} 1 \"\" \"{}\" \"parsons manual\"\n", upper(page.name), roff(version));
    t += fmt::format(".SH NAME\n{} \\- {}\n", roff(page.name), roff(app.get_description()));
    // Synopsis: the command, [OPTIONS], its positionals, or COMMAND if it has commands.
    t += fmt::format(".SH SYNOPSIS\n.B {}\n", roff(command));
    std::string synopsis = "[\\fIOPTIONS\\fR]";
    for (const CLI::Option* o :
         app.get_options([](const CLI::Option* x) { return x->get_positional(); })) {
        const std::string name = fmt::format("\\fI{}\\fR{}", roff(upper(o->get_name())),
                                             o->get_expected_max() > 1 ? " ..." : "");
        synopsis += " " + (o->get_required() ? name : "[" + name + "]");
    }
    const auto subs = subcommands_of(app);
    if (!subs.empty()) {
        synopsis += " \\fICOMMAND\\fR [\\fIOPTIONS\\fR]";
    }
    t += synopsis + "\n";
    t += fmt::format(".SH DESCRIPTION\n{}\n", roff(app.get_description()));
    const auto sections = footer_sections(app.get_footer());
    if (!sections.front().lines.empty()) {
        t += ".PP\n";
        for (const std::string& l : sections.front().lines) {
            t += roff(l) + "\n";
        }
    }
    const auto positionals =
        app.get_options([](const CLI::Option* x) { return x->get_positional(); });
    if (!positionals.empty()) {
        t += ".SH ARGUMENTS\n";
        for (const CLI::Option* o : positionals) {
            t += fmt::format(".TP\n\\fI{}\\fR\n{}\n", roff(upper(o->get_name())),
                             roff(o->get_description()));
        }
    }
    t += ".SH OPTIONS\n";
    for (const CLI::Option* o : named_options(app)) {
        t += option_item(*o);
    }
    if (!subs.empty()) {
        t += ".SH COMMANDS\n";
        for (const CLI::App* s : subs) {
            const std::string sub_path = path.empty() ? s->get_name() : path + " " + s->get_name();
            t += fmt::format(".TP\n.B {}\n{} (\\fB{}\\fR(1))\n", roff(s->get_name()),
                             roff(s->get_description()), roff(page_name(sub_path)));
        }
    }
    for (std::size_t i = 1; i < sections.size(); ++i) {
        t += fmt::format(".SH {}\n.nf\n", roff(section_title(sections[i].heading)));
        for (const std::string& l : sections[i].lines) {
            t += roff(l) + "\n";
        }
        t += ".fi\n";
    }
    t += ".SH SEE ALSO\n";
    std::string see = "\\fBparsons\\fR(1)";
    if (path.empty()) {
        see.clear();
        for (const CLI::App* s : subs) {
            see += fmt::format("{}\\fB{}\\fR(1)", see.empty() ? "" : ", ",
                               roff(page_name(s->get_name())));
        }
    } else if (const auto space = path.rfind(' '); space != std::string::npos) {
        see += fmt::format(", \\fB{}\\fR(1)", roff(page_name(path.substr(0, space))));
    }
    t += see + "\n";
    return page;
}

// The words of a command's completion: its subcommands, its options, the type name of each
// option's value (cli/support/value_names.hpp) and of its first positional.
struct Completion {
    std::string path; // "/gen/airfoil"; "" for the program
    const CLI::App* app;
    std::vector<std::pair<std::string, std::string>> subs;   // name, description
    std::vector<std::pair<std::string, std::string>> opts;   // name, description
    std::vector<std::pair<std::string, std::string>> valued; // option name, its value's type name
    std::string positional;                                  // the first positional's type name
};

std::vector<Completion> completions(const CLI::App& app) {
    std::vector<Completion> out;
    for (const auto& [path, a] : command_paths(app)) {
        Completion c;
        std::string slashed;
        std::istringstream words(path);
        std::string w;
        while (words >> w) {
            slashed += "/" + w;
        }
        c.path = slashed;
        c.app = a;
        for (const CLI::App* s : subcommands_of(*a)) {
            c.subs.emplace_back(s->get_name(), s->get_description());
        }
        for (const CLI::Option* o : named_options(*a)) {
            for (const std::string& n : option_names(*o)) {
                c.opts.emplace_back(n, o->get_description());
                if (takes_value(*o)) {
                    c.valued.emplace_back(n, o->get_type_name());
                }
            }
        }
        if (const auto pos = positional_options(*a); !pos.empty()) {
            c.positional = pos.front()->get_type_name();
        }
        out.push_back(std::move(c));
    }
    return out;
}

// Every type name the completion offers values for, once each, in order of first use.
std::vector<std::string> value_types(const std::vector<Completion>& all) {
    std::vector<std::string> types;
    auto add = [&](const std::string& t) {
        if (!t.empty() && std::find(types.begin(), types.end(), t) == types.end()) {
            types.push_back(t);
        }
    };
    for (const Completion& c : all) {
        for (const auto& v : c.valued) {
            add(v.second);
        }
        add(c.positional);
    }
    return types;
}

// Each extension as typed and in capitals ("cbn CBN"): format_for_path takes either.
std::vector<std::string> both_cases(const std::vector<std::string>& extensions) {
    std::vector<std::string> out;
    for (const std::string& e : extensions) {
        out.push_back(e);
        if (upper(e) != e) {
            out.push_back(upper(e));
        }
    }
    return out;
}

// bash: what to put in COMPREPLY for a value of this type name, the word typed being "$cur".
std::string bash_offer(const std::string& type) {
    const ValueChoices v = value_choices(type);
    std::string s;
    if (!v.words.empty()) {
        // one a line: _parsons_offer splits on newlines only (file names with spaces)
        std::string words;
        for (const std::string& w : v.words) {
            words += (words.empty() ? "" : "\\n") + w;
        }
        s += fmt::format(" $(compgen -W $'{}' -- \"$cur\")", words);
    }
    for (const std::string& e : both_cases(v.extensions)) {
        s += fmt::format(" $(compgen -f -X {} -- \"$cur\")", shell_quoted("!*." + e));
    }
    if (v.any_file) {
        s += " $(compgen -f -- \"$cur\")";
    } else if (v.folders || !v.extensions.empty()) {
        s += " $(compgen -d -- \"$cur\")";
    }
    return "COMPREPLY=(" + (s.empty() ? std::string() : s.substr(1)) + ")";
}

// zsh: the completion call for a value of this type name.
std::string zsh_offer(const std::string& type) {
    const ValueChoices v = value_choices(type);
    std::vector<std::string> calls;
    if (!v.words.empty()) {
        std::string words;
        for (const std::string& w : v.words) {
            words += " " + shell_quoted(w);
        }
        calls.push_back("compadd --" + words);
    }
    if (!v.extensions.empty()) {
        std::string kinds;
        for (const std::string& e : v.extensions) {
            kinds += (kinds.empty() ? "" : "|") + e;
        }
        calls.push_back("_files -g " + shell_quoted("*.(#i)(" + kinds + ")"));
    } else if (v.any_file) {
        calls.push_back("_files");
    } else if (v.folders) {
        calls.push_back("_files -/");
    }
    if (calls.empty()) {
        return "_message " + shell_quoted(type);
    }
    std::string s;
    for (const std::string& c : calls) {
        s += (s.empty() ? "" : "; ") + c;
    }
    return s;
}

template <class Pairs>
std::string first_words(const Pairs& pairs) {
    std::string s;
    for (const auto& p : pairs) {
        s += (s.empty() ? "" : " ") + p.first;
    }
    return s;
}

std::string path_pattern(const std::vector<Completion>& all) {
    std::string p;
    for (const Completion& c : all) {
        if (!c.path.empty()) {
            p += (p.empty() ? "" : "|") + c.path;
        }
    }
    return p;
}

} // namespace

std::vector<std::pair<std::string, const CLI::App*>> command_paths(const CLI::App& app) {
    std::vector<std::pair<std::string, const CLI::App*>> out;
    out.emplace_back("", &app);
    for (std::size_t i = 0; i < out.size(); ++i) {
        const auto [path, a] = out[i];
        std::size_t at = i + 1;
        for (const CLI::App* s : subcommands_of(*a)) {
            // depth first: a command's subcommands right after it
            out.insert(out.begin() + static_cast<std::ptrdiff_t>(at++),
                       {path.empty() ? s->get_name() : path + " " + s->get_name(), s});
        }
    }
    return out;
}

std::vector<CommandWords> command_words(const CLI::App& app) {
    std::vector<CommandWords> out;
    for (const auto& [path, a] : command_paths(app)) {
        CommandWords w;
        w.path = path;
        w.has_subcommands = !subcommands_of(*a).empty();
        for (const CLI::Option* o : named_options(*a)) {
            for (const std::string& n : option_names(*o)) {
                if (takes_value(*o)) {
                    w.valued.emplace_back(n, o->get_type_name());
                } else {
                    w.flags.push_back(n);
                }
            }
        }
        for (const CLI::Option* o : positional_options(*a)) {
            w.positionals.push_back(o->get_type_name());
        }
        out.push_back(std::move(w));
    }
    return out;
}

std::vector<std::string> option_names(const CLI::Option& option) {
    std::vector<std::string> names;
    for (const std::string& s : option.get_snames()) {
        names.push_back("-" + s);
    }
    for (const std::string& l : option.get_lnames()) {
        names.push_back("--" + l);
    }
    return names;
}

std::vector<ManPage> man_pages(const CLI::App& app, const std::string& version) {
    std::vector<ManPage> pages;
    for (const auto& [path, a] : command_paths(app)) {
        pages.push_back(page_of(path, *a, version));
    }
    return pages;
}

std::string bash_completion(const CLI::App& app) {
    const auto all = completions(app);
    std::string s =
        "# bash completion for parsons: written from its command line by parsons_manual; do not "
        "edit.\n"
        "# The values a type name offers (cli/support/value_names.hpp).\n"
        "_parsons_offer() {\n"
        "    local cur=$2 IFS=$'\\n'\n"
        "    case \"$1\" in\n";
    for (const std::string& t : value_types(all)) {
        s += fmt::format("        {}) {} ;;\n", shell_quoted(t), bash_offer(t));
    }
    s += "        *) COMPREPLY=() ;;\n"
         "    esac\n"
         "}\n"
         "_parsons() {\n"
         "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
         "    # --option=VALUE: bash splits the word at the '='.\n"
         "    if [[ $cur == = ]]; then\n"
         "        cur=\"\"\n"
         "    elif [[ $prev == = ]] && ((COMP_CWORD >= 2)); then\n"
         "        prev=${COMP_WORDS[COMP_CWORD-2]}\n"
         "    fi\n"
         "    local cmdpath=\"\" i w\n"
         "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
         "        w=${COMP_WORDS[i]}\n"
         "        case \"$cmdpath/$w\" in\n";
    s += fmt::format("            {}) cmdpath=\"$cmdpath/$w\" ;;\n", path_pattern(all));
    s += "        esac\n"
         "    done\n"
         "    local subs=\"\" opts=\"\" positional=\"\"\n"
         "    case \"$cmdpath\" in\n";
    for (const Completion& c : all) {
        s += fmt::format("        \"{}\") subs=\"{}\"; opts=\"{}\"; positional={} ;;\n", c.path,
                         first_words(c.subs), first_words(c.opts), shell_quoted(c.positional));
    }
    s += "    esac\n"
         "    # The word after an option that takes a value is that value.\n"
         "    case \"$cmdpath $prev\" in\n";
    for (const Completion& c : all) {
        for (const auto& [name, type] : c.valued) {
            s += fmt::format("        {}) _parsons_offer {} \"$cur\"; return ;;\n",
                             shell_quoted(c.path + " " + name), shell_quoted(type));
        }
    }
    s += "    esac\n"
         "    if [[ $cur == -* ]]; then\n"
         "        COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
         "    elif [[ -n $subs ]]; then\n"
         "        COMPREPLY=($(compgen -W \"$subs\" -- \"$cur\"))\n"
         "    else\n"
         "        _parsons_offer \"$positional\" \"$cur\"\n"
         "    fi\n"
         "}\n"
         "complete -o filenames -F _parsons parsons\n";
    return s;
}

std::string zsh_completion(const CLI::App& app) {
    const auto all = completions(app);
    auto described = [](const std::vector<std::pair<std::string, std::string>>& pairs) {
        std::string s;
        for (const auto& [name, what] : pairs) {
            std::string line = what;
            std::replace(line.begin(), line.end(), '\n', ' ');
            s += (s.empty() ? "" : " ") + shell_quoted(name + ":" + line);
        }
        return s;
    };
    std::string s =
        "#compdef parsons\n"
        "# zsh completion for parsons: written from its command line by parsons_manual; do not "
        "edit.\n"
        "# The values a type name offers (cli/support/value_names.hpp).\n"
        "_parsons_offer() {\n"
        "    case \"$1\" in\n";
    for (const std::string& t : value_types(all)) {
        s += fmt::format("        {}) {} ;;\n", shell_quoted(t), zsh_offer(t));
    }
    s += "        *) _message \"$1\" ;;\n"
         "    esac\n"
         "}\n"
         "_parsons() {\n"
         "    local cmdpath=\"\" i w prev=${words[CURRENT-1]}\n"
         "    for ((i = 2; i < CURRENT; i++)); do\n"
         "        w=${words[i]}\n"
         "        case \"$cmdpath/$w\" in\n";
    s += fmt::format("            {}) cmdpath=\"$cmdpath/$w\" ;;\n", path_pattern(all));
    s += "        esac\n"
         "    done\n"
         "    local -a subs opts\n"
         "    local positional=\"\"\n"
         "    case \"$cmdpath\" in\n";
    for (const Completion& c : all) {
        s += fmt::format("        \"{}\") subs=({}); opts=({}); positional={} ;;\n", c.path,
                         described(c.subs), described(c.opts), shell_quoted(c.positional));
    }
    s += "    esac\n"
         "    # --option=VALUE: the value after the '='.\n"
         "    if [[ $PREFIX == -*=* ]]; then\n"
         "        prev=${PREFIX%%=*}\n"
         "        compset -P '*='\n"
         "    fi\n"
         "    # The word after an option that takes a value is that value.\n"
         "    case \"$cmdpath $prev\" in\n";
    for (const Completion& c : all) {
        for (const auto& [name, type] : c.valued) {
            s += fmt::format("        {}) _parsons_offer {}; return ;;\n",
                             shell_quoted(c.path + " " + name), shell_quoted(type));
        }
    }
    s += "    esac\n"
         "    if [[ $PREFIX == -* ]]; then\n"
         "        _describe -t options 'option' opts\n"
         "    elif (( ${#subs} )); then\n"
         "        _describe -t commands 'command' subs\n"
         "    else\n"
         "        _parsons_offer \"$positional\"\n"
         "    fi\n"
         "}\n"
         "_parsons \"$@\"\n";
    return s;
}

} // namespace parsons::cli
