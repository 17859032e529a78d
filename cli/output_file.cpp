#include "cli/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace parsons::cli {
namespace {

std::string temp_name_for(const std::string& path) {
    const std::filesystem::path p(path);
    const std::string name = "." + p.filename().string() + ".partial-" + std::to_string(getpid());
    return (p.parent_path() / name).string();
}

} // namespace

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), temp_path_(temp_name_for(path_)) {
    out_.open(temp_path_, std::ios::binary | std::ios::trunc);
    if (!out_) {
        throw cardreader::DeckError::in_file(path_,
                                             std::string("cannot write: ") + std::strerror(errno));
    }
}

OutputFile::~OutputFile() {
    if (!committed_) {
        out_.close();
        std::error_code ignored;
        std::filesystem::remove(temp_path_, ignored);
    }
}

void OutputFile::commit() {
    out_.flush();
    out_.close();
    if (!out_) {
        throw cardreader::DeckError::in_file(path_, "write error (disk full?)");
    }
    std::error_code ec;
    std::filesystem::rename(temp_path_, path_, ec);
    if (ec) {
        throw cardreader::DeckError::in_file(path_, "cannot rename into place: " + ec.message());
    }
    committed_ = true;
}

void write_file(const std::string& path, const std::string& contents) {
    OutputFile file(path);
    file.stream() << contents;
    file.commit();
}

} // namespace parsons::cli
