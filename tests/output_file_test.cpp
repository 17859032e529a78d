// The one output writer (outputs/output_file.hpp, docs/design-rules.md, Interfaces): a file of ours
// is whole or not there; a link, a FIFO, a device or a socket that is not ours is written through
// and left what it was; every failed write is an error naming the output.
#include "outputs/output_file.hpp"

#include "cardreader/deck_error.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/un.h>
#include <thread>
#include <unistd.h>

using parsons::cli::OutputFile;
using parsons::cli::write_file;
using parsons::test::make_device_node;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;
namespace fs = std::filesystem;

using parsons::test::running_as_root;

namespace {

mode_t kind_of(const fs::path& p) {
    struct stat st {};
    REQUIRE(lstat(p.c_str(), &st) == 0);
    return st.st_mode & S_IFMT;
}

std::vector<std::string> names_in(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Bytes a little over three of the writer's buffers and many pipe buffers, not repeating.
std::string big_output() {
    std::string s;
    for (int i = 0; s.size() < 200'000; ++i) {
        s += std::to_string(i * 7919 % 100'003) + (i % 13 == 0 ? "\n" : ",");
    }
    return s;
}

// Reads a FIFO or a socket to its end on a thread of its own.
class Collector {
public:
    explicit Collector(std::function<int()> open_fd)
        : thread_([this, open_fd] {
              const int fd = open_fd();
              char buf[4096];
              ssize_t n = 0;
              while (fd >= 0 && (n = ::read(fd, buf, sizeof buf)) > 0) {
                  got_.append(buf, static_cast<std::size_t>(n));
              }
              if (fd >= 0) {
                  ::close(fd);
              }
          }) {}
    std::string wait() {
        thread_.join();
        return got_;
    }

private:
    std::string got_;
    std::thread thread_;
};

} // namespace

TEST_CASE("Output writer: a new name is written whole and nothing else is left beside it",
          "[output]") {
    TempDir dir;
    const std::string text = big_output();
    write_file(dir.str("deck.json"), text);
    CHECK(read_bytes(dir.path("deck.json")) == text);
    CHECK(names_in(dir.path("")) == std::vector<std::string>{"deck.json"});
}

TEST_CASE("Output writer: an output never committed leaves neither the name nor a temporary file",
          "[output]") {
    TempDir dir;
    write_bytes(dir.path("old.json"), "the old report\n");
    {
        OutputFile out(dir.str("new.json"));
        out.stream() << big_output();
        OutputFile replaced(dir.str("old.json"));
        replaced.stream() << "half a report";
    }
    CHECK(names_in(dir.path("")) == std::vector<std::string>{"old.json"});
    CHECK(read_bytes(dir.path("old.json")) == "the old report\n");
}

TEST_CASE("Output writer: a regular file is replaced whole and keeps its permissions", "[output]") {
    TempDir dir;
    write_bytes(dir.path("r.json"), "old");
    fs::permissions(dir.path("r.json"), fs::perms::owner_read | fs::perms::owner_write);
    write_file(dir.str("r.json"), "new contents\n");
    CHECK(read_bytes(dir.path("r.json")) == "new contents\n");
    CHECK(fs::status(dir.path("r.json")).permissions() ==
          (fs::perms::owner_read | fs::perms::owner_write));
}

TEST_CASE("Output writer: a name that became a device, a FIFO or a folder while the output was "
          "written is not replaced, and nothing is left beside it",
          "[output][never-lose]") {
    // The writer chose a temporary file for a new name (or a regular file); by the time it
    // commits, something else stands there. The last look before the rename keeps it.
    TempDir dir;
    auto became = [&dir](const std::string& name, const std::function<void(const fs::path&)>& make,
                         mode_t kind) {
        INFO(name);
        {
            OutputFile out(dir.str(name));
            out.stream() << big_output();
            make(dir.path(name));
            CHECK_THROWS_WITH(out.commit(), Catch::Contains(dir.str(name)) &&
                                                Catch::Contains("is no longer a regular file") &&
                                                Catch::Contains("not replaced"));
        }
        CHECK(kind_of(dir.path(name)) == kind);
        CHECK(names_in(dir.path("")).size() == 1); // no temporary file beside it
        fs::remove(dir.path(name));
    };
    became(
        "fifo", [](const fs::path& p) { REQUIRE(mkfifo(p.c_str(), 0600) == 0); }, S_IFIFO);
    became(
        "folder", [](const fs::path& p) { fs::create_directory(p); }, S_IFDIR);
    write_bytes(dir.path("was-a-file"), "old");
    became(
        "was-a-file",
        [](const fs::path& p) {
            fs::remove(p);
            REQUIRE(mkfifo(p.c_str(), 0600) == 0);
        },
        S_IFIFO);
    if (make_device_node(dir.path(""), "probe", 1, 3)) {
        fs::remove(dir.path("probe"));
        became(
            "null",
            [&dir](const fs::path& p) {
                REQUIRE(make_device_node(dir.path(""), p.filename().string(), 1, 3));
            },
            S_IFCHR);
    } else {
        WARN("the character device case skipped: mknod is not permitted here");
    }
}

TEST_CASE("Output writer: a file named like its temporary file is not ours and stays", "[output]") {
    TempDir dir;
    const std::string lookalike = ".r.json.partial-" + std::to_string(getpid());
    write_bytes(dir.path(lookalike), "someone else's");
    write_file(dir.str("r.json"), "report\n");
    CHECK(read_bytes(dir.path(lookalike)) == "someone else's");
    CHECK(read_bytes(dir.path("r.json")) == "report\n");
    CHECK(names_in(dir.path("")) == std::vector<std::string>{lookalike, "r.json"});
}

TEST_CASE("Output writer: a symbolic link stays a link and its final target takes the output",
          "[output]") {
    TempDir dir;
    fs::create_directories(dir.path("store"));
    write_bytes(dir.path("store/real.json"), "old");
    // A chain: out.json -> mid.json -> store/real.json (relative links, each from its folder).
    fs::create_symlink("store/real.json", dir.path("mid.json"));
    fs::create_symlink("mid.json", dir.path("out.json"));
    fs::create_symlink("store/none-yet.json", dir.path("dangling.json"));
    write_file(dir.str("out.json"), "through two links\n");
    write_file(dir.str("dangling.json"), "a link to a name not made yet\n");

    CHECK(kind_of(dir.path("out.json")) == S_IFLNK);
    CHECK(kind_of(dir.path("mid.json")) == S_IFLNK);
    CHECK(fs::read_symlink(dir.path("out.json")) == "mid.json");
    CHECK(read_bytes(dir.path("store/real.json")) == "through two links\n");
    CHECK(kind_of(dir.path("dangling.json")) == S_IFLNK);
    CHECK(read_bytes(dir.path("store/none-yet.json")) == "a link to a name not made yet\n");
    // The temporary files went beside the targets, and are gone.
    CHECK(names_in(dir.path("store")) == std::vector<std::string>{"none-yet.json", "real.json"});
}

TEST_CASE("Output writer: a link loop is an error naming the output", "[output]") {
    TempDir dir;
    fs::create_symlink("b", dir.path("a"));
    fs::create_symlink("a", dir.path("b"));
    CHECK_THROWS_WITH(write_file(dir.str("a"), "x"),
                      Catch::Contains(dir.str("a")) && Catch::Contains("symbolic links"));
    CHECK(kind_of(dir.path("a")) == S_IFLNK);
}

TEST_CASE("Output writer: a FIFO stays a FIFO and its reader gets every byte", "[output]") {
    TempDir dir;
    const fs::path fifo = dir.path("live.vcd");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string text = big_output();
    Collector reader([&] { return ::open(fifo.c_str(), O_RDONLY); });
    write_file(fifo.string(), text);
    CHECK(reader.wait() == text);
    CHECK(kind_of(fifo) == S_IFIFO);
    CHECK(names_in(dir.path("")) == std::vector<std::string>{"live.vcd"});
}

TEST_CASE("Output writer: a FIFO whose reader went away is a broken pipe naming it, not a "
          "DeckError",
          "[output]") {
    TempDir dir;
    const fs::path fifo = dir.path("gone");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    std::signal(SIGPIPE, SIG_IGN); // as the parsons executable does
    // A reader that opens the FIFO and closes it unread: more than a pipe's buffer cannot go.
    std::thread quick([&] {
        const int fd = ::open(fifo.c_str(), O_RDONLY);
        ::close(fd);
    });
    OutputFile out(fifo.string());
    quick.join();
    out.stream() << big_output();
    CHECK(out.reader_gone());
    try {
        out.commit();
        FAIL("commit() wrote to a FIFO nobody reads");
    } catch (const parsons::cli::BrokenPipe& e) {
        CHECK(e.output() == fifo.string());
        CHECK_THAT(e.what(), Catch::Contains("broken pipe"));
    }
    CHECK(kind_of(fifo) == S_IFIFO);
}

TEST_CASE("Output writer: a character device is written straight through and stays a device",
          "[output]") {
    // Devices of the test's own (mknod), never the machine's /dev/null or /dev/full (issue 53).
    TempDir dir;
    const auto null = make_device_node(dir.path(""), "null", 1, 3);
    const auto full = make_device_node(dir.path(""), "full", 1, 7);
    if (!null || !full) {
        WARN("skipped: mknod is not permitted here (not root, or no CAP_MKNOD), and the test "
             "writes no device but its own");
        return;
    }
    write_file(null->string(), big_output());
    CHECK(kind_of(*null) == S_IFCHR);
    write_file(null->string(), "discarded");
    CHECK(kind_of(*null) == S_IFCHR);
    CHECK_THROWS_WITH(write_file(full->string(), big_output()),
                      Catch::Contains(full->string()) &&
                          Catch::Contains("No space left on device"));
    CHECK(kind_of(*full) == S_IFCHR);
    // Nothing beside them: no temporary file, no companion.
    CHECK(names_in(dir.path("")) == std::vector<std::string>{"full", "null"});
}

TEST_CASE("Output writer: a Unix socket that listens gets the whole output", "[output]") {
    TempDir dir;
    const fs::path socket_path = dir.path("viewer.sock");
    const int server = ::socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(server >= 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    REQUIRE(socket_path.string().size() < sizeof(address.sun_path));
    std::strcpy(address.sun_path, socket_path.c_str());
    REQUIRE(::bind(server, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0);
    REQUIRE(::listen(server, 1) == 0);
    const std::string text = big_output();
    Collector reader([&] { return ::accept(server, nullptr, nullptr); });
    write_file(socket_path.string(), text);
    CHECK(reader.wait() == text);
    ::close(server);
    CHECK(kind_of(socket_path) == S_IFSOCK);
}

TEST_CASE("Output writer: a directory or a block device is refused, named, and left alone",
          "[output]") {
    TempDir dir;
    fs::create_directories(dir.path("folder"));
    CHECK_THROWS_WITH(write_file(dir.str("folder"), "x"),
                      Catch::Contains(dir.str("folder")) && Catch::Contains("is a directory"));
    CHECK(fs::is_directory(dir.path("folder")));
    if (running_as_root()) {
        const fs::path disk = dir.path("disk");
        REQUIRE(mknod(disk.c_str(), S_IFBLK | 0600, makedev(7, 200)) == 0);
        CHECK_THROWS_WITH(write_file(disk.string(), "x"), Catch::Contains("block device"));
        CHECK(kind_of(disk) == S_IFBLK);
    }
}

TEST_CASE("Output writer: a folder for outputs that cannot be made is an error naming it",
          "[output]") {
    TempDir dir;
    write_bytes(dir.path("plain"), "a file, not a folder");
    CHECK_THROWS_AS(parsons::cli::make_folder(dir.str("plain/sub")),
                    parsons::cardreader::DeckError);
    CHECK_THROWS_WITH(parsons::cli::make_folder(dir.str("plain")),
                      Catch::Contains("plain") && Catch::Contains("cannot make the folder"));
}

// ---- every command's every output, end to end ----------------------------------------------

namespace {

struct OutputCase {
    std::string name;
    std::string command; // {OUT} stands for the output's name
    int exit_code = 0;
    std::string file_in_dir; // for an output into a folder: {OUT} is the folder, this the file
};

// The outputs of every command. Each names exactly one output {OUT}.
std::vector<OutputCase> output_cases() {
    return {
        {"run --report", "run deck.cbn -q --report {OUT}", 0, ""},
        {"run --trace", "run deck.cbn -q --trace {OUT}", 0, ""},
        {"run --events", "run deck.cbn -q --events {OUT}", 0, ""},
        {"run --path", "run deck.cbn -q --path {OUT}", 0, ""},
        {"run --plot", "run deck.cbn -q --plot {OUT}", 0, ""},
        {"run --cut", "run wing.cbn -q --cut {OUT}", 0, ""},
        {"run --save-state", "run deck.cbn -q --limit table=0:5 --save-state {OUT}", 3, ""},
        {"punch -o", "punch listing.csv --to cbn -o {OUT}", 0, ""},
        {"convert -o", "convert deck.cbn --to bin -o {OUT}", 0, ""},
        {"gen -o", "gen airfoil --naca 0012 --chord 2 --stations 12 --to cbn -o {OUT}", 0, ""},
        {"gen --centres",
         "gen airfoil --naca 0012 --chord 2 --stations 12 -o g.cbn --centres {OUT}", 0, ""},
        {"show --svg (a card picture)", "show deck.cbn --svg {OUT}", 0, "card-0002.svg"},
    };
}

std::string replaced(std::string text, const std::string& what, const std::string& with) {
    for (auto at = text.find(what); at != std::string::npos;
         at = text.find(what, at + with.size())) {
        text.replace(at, what.size(), with);
    }
    return text;
}

// A scratch folder with the sample deck, its listing and a generated template deck.
void prepare(const TempDir& dir) {
    write_bytes(dir.path("listing.csv"),
                read_bytes(source_path("decks/samples/patent-example.csv")));
    REQUIRE(
        run_shell("cd " + q(dir.str("")) + " && PARSONS punch listing.csv -o deck.cbn").exit_code ==
        0);
    REQUIRE(run_shell("cd " + q(dir.str("")) +
                      " && PARSONS gen airfoil --naca 0012 --chord 2 --stations 12 -o wing.cbn")
                .exit_code == 0);
}

} // namespace

TEST_CASE("CLI: every output goes into a FIFO, through a link and into a device unharmed",
          "[output][cli]") {
    TempDir dir;
    prepare(dir);
    const std::string cd = "cd " + q(dir.str("")) + " && ";
    for (const OutputCase& c : output_cases()) {
        INFO(c.name);
        const bool in_dir = !c.file_in_dir.empty();
        auto command = [&](const std::string& out) {
            return cd + "PARSONS " + replaced(c.command, "{OUT}", out);
        };
        // What a regular file gets: the reference the others must equal byte for byte.
        if (in_dir) {
            fs::create_directories(dir.path("ref"));
        }
        const auto ref = run_shell(command("ref"));
        INFO(ref.output);
        REQUIRE(ref.exit_code == c.exit_code);
        const std::string expected = read_bytes(dir.path(in_dir ? "ref/" + c.file_in_dir : "ref"));
        REQUIRE(expected.size() > 20);

        // A FIFO with a reader.
        const std::string fifo_out = in_dir ? "fifo-dir" : "fifo";
        const fs::path fifo = dir.path(in_dir ? "fifo-dir/" + c.file_in_dir : "fifo");
        fs::create_directories(fifo.parent_path());
        REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
        // If parsons never opened the FIFO, opening it read-write (which never waits) and
        // closing it ends cat's wait: no hang whatever parsons did.
        const auto fed = run_shell(cd + "{ cat " + q(fifo.string()) + " > from-fifo & " +
                                   command(fifo_out).substr(cd.size()) + "; rc=$?; exec 3<>" +
                                   q(fifo.string()) + "; exec 3>&-; wait; exit $rc; }");
        INFO(fed.output);
        CHECK(fed.exit_code == c.exit_code);
        CHECK(kind_of(fifo) == S_IFIFO);
        CHECK(read_bytes(dir.path("from-fifo")) == expected);

        // A symbolic link: still a link, its target holds the output.
        const std::string link_out = in_dir ? "link-dir" : "link";
        const fs::path link = dir.path(in_dir ? "link-dir/" + c.file_in_dir : "link");
        fs::create_directories(link.parent_path());
        fs::create_directories(dir.path("targets"));
        write_bytes(dir.path("targets/t"), "old");
        fs::create_symlink(dir.path("targets/t"), link);
        CHECK(run_shell(command(link_out)).exit_code == c.exit_code);
        CHECK(kind_of(link) == S_IFLNK);
        CHECK(read_bytes(dir.path("targets/t")) == expected);

        // A character device: a null device of our own where we may make one (never the
        // machine's /dev/null), else none.
        const std::string device_out = in_dir ? "dev-dir" : "null";
        const fs::path device = dir.path(in_dir ? "dev-dir/" + c.file_in_dir : "null");
        fs::create_directories(device.parent_path());
        if (make_device_node(device.parent_path(), device.filename().string(), 1, 3)) {
            CHECK(run_shell(command(device_out)).exit_code == c.exit_code);
            CHECK(kind_of(device) == S_IFCHR);
        } else {
            WARN("the character device case skipped: mknod is not permitted here");
        }
        for (const char* name : {"ref", "fifo", "link", "null", "from-fifo", "fifo-dir", "link-dir",
                                 "dev-dir", "targets"}) {
            fs::remove_all(dir.path(name));
        }
    }
}

TEST_CASE("CLI: --report - writes the report to standard output and the summary to stderr",
          "[output][cli]") {
    TempDir dir;
    prepare(dir);
    const auto r = run_shell("cd " + q(dir.str("")) +
                             " && PARSONS run deck.cbn --report - "
                             "2>summary.txt");
    REQUIRE(r.exit_code == 0);
    const auto report = nlohmann::json::parse(r.output); // nothing but the report
    CHECK(report["status"] == "completed");
    CHECK(read_bytes(dir.path("summary.txt")).find("cards run      4") != std::string::npos);
    // Two outputs cannot share standard output.
    const auto two = run_shell("cd " + q(dir.str("")) +
                               " && PARSONS run deck.cbn --report - --path - >/dev/null");
    CHECK(two.exit_code == 2);
    CHECK(two.output.find("only one output can go to standard output") != std::string::npos);
}

TEST_CASE("CLI: a full disk on standard output is exit 2 with the reason, for every command and "
          "every --json document",
          "[output][cli]") {
    TempDir dir;
    prepare(dir);
    const std::string cd = "cd " + q(dir.str("")) + " && ";
    for (const char* command :
         {"run deck.cbn", "run deck.cbn -q --report -", "show deck.cbn", "check deck.cbn",
          "convert deck.cbn --to listing -o -", "punch listing.csv --to cbn -o -", "profile",
          "run --help", "show deck.cbn --json", "check deck.cbn --json",
          "punch listing.csv -o d.cbn --json",
          "gen airfoil --naca 2412 --stations 10 -o g.cbn --json"}) {
        INFO(command);
        const auto r = run_shell(cd + "PARSONS " + command + " > /dev/full");
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("parsons: error: standard output: cannot write: No space left on "
                            "device") != std::string::npos);
    }
}

TEST_CASE("CLI: demo --out where no folder can be made is an ordinary error", "[output][cli]") {
    TempDir dir;
    write_bytes(dir.path("plain"), "a file");
    const auto r = run_parsons("demo --out " + q(dir.str("plain/demo")));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("parsons: error: " + dir.str("plain/demo")) != std::string::npos);
    CHECK(r.output.find("internal error") == std::string::npos);
}

TEST_CASE("CLI: '-' reads a deck from standard input, its format told from its bytes",
          "[output][cli]") {
    TempDir dir;
    prepare(dir);
    const std::string cd = "cd " + q(dir.str("")) + " && ";
    const auto direct = run_shell(cd + "PARSONS show deck.cbn");
    REQUIRE(direct.exit_code == 0);
    const std::string cards = direct.output.substr(direct.output.find("card 1 "));
    for (const char* format : {"cbn", "bin", "listing"}) {
        INFO(format);
        REQUIRE(run_shell(cd + "PARSONS convert deck.cbn -o copy --to " + format).exit_code == 0);
        const auto shown = run_shell(cd + "PARSONS show - < copy");
        CHECK(shown.exit_code == 0);
        CHECK(shown.output.find(std::string("deck - (") + format) != std::string::npos);
        const auto at = shown.output.find("card 1 ");
        REQUIRE(at != std::string::npos);
        CHECK(shown.output.substr(at) == cards);
        // Given rather than told: the same.
        CHECK(run_shell(cd + "PARSONS check --format " + format + " - < copy").exit_code == 0);
    }
    // Text card images (the sample deck's 12-0 sequence punches are no 029 character).
    write_bytes(dir.path("words.txt"), "PARSONS AND STULEN 1952\nFIG. 8\n");
    REQUIRE(run_shell(cd + "PARSONS convert words.txt -o words.cbn").exit_code == 0);
    const auto text_in = run_shell(cd + "PARSONS convert - --to cbn -o from-stdin.cbn < words.txt");
    CHECK(text_in.exit_code == 0);
    CHECK(text_in.output.find("converted 2 cards: - (text)") != std::string::npos);
    CHECK(read_bytes(dir.path("from-stdin.cbn")) == read_bytes(dir.path("words.cbn")));
    const auto piped = run_shell(cd + "PARSONS convert deck.cbn --to bin -o - | PARSONS run - -q "
                                      "--report r.json");
    CHECK(piped.exit_code == 0);
    CHECK(nlohmann::json::parse(read_bytes(dir.path("r.json")))["cards_read"] == 4);
    const auto junk = run_shell(cd + "printf '\\001\\002\\003' | PARSONS show -");
    CHECK(junk.exit_code == 2);
    CHECK(junk.output.find("standard input: cannot tell the deck format") != std::string::npos);
    const auto no_to = run_shell(cd + "PARSONS convert deck.cbn -o -");
    CHECK(no_to.exit_code == 2);
    CHECK(no_to.output.find("needs --to") != std::string::npos);
}
