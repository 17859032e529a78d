// parsons bench: how fast the emulator runs, measured end to end through `parsons run`.
//
// It writes its own decks to a temporary folder, runs each through run_deck() (what
// `parsons run` calls) several times and prints one line per figure, the median of the runs:
//   impulse level, no observer ........ impulses a second (--impulse-level, every rule applied)
//   bare stepping-chain loop ........... the same impulses through one axis's two counters alone
//                                        (cli/bench_bare_loop.hpp), and the impulse level's ratio
//   VCD trace .......................... impulses, trace events and MB a second, to a file
//   fast-forward, long moves ........... the same deck as the first line, fast-forwarded
//   fast-forward, short moves .......... cards a second (0.010 in moves)
//   short moves, by phase .............. a card's time by phase, its heap allocations and a run's
//   cost per card vs move length ....... microseconds a card for 0.010 in and 10 in moves
//   cut sweep .......................... run --cut of a 2,000-station template deck
//   deck generation .................... a 9,997-station template deck (the most a deck holds)
//   peak memory ........................ resident size of `parsons run` on 1,000 / 10,000 /
//                                        100,000 cards (--memory-cards; a child process each)
//   press cycles ....................... a press-feeder cycle looped 1,000 times (--press-cycles)
//                                        under parsons-extended, fast-forward (press sync, an
//                                        addition after EP 0436887): seconds, and the peak
//                                        memory of a tenth of the cycles and of all (flat)
// A benchmark, not a test: it asserts nothing about time. --json for the same as JSON. Each
// figure is printed as soon as it is measured; a reader that goes away (`| head -3`) ends the
// benchmark there, quietly (exit 141).
#include "axes/json_text.hpp"
#include "cli/bench_bare_loop.hpp"
#include "cli/bench_decks.hpp"
#include "cli/commands.hpp"
#include "cli/support/allocation_count.hpp"
#include "cli/support/progress_line.hpp"
#include "outputs/output_file.hpp"

#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "decks/deck_limits.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace parsons::cli {
namespace {

namespace fs = std::filesystem;
using cardreader::Axis;
using cardreader::CardOrders;
using Clock = std::chrono::steady_clock;
using bench::kLongMoves;
using bench::kShortMoves;
using bench::kTenInchMoves;
using bench::write_deck;
using bench::write_press_deck;

#ifndef PARSONS_BUILD_TYPE
#define PARSONS_BUILD_TYPE "unknown"
#endif

struct BenchOptions {
    int runs = 5;
    int long_cards = 400;
    int trace_cards = 40;
    int short_cards = 100000;
    int memory_cards = 100000; // the longest of the memory figure's three decks
    int press_cycles = 1000;
    bool json = false;
    bool scaling = false;
    std::string child_deck;   // internal: run this deck and exit (the memory figure's child)
    std::string child_report; // internal: where the child writes its peak resident size
    bool child_impulse_level = false;
    std::string child_trace;
    std::string child_profile;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.at(v.size() / 2);
}

template <typename F>
double seconds(F&& f) {
    const auto t0 = Clock::now();
    f();
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::int64_t impulses_of(const relaylogic::RunResult& r) {
    std::int64_t n = 0;
    for (const auto& a : r.axes) {
        n += a.impulses;
    }
    return n;
}

struct Timed {
    relaylogic::RunResult result;
    double seconds = 0; // median
};

// The stage of the benchmark being measured, on the progress line (a terminal only).
class Stages {
public:
    explicit Stages(int total) : total_(total) {}
    void begin(const std::string& name) {
        name_ = name;
        ++done_;
        run(0, 1);
    }
    void run(int r, int runs) {
        progress_.show((done_ - 1 + static_cast<double>(r) / runs) / total_,
                       fmt::format("{} ({}/{}), run {} of {}", name_, done_, total_, r + 1, runs),
                       true);
    }
    void clear() { progress_.clear(); }

private:
    int total_;
    int done_ = 0;
    std::string name_;
    ProgressLine progress_;
};

Timed time_run(const RunRequest& request, int runs, Stages& stages) {
    Timed t;
    std::vector<double> s;
    for (int r = 0; r < runs; ++r) {
        stages.run(r, runs);
        s.push_back(seconds([&] {
            if (run_deck(request, &t.result) != ExitCode::ok) {
                throw std::runtime_error("benchmark deck " + request.input + " did not complete");
            }
        }));
    }
    t.seconds = median(s);
    return t;
}

RunRequest quiet_run(const std::string& deck) {
    RunRequest r;
    r.input = deck;
    r.quiet = true;
    r.deck.max_cards = std::numeric_limits<std::int64_t>::max(); // the bench's decks are long

    return r;
}

// This process's own peak resident size (VmHWM), in MB.
double own_peak_mb() {
    std::ifstream in("/proc/self/status");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("VmHWM:", 0) == 0) {
            return std::stod(line.substr(6)) / 1024.0;
        }
    }
    return 0;
}

// Peak resident size of `parsons bench --child-deck DECK --child-report FILE`, which runs the
// deck as `parsons run DECK -q` does and writes its own peak (VmHWM) to FILE, in MB. (The
// kernel's ru_maxrss of a child would include this process's size from before the exec.)
double child_peak_mb(const std::string& deck, const std::string& report,
                     const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"/proc/self/exe", "bench", "--child-deck", deck,
                                     "--child-report", report};
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (auto& a : args) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ) != 0) {
        throw std::runtime_error("cannot start a child process for the memory figure");
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        throw std::runtime_error("the memory figure's child run of " + deck + " failed");
    }
    std::ifstream in(report);
    double mb = 0;
    if (!(in >> mb)) {
        throw std::runtime_error("the memory figure's child wrote no figure");
    }
    return mb;
}

std::string cpu_model() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            return line.substr(line.find(':') + 2);
        }
    }
    return "unknown";
}

// Value-change lines of a VCD file: every trace event is one.
std::int64_t vcd_events(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    bool body = false;
    std::int64_t n = 0;
    while (std::getline(in, line)) {
        if (!body) {
            body = line.rfind("$enddefinitions", 0) == 0;
            continue;
        }
        n += !line.empty() && line[0] != '#' && line[0] != '$' ? 1 : 0;
    }
    return n;
}

// One benchmark: its scratch folder, the JSON it fills and the lines it says, measured in steps.
class Bench {
public:
    explicit Bench(const BenchOptions& o)
        : o_(o), scratch_("parsons-bench"), dir_(scratch_.path()),
          stages_(13 + (o.scaling ? 4 : 0)) {}

    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    void say(const std::string& s) {
        stages_.clear();
        if (!o_.json) {
            fmt::print("{}\n", s);
            finish_standard_output(); // a reader gone (`| head -3`) ends the benchmark here
        }
    }
    void machine();
    void impulse_level_and_fast_forward();
    void vcd_trace();
    void short_moves();
    void card_phases(double median_seconds);
    void generation_and_cut();
    void peak_memory();
    void press_cycles();
    void scaling();
    void print_json() const {
        if (o_.json) {
            fmt::print("{}\n", axes::json_text(j_, 2));
        }
    }

private:
    const BenchOptions& o_;
    const ScratchFolder scratch_; // made new, so removing it harms nothing else
    const fs::path dir_;
    nlohmann::json j_;
    Stages stages_;
};

void Bench::machine() {
    j_["machine"] = {{"cpu", cpu_model()},
                     {"cores", sysconf(_SC_NPROCESSORS_ONLN)},
                     {"build", PARSONS_BUILD_TYPE}};
    j_["runs"] = o_.runs;
    say(fmt::format("parsons bench: {} ({} cores), {} build, median of {} runs", cpu_model(),
                    sysconf(_SC_NPROCESSORS_ONLN), PARSONS_BUILD_TYPE, o_.runs));
}

// Impulse level and fast-forward on the same long deck.
void Bench::impulse_level_and_fast_forward() {
    stages_.begin("impulse level");
    write_deck(path("long.cbn"), o_.long_cards, kLongMoves);
    RunRequest impulse_level = quiet_run(path("long.cbn"));
    impulse_level.impulse_level = true;
    const Timed il = time_run(impulse_level, o_.runs, stages_);
    const std::int64_t impulses = impulses_of(il.result);
    j_["impulse_level"] = {{"cards", o_.long_cards},
                           {"impulses", impulses},
                           {"seconds", il.seconds},
                           {"impulses_per_s", static_cast<double>(impulses) / il.seconds}};
    say(fmt::format("impulse level, no observer  {:>8.1f} M impulses/s  ({} cards, {} impulses "
                    "in {:.3f} s)",
                    static_cast<double>(impulses) / il.seconds / 1e6, o_.long_cards, impulses,
                    il.seconds));
    // The same number of impulses through one axis's two counters and nothing else, in the
    // same run: the least an impulse can cost (cli/bench_bare_loop.hpp).
    const bench::BareLoop bare = bench::bare_stepping_chain(impulses, o_.runs);
    const double bare_rate = static_cast<double>(bare.impulses) / bare.seconds;
    const double ratio = static_cast<double>(impulses) / il.seconds / bare_rate;
    j_["bare_loop"] = {{"impulses", bare.impulses},
                       {"seconds", bare.seconds},
                       {"impulses_per_s", bare_rate},
                       {"counters_read", bare.reading}};
    j_["impulse_level"]["ratio_to_bare_loop"] = ratio;
    say(fmt::format("bare stepping-chain loop    {:>8.1f} M impulses/s  (the two counters' "
                    "switches alone; impulse level is {:.2f} x it)",
                    bare_rate / 1e6, ratio));

    stages_.begin("fast-forward, long moves");
    const Timed ff = time_run(quiet_run(path("long.cbn")), o_.runs, stages_);
    j_["fast_forward_long"] = {{"cards", o_.long_cards},
                               {"impulses", impulses_of(ff.result)},
                               {"seconds", ff.seconds},
                               {"impulses_per_s", static_cast<double>(impulses) / ff.seconds},
                               {"cards_per_s", o_.long_cards / ff.seconds}};
    say(fmt::format("fast-forward, long moves    {:>8.1f} M impulses/s  (the same deck: {:.0f} "
                    "cards/s)",
                    static_cast<double>(impulses) / ff.seconds / 1e6, o_.long_cards / ff.seconds));
}

// The VCD trace, written to a file.
void Bench::vcd_trace() {
    stages_.begin("VCD trace");
    write_deck(path("trace.cbn"), o_.trace_cards, kLongMoves);
    RunRequest traced = quiet_run(path("trace.cbn"));
    traced.trace = path("trace.vcd");
    const Timed tr = time_run(traced, o_.runs, stages_);
    const std::int64_t events = vcd_events(traced.trace);
    const double mb = static_cast<double>(fs::file_size(traced.trace)) / 1e6;
    const std::int64_t trace_impulses = impulses_of(tr.result);
    j_["vcd"] = {{"cards", o_.trace_cards},
                 {"impulses", trace_impulses},
                 {"events", events},
                 {"mb", mb},
                 {"seconds", tr.seconds},
                 {"impulses_per_s", static_cast<double>(trace_impulses) / tr.seconds},
                 {"events_per_s", static_cast<double>(events) / tr.seconds},
                 {"mb_per_s", mb / tr.seconds}};
    say(fmt::format("VCD trace to a file         {:>8.1f} M events/s    ({:.1f} M impulses/s, "
                    "{:.1f} MB in {:.3f} s, {:.0f} MB/s)",
                    static_cast<double>(events) / tr.seconds / 1e6,
                    static_cast<double>(trace_impulses) / tr.seconds / 1e6, mb, tr.seconds,
                    mb / tr.seconds));
}

// Short moves: cards a second; and the cost of a card against the length of its move.
void Bench::short_moves() {
    stages_.begin("fast-forward, short moves");
    write_deck(path("short.cbn"), o_.short_cards, kShortMoves);
    const Timed sh = time_run(quiet_run(path("short.cbn")), o_.runs, stages_);
    j_["short_moves"] = {{"cards", o_.short_cards},
                         {"seconds", sh.seconds},
                         {"cards_per_s", o_.short_cards / sh.seconds}};
    say(fmt::format("fast-forward, short moves   {:>8.3f} M cards/s     ({} cards of 0.010 in "
                    "in {:.3f} s)",
                    o_.short_cards / sh.seconds / 1e6, o_.short_cards, sh.seconds));
    const int per = std::max(1000, o_.short_cards / 10);
    write_deck(path("ten.cbn"), per, kTenInchMoves);
    write_deck(path("hundredth.cbn"), per, kShortMoves);
    card_phases(sh.seconds);
    stages_.begin("cost per card, 10 in moves");
    const Timed ten = time_run(quiet_run(path("ten.cbn")), o_.runs, stages_);
    stages_.begin("cost per card, 0.010 in moves");
    const Timed hundredth = time_run(quiet_run(path("hundredth.cbn")), o_.runs, stages_);
    const double us_ten = ten.seconds / per * 1e6;
    const double us_hundredth = hundredth.seconds / per * 1e6;
    j_["move_length"] = {
        {"cards", per}, {"us_per_card_0_01_in", us_hundredth}, {"us_per_card_10_in", us_ten}};
    say(fmt::format("cost per card               {:>8.2f} us (0.010 in move), {:.2f} us (10 in "
                    "move, {} impulses a card)",
                    us_hundredth, us_ten, impulses_of(ten.result) / per));
}

// The short-move deck once more, its time split by phase of the card cycle (the cabinet marks
// each change of phase on a relaylogic::PhaseClock; the shares of its ticks apportion the
// median time of a card measured above, untimed runs' own cost aside); and the heap
// allocations (cli/support/allocation_count.hpp) of two decks of the same moves a real deck's
// length, 1,000 and 2,000 cards: what a card adds, apart from what a run allocates once.
void Bench::card_phases(double median_seconds) {
    stages_.begin("short moves, by phase");
    const auto counted_run = [&](const std::string& deck, relaylogic::PhaseClock* clock) {
        RunRequest request = quiet_run(path(deck));
        request.phases = clock;
        const std::uint64_t before = allocations();
        if (run_deck(request) != ExitCode::ok) {
            throw std::runtime_error("benchmark deck " + deck + " did not complete");
        }
        return static_cast<double>(allocations() - before);
    };
    relaylogic::PhaseClock clock;
    counted_run("short.cbn", &clock);
    constexpr int kShorter = 1000, kLonger = 2000;
    write_deck(path("alloc1.cbn"), kShorter, kShortMoves);
    write_deck(path("alloc2.cbn"), kLonger, kShortMoves);
    const double allocated_shorter = counted_run("alloc1.cbn", nullptr);
    const double allocated = counted_run("alloc2.cbn", nullptr);
    const double us_per_card = median_seconds / o_.short_cards * 1e6;
    const double ticks = static_cast<double>(std::max<std::uint64_t>(1, clock.total()));
    nlohmann::json phases = nlohmann::json::object();
    std::string line;
    for (std::size_t i = 0; i < relaylogic::kPhases; ++i) {
        const auto phase = static_cast<relaylogic::Phase>(i);
        const double us = static_cast<double>(clock.spent(phase)) / ticks * us_per_card;
        phases[std::string(relaylogic::phase_name(phase))] = us;
        line += fmt::format("\n  {:<28}{:>8.3f} us a card", relaylogic::phase_name(phase), us);
    }
    j_["short_moves"]["us_per_card_by_phase"] = phases;
    j_["short_moves"]["allocations_per_card"] = nullptr;
    j_["short_moves"]["allocations_per_run"] = nullptr;
    if (!allocations_counted()) {
        line += "\n  heap allocations            not counted in this build (AddressSanitizer)";
    } else {
        const double per_card = (allocated - allocated_shorter) / (kLonger - kShorter);
        const double per_run = allocated_shorter - per_card * kShorter;
        j_["short_moves"]["allocations_per_card"] = per_card;
        j_["short_moves"]["allocations_per_run"] = per_run;
        line += fmt::format("\n  heap allocations            {:>8.3f} a card, and {:.0f} a run "
                            "whatever its length ({} in {} cards, {} in {})",
                            per_card, per_run, allocated_shorter, kShorter, allocated, kLonger);
    }
    say(fmt::format("short moves, by phase       {:>8.3f} us a card{}", us_per_card, line));
}

// Deck generation and the cut sweep.
void Bench::generation_and_cut() {
    decks::JobDescription big;
    big.airfoil = "naca 2412";
    // The most stations one surface's deck can hold: 9,997 and 3 cards to approach, 9,999 cards
    // (decks/deck_limits.hpp).
    constexpr int kBigStations = static_cast<int>(decks::kMaxDeckCards) - 2;
    big.options.stations = kBigStations;
    std::vector<double> gen_s;
    stages_.begin("deck generation");
    for (int r = 0; r < o_.runs; ++r) {
        stages_.run(r, o_.runs);
        gen_s.push_back(
            seconds([&] { generate_job(big, axes::default_profile(), path("gen.cbn"), "", ""); }));
    }
    j_["generation"] = {{"stations", kBigStations}, {"seconds", median(gen_s)}};
    say(fmt::format("deck generation             {:>8.3f} s         ({} stations, the most a "
                    "deck holds, NACA 2412, written)",
                    median(gen_s), decks::count_text(kBigStations)));
    stages_.begin("cut sweep");
    decks::JobDescription cut_job;
    cut_job.airfoil = "naca 2412";
    cut_job.options.stations = 2000;
    generate_job(cut_job, axes::default_profile(), path("cut.cbn"), "", "");
    RunRequest cut = quiet_run(path("cut.cbn"));
    cut.cut = path("cut.svg");
    const Timed sweep = time_run(cut, o_.runs, stages_);
    j_["cut_sweep"] = {{"stations", 2000}, {"seconds", sweep.seconds}};
    say(fmt::format("cut sweep                   {:>8.3f} s         (run --cut of a 2,000-station "
                    "deck)",
                    sweep.seconds));
}

// Memory: one child process per deck length.
void Bench::peak_memory() {
    nlohmann::json memory = nlohmann::json::object();
    std::string line;
    for (int cards : {o_.memory_cards / 100, o_.memory_cards / 10, o_.memory_cards}) {
        stages_.begin(fmt::format("peak memory, {} cards", cards));
        const std::string deck = path(fmt::format("mem{}.cbn", cards));
        write_deck(deck, cards, kShortMoves);
        const double peak = child_peak_mb(deck, path("peak.txt"), {});
        memory[std::to_string(cards)] = peak;
        line += fmt::format("{}{:.1f} MB ({} card{})", line.empty() ? "" : ", ", peak, cards,
                            cards == 1 ? "" : "s");
    }
    j_["peak_memory_mb"] = memory;
    say(fmt::format("peak memory of parsons run  {}", line));
}

// Press synchronisation: 1,000 press cycles in fast-forward, and memory flat in cycles.
void Bench::press_cycles() {
    stages_.begin("press cycles");
    const int cycles = o_.press_cycles;
    const int tenth = std::max(2, cycles / 10); // a loop card repeats 1 .. 9,999 times
    write_press_deck(path("press.cbn"), cycles);
    RunRequest press = quiet_run(path("press.cbn"));
    press.profile = "parsons-extended";
    const Timed pc = time_run(press, o_.runs, stages_);
    if (!pc.result.press || pc.result.press->cycles != cycles) {
        throw std::logic_error(fmt::format("the press benchmark deck did not run {} cycles",
                                           decks::count_text(cycles)));
    }
    write_press_deck(path("press-tenth.cbn"), tenth);
    const double peak_tenth = child_peak_mb(path("press-tenth.cbn"), path("peak.txt"),
                                            {"--child-profile", "parsons-extended"});
    const double peak_all =
        child_peak_mb(path("press.cbn"), path("peak.txt"), {"--child-profile", "parsons-extended"});
    j_["press_cycles"] = {
        {"cycles", cycles},
        {"cards", pc.result.cards_read},
        {"machine_seconds", pc.result.machine_seconds},
        {"seconds", pc.seconds},
        {"peak_mb", {{std::to_string(tenth), peak_tenth}, {std::to_string(cycles), peak_all}}}};
    say(fmt::format("press cycles, fast-forward  {:>8.3f} s         ({} cycles, {} cards, "
                    "{:.0f} s of machine time; peak {:.1f} MB at {} cycles, {:.1f} MB at {})",
                    pc.seconds, decks::count_text(cycles), pc.result.cards_read,
                    pc.result.machine_seconds, peak_tenth, decks::count_text(tenth), peak_all,
                    decks::count_text(cycles)));
}

// How cost grows: decks of short moves, 10^3 .. 10^6 cards, each run once in a child process
// (wall time and peak memory): fast-forward, impulse level, and with a VCD.
void Bench::scaling() {
    say("scaling (short moves; one run each, in a child process):");
    say("     cards   fast-fwd s  impulse s   VCD s   VCD MB   peak MB");
    nlohmann::json rows = nlohmann::json::array();
    for (int cards : {1000, 10000, 100000, 1000000}) {
        stages_.begin(fmt::format("scaling, {} cards", cards));
        const std::string deck = path("scale.cbn");
        write_deck(deck, cards, kShortMoves);
        double peak = 0;
        const double ff_s = seconds([&] { peak = child_peak_mb(deck, path("peak.txt"), {}); });
        const double il_s =
            seconds([&] { child_peak_mb(deck, path("peak.txt"), {"--child-impulse-level"}); });
        double vcd_s = 0;
        double vcd_mb = 0;
        if (cards <= 100000) {
            const std::string vcd = path("scale.vcd");
            vcd_s = seconds([&] { child_peak_mb(deck, path("peak.txt"), {"--child-trace", vcd}); });
            vcd_mb = static_cast<double>(fs::file_size(vcd)) / 1e6;
            fs::remove(vcd);
        }
        rows.push_back({{"cards", cards},
                        {"fast_forward_s", ff_s},
                        {"impulse_level_s", il_s},
                        {"vcd_s", vcd_s},
                        {"vcd_mb", vcd_mb},
                        {"peak_mb", peak}});
        say(fmt::format("  {:>8}   {:>10.3f} {:>10.3f} {:>7} {:>8} {:>9.1f}", cards, ff_s, il_s,
                        vcd_s > 0 ? fmt::format("{:.3f}", vcd_s) : "-",
                        vcd_s > 0 ? fmt::format("{:.1f}", vcd_mb) : "-", peak));
    }
    j_["scaling"] = rows;
}

ExitCode run_bench(const BenchOptions& o) {
    if (!o.child_deck.empty()) {
        RunRequest child = quiet_run(o.child_deck);
        child.impulse_level = o.child_impulse_level;
        child.trace = o.child_trace;
        child.profile = o.child_profile;
        const ExitCode code = run_deck(child);
        std::ofstream(o.child_report) << own_peak_mb() << "\n";
        return code;
    }
    Bench bench(o);
    bench.machine();
    bench.impulse_level_and_fast_forward();
    bench.vcd_trace();
    bench.short_moves();
    bench.generation_and_cut();
    bench.peak_memory();
    bench.press_cycles();
    if (o.scaling) {
        bench.scaling();
    }
    bench.print_json();
    return ExitCode::ok;
}

} // namespace

void add_bench_command(CLI::App& app, Command& selected) {
    auto o = std::make_shared<BenchOptions>();
    CLI::App* cmd = app.add_subcommand(
        "bench", "Measure the emulator: impulses, trace events, cards a second, memory");
    cmd->add_option("--runs", o->runs, "Runs per figure (the median is printed)")
        ->capture_default_str()
        ->check(CLI::Range(1, 101));
    cmd->add_option("--long-cards", o->long_cards, "Cards in the long-move deck")
        ->capture_default_str()
        ->check(CLI::Range(2, 100000));
    cmd->add_option("--trace-cards", o->trace_cards, "Cards in the traced deck")
        ->capture_default_str()
        ->check(CLI::Range(2, 10000));
    cmd->add_option("--short-cards", o->short_cards, "Cards in the short-move deck")
        ->capture_default_str()
        ->check(CLI::Range(10, 10000000));
    cmd->add_option("--memory-cards", o->memory_cards,
                    "Cards in the longest of the memory figure's three decks (a hundredth, a "
                    "tenth and all of them)")
        ->capture_default_str()
        ->check(CLI::Range(100, 10000000));
    cmd->add_option("--press-cycles", o->press_cycles,
                    "Press cycles the press deck loops (its memory is also taken at a tenth)")
        ->capture_default_str()
        ->check(CLI::Range(2, 10000)); // the loop card's count, 1 .. 9,999, and the first pass
    cmd->add_flag("--json", o->json, "Print the figures as JSON");
    cmd->add_flag("--scaling", o->scaling,
                  "Also time decks of 10^3 .. 10^6 cards (fast-forward, impulse level, VCD)");
    cmd->add_option("--child-deck", o->child_deck)->group(""); // internal: the memory figure
    cmd->add_option("--child-report", o->child_report)->group("");
    cmd->add_flag("--child-impulse-level", o->child_impulse_level)->group("");
    cmd->add_option("--child-trace", o->child_trace)->group("");
    cmd->add_option("--child-profile", o->child_profile)->group("");
    cmd->footer(exit_codes_help({{ExitCode::ok, "the figures were printed"}}) +
                "Examples:\n  parsons bench\n  parsons bench --runs 1 --short-cards 1000 "
                "--memory-cards 1000 "
                "--json > quick.json   (a quick look: one run each, smaller decks)");
    cmd->callback([&selected, o] { selected = [o] { return run_bench(*o); }; });
}

} // namespace parsons::cli
