#include "tests/test_support.hpp"

#include "cardreader/deck_error.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace parsons::test {

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
    FILE* pipe = popen(command.c_str(), "r");
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

std::string source_path(const std::string& relative) {
    return std::string(PARSONS_SOURCE_DIR) + "/" + relative;
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

} // namespace parsons::test
