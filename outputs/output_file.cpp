#include "outputs/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <pthread.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <unistd.h>

namespace parsons::cli {
namespace {

namespace fs = std::filesystem;
using cardreader::DeckError;

constexpr std::size_t kBufferBytes = 1 << 16;
constexpr int kMostLinks = 40; // as the kernel's own limit on a chain of links (ELOOP)

bool g_standard_output_taken = false;

std::string reason(int error) {
    return std::strerror(error);
}

// A Unix socket someone listens on, connected for writing.
int connect_socket(const std::string& path, const std::string& name) {
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (path.size() >= sizeof(address.sun_path)) {
        throw DeckError::in_file(name, "the socket's name is too long to connect to");
    }
    std::memcpy(address.sun_path, path.c_str(), path.size() + 1);
    const int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) {
        throw DeckError::in_file(name, "cannot write to the socket: " + reason(errno));
    }
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof(address)) != 0) {
        const int error = errno;
        ::close(fd);
        throw DeckError::in_file(name, "cannot write to the socket: " + reason(error));
    }
    return fd;
}

// The signals that end a command, whose handler removes the temporary files.
constexpr std::array<int, 4> kStopSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};

const volatile std::sig_atomic_t* g_give_up = nullptr;
volatile std::sig_atomic_t* g_broken_pipe_flag = nullptr;

// The temporary files open now, where a signal handler can find them: fixed slots of
// pointers, read and cleared atomically (async-signal-safe), each a copy owned by its
// OutputFile. A process with more outputs open at once than slots leaves the rest unregistered
// (removed by their OutputFile as usual, but not on a signal).
constexpr int kTemporarySlots = 64;
std::atomic<const char*> g_temporaries[kTemporarySlots];

int register_temporary(const char* path) {
    for (int i = 0; i < kTemporarySlots; ++i) {
        const char* empty = nullptr;
        if (g_temporaries[i].compare_exchange_strong(empty, path)) {
            return i;
        }
    }
    return -1;
}

void unregister_temporary(int slot) {
    if (slot >= 0) {
        g_temporaries[slot].store(nullptr);
    }
}

extern "C" void remove_temporaries_and_end(int signal) {
    for (auto& slot : g_temporaries) {
        if (const char* path = slot.load()) {
            ::unlink(path); // ours alone (created with O_EXCL)
        }
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// The descriptor of a pipe or FIFO whose reading end is closed: poll says POLLERR at once.
bool pipe_closed(int fd) {
    struct stat st {};
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISFIFO(st.st_mode)) {
        return false;
    }
    pollfd p{fd, 0, 0};
    return ::poll(&p, 1, 0) == 1 && (p.revents & POLLERR) != 0;
}

// An EINTR to try again after: not once the operator has stopped the run.
bool try_again(int error) {
    return error == EINTR && (g_give_up == nullptr || *g_give_up == 0);
}

// A FIFO opened for writing: the wait for its reader, as any Unix program writing to one makes
// it, but in steps of 20 ms, so that the operator's signal ends it whenever it came. A blocking
// open() is ended only by a signal that comes during it: one that came just before (while the
// command was still generating, say) would leave it waiting for a reader for ever. -1 with
// errno set when it cannot be opened, EINTR once the operator has stopped the run.
int open_fifo_for_writing(const std::string& target) {
    for (;;) {
        if (g_give_up != nullptr && *g_give_up != 0) {
            errno = EINTR;
            return -1;
        }
        const int fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC | O_NONBLOCK);
        if (fd >= 0) {
            const int flags = ::fcntl(fd, F_GETFL);
            if (flags < 0 || ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) < 0) {
                const int error = errno;
                ::close(fd);
                errno = error;
                return -1;
            }
            return fd;
        }
        if (errno != ENXIO && errno != EINTR) { // ENXIO: no reader yet
            return -1;
        }
        ::poll(nullptr, 0, 20); // a signal ends the pause early
    }
}

} // namespace

std::string final_target(const std::string& path) {
    fs::path p(path);
    for (int i = 0; i < kMostLinks; ++i) {
        struct stat st {};
        if (lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) {
            return p.string();
        }
        std::error_code ec;
        const fs::path next = fs::read_symlink(p, ec);
        if (ec) {
            throw DeckError::in_file(path, "cannot read the symbolic link: " + ec.message());
        }
        p = next.is_absolute() ? next : p.parent_path() / next;
    }
    throw DeckError::in_file(path, reason(ELOOP));
}

void give_up_on_signal(const volatile std::sig_atomic_t* flag) {
    g_give_up = flag;
}

void stop_on_broken_pipe(volatile std::sig_atomic_t* flag) {
    g_broken_pipe_flag = flag;
}

void remove_temporaries_on_signals() {
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_end;
    sigemptyset(&action.sa_mask);
    for (int signal : kStopSignals) {
        struct sigaction before {};
        sigaction(signal, nullptr, &before);
        if (before.sa_handler != SIG_IGN) { // ignored (nohup, a background job): left so
            sigaction(signal, &action, nullptr);
        }
    }
}

DescriptorBuffer::DescriptorBuffer() : buffer_(new char[kBufferBytes]) {
    setp(buffer_.get(), buffer_.get() + kBufferBytes);
}

bool DescriptorBuffer::write_out(const char* data, std::size_t size) {
    while (size > 0 && error_ == 0) {
        const ssize_t n = ::write(fd_, data, size);
        if (n < 0) {
            if (!try_again(errno)) {
                error_ = errno;
                if (error_ == EPIPE && g_broken_pipe_flag != nullptr) {
                    *g_broken_pipe_flag = SIGPIPE; // a run stops: nobody reads on
                }
            }
            continue;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return error_ == 0;
}

bool DescriptorBuffer::flush_all() {
    const bool ok = write_out(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    setp(buffer_.get(), buffer_.get() + kBufferBytes);
    return ok;
}

DescriptorBuffer::int_type DescriptorBuffer::overflow(int_type ch) {
    if (!flush_all()) {
        return traits_type::eof();
    }
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
        *pptr() = traits_type::to_char_type(ch);
        pbump(1);
    }
    return traits_type::not_eof(ch);
}

int DescriptorBuffer::sync() {
    return flush_all() ? 0 : -1;
}

std::streamsize DescriptorBuffer::xsputn(const char* s, std::streamsize n) {
    if (n >= static_cast<std::streamsize>(kBufferBytes)) {
        // A large block: out with what is buffered, then the block itself, unbuffered.
        if (!flush_all() || !write_out(s, static_cast<std::size_t>(n))) {
            return 0;
        }
        return n;
    }
    return std::streambuf::xsputn(s, n);
}

OutputFile::OutputFile(std::string path) : path_(std::move(path)), out_(&buffer_) {
    if (path_.empty()) {
        throw DeckError("an output needs a name (or - for standard output)");
    }
    if (path_ == "-") {
        if (g_standard_output_taken) {
            throw DeckError("only one output can go to standard output ('-')");
        }
        g_standard_output_taken = true;
        std::fflush(stdout); // what was printed before comes first
        kind_ = Kind::standard_output;
        fd_ = STDOUT_FILENO;
        buffer_.attach(fd_);
        return;
    }
    target_ = final_target(path_);
    struct stat st {};
    if (stat(target_.c_str(), &st) != 0) {
        if (errno != ENOENT) {
            throw DeckError::in_file(path_, "cannot write: " + reason(errno));
        }
        open_temporary(target_); // a new name: made whole, then given its name
        return;
    }
    if (S_ISDIR(st.st_mode)) {
        throw DeckError::in_file(path_, "is a directory, not a file to write");
    }
    if (S_ISBLK(st.st_mode)) {
        throw DeckError::in_file(path_, "is a block device (a disk): parsons writes to files, "
                                        "character devices, FIFOs and sockets only");
    }
    if (S_ISREG(st.st_mode)) {
        open_temporary(target_);
        // The new file takes the old one's permissions (and owner, where we may set it).
        fchmod(fd_, st.st_mode & 07777);
        if (st.st_uid != geteuid() || st.st_gid != getegid()) {
            [[maybe_unused]] const int ignored = fchown(fd_, st.st_uid, st.st_gid);
        }
        return;
    }
    kind_ = Kind::straight_through;
    if (S_ISSOCK(st.st_mode)) {
        fd_ = connect_socket(target_, path_);
    } else if (S_ISFIFO(st.st_mode)) {
        fd_ = open_fifo_for_writing(target_);
        if (fd_ < 0) {
            throw DeckError::in_file(path_, "cannot write: " + reason(errno));
        }
    } else {
        // A character device: opened as it is, never created or truncated.
        do {
            fd_ = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
        } while (fd_ < 0 && try_again(errno));
        if (fd_ < 0) {
            throw DeckError::in_file(path_, "cannot write: " + reason(errno));
        }
    }
    buffer_.attach(fd_);
}

void OutputFile::open_temporary(const std::string& target) {
    const fs::path t(target);
    const fs::path dir = t.parent_path().empty() ? fs::path(".") : t.parent_path();
    for (int attempt = 0; fd_ < 0; ++attempt) {
        const std::string name =
            fmt::format(".{}.partial-{}{}", t.filename().string(), getpid(),
                        attempt == 0 ? std::string() : "-" + std::to_string(attempt));
        temp_path_ = (dir / name).string();
        // O_EXCL: the temporary file is certainly ours, so removing it can harm nothing else.
        // The stop signals wait while it is made and registered, so that a handler never finds
        // it made and not registered.
        sigset_t stops;
        sigset_t before;
        sigemptyset(&stops);
        for (int signal : kStopSignals) {
            sigaddset(&stops, signal);
        }
        pthread_sigmask(SIG_BLOCK, &stops, &before);
        fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        const int error = errno;
        if (fd_ >= 0) {
            temp_slot_ = register_temporary(temp_path_.c_str());
        }
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        errno = error;
        if (fd_ < 0 && (errno != EEXIST || attempt >= 100)) {
            const int error = errno;
            temp_path_.clear();
            throw DeckError::in_file(path_,
                                     fmt::format("cannot write: cannot make a temporary file in "
                                                 "{}: {}",
                                                 dir.string(), reason(error)));
        }
    }
    kind_ = Kind::replaced_file;
    buffer_.attach(fd_);
}

OutputFile::~OutputFile() {
    if (kind_ != Kind::standard_output && fd_ >= 0) {
        ::close(fd_);
    }
    if (!committed_ && kind_ == Kind::replaced_file && !temp_path_.empty()) {
        ::unlink(temp_path_.c_str()); // ours alone (created with O_EXCL)
    }
    unregister_temporary(temp_slot_);
}

void OutputFile::commit() {
    out_.flush();
    const bool written = buffer_.flush_all();
    const std::string name = kind_ == Kind::standard_output ? "standard output" : path_;
    if (!written || !out_) {
        const int error = buffer_.error() != 0 ? buffer_.error() : EIO;
        if (error == EPIPE) {
            throw BrokenPipe(name);
        }
        throw DeckError::in_file(name, "cannot write: " + reason(error));
    }
    if (kind_ == Kind::standard_output) {
        committed_ = true;
        return;
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0 && errno != EINTR) {
        throw DeckError::in_file(name, "cannot write: " + reason(errno));
    }
    if (kind_ == Kind::replaced_file) {
        // The last look before the rename: a name that is not, or no longer, a regular file of
        // its own (a device, a FIFO, a socket, a folder made there since it was opened) is never
        // replaced, whatever the checks before decided. The temporary file goes (destructor).
        struct stat st {};
        if (lstat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
            throw DeckError::in_file(name, "is no longer a regular file (something else now "
                                           "stands under its name): not replaced, nothing "
                                           "written");
        }
        if (::rename(temp_path_.c_str(), target_.c_str()) != 0) {
            throw DeckError::in_file(name, "cannot put the file in place: " + reason(errno));
        }
    }
    committed_ = true;
    unregister_temporary(temp_slot_); // renamed: nothing of ours left to remove
    temp_slot_ = -1;
}

bool character_device(const std::string& path) {
    struct stat st {};
    return path != "-" && stat(path.c_str(), &st) == 0 && S_ISCHR(st.st_mode);
}

bool null_device(const std::string& path) {
    struct stat st {};
    return character_device(path) && stat(path.c_str(), &st) == 0 && st.st_rdev == makedev(1, 3);
}

void make_folder(const std::string& dir) {
    if (character_device(dir)) {
        return;
    }
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir, ec)) {
        throw DeckError::in_file(dir, "cannot make the folder: " +
                                          (ec ? ec.message() : std::string("not a folder")));
    }
}

ScratchFolder::ScratchFolder(const std::string& prefix) {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) {
        base = "/tmp";
    }
    std::string name = (base / (prefix + "-XXXXXX")).string();
    if (::mkdtemp(name.data()) == nullptr) {
        throw DeckError::in_file(base.string(), "cannot make a scratch folder: " + reason(errno));
    }
    path_ = name;
}

ScratchFolder::~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec); // made by mkdtemp above: ours, and all in it
}

std::string file_in_folder(const std::string& dir, const std::string& name) {
    return character_device(dir) ? dir : (fs::path(dir) / name).string();
}

void write_file(const std::string& path, const std::string& contents) {
    OutputFile file(path);
    file.stream() << contents;
    file.commit();
}

void reset_standard_output() {
    g_standard_output_taken = false;
}

bool standard_output_taken() {
    return g_standard_output_taken;
}

std::FILE* message_stream() {
    return g_standard_output_taken ? stderr : stdout;
}

namespace {
// The errno of the last write to standard output that say() saw fail (0: none).
int g_standard_output_errno = 0;
} // namespace

void finish_standard_output(int seen_errno) {
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
        if (errno == 0) {
            errno = seen_errno != 0 ? seen_errno : g_standard_output_errno;
        }
        if (reader_gone(stdout)) {
            throw BrokenPipe("standard output");
        }
        const int error = errno != 0 ? errno : EIO;
        throw DeckError::in_file("standard output", "cannot write: " + reason(error));
    }
}

bool reader_gone(std::FILE* stream) {
    return errno == EPIPE || pipe_closed(fileno(stream));
}

bool say(std::FILE* stream, const std::string& text) {
    // A stream that is gone takes nothing, and says nothing.
    errno = 0;
    const bool put = std::fputs(text.c_str(), stream) >= 0;
    const bool said = std::fflush(stream) == 0 && put && std::ferror(stream) == 0;
    if (!said && stream == stdout && errno != 0) {
        g_standard_output_errno = errno;
    }
    return said;
}

} // namespace parsons::cli
