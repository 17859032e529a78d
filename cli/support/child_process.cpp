#include "cli/support/child_process.hpp"

#include "cardreader/deck_error.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h> // environ

namespace parsons::cli {

namespace {

bool g_registered = false;
constexpr const char* kSelf = "/proc/self/exe";

// posix_spawn's file actions, released when they go.
class FileActions {
public:
    FileActions() { posix_spawn_file_actions_init(&actions_); }
    ~FileActions() { posix_spawn_file_actions_destroy(&actions_); }
    FileActions(const FileActions&) = delete;
    FileActions& operator=(const FileActions&) = delete;
    posix_spawn_file_actions_t* get() { return &actions_; }

private:
    posix_spawn_file_actions_t actions_{};
};

} // namespace

void register_parsons_executable() {
    g_registered = true;
}

bool parsons_executable_registered() {
    return g_registered;
}

pid_t start_parsons(const std::vector<std::string>& args, const std::string& out,
                    const std::string& err) {
    if (!g_registered) {
        throw cardreader::DeckError("this program is not the parsons executable, so it cannot "
                                    "start parsons as a child process (run the command with "
                                    "the parsons program itself)");
    }
    std::vector<std::string> all = {"parsons"};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    argv.reserve(all.size() + 1);
    for (std::string& a : all) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    FileActions actions;
    posix_spawn_file_actions_addopen(actions.get(), 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(actions.get(), 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    posix_spawn_file_actions_addopen(actions.get(), 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0644);
    pid_t pid = -1;
    const int e = posix_spawn(&pid, kSelf, actions.get(), nullptr, argv.data(), environ);
    if (e != 0) {
        throw cardreader::DeckError(std::string("cannot start parsons as a child process: ") +
                                    std::strerror(e));
    }
    return pid;
}

ChildEnd wait_for_child() {
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
        return {};
    }
    if (WIFEXITED(status)) {
        return {pid, WEXITSTATUS(status)};
    }
    return {pid, 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0)};
}

} // namespace parsons::cli
