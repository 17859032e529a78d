// Every file a command reads and every file it writes, named before anything is written and
// compared by what they are, not by how they are spelled (docs/reliability.md, "An output is
// never an input").
//
// A command lists its inputs (the deck, a profile file, a job description, a saved state...)
// and its outputs (each output option, and the files it writes on its own beside another: a
// deck's job description and profile), then calls check() before it opens anything for
// writing. Two names are the same file when
//
//   the name is                      | its identity
//   ---------------------------------+---------------------------------------------------------
//   an existing file, FIFO, socket   | device and inode (so ./x, a hard link and a symbolic
//   or folder                        | link to it are all the same file)
//   a name not taken yet             | the path it resolves to: links followed, the folder
//                                    | made absolute and canonical
//   "-"                              | standard input (as an input) or standard output (as an
//                                    | output), by what the descriptor is open on
//   a character device (/dev/null,   | none: a device is not a file that can be lost, and any
//   a terminal)                      | number of outputs may go to one
//
// except that "-" as an output is taken by name too: two outputs never share standard output.
// A clash is a DeckError (exit 2) naming both options and the file; nothing has been written.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace parsons::cli {

class FilePlan {
public:
    // A file the command reads: `option` as the user wrote it ("DECK", "--profile") or what
    // the file is ("the job description of --press-proof"); "-" is standard input. An empty
    // path is nothing.
    void read(std::string option, std::string path);
    // A file the command writes; "-" is standard output. An empty path is nothing.
    void write(std::string option, std::string path);
    // A folder the command writes files into, those whose names `ours` accepts (show --svg:
    // card-0001.svg ...). The folder itself must not be an input or another output, and no
    // file of it that the command would write may be an input.
    void write_folder(std::string option, std::string dir,
                      std::function<bool(const std::string&)> ours);

    // Throws DeckError on the first clash: two outputs on standard output, an output that is
    // an input, two outputs that are one file.
    void check() const;

private:
    struct Entry {
        std::string option;
        std::string path;
    };
    struct Folder {
        std::string option;
        std::string dir;
        std::function<bool(const std::string&)> ours;
    };
    std::vector<Entry> inputs_;
    std::vector<Entry> outputs_;
    std::vector<Folder> folders_;
};

// What a name is, for the files a command writes on its own beside another (a generated deck's
// job description and profile): only a file of ours (a regular file, a name not taken yet, or
// a link to one of those) has a companion beside it; standard output ("-"), a character
// device, a FIFO and a socket have none.
bool takes_companions(const std::string& path);

// The companion `suffix` of `path` (path + suffix), or "" when `path` takes none.
std::string companion_of(const std::string& path, const std::string& suffix);

// Where a generated deck's job description goes: `job_out` (--job-out FILE) when given, else
// beside the deck (DECK.job.json) when the deck takes companions; "" for nowhere.
std::string job_file_for(const std::string& deck, const std::string& job_out);
// Where a press or tapping job's profile goes: beside its job description, DECK.profile.json
// for DECK.job.json, J.profile.json for J.json, F.profile.json for another name F, when the job
// description takes companions; "" when it does not.
std::string profile_file_for(const std::string& job_file);
// Where the GTKWave save file of a VCD trace goes: beside it, the trace's name with its
// extension (if any) replaced by ".gtkw" (out.vcd -> out.gtkw, trace -> trace.gtkw), when the
// trace takes companions and the save file's name is free or a regular file; "" for none (a
// trace on standard output, a device or a FIFO; a trace itself named *.gtkw; a name with a line
// break, which the save file cannot quote).
std::string gtkwave_save_file_for(const std::string& trace);
// What a generator's summary names for its job description: "--job-out" when given, else "the
// job description beside -o".
std::string job_option(const std::string& job_out);

} // namespace parsons::cli
