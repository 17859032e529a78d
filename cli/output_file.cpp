#include "cli/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/socket.h>
#include <sys/stat.h>
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

// The file a chain of symbolic links finally names (which may not exist yet); `path` itself
// when it is no link.
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

const volatile std::sig_atomic_t* g_give_up = nullptr;

// An EINTR to try again after: not once the operator has stopped the run.
bool try_again(int error) {
    return error == EINTR && (g_give_up == nullptr || *g_give_up == 0);
}

} // namespace

void give_up_on_signal(const volatile std::sig_atomic_t* flag) {
    g_give_up = flag;
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
    } else {
        // A character device or a FIFO: opened as it is, never created or truncated. (A FIFO
        // waits here for its reader, as any Unix program writing to one does.)
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
        fd_ = ::open(temp_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
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
}

void OutputFile::commit() {
    out_.flush();
    const bool written = buffer_.flush_all();
    const std::string name = kind_ == Kind::standard_output ? "standard output" : path_;
    if (!written || !out_) {
        const int error = buffer_.error() != 0 ? buffer_.error() : EIO;
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
    if (kind_ == Kind::replaced_file && ::rename(temp_path_.c_str(), target_.c_str()) != 0) {
        throw DeckError::in_file(name, "cannot put the file in place: " + reason(errno));
    }
    committed_ = true;
}

void make_folder(const std::string& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
        throw DeckError::in_file(dir, "cannot make the folder: " +
                                          (ec ? ec.message() : std::string("not a folder")));
    }
}

void write_file(const std::string& path, const std::string& contents) {
    OutputFile file(path);
    file.stream() << contents;
    file.commit();
}

bool standard_output_taken() {
    return g_standard_output_taken;
}

std::FILE* message_stream() {
    return g_standard_output_taken ? stderr : stdout;
}

void finish_standard_output() {
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
        const int error = errno != 0 ? errno : EIO;
        throw DeckError::in_file("standard output", "cannot write: " + reason(error));
    }
}

} // namespace parsons::cli
