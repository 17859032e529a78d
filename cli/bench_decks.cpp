// The decks `parsons bench` writes (cli/bench_decks.hpp).
#include "cli/bench_decks.hpp"

#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/layout.hpp"
#include "outputs/output_file.hpp"

#include <cstdlib>
#include <stdexcept>

namespace parsons::cli::bench {
namespace {

using cardreader::CardOrders;

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

} // namespace

void write_deck(const std::string& path, int cards, const std::array<Shuttle, 5>& shuttles) {
    OutputFile file(path);
    cardreader::DeckOptions options;
    options.file_name = path;
    auto sink = cardreader::open_card_sink(file.stream(), options);
    std::array<int, 5> at{};
    for (int n = 0; n < cards; ++n) {
        CardOrders o;
        o.number = (n + 1) % 10000;
        o.spindle = cardreader::Spindle::forward;
        for (std::size_t i = 0; i < 5; ++i) {
            const Shuttle& s = shuttles.at(i);
            const int to = n % 2 == 0 ? s.b : s.a;
            o.axes.at(i) = move(at.at(i), to, at.at(i) == to ? 3 : s.speed, s.seq);
            at.at(i) = to;
        }
        sink->write(cardreader::encode(o, cardreader::fig8_layout()).card);
    }
    sink.reset();
    file.commit();
}

void write_press_deck(const std::string& path, int cycles) {
    OutputFile file(path);
    cardreader::DeckOptions options;
    options.file_name = path;
    auto sink = cardreader::open_card_sink(file.stream(), options);
    auto idle = [](CardOrders& o) {
        for (std::size_t i = 1; i < 5; ++i) {
            o.axes.at(i) = move(500, 500, 3, static_cast<cardreader::SequencePattern>(1U << i));
        }
    };
    CardOrders sync;
    sync.kind = cardreader::CardKind::sync;
    sync.number = 1;
    sync.sync.position_sync = true;
    sync.sync.angle_deg = 30;
    sync.sync.travel_per_pulse.at(0) = 125;
    CardOrders out;
    out.number = 2;
    out.axes.at(0) = move(500, 1100, 1, 0b00001);
    idle(out);
    CardOrders back;
    back.number = 3;
    back.axes.at(0) = move(1100, 500, 1, 0b00001);
    idle(back);
    CardOrders loop;
    loop.kind = cardreader::CardKind::sync;
    loop.number = 4;
    loop.sync.loop = true;
    loop.sync.loop_to = 1;
    loop.sync.loop_count = cycles - 1;
    // Before the loop every axis stands at 0.500: a first card takes them there.
    CardOrders first;
    first.number = 0;
    first.axes.at(0) = move(0, 500, 2, 0b00001);
    for (std::size_t i = 1; i < 5; ++i) {
        first.axes.at(i) = move(0, 500, 2, static_cast<cardreader::SequencePattern>(1U << i));
    }
    for (const CardOrders& o : {first, sync, out, back, loop}) {
        const cardreader::EncodeResult e = cardreader::encode(o, cardreader::fig8_layout());
        if (!e) {
            throw std::logic_error("press benchmark deck: " + *e.error);
        }
        sink->write(e.card);
    }
    sink.reset();
    file.commit();
}

} // namespace parsons::cli::bench
