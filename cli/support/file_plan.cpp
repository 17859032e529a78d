#include "cli/support/file_plan.hpp"

#include "outputs/output_file.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <sys/stat.h>
#include <unistd.h>

namespace parsons::cli {
namespace {

namespace fs = std::filesystem;
using cardreader::DeckError;

// What a name is, to compare with another (file_plan.hpp's table).
struct Identity {
    enum class Kind { none, inode, name };
    Kind kind = Kind::none;
    dev_t device = 0;
    ino_t inode = 0;
    std::string name; // the resolved path of a name not taken yet

    bool same_as(const Identity& other) const {
        if (kind == Kind::none || kind != other.kind) {
            return false;
        }
        return kind == Kind::inode ? device == other.device && inode == other.inode
                                   : name == other.name;
    }
};

Identity of_stat(const struct stat& st) {
    Identity id;
    if (!S_ISCHR(st.st_mode)) {
        id.kind = Identity::Kind::inode;
        id.device = st.st_dev;
        id.inode = st.st_ino;
    }
    return id;
}

// Where a name not taken yet will be made: its links followed, its folder made canonical.
std::string resolved_name(const std::string& path) {
    fs::path target;
    try {
        target = final_target(path);
    } catch (const DeckError&) {
        target = path; // a loop of links: the name as given (opening it fails later anyway)
    }
    std::error_code ec;
    const fs::path absolute = fs::absolute(target, ec);
    if (ec) {
        return target.lexically_normal().string();
    }
    const fs::path canonical = fs::weakly_canonical(absolute, ec);
    return (ec ? absolute.lexically_normal() : canonical).string();
}

Identity identity_of(const std::string& path, bool output) {
    struct stat st {};
    if (path == "-") {
        return fstat(output ? STDOUT_FILENO : STDIN_FILENO, &st) == 0 ? of_stat(st) : Identity{};
    }
    if (stat(path.c_str(), &st) == 0) {
        return of_stat(st);
    }
    Identity id;
    id.kind = Identity::Kind::name;
    id.name = resolved_name(path);
    return id;
}

// "--report x and DECK x" or "--report ./x and DECK x" as the user wrote them.
std::string both(const std::string& a, const std::string& path_a, const std::string& b,
                 const std::string& path_b) {
    if (path_a == path_b) {
        return fmt::format("{} and {} both name {}", a, b, path_a);
    }
    return fmt::format("{} {} and {} {} are the same file", a, path_a, b, path_b);
}

DeckError output_is_input(const std::string& out, const std::string& out_path,
                          const std::string& in, const std::string& in_path) {
    return DeckError(fmt::format("{}: an output never replaces an input (nothing was written; "
                                 "give {} another name)",
                                 both(out, out_path, in, in_path), out));
}

DeckError two_outputs(const std::string& a, const std::string& path_a, const std::string& b,
                      const std::string& path_b) {
    return DeckError(fmt::format("{}: one output would replace the other (nothing was written; "
                                 "give each output its own name)",
                                 both(a, path_a, b, path_b)));
}

struct Named {
    std::string option;
    std::string path;
    Identity id;
};

} // namespace

void FilePlan::read(std::string option, std::string path) {
    if (!path.empty()) {
        inputs_.push_back({std::move(option), std::move(path)});
    }
}

void FilePlan::write(std::string option, std::string path) {
    if (!path.empty()) {
        outputs_.push_back({std::move(option), std::move(path)});
    }
}

void FilePlan::write_folder(std::string option, std::string dir,
                            std::function<bool(const std::string&)> ours) {
    if (!dir.empty()) {
        folders_.push_back({std::move(option), std::move(dir), std::move(ours)});
    }
}

void FilePlan::check() const {
    // Standard output, by name: one output at most.
    const Entry* on_stdout = nullptr;
    for (const Entry& out : outputs_) {
        if (out.path != "-") {
            continue;
        }
        if (on_stdout != nullptr) {
            throw DeckError(fmt::format("only one output can go to standard output ('-'): {} and "
                                        "{} both name it (nothing was written)",
                                        on_stdout->option, out.option));
        }
        on_stdout = &out;
    }
    std::vector<Named> inputs;
    for (const Entry& in : inputs_) {
        inputs.push_back({in.option, in.path, identity_of(in.path, false)});
    }
    // Every output and every folder, in the order given, against the inputs and those before.
    std::vector<Named> outputs;
    auto add_output = [&](const std::string& option, const std::string& path) {
        Named out{option, path, identity_of(path, true)};
        for (const Named& in : inputs) {
            if (out.id.same_as(in.id)) {
                throw output_is_input(out.option, out.path, in.option, in.path);
            }
        }
        for (const Named& earlier : outputs) {
            if (out.id.same_as(earlier.id)) {
                throw two_outputs(earlier.option, earlier.path, out.option, out.path);
            }
        }
        outputs.push_back(std::move(out));
    };
    for (const Entry& out : outputs_) {
        add_output(out.option, out.path);
    }
    for (const Folder& folder : folders_) {
        if (folder.dir == "-") {
            throw DeckError(fmt::format("{} -: standard output takes one output, not a folder of "
                                        "them (give a folder, or /dev/null to discard them)",
                                        folder.option));
        }
        add_output(folder.option, folder.dir);
    }
    // The files a folder output would write: an existing one may be an input (or a link to
    // one), a new one may be another output's new name.
    for (const Folder& folder : folders_) {
        std::error_code ec;
        if (fs::is_directory(folder.dir, ec)) {
            for (const auto& entry : fs::directory_iterator(folder.dir, ec)) {
                const std::string name = entry.path().filename().string();
                if (!folder.ours(name)) {
                    continue;
                }
                const std::string file = entry.path().string();
                const Identity id = identity_of(file, true);
                for (const Named& in : inputs) {
                    if (id.same_as(in.id)) {
                        throw DeckError(fmt::format(
                            "{} would write {}, which is {} {}: an output never replaces an "
                            "input (nothing was written; give {} another folder)",
                            folder.option, file, in.option, in.path, folder.option));
                    }
                }
                for (const Named& out : outputs) {
                    if (out.option != folder.option && id.same_as(out.id)) {
                        throw DeckError(fmt::format(
                            "{} would write {}, which is {} {}: one output would replace the "
                            "other (nothing was written; give each output its own name)",
                            folder.option, file, out.option, out.path));
                    }
                }
            }
        }
        const std::string dir = resolved_name(folder.dir);
        for (const Named& out : outputs) {
            if (out.id.kind == Identity::Kind::name &&
                fs::path(out.id.name).parent_path() == fs::path(dir) &&
                folder.ours(fs::path(out.id.name).filename().string())) {
                throw two_outputs(out.option, out.path, folder.option, folder.dir);
            }
        }
    }
}

bool takes_companions(const std::string& path) {
    if (path.empty() || path == "-") {
        return false;
    }
    struct stat st {};
    return stat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode);
}

std::string companion_of(const std::string& path, const std::string& suffix) {
    return takes_companions(path) ? path + suffix : std::string();
}

} // namespace parsons::cli

namespace parsons::cli {

std::string job_file_for(const std::string& deck, const std::string& job_out) {
    return job_out.empty() ? companion_of(deck, ".job.json") : job_out;
}

std::string profile_file_for(const std::string& job_file) {
    if (!takes_companions(job_file)) {
        return "";
    }
    auto ends_with = [&job_file](const std::string& suffix) {
        return job_file.size() > suffix.size() &&
               job_file.compare(job_file.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    for (const std::string suffix : {".job.json", ".json"}) {
        if (ends_with(suffix)) {
            return job_file.substr(0, job_file.size() - suffix.size()) + ".profile.json";
        }
    }
    return job_file + ".profile.json";
}

std::string gtkwave_save_file_for(const std::string& trace) {
    if (!takes_companions(trace) || trace.find_first_of("\n\r") != std::string::npos) {
        return "";
    }
    fs::path save(trace);
    if (save.filename().empty()) {
        return ""; // "out/": a folder, which the trace's own writer refuses
    }
    save.replace_extension(".gtkw");
    const std::string name = save.string();
    return name == trace || !takes_companions(name) ? std::string() : name;
}

std::string job_option(const std::string& job_out) {
    return job_out.empty() ? "the job description beside -o" : "--job-out";
}

} // namespace parsons::cli
