// The one output writer of every command (reports, traces, events, paths, plots, cut and card
// pictures, saved states, decks). What it does depends on what the name is (docs/design-rules.md,
// Interfaces):
//
//   the name is              | writes                                  | on commit()
//   -------------------------+-----------------------------------------+------------------------
//   a regular file, or new   | a hidden temporary file beside it       | renames it over the name
//   a symbolic link          | a temporary file beside the link's      | renames it over the
//                            | final target (the link stays a link)    | target
//   a character device, a    | straight through (opened, never         | flushes and closes
//   FIFO or a Unix socket    | created, truncated or renamed)          |
//   "-"                      | standard output                         | flushes
//   a directory, a block     | nothing: an error naming it             |
//   device                   |                                         |
//
// So a file that is ours is either whole or not there at all (a truncated deck never looks
// whole), and nothing that is not ours is ever removed or renamed (commit() looks once more
// before its rename: a name that is by then anything but a regular file is never replaced): the
// only file the writer ever deletes is its own temporary file, created exclusively. Every failed
// write, standard output included, is a DeckError naming the output and the system's reason (exit
// 2).
#pragma once

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>

namespace parsons::cli {

// The reader of an output went away (a closed pipe, FIFO or socket: EPIPE). Not a DeckError:
// the command ends at once and quietly, with exit 141 (command_line.hpp), as `cat` and `grep` do
// when `head` has read enough.
class BrokenPipe : public std::runtime_error {
public:
    // `output`: as the user named it, or "standard output" / "standard error".
    explicit BrokenPipe(const std::string& output)
        : std::runtime_error(output + ": the reader went away (broken pipe)"), output_(output) {}
    const std::string& output() const { return output_; }

private:
    std::string output_;
};

// A stream buffer over a file descriptor that remembers the first write error (errno).
class DescriptorBuffer : public std::streambuf {
public:
    DescriptorBuffer();
    void attach(int fd) { fd_ = fd; }
    int error() const { return error_; }
    // Writes out what is buffered; false (and error() set) if the system refused.
    bool flush_all();

protected:
    int_type overflow(int_type ch) override;
    int sync() override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;

private:
    bool write_out(const char* data, std::size_t size);
    int fd_ = -1;
    int error_ = 0;
    std::unique_ptr<char[]> buffer_;
};

class OutputFile {
public:
    // Opens the output named `path` ("-" is standard output); throws DeckError naming it when
    // it cannot be written.
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& stream() { return out_; }
    // Finishes the output: flushes and closes it, and for a file of ours renames it into place.
    // Throws DeckError naming the output if any write, the close or the rename failed.
    void commit();
    // The output as the user named it ("standard output" for "-").
    std::string name() const { return kind_ == Kind::standard_output ? "standard output" : path_; }
    // Its reader went away (EPIPE): nothing more can be written to it.
    bool reader_gone() const { return buffer_.error() == EPIPE; }

private:
    enum class Kind { replaced_file, straight_through, standard_output };
    void open_temporary(const std::string& target);

    std::string path_;   // as the user named it, for messages
    std::string target_; // the file finally written: the name, or its link's final target
    std::string temp_path_;
    int temp_slot_ = -1; // where the signal handler finds temp_path_ (-1: not registered)
    Kind kind_ = Kind::replaced_file;
    int fd_ = -1;
    DescriptorBuffer buffer_;
    std::ostream out_;
    bool committed_ = false;
};

// True when `path` names a character device (/dev/null, a terminal), through any links.
bool character_device(const std::string& path);

// True when `path` names the null device (/dev/null, or a node of it made with mknod): what is
// written there is discarded, so a deck needs no format to go there.
bool null_device(const std::string& path);

// Makes a folder for outputs (and its parents); throws DeckError naming it when it cannot. A
// character device (/dev/null) is taken as it is: every file "in" it goes straight to it.
void make_folder(const std::string& dir);
// The output named `name` in the folder `dir`: dir/name, or the device itself when `dir` is a
// character device (show --svg /dev/null discards the pictures).
std::string file_in_folder(const std::string& dir, const std::string& name);

// A scratch folder of our own: made new (mkdtemp) under the system's temporary folder, and
// removed with everything in it when the object goes. Only a folder made here is ever removed.
class ScratchFolder {
public:
    // `prefix`: the start of its name ("parsons-bench"). Throws DeckError when none can be made.
    explicit ScratchFolder(const std::string& prefix);
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Writes a whole string to an output through OutputFile.
void write_file(const std::string& path, const std::string& contents);

// Forgets that standard output was taken: a new command in the same process (the page, the
// cli fuzz target). command_line_main calls it first.
void reset_standard_output();

// True once any output of this run was "-": messages meant for a person then go to standard
// error, so standard output carries only the data asked for.
bool standard_output_taken();
// Where the summary lines of a command go: stdout, or stderr when stdout carries an output.
std::FILE* message_stream();

// The operator's stop: once *flag is non-zero (a signal handler sets it), an open or a write
// that the signal interrupted gives up with a DeckError instead of trying again (a FIFO whose
// reader never comes, or stops reading). Null: always try again.
void give_up_on_signal(const volatile std::sig_atomic_t* flag);

// While a run goes on: once an output's reader has gone away, *flag is set to SIGPIPE, so the
// machine stops at its next event instead of running on for nobody. Null: nothing is set.
void stop_on_broken_pipe(volatile std::sig_atomic_t* flag);

// Standard output as the process ends: flushes it; throws DeckError ("standard output: ...")
// when it cannot be written (a full disk: "no space left on device"), and BrokenPipe when its
// reader went away. A write that failed before (CLI11's --help and --version through std::cout,
// say()) set the stream's error and an errno that later calls may have cleared: `seen_errno`
// (the errno just after such a write) or the one say() kept names the cause, EIO only when
// nothing does.
void finish_standard_output(int seen_errno = 0);

// True when `stream` (stdout or stderr) failed because its reader went away: errno is EPIPE,
// or its descriptor is a pipe or FIFO whose reading end is closed.
bool reader_gone(std::FILE* stream);

// Writes `text` to `stream` and flushes it, never throwing: for the last words of a command
// (its error message), which must not fail on a stream that is gone. False when it could not.
bool say(std::FILE* stream, const std::string& text);

// SIGINT, SIGTERM, SIGHUP and SIGQUIT, outside a run (which stops the machine instead): the
// output writer's temporary files are removed, then the signal ends the process as it would
// have (exit 128 + the signal in the shell). Installed by command_line_main; a signal the
// process was started ignoring (nohup, a background job) stays ignored.
void remove_temporaries_on_signals();

// The file a chain of symbolic links finally names (which may not exist yet); `path` itself
// when it is no link. Throws DeckError on a loop of links.
std::string final_target(const std::string& path);

} // namespace parsons::cli
