#include "tests/test_support.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/listing_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>

#include <unistd.h>

namespace parsons::test {

std::string listing_error(const std::string& rows) {
    std::istringstream in(std::string(cardreader::kListingHeader) + "\n" + rows);
    cardreader::ListingReader reader(in, "t.csv");
    try {
        while (reader.next()) {
        }
    } catch (const cardreader::DeckError& e) {
        return e.what();
    }
    return "no error";
}

std::vector<cardreader::ReviewNote> review_all(cardreader::DeckReviewer& reviewer,
                                               const std::vector<cardreader::CardOrders>& cards) {
    std::vector<cardreader::ReviewNote> notes;
    for (const cardreader::CardOrders& c : cards) {
        for (cardreader::ReviewNote& n : reviewer.review(c)) {
            notes.push_back(std::move(n));
        }
    }
    for (cardreader::ReviewNote& n : reviewer.finish()) {
        notes.push_back(std::move(n));
    }
    return notes;
}

std::string q(const std::string& text) {
    return "'" + text + "'";
}

std::string read_error(const std::string& bytes, cardreader::DeckFormat format,
                       const std::string& file_name) {
    std::istringstream in(bytes);
    cardreader::DeckOptions options;
    options.format = format;
    options.file_name = file_name;
    auto source = cardreader::open_card_source(in, options);
    try {
        while (source->next()) {
        }
    } catch (const cardreader::DeckError& e) {
        return e.what();
    }
    return "no error";
}

namespace {

ProcessResult run_command(const std::string& command);

} // namespace

ProcessResult run_parsons(const std::string& args) {
    return run_command(std::string("'") + PARSONS_EXE + "' " + args + " 2>&1");
}

ProcessResult run_shell(const std::string& command_line) {
    std::string command = "{ " + command_line + " ; } 2>&1";
    const std::string exe = std::string("'") + PARSONS_EXE + "'";
    for (auto at = command.find("PARSONS"); at != std::string::npos;
         at = command.find("PARSONS", at + exe.size())) {
        command.replace(at, 7, exe);
    }
    return run_command(command);
}

namespace {

ProcessResult run_command(const std::string& command) {
    ProcessResult result;
    // The shell starts with SIGPIPE at its default, as from a terminal: the in-process command
    // line ignores it (cli/command_line.cpp), an ignored signal is inherited, and a shell cannot
    // restore one ignored when it started - a producer loop feeding a pipe whose reader has
    // gone would then run for ever.
    const auto before = std::signal(SIGPIPE, SIG_DFL);
    FILE* pipe = popen(command.c_str(), "r");
    std::signal(SIGPIPE, before);
    if (!pipe) {
        return result;
    }
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) {
        result.output.append(buffer.data(), n);
    }
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

} // namespace

TempDir::TempDir() {
    static std::mt19937_64 rng{std::random_device{}()};
    dir_ = std::filesystem::temp_directory_path() /
           ("parsons-test-" + std::to_string(rng() % 1000000000));
    std::filesystem::create_directories(dir_);
}

TempDir::~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
}

void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        lines.push_back(line);
    }
    return lines;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

bool running_as_root() {
    return geteuid() == 0;
}

namespace {

double test_share() {
    const char* v = std::getenv("PARSONS_TEST_SHARE");
    if (v == nullptr || *v == '\0') {
        return 1.0;
    }
    char* end = nullptr;
    const double share = std::strtod(v, &end);
    if (end == v || *end != '\0' || !(share > 0.0 && share <= 1.0)) {
        throw std::invalid_argument(std::string("PARSONS_TEST_SHARE: '") + v +
                                    "' is not a fraction in (0, 1]");
    }
    return share;
}

} // namespace

int share_of_cases(int n) {
    return std::max(1, static_cast<int>(std::lround(n * test_share())));
}

bool whole_share() {
    return test_share() == 1.0;
}

std::optional<std::filesystem::path> make_device_node(const std::filesystem::path& dir,
                                                      const std::string& name, unsigned major,
                                                      unsigned minor) {
    const std::filesystem::path node = dir / name;
    if (::mknod(node.c_str(), S_IFCHR | 0666, makedev(major, minor)) != 0) {
        return std::nullopt; // EPERM: not root, or no CAP_MKNOD
    }
    ::chmod(node.c_str(), 0666); // whatever the umask: a user the test runs as may write it
    // On a folder mounted nodev the node is made but cannot be opened: no use to a test.
    const int fd = ::open(node.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        ::unlink(node.c_str());
        return std::nullopt;
    }
    ::close(fd);
    return node;
}

std::string node_kind(const std::filesystem::path& p) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0) {
        return "absent";
    }
    if (S_ISCHR(st.st_mode)) {
        return fmt::format("character device {}:{}", major(st.st_rdev), minor(st.st_rdev));
    }
    return S_ISREG(st.st_mode)    ? "regular file"
           : S_ISDIR(st.st_mode)  ? "folder"
           : S_ISLNK(st.st_mode)  ? "symbolic link"
           : S_ISFIFO(st.st_mode) ? "FIFO"
                                  : "other";
}

std::string source_path(const std::string& relative) {
    return std::string(PARSONS_SOURCE_DIR) + "/" + relative;
}

std::string deck_bytes(const std::vector<cardreader::Card>& cards, cardreader::DeckFormat format) {
    std::ostringstream out;
    cardreader::DeckOptions options;
    options.format = format;
    auto sink = cardreader::open_card_sink(out, options);
    for (const auto& c : cards) {
        sink->write(c);
    }
    return out.str();
}

double widest_span_in(const std::string& refusal) {
    std::smatch m;
    if (!std::regex_search(refusal, m,
                           std::regex(R"(spans ([0-9.]+) x ([0-9.]+)(?: x ([0-9.]+))? in)"))) {
        return -1;
    }
    double widest = 0;
    for (std::size_t i = 1; i < m.size(); ++i) {
        if (m[i].matched) {
            widest = std::max(widest, std::stod(m[i].str()));
        }
    }
    return widest;
}

cardreader::CardOrders random_orders(std::mt19937& rng, const cardreader::CardLayout& layout) {
    using namespace cardreader;
    auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    CardOrders o;
    o.number = pick(0, 9999);
    o.spindle = static_cast<Spindle>(pick(0, 2));
    for (Axis a : kAxes) {
        AxisOrder& ax = o.axis(a);
        ax.motion = pick(0, 1) ? Motion::forward : Motion::reverse;
        ax.start_speed = pick(1, 3);
        for (std::size_t i = 0; i < 2; ++i) {
            const FieldKind kind = i == 0 ? FieldKind::slow_down_1 : FieldKind::slow_down_2;
            if (layout.find(kind, a) && pick(0, 1)) {
                ax.slow_down.at(i) = static_cast<Thousandths>(pick(0, 9999));
            }
        }
        ax.stop = static_cast<Thousandths>(pick(0, 9999));
        ax.check = static_cast<Thousandths>(pick(0, 9999));
        ax.sequence = static_cast<SequencePattern>(pick(0, 31));
    }
    return o;
}

// A deck of long moves on every axis, as a listing: each card shuttles the table 9 inches at
// speed 1 (patent slow-downs), the cross 1.9 in at speed 2, and so on.
std::string idle_rest(int card) {
    return fmt::format("{0},0,cross,+,3,,,0.000,0.000,2\n{0},0,vertical,+,3,,,0.000,0.000,3\n"
                       "{0},0,swivel,+,3,,,0.000,0.000,4\n{0},0,tilt,+,3,,,0.000,0.000,5\n",
                       card);
}

std::string long_listing(int cards) {
    struct Shuttle {
        const char* axis;
        int a, b, speed;
        const char* seq;
    };
    const std::array<Shuttle, 5> shuttles = {{{"table", 485, 9485, 1, "12"},
                                              {"cross", 1085, 2985, 2, "12"},
                                              {"vertical", 500, 1500, 2, "34"},
                                              {"swivel", 200, 400, 3, "34"},
                                              {"tilt", 100, 200, 3, "5"}}};
    std::string out = "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n";
    std::array<int, 5> at{};
    for (int n = 0; n < cards; ++n) {
        for (std::size_t i = 0; i < 5; ++i) {
            const Shuttle& s = shuttles.at(i);
            const int to = n % 2 == 0 ? s.b : s.a;
            const int from = at.at(i);
            const int sign = to >= from ? 1 : -1;
            const int speed = from == to ? 3 : s.speed;
            auto in = [](int t) { return fmt::format("{}.{:03}", t / 1000, t % 1000); };
            const std::string slow1 = speed <= 2 ? in(to - sign * (speed == 1 ? 200 : 100)) : "";
            const std::string slow2 = speed == 1 ? in(to - sign * 100) : "";
            out += fmt::format("{},1,{},{},{},{},{},{},{},{}\n", (n + 1) % 10000, s.axis,
                               sign > 0 ? "+" : "-", speed, slow1, slow2, in(to),
                               in(std::abs(to - from)), s.seq);
            at.at(i) = to;
        }
    }
    return out;
}

} // namespace parsons::test
