// A deck built in code, run on the emulated cabinet with an observer that prints the relays.
//
// Three cards: the table goes out 0.250 in and the cross slide 0.120 in, then both come back.
// The move planner (parsons::decks) chooses each axis's start speed and slow-downs the way a
// 1952 programmer did; the keypunch (parsons::cardreader) punches the orders into cards; the
// control cabinet (parsons::relaylogic) reads them and drives the five axes (parsons::axes).
// The observer hears every signal: this one prints each relay and lamp that changes, each card
// as it is read, and the stop or the finish.
//
// Build it against an installed parsons (docs/install.md):
//   cmake -S examples -B build-examples -DCMAKE_PREFIX_PATH=/usr/local && cmake --build
//   build-examples build-examples/relay_events
#include <axes/machine_profile.hpp>
#include <cardreader/deck_io.hpp>
#include <cardreader/layout.hpp>
#include <decks/move_planner.hpp>
#include <relaylogic/control_cabinet.hpp>
#include <relaylogic/machine_observer.hpp>

#include <cstdio>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cr = parsons::cardreader;
namespace rl = parsons::relaylogic;

namespace {

// A deck held in memory: the cabinet reads any CardSource.
class DeckInMemory : public cr::CardSource {
public:
    explicit DeckInMemory(std::vector<cr::Card> cards) : cards_(std::move(cards)) {}
    std::optional<cr::Card> next() override {
        if (next_ == cards_.size()) {
            return std::nullopt;
        }
        return cards_[next_++];
    }

private:
    std::vector<cr::Card> cards_;
    std::size_t next_ = 0;
};

// Prints every change of a one-bit signal (a relay, a lamp, a contact) with its patent numeral.
class RelayPrinter : public rl::MachineObserver {
public:
    void on_signal_defined(const rl::SignalInfo& info, std::uint32_t /*initial*/) override {
        if (info.width == 1) {
            relays_[info.id] = info;
        }
    }
    void on_signal(double t, rl::SignalId id, std::uint32_t, std::uint32_t now) override {
        const auto it = relays_.find(id);
        if (it == relays_.end()) {
            return;
        }
        const rl::SignalInfo& s = it->second;
        std::printf("%10.4f s  %-8s %-44s %s  (%s, numeral %s)\n", t, s.scope.c_str(),
                    s.name.c_str(), now != 0 ? "picks  " : "drops  ", s.component.c_str(),
                    s.numeral.empty() ? "-" : s.numeral.c_str());
        ++changes;
    }
    void on_card(double t, long index, const cr::CardOrders& orders) override {
        std::printf("%10.4f s  card %ld read (number %04d)\n", t, index, orders.number);
    }
    void on_stop(double t, const rl::StopInfo& stop) override {
        std::printf("%10.4f s  machine stop: %s\n", t, stop.message.c_str());
    }
    void on_finish(double t) override { std::printf("%10.4f s  finished\n", t); }
    bool follows_motion() const override { return false; }

    long changes = 0;

private:
    std::map<rl::SignalId, rl::SignalInfo> relays_;
};

// One card: the table and the cross slide from (x, y) to (to_x, to_y), thousandths. The
// sequence pattern gives each axis its position on stepping shaft 280: the standing axes
// (vertical, swivel, tilt; stop 0, check 0) take positions 1-3 and stop at once, then the table
// moves (4), then the cross slide (5). Bit n of a pattern is position n + 1.
cr::CardOrders card(int number, int x, int y, int to_x, int to_y,
                    const parsons::axes::MachineProfile& profile) {
    cr::CardOrders c;
    c.number = number;
    c.spindle = cr::Spindle::forward;
    c.axis(cr::Axis::vertical).sequence = 0b00001;
    c.axis(cr::Axis::swivel).sequence = 0b00010;
    c.axis(cr::Axis::tilt).sequence = 0b00100;
    c.axis(cr::Axis::table) =
        parsons::decks::plan_move({x, to_x, 2, false, 0b01000}, profile.axes.at(0), profile);
    c.axis(cr::Axis::cross) =
        parsons::decks::plan_move({y, to_y, 1, false, 0b10000}, profile.axes.at(1), profile);
    return c;
}

} // namespace

int main() {
    const parsons::axes::MachineProfile profile = parsons::axes::default_profile();
    const cr::CardLayout& layout = cr::fig8_layout();

    const std::vector<cr::CardOrders> orders = {card(1, 0, 0, 250, 0, profile),
                                                card(2, 250, 0, 250, 120, profile),
                                                card(3, 250, 120, 0, 0, profile)};
    std::vector<cr::Card> punched;
    for (const cr::CardOrders& o : orders) {
        const cr::EncodeResult e = cr::encode(o, layout);
        if (!e) {
            std::fprintf(stderr, "relay_events: card %d: %s\n", o.number, e.error->c_str());
            return 2;
        }
        punched.push_back(e.card);
    }

    DeckInMemory deck(punched);
    RelayPrinter printer;
    rl::ControlCabinet cabinet(profile, layout);
    cabinet.attach(&printer);
    const rl::RunResult result = cabinet.run(deck);

    std::printf("%ld cards read, %ld relay changes, machine time %.3f s, %s\n", result.cards_read,
                printer.changes, result.machine_seconds,
                result.completed ? "completed" : "stopped");
    std::printf("table at %.4f in, cross slide at %.4f in\n", result.axes.at(0).real_in,
                result.axes.at(1).real_in);
    return result.completed ? 0 : 3;
}
