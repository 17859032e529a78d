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
// whole), and nothing that is not ours is ever removed or renamed: the only file the writer
// ever deletes is its own temporary file, created exclusively. Every failed write, standard
// output included, is a DeckError naming the output and the system's reason (exit 2).
#pragma once

#include <csignal>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>

namespace parsons::cli {

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

private:
    enum class Kind { replaced_file, straight_through, standard_output };
    void open_temporary(const std::string& target);

    std::string path_;   // as the user named it, for messages
    std::string target_; // the file finally written: the name, or its link's final target
    std::string temp_path_;
    Kind kind_ = Kind::replaced_file;
    int fd_ = -1;
    DescriptorBuffer buffer_;
    std::ostream out_;
    bool committed_ = false;
};

// Makes a folder for outputs (and its parents); throws DeckError naming it when it cannot.
void make_folder(const std::string& dir);

// Writes a whole string to an output through OutputFile.
void write_file(const std::string& path, const std::string& contents);

// True once any output of this run was "-": messages meant for a person then go to standard
// error, so standard output carries only the data asked for.
bool standard_output_taken();
// Where the summary lines of a command go: stdout, or stderr when stdout carries an output.
std::FILE* message_stream();

// The operator's stop: once *flag is non-zero (a signal handler sets it), an open or a write
// that the signal interrupted gives up with a DeckError instead of trying again (a FIFO whose
// reader never comes, or stops reading). Null: always try again.
void give_up_on_signal(const volatile std::sig_atomic_t* flag);

// Standard output as the process ends: flushes it; throws DeckError ("standard output: ...")
// when it cannot be written (a full disk, a closed pipe).
void finish_standard_output();

} // namespace parsons::cli
