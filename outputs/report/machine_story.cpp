#include "outputs/report/machine_story.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::cli {
namespace {

using cardreader::Axis;
using cardreader::kAxes;
using cardreader::kAxisCount;

// A card's tale of one axis longer than this is told by its first and last phrases.
constexpr std::size_t kHead = 4;
constexpr std::size_t kTail = 8;

std::optional<int> axis_of_scope(const std::string& scope) {
    if (const auto a = cardreader::axis_named(scope)) {
        return static_cast<int>(cardreader::axis_index(*a));
    }
    return std::nullopt;
}

// The place of a counter's stepping switch: 104/316 inches .. 110/310 thousandths.
int counter_place(const std::string& numeral) {
    if (numeral == "104" || numeral == "316") {
        return 3;
    }
    if (numeral == "106" || numeral == "314") {
        return 2;
    }
    if (numeral == "108" || numeral == "312") {
        return 1;
    }
    return 0;
}

std::string joined(const std::vector<std::string>& phrases) {
    std::string text;
    for (const std::string& p : phrases) {
        text += (text.empty() ? "" : "; ") + p;
    }
    return text;
}

} // namespace

void MachineStory::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
    Signal s;
    s.value = initial;
    s.numeral = info.numeral;
    if (const auto axis = axis_of_scope(info.scope)) {
        s.axis = *axis;
        const std::string& n = info.name;
        if (n == "speed_switch_236") {
            s.part = Part::speed_switch_236;
            speed_.at(static_cast<std::size_t>(*axis)) = initial;
        } else if (n.rfind("motor_", 0) == 0) {
            s.part = Part::motor;
            motor_numeral_.at(static_cast<std::size_t>(*axis)) = info.numeral;
        } else if (n == "absolute_comparer_122a") {
            s.part = Part::absolute_comparer;
        } else if (n == "incremental_comparer_122b") {
            s.part = Part::incremental_comparer;
        } else if (n == "delay_device_258") {
            s.part = Part::delay_258;
        } else if (n.rfind("absolute_counter_", 0) == 0 || n.rfind("increment_counter_", 0) == 0) {
            const bool absolute = n.rfind("absolute_counter_", 0) == 0;
            s.part = absolute ? Part::absolute_counter : Part::increment_counter;
            s.digit = counter_place(info.numeral);
            (absolute ? absolute_ : increment_)
                .at(static_cast<std::size_t>(*axis))
                .at(static_cast<std::size_t>(s.digit)) = initial;
        } else if (n.rfind("lamp_", 0) == 0) {
            s.part = Part::lamp;
        }
    }
    if (signals_.size() <= info.id) {
        signals_.resize(info.id + 1);
    }
    signals_.at(info.id) = std::move(s);
}

int MachineStory::reading(int axis, Part counter) const {
    const auto& digits = (counter == Part::absolute_counter ? absolute_ : increment_)
                             .at(static_cast<std::size_t>(axis));
    return static_cast<int>(digits[3] * 1000 + digits[2] * 100 + digits[1] * 10 + digits[0]);
}

std::string MachineStory::speed_name(std::uint32_t speed) const {
    return speed == 0 ? std::string("off (contact 238 closed)") : fmt::format("speed {}", speed);
}

// A counter reading named by the field of the card that punches it.
std::string MachineStory::label(int axis, int value) const {
    const std::string inches =
        cardreader::format_inches(static_cast<cardreader::Thousandths>(value));
    if (!current_) {
        return inches;
    }
    const cardreader::AxisOrder& o =
        current_->orders.axis(kAxes.at(static_cast<std::size_t>(axis)));
    if (o.stop == value) {
        return "the stop " + inches;
    }
    for (std::size_t i = 0; i < o.slow_down.size(); ++i) {
        if (o.slow_down.at(i) && *o.slow_down.at(i) == value) {
            return fmt::format("slow-down {} at {}", i + 1, inches);
        }
    }
    return inches + ", which no field of the card punches (the banks 350-356 that slow-downs "
                    "and stop share compare equal there)";
}

void MachineStory::on_signal(double t, relaylogic::SignalId id, std::uint32_t old_value,
                             std::uint32_t new_value) {
    if (id >= signals_.size()) {
        return;
    }
    Signal& s = signals_[id];
    s.value = new_value;
    if (s.part == Part::none || s.axis < 0) {
        return;
    }
    const auto axis = static_cast<std::size_t>(s.axis);
    if (current_ && current_->axes.at(axis).instant >= 0 && current_->axes.at(axis).instant != t) {
        close_instant(s.axis); // a counter's step at a later instant ends the one gathered
    }
    if (s.part == Part::absolute_counter || s.part == Part::increment_counter) {
        (s.part == Part::absolute_counter ? absolute_ : increment_)
            .at(axis)
            .at(static_cast<std::size_t>(s.digit)) = new_value;
        const bool wrapped =
            (old_value == 9 && new_value == 0) || (old_value == 0 && new_value == 9);
        if (current_ && s.part == Part::absolute_counter && s.digit == 3 && wrapped) {
            current_->axes.at(axis).phrases.push_back(
                old_value == 9 ? "the counters passed 9.999 and counted on from 0.000, 10 inches "
                                 "on"
                               : "the counters passed 0.000 and counted on from 9.999, 10 inches "
                                 "back");
        }
        return;
    }
    if (!current_) {
        if (s.part == Part::speed_switch_236) {
            speed_.at(axis) = new_value;
        } else if (s.part == Part::delay_258) {
            delay_held_.at(axis) = new_value != 0;
        } else if (s.part == Part::absolute_comparer) {
            absolute_on_.at(axis) = new_value != 0;
        }
        return;
    }
    AxisTale& tale = current_->axes.at(axis);
    if (tale.instant != t) {
        close_instant(s.axis);
        tale.instant = t;
        tale.delay_held = delay_held_.at(axis);
    }
    switch (s.part) {
    case Part::speed_switch_236:
        if (!tale.speed_before) {
            tale.speed_before = old_value;
        }
        speed_.at(axis) = new_value;
        break;
    case Part::motor:
        (new_value != 0 ? tale.motor_started : tale.motor_stopped) = true;
        break;
    case Part::absolute_comparer:
        tale.absolute_met = tale.absolute_met || (new_value != 0 && !absolute_on_.at(axis));
        absolute_on_.at(axis) = new_value != 0;
        break;
    case Part::incremental_comparer:
        tale.increment_met = tale.increment_met || new_value != 0;
        break;
    case Part::delay_258:
        delay_held_.at(axis) = new_value != 0;
        break;
    case Part::lamp:
        if (new_value != 0) {
            tale.lamps.push_back("lamp " + s.numeral);
        }
        break;
    default:
        break;
    }
}

void MachineStory::close_instant(int axis) {
    AxisTale& tale = current_->axes.at(static_cast<std::size_t>(axis));
    if (tale.instant < 0) {
        return;
    }
    const auto a = static_cast<std::size_t>(axis);
    const Axis named = kAxes.at(a);
    const std::uint32_t speed = speed_.at(a);
    const int at = reading(axis, Part::absolute_counter);
    const std::string motor = "motor " + motor_numeral_.at(a);
    std::vector<std::string>& out = tale.phrases;
    if (tale.motor_started && tale.motor_stopped) {
        out.push_back(fmt::format(
            "{} was switched on and off at once at {}: 236 stood on off, "
            "nothing to travel",
            motor, cardreader::format_inches(static_cast<cardreader::Thousandths>(at))));
        tale.motor_started = false;
        tale.motor_stopped = false;
    }
    if (tale.motor_started) {
        tale.ran = true;
        out.push_back(
            fmt::format("{} started on {} at {}", motor, speed_name(speed),
                        cardreader::format_inches(static_cast<cardreader::Thousandths>(at))));
    }
    const bool stepped = tale.speed_before && *tale.speed_before != speed;
    if (tale.absolute_met) {
        ++tale.equalities;
        std::string phrase = fmt::format(
            "at {} the absolute comparer 122' met {}",
            cardreader::format_inches(static_cast<cardreader::Thousandths>(at)), label(axis, at));
        if (tale.increment_met) {
            phrase += fmt::format(" and the increment comparer 122'' met the check {}",
                                  cardreader::format_inches(static_cast<cardreader::Thousandths>(
                                      reading(axis, Part::increment_counter))));
        }
        if (stepped) {
            phrase += fmt::format(": relay 256 stepped 236 from {} to {}",
                                  speed_name(*tale.speed_before), speed_name(speed));
        } else if (tale.delay_held) {
            phrase += fmt::format(": delay 258 held channel 257 open, so relay 256 did not step "
                                  "and 236 stayed on {}",
                                  speed_name(speed));
        } else {
            phrase += fmt::format(": 236 stayed on {}", speed_name(speed));
        }
        out.push_back(std::move(phrase));
        const cardreader::AxisOrder& o = current_->orders.axis(named);
        const bool punched = at == o.stop || (o.slow_down[0] && *o.slow_down[0] == at) ||
                             (o.slow_down[1] && *o.slow_down[1] == at);
        if (!punched) {
            notes_.push_back({current_->index, current_->number, named,
                              fmt::format("the absolute comparer 122' met {}", label(axis, at))});
        } else if (at == o.stop && stepped && speed != 0) {
            notes_.push_back(
                {current_->index, current_->number, named,
                 fmt::format("it met its stop {} on {}: relay 256 only stepped 236 on to {} "
                             "(one impulse, one step), and the axis ran on",
                             cardreader::format_inches(o.stop), speed_name(*tale.speed_before),
                             speed_name(speed))});
        }
    } else if (tale.increment_met) {
        out.push_back(fmt::format(
            "at {} the increment comparer 122'' met the check {} while the absolute comparer 122' "
            "{}",
            cardreader::format_inches(static_cast<cardreader::Thousandths>(at)),
            cardreader::format_inches(
                static_cast<cardreader::Thousandths>(reading(axis, Part::increment_counter))),
            absolute_on_.at(a) ? "still conducted from the number before, which its banks also "
                                 "hold: it closed no circuit anew, and no impulse went to relay 256"
                               : "did not conduct"));
    } else if (stepped && !tale.motor_started && tale.ran) {
        out.push_back(
            fmt::format("at {} 236 went from {} to {}",
                        cardreader::format_inches(static_cast<cardreader::Thousandths>(at)),
                        speed_name(*tale.speed_before), speed_name(speed)));
    }
    if (tale.motor_stopped) {
        tale.off_at = at;
        out.push_back(
            fmt::format("{} switched off at {}", motor,
                        cardreader::format_inches(static_cast<cardreader::Thousandths>(at))));
    }
    if (!tale.lamps.empty()) {
        std::string lit;
        for (const std::string& l : tale.lamps) {
            lit += (lit.empty() ? "" : " and ") + l;
        }
        out.push_back(lit + " lit");
    }
    tale.instant = -1;
    tale.absolute_met = false;
    tale.increment_met = false;
    tale.speed_before.reset();
    tale.motor_started = false;
    tale.motor_stopped = false;
    tale.lamps.clear();
}

void MachineStory::close_card() {
    if (!current_) {
        return;
    }
    for (int a = 0; a < kAxisCount; ++a) {
        close_instant(a);
        // The coast: where the counters stand now against where the motor was switched off.
        AxisTale& tale = current_->axes.at(static_cast<std::size_t>(a));
        const int now = reading(a, Part::absolute_counter);
        if (!tale.off_at || now == *tale.off_at) {
            continue;
        }
        const Axis named = kAxes.at(static_cast<std::size_t>(a));
        const bool up = current_->orders.axis(named).motion == cardreader::Motion::forward;
        const int past = ((up ? now - *tale.off_at : *tale.off_at - now) % 10000 + 10000) % 10000;
        const std::string what = fmt::format(
            "it coasted on after motor {} was switched off at {}: the counters counted {} "
            "thousandth{} more, to {}",
            motor_numeral_.at(static_cast<std::size_t>(a)),
            cardreader::format_inches(static_cast<cardreader::Thousandths>(*tale.off_at)), past,
            past == 1 ? "" : "s",
            cardreader::format_inches(static_cast<cardreader::Thousandths>(now)));
        tale.phrases.push_back(what);
        notes_.push_back({current_->index, current_->number, named, what});
    }
}

void MachineStory::on_card(double /*t*/, std::int64_t index, const cardreader::CardOrders& orders) {
    close_card();
    previous_ = std::move(current_);
    current_ = CardTale{};
    current_->index = index;
    current_->number = orders.number;
    current_->orders = orders;
}

void MachineStory::on_stop(double /*t*/, const relaylogic::StopInfo& stop) {
    stop_ = stop;
}

void MachineStory::on_finish(double /*t*/) {
    close_card();
    if (!stop_) {
        return;
    }
    if (current_ && current_->index == stop_->card) {
        stop_card_ = current_;
        stop_previous_ = previous_;
    } else {
        stop_previous_ = current_; // the stop came as its card was read: none of it ran
    }
}

std::vector<std::string> MachineStory::tale_lines(const CardTale& card,
                                                  const std::optional<Axis>& axis) const {
    std::vector<std::string> lines;
    for (std::size_t a = 0; a < kAxisCount; ++a) {
        const AxisTale& tale = card.axes.at(a);
        // An axis is told when it ran, and the axis that stopped the machine always.
        const bool told_anyway =
            axis && *axis == kAxes.at(a) && stop_card_ && &card == &*stop_card_;
        if ((axis && *axis != kAxes.at(a)) || tale.phrases.empty() || (!tale.ran && !told_anyway)) {
            continue;
        }
        std::vector<std::string> told = tale.phrases;
        if (told.size() > kHead + kTail + 1) {
            const std::size_t left_out = told.size() - kHead - kTail;
            told.erase(told.begin() + static_cast<std::ptrdiff_t>(kHead),
                       told.end() - static_cast<std::ptrdiff_t>(kTail));
            told.insert(told.begin() + static_cast<std::ptrdiff_t>(kHead),
                        fmt::format("... {} more events ...", left_out));
        }
        lines.push_back(fmt::format("card {} (number {:04}), {}: {}", card.index, card.number,
                                    cardreader::axis_name(kAxes.at(a)), joined(told)));
    }
    return lines;
}

std::vector<std::string> MachineStory::stop_chain() const {
    std::vector<std::string> chain;
    if (!stop_) {
        return chain;
    }
    // The card before is told for the axis that stopped the machine (its coast, its last
    // reading, carry into the stop's card); a stop of no axis is told from its own card.
    const bool before = stop_->axis.has_value() && stop_card_.has_value();
    for (const auto* card : {&stop_previous_, &stop_card_}) {
        if (*card && (card == &stop_card_ || before)) {
            for (std::string& line : tale_lines(**card, stop_->axis)) {
                chain.push_back(std::move(line));
            }
        }
    }
    if (!stop_card_) {
        chain.push_back(fmt::format("card {} was read, and the reader stopped the machine before "
                                    "any axis ran on it",
                                    stop_->card));
    }
    std::string lamps;
    for (const std::string& l : stop_->lamps) {
        lamps += (lamps.empty() ? "" : ", ") + l;
    }
    chain.push_back(fmt::format("the machine stopped: {}: {}{}",
                                relaylogic::stop_reason_name(stop_->reason), stop_->message,
                                lamps.empty() ? std::string() : "; lamps lit: " + lamps));
    return chain;
}

} // namespace parsons::cli
