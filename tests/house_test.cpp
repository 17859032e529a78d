// The house (docs/architecture.md), held to its whiteboard: no room too big to read (no source
// file over 700 lines, no function over 150), cli/ keeps its commands only (at most 30 files at
// its top level), and the layers keep their order (no file of the 1952 machine includes a later
// system's folder; no library of the machine includes cli/, outputs/ or web/).
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using parsons::test::read_bytes;
using parsons::test::source_path;

namespace {

namespace fs = std::filesystem;

// The project's own C++ sources (tests aside: a test file may be as long as its cases).
const std::vector<std::string> kParts = {"cardreader", "relaylogic", "axes", "decks",
                                         "cli",        "outputs",    "web"};

std::vector<fs::path> sources() {
    std::vector<fs::path> files;
    for (const auto& part : kParts) {
        const fs::path root = source_path(part);
        if (!fs::exists(root)) {
            continue;
        }
        for (const auto& e : fs::recursive_directory_iterator(root)) {
            const std::string ext = e.path().extension().string();
            if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp")) {
                files.push_back(e.path());
            }
        }
    }
    std::sort(files.begin(), files.end());
    return files;
}

std::string project_path(const fs::path& p) {
    return fs::relative(p, source_path("")).generic_string();
}

// The text with comments, string and character literals blanked (newlines kept), so that
// braces and parentheses are code.
std::string code_of(const std::string& text) {
    std::string out = text;
    enum class In { code, line_comment, block_comment, string, character, raw } in = In::code;
    std::string raw_end;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const char c = text[i];
        const char next = i + 1 < text.size() ? text[i + 1] : '\0';
        switch (in) {
        case In::code:
            if (c == '/' && next == '/') {
                in = In::line_comment;
            } else if (c == '/' && next == '*') {
                in = In::block_comment;
            } else if (c == 'R' && next == '"' && (i == 0 || !std::isalnum(text[i - 1]))) {
                const std::size_t open = text.find('(', i + 2);
                raw_end = ")" + text.substr(i + 2, open - (i + 2)) + "\"";
                in = In::raw;
                continue;
            } else if (c == '"') {
                in = In::string;
                continue;
            } else if (c == '\'' && !(i > 0 && std::isxdigit(text[i - 1]))) {
                in = In::character; // not a digit separator (1'000)
                continue;
            } else {
                continue;
            }
            break;
        case In::line_comment:
            if (c == '\n') {
                in = In::code;
                continue;
            }
            break;
        case In::block_comment:
            if (c == '*' && next == '/') {
                out[i] = ' ';
                out[++i] = ' ';
                in = In::code;
                continue;
            }
            break;
        case In::string:
        case In::character:
            if (c == '\\') {
                out[i] = ' ';
                if (i + 1 < out.size() && text[i + 1] != '\n') {
                    out[++i] = ' ';
                }
                continue;
            }
            if ((in == In::string && c == '"') || (in == In::character && c == '\'')) {
                in = In::code;
                continue;
            }
            break;
        case In::raw:
            if (text.compare(i, raw_end.size(), raw_end) == 0) {
                i += raw_end.size() - 1;
                in = In::code;
                continue;
            }
            break;
        }
        if (c != '\n') {
            out[i] = ' ';
        }
    }
    return out;
}

// An '=' outside parentheses, not an operator's name: `x = {`, `auto f = [](int) {`.
bool initializer(const std::string& head) {
    if (head.find("operator") != std::string::npos) {
        return false;
    }
    int depth = 0;
    for (char c : head) {
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (c == '=' && depth == 0) {
            return true;
        }
    }
    return false;
}

struct Function {
    std::string where; // file:line of its opening brace
    int lines = 0;     // from the line of its opening brace to the line of its closing one
};

// Every function body at namespace or class scope: a brace after a parameter list that is not
// a control statement's, whose enclosing braces are namespaces, classes or nothing.
std::vector<Function> functions_in(const fs::path& file) {
    const std::string code = code_of(read_bytes(file));
    enum class Scope { container, function, other };
    struct Open {
        Scope scope;
        int line;
    };
    std::vector<Open> stack;
    std::vector<Function> found;
    std::string head; // the code since the last ; { or } at this depth
    int line = 1;
    static const std::regex container(R"(\b(namespace|class|struct|union|enum)\b)");
    static const std::regex control(R"(^\s*(if|for|while|switch|catch|do|else|try)\b)");
    for (char c : code) {
        if (c == '\n') {
            ++line;
        }
        if (c == '{') {
            const bool nested_in_function =
                std::any_of(stack.begin(), stack.end(),
                            [](const Open& o) { return o.scope != Scope::container; });
            Scope s = Scope::other;
            if (!nested_in_function) {
                if (std::regex_search(head, container) && head.find('(') == std::string::npos) {
                    s = Scope::container;
                } else if (head.find(')') != std::string::npos &&
                           !std::regex_search(head, control) && !initializer(head)) {
                    s = Scope::function;
                } else if (head.find("extern") != std::string::npos) {
                    s = Scope::container;
                }
            }
            stack.push_back({s, line});
            head.clear();
        } else if (c == '}') {
            if (!stack.empty()) {
                if (stack.back().scope == Scope::function) {
                    found.push_back({project_path(file) + ":" + std::to_string(stack.back().line),
                                     line - stack.back().line + 1});
                }
                stack.pop_back();
            }
            head.clear();
        } else if (c == ';') {
            head.clear();
        } else {
            head += c;
        }
    }
    return found;
}

int line_count(const fs::path& file) {
    const std::string text = read_bytes(file);
    return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

} // namespace

TEST_CASE("House: the function finder sees a function, a member function, a lambda's function "
          "and not a control block or an initializer") {
    const fs::path dir = fs::temp_directory_path() / "parsons-house-test";
    fs::create_directories(dir);
    const fs::path f = dir / "sample.cpp";
    parsons::test::write_bytes(f, "namespace a {\n"                      // 1
                                  "const int t[] = {1, 2};\n"            // 2
                                  "int f(int x) {\n"                     // 3
                                  "    if (x) {\n"                       // 4
                                  "        return [] { return 1; }();\n" // 5
                                  "    }\n"                              // 6
                                  "    return \"}\"[0];\n"               // 7
                                  "}\n"                                  // 8
                                  "struct S {\n"                         // 9
                                  "    void g() const {\n"               // 10
                                  "    } // }\n"                         // 11
                                  "};\n"                                 // 12
                                  "} // namespace a\n");
    const auto found = functions_in(f);
    fs::remove_all(dir);
    REQUIRE(found.size() == 2);
    CHECK(found[0].lines == 6); // f: lines 3 to 8
    CHECK(found[1].lines == 2); // S::g: lines 10 to 11
}

TEST_CASE("House: no source file over 700 lines and no function over 150 lines") {
    const auto files = sources();
    REQUIRE(files.size() > 150);
    std::string largest;
    int largest_lines = 0;
    Function longest;
    for (const auto& file : files) {
        const int lines = line_count(file);
        if (lines > largest_lines) {
            largest_lines = lines;
            largest = project_path(file);
        }
        INFO(project_path(file) << ": " << lines << " lines");
        CHECK(lines <= 700);
        for (const Function& fn : functions_in(file)) {
            if (fn.lines > longest.lines) {
                longest = fn;
            }
            INFO("the function at " << fn.where << ": " << fn.lines << " lines");
            CHECK(fn.lines <= 150);
        }
    }
    // The figures docs/architecture.md quotes.
    WARN("largest file " << largest << " (" << largest_lines << " lines); longest function at "
                         << longest.where << " (" << longest.lines << " lines)");
}

TEST_CASE("House: cli/ holds the commands, at most 30 files at its top level") {
    int top = 0;
    for (const auto& e : fs::directory_iterator(source_path("cli"))) {
        top += e.is_regular_file() ? 1 : 0;
    }
    INFO(top << " files at cli/'s top level");
    CHECK(top <= 30);
}

TEST_CASE("House: no file of the 1952 machine includes a later system's folder, and no library "
          "of the machine includes cli/, outputs/ or web/") {
    const std::regex later(R"(#include "relaylogic/(conditions|press|tapping|contouring)/)");
    const std::regex upward(R"(#include "(cli|outputs|web)/)");
    // The two files that name every later system by design: the registry, and the result that
    // lists each system's part.
    const std::vector<std::string> allowed = {"attachments.cpp", "run_result.hpp"};
    int read = 0;
    for (const auto& e : fs::directory_iterator(source_path("relaylogic"))) {
        const std::string name = e.path().filename().string();
        if (!e.is_regular_file() ||
            std::find(allowed.begin(), allowed.end(), name) != allowed.end()) {
            continue;
        }
        ++read;
        INFO("relaylogic/" << name);
        CHECK_FALSE(std::regex_search(read_bytes(e.path()), later));
    }
    CHECK(read > 20);
    for (const char* part : {"relaylogic", "axes", "cardreader", "decks"}) {
        for (const auto& e : fs::recursive_directory_iterator(source_path(part))) {
            const std::string ext = e.path().extension().string();
            if (!e.is_regular_file() || (ext != ".cpp" && ext != ".hpp")) {
                continue;
            }
            INFO(e.path().string());
            CHECK_FALSE(std::regex_search(read_bytes(e.path()), upward));
        }
    }
}
