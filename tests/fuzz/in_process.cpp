#include "tests/fuzz/in_process.hpp"

#include "cli/command_line.hpp"

#include <cstdio>
#include <unistd.h>

namespace parsons::fuzz {

int run_in_process(std::vector<std::string> args, int in, int out, int err) {
    std::fflush(stdout);
    std::fflush(stderr);
    const int saved[3] = {dup(0), dup(1), dup(2)};
    dup2(in, 0);
    dup2(out, 1);
    dup2(err, 2);
    args.insert(args.begin(), "parsons");
    std::vector<char*> argv;
    for (std::string& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    const int code =
        cli::command_line_main(static_cast<int>(args.size()), argv.data(), "parsons (fuzz)");
    std::fflush(stdout);
    std::fflush(stderr);
    for (int fd = 0; fd < 3; ++fd) {
        dup2(saved[fd], fd);
        ::close(saved[fd]);
    }
    std::clearerr(stdout);
    std::clearerr(stderr);
    std::clearerr(stdin);
    return code;
}

} // namespace parsons::fuzz
