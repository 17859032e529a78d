// parsons_bench: how fast the impulse-level emulation runs. A benchmark, not a test: it prints
// figures (median of several runs) and asserts nothing about time.
//
//   build/tests/bench/parsons_bench [--cards N] [--trace-cards N] [--runs N]
//
// It generates a long valid deck in memory (every card moves all five axes, the table 9 inches
// at speed 1 with the patent's slow-downs), runs it through relaylogic::ControlCabinet with no
// observer, then a shorter deck with the VCD trace written to a temporary file, and reports
// impulses per second, trace events per second, MB written and peak resident memory.
#include "axes/machine_profile.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "cli/trace_outputs.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <sys/resource.h>
#include <vector>

using namespace parsons;
using cardreader::Axis;

namespace {

class VectorDeck : public cardreader::CardSource {
public:
    explicit VectorDeck(const std::vector<cardreader::Card>& cards) : cards_(cards) {}
    std::optional<cardreader::Card> next() override {
        if (i_ >= cards_.size()) {
            return std::nullopt;
        }
        return cards_[i_++];
    }

private:
    const std::vector<cardreader::Card>& cards_;
    std::size_t i_ = 0;
};

cardreader::AxisOrder move(int from, int to, int speed, cardreader::SequencePattern seq) {
    cardreader::AxisOrder o;
    const int sign = to >= from ? +1 : -1;
    o.motion = sign > 0 ? cardreader::Motion::forward : cardreader::Motion::reverse;
    o.start_speed = speed;
    if (speed <= 2) {
        o.slow_down[0] = static_cast<cardreader::Thousandths>(to - sign * (speed == 1 ? 200 : 100));
    }
    if (speed == 1) {
        o.slow_down[1] = static_cast<cardreader::Thousandths>(to - sign * 100);
    }
    o.stop = static_cast<cardreader::Thousandths>(to);
    o.check = static_cast<cardreader::Thousandths>(std::abs(to - from));
    o.sequence = seq;
    if (!cardreader::spurious_matches_on_path(o, static_cast<cardreader::Thousandths>(from))
             .empty()) {
        throw std::logic_error("benchmark deck has a shared-bank hazard");
    }
    return o;
}

// Each axis shuttles between two positions; the patent's sequence (12, 12, 34, 34, 5).
std::vector<cardreader::Card> long_deck(int cards) {
    struct Shuttle {
        int a, b, speed;
        cardreader::SequencePattern seq;
    };
    const std::array<Shuttle, 5> shuttles = {{{485, 9485, 1, 0b00011},
                                              {1085, 2985, 2, 0b00011},
                                              {500, 1500, 2, 0b01100},
                                              {200, 400, 3, 0b01100},
                                              {100, 200, 3, 0b10000}}};
    std::vector<cardreader::Card> deck;
    std::array<int, 5> at{};
    for (int n = 0; n < cards; ++n) {
        cardreader::CardOrders o;
        o.number = (n + 1) % 10000;
        o.spindle = cardreader::Spindle::forward;
        for (std::size_t i = 0; i < 5; ++i) {
            const auto& s = shuttles.at(i);
            const int to = n % 2 == 0 ? s.b : s.a;
            // The first card starts from zero: plain speed 3 to the first position is slow, so
            // it starts fast like the rest.
            o.axes.at(i) = move(at.at(i), to, s.speed, s.seq);
            at.at(i) = to;
        }
        auto e = cardreader::encode(o, cardreader::fig8_layout());
        deck.push_back(e.card);
    }
    return deck;
}

struct Counting : relaylogic::MachineObserver {
    explicit Counting(relaylogic::MachineObserver& inner) : inner_(inner) {}
    void on_signal_defined(const relaylogic::SignalInfo& i, std::uint32_t v) override {
        inner_.on_signal_defined(i, v);
    }
    void on_start() override { inner_.on_start(); }
    void on_signal(double t, relaylogic::SignalId id, std::uint32_t a, std::uint32_t b) override {
        ++events;
        inner_.on_signal(t, id, a, b);
    }
    void on_card(double t, long i, const cardreader::CardOrders& o) override {
        inner_.on_card(t, i, o);
    }
    void on_stop(double t, const relaylogic::StopInfo& s) override { inner_.on_stop(t, s); }
    void on_finish(double t) override { inner_.on_finish(t); }
    long events = 0;

private:
    relaylogic::MachineObserver& inner_;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.at(v.size() / 2);
}

long impulses_of(const relaylogic::RunResult& r) {
    long n = 0;
    for (const auto& a : r.axes) {
        n += a.impulses;
    }
    return n;
}

double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return static_cast<double>(u.ru_maxrss) / 1024.0;
}

} // namespace

int main(int argc, char** argv) {
    int cards = 400;
    int trace_cards = 40;
    int runs = 5;
    for (int i = 1; i + 1 < argc; i += 2) {
        const int v = std::atoi(argv[i + 1]);
        if (std::strcmp(argv[i], "--cards") == 0) {
            cards = v;
        } else if (std::strcmp(argv[i], "--trace-cards") == 0) {
            trace_cards = v;
        } else if (std::strcmp(argv[i], "--runs") == 0) {
            runs = v;
        }
    }
    const auto profile = axes::default_profile();
    using clock = std::chrono::steady_clock;

    const auto deck = long_deck(cards);
    std::vector<double> rates;
    long impulses = 0;
    double machine_s = 0;
    for (int r = 0; r < runs; ++r) {
        VectorDeck source(deck);
        relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
        const auto t0 = clock::now();
        const auto result = cabinet.run(source);
        const double s = std::chrono::duration<double>(clock::now() - t0).count();
        if (!result.completed) {
            fmt::print(stderr, "benchmark deck stopped: {}\n", result.stop->message);
            return 1;
        }
        impulses = impulses_of(result);
        machine_s = result.machine_seconds;
        rates.push_back(static_cast<double>(impulses) / s);
    }
    fmt::print("no observer:  {} cards, {} impulses, {:.0f} s of machine time: median {:.2f} "
               "million impulses/s ({} runs)\n",
               cards, impulses, machine_s, median(rates) / 1e6, runs);

    const auto trace_deck = long_deck(trace_cards);
    const auto path = std::filesystem::temp_directory_path() / "parsons-bench.vcd";
    std::vector<double> trace_rates;
    std::vector<double> event_rates;
    double mb = 0;
    for (int r = 0; r < runs; ++r) {
        VectorDeck source(trace_deck);
        relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
        std::ofstream out(path, std::ios::binary);
        cli::VcdWriter vcd(out, "benchmark");
        Counting counting(vcd);
        cabinet.attach(&counting);
        const auto t0 = clock::now();
        const auto result = cabinet.run(source);
        out.flush();
        const double s = std::chrono::duration<double>(clock::now() - t0).count();
        trace_rates.push_back(static_cast<double>(impulses_of(result)) / s);
        event_rates.push_back(static_cast<double>(counting.events) / s);
        out.close();
        mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    }
    std::filesystem::remove(path);
    fmt::print("VCD trace:    {} cards: median {:.2f} million impulses/s, {:.2f} million trace "
               "events/s, {:.1f} MB written a run\n",
               trace_cards, median(trace_rates) / 1e6, median(event_rates) / 1e6, mb);
    fmt::print("peak memory:  {:.1f} MB resident\n", peak_rss_mb());
    return 0;
}
