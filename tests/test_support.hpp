// Helpers shared by the tests: running the parsons executable, temporary directories, files,
// and random valid card orders.
#pragma once

#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "cardreader/orders.hpp"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace parsons::test {

struct ProcessResult {
    int exit_code = -1;
    std::string output; // stdout and stderr together
};

// 'text' quoted for the shell.
std::string q(const std::string& text);

// Reads a whole deck of the given format from bytes; returns the DeckError's message, or
// "no error".
std::string read_error(const std::string& bytes, cardreader::DeckFormat format,
                       const std::string& file_name);

// The DeckError a listing (the standard header, then `rows`) gives when read through, or
// "no error".
std::string listing_error(const std::string& rows);

// Every note a reviewer gives on the cards, then at the deck's end.
std::vector<cardreader::ReviewNote> review_all(cardreader::DeckReviewer& reviewer,
                                               const std::vector<cardreader::CardOrders>& cards);

// Runs `parsons ARGS` through the shell; ARGS is pasted verbatim.
ProcessResult run_parsons(const std::string& args);
// Runs a whole shell command line; the word PARSONS in it stands for the executable.
ProcessResult run_shell(const std::string& command_line);

// A fresh directory under the system temp dir, removed when the object goes.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::filesystem::path path(const std::string& name) const { return dir_ / name; }
    std::string str(const std::string& name) const { return path(name).string(); }

private:
    std::filesystem::path dir_;
};

void write_bytes(const std::filesystem::path& p, const std::string& bytes);
std::string read_bytes(const std::filesystem::path& p);
// The lines of a text, without their newlines.
std::vector<std::string> lines_of(const std::string& text);
// How often `what` occurs in `text`, overlapping occurrences too.
std::size_t count(const std::string& text, const std::string& what);
// Whether the tests run as root, for whom a file's permissions do not stop a write.
bool running_as_root();

// The share of its random cases a heavy test runs: PARSONS_TEST_SHARE, a fraction in (0, 1]
// (default 1, the whole count). The sanitizer run (CMakePresets.json, preset sanitize) sets a
// quarter: the memory errors it looks for show on any case, and the main suite runs them all.
// share_of_cases(n) is that share of n, at least 1; whole_share() says whether it is all of them (a
// test's checks on how its random cases are spread hold only then, and a run that repeats what
// another case or pass already ran, such as a second whole demo, is left out under a share).
int share_of_cases(int n);
bool whole_share();
// A character device node of the test's own, `dir`/`name` made with mknod (major, minor: 1, 3 is
// a null device, 1, 7 a full one), so that no test writes the machine's real /dev/null or
// /dev/full; std::nullopt when the system does not permit it (not root, no CAP_MKNOD, or a
// folder on a nodev mount: a node there could not be written), and the test says so and skips.
std::optional<std::filesystem::path> make_device_node(const std::filesystem::path& dir,
                                                      const std::string& name, unsigned major,
                                                      unsigned minor);
// What a path is, for a check that the real /dev/null is untouched: its kind and device numbers
// ("character device 1:3"), or "absent", "regular file" and so on; never follows a link.
std::string node_kind(const std::filesystem::path& p);
std::string source_path(const std::string& relative); // a file of the source tree

// Random orders a layout can hold (a second slow-down only where the layout has the field).
cardreader::CardOrders random_orders(std::mt19937& rng, const cardreader::CardLayout& layout);

// The widest of the sizes a generator's refusal names ("the cutter path spans 6.484 x 0.766 in",
// "the job spans 4.5 x 6.2 x 1.0 in"), or -1 when it names none.
double widest_span_in(const std::string& refusal);

// The cards as a deck file of `format` holds them (the card sink `convert` writes through).
std::string deck_bytes(const std::vector<cardreader::Card>& cards, cardreader::DeckFormat format);

// The patent's example deck, relative to the source tree (where run_parsons runs).
inline const std::string kSample = "decks/samples/patent-example.csv";

// The header of a listing (docs/deck-formats.md).
inline constexpr const char* kHeader =
    "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n";

// Listing rows for every axis but the table, idle at 0.000, each at its own position 2 .. 5.
std::string idle_rest(int card);

// A deck of long moves on every axis, as a listing: each card shuttles the table 9 inches at
// speed 1 (patent slow-downs), the cross 1.9 in at speed 2, and so on.
std::string long_listing(int cards);

} // namespace parsons::test
