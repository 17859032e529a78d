// An output file that is either complete or not there at all.
//
// Writes go to a hidden temporary file beside the target (".NAME.partial-PID"); commit()
// flushes, closes and renames it over the target. If the command fails or is killed before
// commit(), no file named as the output is left behind (the destructor removes the partial
// one), so a truncated deck or picture never looks whole.
#pragma once

#include <fstream>
#include <string>

namespace parsons::cli {

class OutputFile {
public:
    explicit OutputFile(std::string path);
    ~OutputFile();
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;

    std::ostream& stream() { return out_; }
    // Throws cardreader::DeckError naming the file if the write or rename failed.
    void commit();

private:
    std::string path_;
    std::string temp_path_;
    std::ofstream out_;
    bool committed_ = false;
};

// Writes a whole string to a file through OutputFile.
void write_file(const std::string& path, const std::string& contents);

} // namespace parsons::cli
