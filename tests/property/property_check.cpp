// The invariants the docs promise, checked on one property case (docs/testing.md, "The property
// test"). Everything runs in-process: the profile through the real loader (AppliedProfile, as
// --profile reads it), `run` through run_deck, `check` through predict_deck, and the cabinet
// itself for the observed, impulse-level and resumed runs.
#include "tests/property/property_case.hpp"

#include "tests/test_support.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/tap_review.hpp"
#include "cli/commands.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/deck_prediction.hpp"
#include "outputs/report/run_report.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <map>
#include <unistd.h>

namespace parsons::test {

std::vector<std::string> profile_keys(const nlohmann::json& profile);

namespace {

using namespace parsons::relaylogic;
using cardreader::DeckError;

// The documented bounds (docs/tapping.md, docs/press-sync.md) and the slack of their figures.
constexpr double kTapDepthIn = 0.001;          // a completed tap within a thousandth of its depth
constexpr double kBetweenCrossingsIn = 0.0005; // the part at rest between two crossings
constexpr double kLoopShare = 0.5;             // the position loop adds at most half the speed
constexpr double kGovernorMost = 1.5; // drift compounds up to x 1.5 (docs/machine-profile.md)

struct InvariantFailure {
    Violation v;
};

[[noreturn]] void fail_invariant(std::string invariant, std::string detail) {
    throw InvariantFailure{{std::move(invariant), std::move(detail)}};
}

// What a run did, in the figures `check`, `run`, fast-forward, impulse level and a resumed run
// must agree on (tests/fast_forward_test.cpp compares the same, and the relay events too).
std::string run_figures(const RunResult& r) {
    std::string s = fmt::format("{} after {} cards at {} s", r.completed ? "completed" : "stopped",
                                r.cards_read, r.machine_seconds);
    if (r.stop) {
        s += fmt::format(" ({} card {} axis {}: {} [{}])", stop_reason_name(r.stop->reason),
                         r.stop->card, r.stop->axis ? std::string(axis_name(*r.stop->axis)) : "-",
                         r.stop->message, fmt::join(r.stop->lamps, ", "));
    }
    for (std::size_t i = 0; i < r.axes.size(); ++i) {
        const AxisResult& a = r.axes.at(i);
        s += fmt::format("; {} counter {} real {} impulses {} lost {} slip {} screw {}",
                         axis_name(cardreader::kAxes.at(i)), a.counter_in, a.real_in, a.impulses,
                         a.lost_steps, a.slip_in, a.screw_in);
    }
    for (const auto& x : r.actions) {
        s += fmt::format("; event {} {} {} {}", x.event, x.tripped_s, x.acknowledged_s,
                         x.motion_end_s);
    }
    if (r.tool_in_spindle) {
        s += fmt::format("; tool {}", *r.tool_in_spindle);
    }
    if (r.press) {
        const PressResult& p = *r.press;
        s += fmt::format("; press rev {} crank {} register {} stopped {} cycles {} loops {} "
                         "waited {} lag {} {}",
                         p.revolution, p.crank_angle_deg, p.position_register, p.press_stopped,
                         p.cycles, p.loop_backs, p.waited_s, p.max_lag_position_sync_in,
                         p.max_lag_speed_only_in);
        if (const auto& d = p.drive_saturated) {
            s += fmt::format("; drive saturated {} card {} speed {} at {} asked {} most {}",
                             axis_name(d->axis), d->card, d->speed_position, d->t_s,
                             d->asked_in_per_min, d->most_asked_in_per_min);
        }
    }
    if (r.tapping) {
        for (const HoleRecord& h : r.tapping->holes) {
            s += fmt::format("; hole {} tool {} deepest {} end {} {}-{} {}", h.card, h.tool,
                             h.deepest_in, h.end_in, h.reverse_s, h.end_s, h.completed);
        }
    }
    return s;
}

void require_same_figures(const char* invariant, const char* a_name, const RunResult& a,
                          const char* b_name, const RunResult& b) {
    const std::string x = run_figures(a);
    const std::string y = run_figures(b);
    if (x != y) {
        fail_invariant(invariant, fmt::format("{}: {}\n{}: {}", a_name, x, b_name, y));
    }
}

// Standard error sent to a file of the case's own while `run` runs (its stop message, which
// the figures carry), so that thousands of runs do not fill the test's output.
class QuietStderr {
public:
    explicit QuietStderr(const std::string& file)
        : saved_(dup(2)), fd_(open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644)) {
        std::fflush(stderr);
        if (saved_ >= 0 && fd_ >= 0) {
            dup2(fd_, 2);
        }
    }
    ~QuietStderr() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            dup2(saved_, 2);
            close(saved_);
        }
        if (fd_ >= 0) {
            close(fd_);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

private:
    int saved_;
    int fd_;
};

// Watches processor 63's commands (press synchronisation): the largest command against the
// fastest per-pulse travel any card or slow-down gave the axis.
class LoopWatch : public MachineObserver {
public:
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
    void on_signal_defined(const SignalInfo& info, std::uint32_t) override {
        if (info.scope != "press") {
            return;
        }
        for (std::size_t i = 0; i < cardreader::kAxes.size(); ++i) {
            const std::string axis(axis_name(cardreader::kAxes.at(i)));
            if (info.name == "processor_63." + axis) {
                command_.emplace(info.id, i);
            } else if (info.name == "feed_speed_reader_62." + axis) {
                feed_.emplace(info.id, i);
            }
        }
    }
    void on_signal(double t, SignalId id, std::uint32_t, std::uint32_t v) override {
        if (auto f = feed_.find(id); f != feed_.end()) {
            most_feed.at(f->second) = std::max(most_feed.at(f->second), v * 1e-5);
            if (v > 0) {
                least_feed = std::min(least_feed, v * 1e-5);
            }
        } else if (auto c = command_.find(id); c != command_.end()) {
            const double in_per_s = v / 60000.0;
            if (in_per_s > most_command.at(c->second)) {
                most_command.at(c->second) = in_per_s;
                when.at(c->second) = t;
            }
        }
    }
    std::array<double, 5> most_feed{};    // in a pulse (F), the largest shown
    std::array<double, 5> most_command{}; // in/s, the largest sent to the drive
    std::array<double, 5> when{};
    double least_feed = 1e9; // in a pulse, the smallest F shown (0: not synchronised)

private:
    std::map<SignalId, std::size_t> command_;
    std::map<SignalId, std::size_t> feed_;
};

// Cuts a run as card `card` is fed (an operator's Ctrl-C).
class CutAt : public MachineObserver {
public:
    CutAt(std::int64_t card, volatile std::sig_atomic_t* flag) : card_(card), flag_(flag) {}
    bool follows_impulses() const override { return false; }
    bool follows_motion() const override { return false; }
    void on_card(double, std::int64_t index, const cardreader::CardOrders&) override {
        if (index >= card_) { // 1-based
            *flag_ = 1;
        }
    }

private:
    std::int64_t card_;
    volatile std::sig_atomic_t* flag_;
};

RunResult run_property_cabinet(const axes::MachineProfile& profile, const std::string& deck_file,
                               const std::vector<Fault>& faults, Pace pace,
                               MachineObserver* observer, const nlohmann::json* resume = nullptr,
                               nlohmann::json* saved = nullptr,
                               const volatile std::sig_atomic_t* interrupt = nullptr) {
    cli::InputDeck deck(deck_file, cli::DeckFlags{});
    axes::MachineProfile fed = profile;
    cli::apply_feed(fed, "", deck.options()); // as run applies the deck's medium
    ControlCabinet cabinet(fed, *deck.options().layout);
    for (const Fault& f : faults) {
        cabinet.add_fault(f);
    }
    if (resume != nullptr) {
        cabinet.resume(*resume);
    }
    cabinet.set_pace(pace);
    cabinet.keep_resume_point(saved != nullptr);
    if (interrupt != nullptr) {
        cabinet.watch_interrupt(interrupt);
    }
    if (observer != nullptr) {
        cabinet.attach(observer);
    }
    RunResult r = cabinet.run(deck.cards());
    if (saved != nullptr) {
        *saved = nlohmann::json::parse(cabinet.resume_point().dump()); // through the text
    }
    return r;
}

// The profile: refused naming a key the file holds, or loaded (and then never a key past its
// range). Returns the profile loaded, or nothing when it was refused as it should be.
std::optional<axes::MachineProfile> load_drawn_profile(const PropertyCase& c,
                                                       const std::string& file) {
    try {
        cli::AppliedProfile applied = cli::AppliedProfile::load(file);
        if (!c.out_of_range.empty()) {
            fail_invariant("profile-refused-past-range",
                           c.out_of_range +
                               " was drawn past its documented range and the loader took it");
        }
        return applied.profile();
    } catch (const DeckError& e) {
        const std::string said = e.what();
        // The key as the file writes it ("press.stroke_in"), or by its own name where the
        // message tells a relation ("... longer than the crank throw, stroke_in / 2").
        for (const std::string& key : profile_keys(c.profile)) {
            const std::string own = key.substr(key.rfind('.') + 1);
            if (said.find(key) != std::string::npos || said.find(own) != std::string::npos) {
                return std::nullopt;
            }
        }
        fail_invariant("profile-refusal-names-its-key",
                       "the loader refused naming none of the file's "
                       "keys: " +
                           said);
    }
}

void check_bounds(const PropertyCase& c, const axes::MachineProfile& p, const RunResult& r,
                  const LoopWatch& loop);

void check_deck(const PropertyCase& c, const TempDir& dir, const axes::MachineProfile& p) {
    const std::string deck = dir.str("deck." + std::string(cardreader::format_name(c.deck.medium)));
    write_bytes(deck, deck_bytes(punched_cards(c.deck), c.deck.medium));
    std::vector<std::string> specs;
    for (const Fault& f : c.deck.faults) {
        specs.push_back(f.spec);
    }
    // `run` as the command runs it, and `check`'s prediction: the same refusal, or the same run.
    cli::RunRequest request;
    request.input = deck;
    request.profile = dir.str("profile.json");
    request.faults = specs;
    request.quiet = true;
    RunResult ran;
    std::string run_refused;
    cli::ExitCode code = cli::ExitCode::ok;
    try {
        const QuietStderr quiet(dir.str("run.stderr"));
        code = cli::run_deck(request, &ran);
    } catch (const DeckError& e) {
        run_refused = e.what();
    }
    std::string check_refused;
    std::optional<cli::Prediction> predicted;
    try {
        cli::PredictionRequest pr;
        pr.input = deck;
        pr.profile = request.profile;
        pr.faults = specs;
        cli::InputDeck input(deck, pr.deck);
        predicted = cli::predict_deck(pr, input);
    } catch (const DeckError& e) {
        check_refused = e.what();
    }
    if (run_refused != check_refused) {
        fail_invariant("check-equals-run", fmt::format("run refused: \"{}\"; check refused: \"{}\"",
                                                       run_refused, check_refused));
    }
    if (!run_refused.empty()) {
        return; // a deck error, exit 2 from both: nothing ran
    }
    const int expected = ran.completed                                             ? 0
                         : ran.stop && ran.stop->reason == StopReason::interrupted ? 130
                                                                                   : 3;
    if (cli::to_int(code) != expected) {
        fail_invariant("run-exit-code",
                       fmt::format("run exited {} after {}", cli::to_int(code), run_figures(ran)));
    }
    require_same_figures("check-equals-run", "run", ran, "check", predicted->result);

    // The machine with an observer of processor 63: the same run, and every documented bound.
    const auto faults = cli::parse_faults(specs);
    LoopWatch loop;
    const RunResult watched = run_property_cabinet(p, deck, faults, Pace::fast_forward, &loop);
    require_same_figures("observer-changes-nothing", "run", ran, "watched", watched);
    check_bounds(c, p, ran, loop);
    if (!c.deep) {
        return;
    }
    const RunResult impulses = run_property_cabinet(p, deck, faults, Pace::impulse_level, nullptr);
    require_same_figures("fast-forward-equals-impulse-level", "fast-forward", ran, "impulse level",
                         impulses);
    // Cut as a card is fed, saved, resumed from the state through its text: the same figures.
    volatile std::sig_atomic_t flag = 0;
    CutAt cut(c.interrupt_card, &flag);
    nlohmann::json saved;
    const RunResult first =
        run_property_cabinet(p, deck, faults, Pace::fast_forward, &cut, nullptr, &saved, &flag);
    if (!first.stop || first.stop->reason != StopReason::interrupted) {
        return; // it ended before the cut
    }
    const RunResult rest =
        run_property_cabinet(p, deck, faults, Pace::fast_forward, nullptr, &saved);
    require_same_figures("resume-equals-straight", "straight", ran, "resumed", rest);
}

void check_bounds(const PropertyCase& c, const axes::MachineProfile& p, const RunResult& r,
                  const LoopWatch& loop) {
    if (r.completed == r.stop.has_value() || (r.stop && r.stop->message.empty())) {
        fail_invariant("ends-completed-or-stopped-saying-why", run_figures(r));
    }
    // Each axis ends where its counters say, or the chain's figures and the counters' own
    // miscounts (what the summary names, docs/report.md) make up the difference.
    for (std::size_t i = 0; i < r.axes.size(); ++i) {
        const AxisResult& a = r.axes.at(i);
        const std::string axis(axis_name(cardreader::kAxes.at(i)));
        const double counting = a.error_in - (a.real_in - a.commutator_in);
        const bool told = a.wrong_way > 0 || a.thousandths_uncounted > 0 || a.lost_steps > 0 ||
                          a.skipped_steps > 0;
        if (std::abs(counting) > 1e-9 && !told) {
            fail_invariant(
                "axis-ends-where-counters-say",
                fmt::format("{}: the counters are {:+.5f} in off the commutators' reading and "
                            "the summary names no miscount ({})",
                            axis, counting, run_figures(r)));
        }
        const double rest = a.real_in - a.commutator_in - a.chain.sum();
        if (std::abs(rest) > kBetweenCrossingsIn + 1e-9) {
            fail_invariant(
                "axis-ends-where-counters-say",
                fmt::format("{}: the part is {:+.5f} in from the reading beyond what the chain "
                            "names ({})",
                            axis, rest, run_figures(r)));
        }
        // (the summary warns whenever the counter does not read the last stop: "ends at ...,
        // not on its last stop"; and when the counters went whole turns past what the cards
        // ordered: "ends +10.000 in from where its cards put it", outputs/report/run_report.cpp,
        // the reading then the stop that many turns on)
        // And the summary's "ends +0.0037 in from where its counters say (lost ...)": the
        // counters read the stop, the part is not there, and the summary says why.
        const bool warned = (a.last_stop_in && std::abs(a.counter_in - *a.last_stop_in) >= 0.001) ||
                            std::abs(a.error_in) >= 0.0005;
        const auto turns =
            static_cast<double>(cli::counter_turns_unseen(r, cardreader::kAxes.at(i)));
        if (r.completed && a.last_stop_in && !warned &&
            std::abs(a.commutator_in - 10.0 * turns - *a.last_stop_in) > 0.0015) {
            fail_invariant(
                "axis-ends-at-its-stop",
                fmt::format("{}: completed with the reading {:.5f} in, its last card's stop "
                            "{:.3f} in ({})",
                            axis, a.commutator_in, *a.last_stop_in, run_figures(r)));
        }
    }
    // Each tap within a thousandth of its depth, or a stop or the summary's warning that says
    // how far it is off (outputs/report/run_report.hpp, tap_hole_warning).
    if (r.tapping) {
        const std::string summary = cli::summary_text(r, "deck", "profile");
        for (std::size_t i = 0; i < r.tapping->holes.size(); ++i) {
            const HoleRecord& h = r.tapping->holes.at(i);
            const bool hole_warned = summary.find(fmt::format("warning: hole {} (card {},", i + 1,
                                                              h.card)) != std::string::npos;
            // The NC knows the tool's turns to an encoder edge (docs/tapping.md: within 0.85 of
            // one for the built-in profile's taps): a thousandth, or one edge's feed if coarser.
            const double edge_in =
                h.pitch_ordered_in * h.ratio_used / p.spindle.encoder_pulses_per_rev;
            if (h.completed && !hole_warned &&
                std::abs(h.deepest_in - h.depth_in) > std::max(kTapDepthIn, edge_in) + 1e-9) {
                fail_invariant(
                    "tap-within-a-thousandth",
                    fmt::format(
                        "card {} (S {}, tool {}): depth {:.4f}, deepest {:.4f}, "
                        "completed; an encoder edge feeds {:.5f} in, a sample "
                        "holds {:.2f} edges, pitch ordered {} head {}",
                        h.card, h.rpm, h.tool, h.depth_in, h.deepest_in,
                        h.pitch_ordered_in * h.ratio_used / p.spindle.encoder_pulses_per_rev,
                        h.rpm / 60.0 * p.spindle.encoder_pulses_per_rev * p.spindle.sample_s,
                        h.pitch_ordered_in, h.tap_pitch_in.value_or(0)));
            }
            // Not completed: a stop says why, or (docs/tapping.md, "Near the top": a feed that
            // does not settle leaves the next card's check to find it) the summary's warning
            // that the feed axis does not end on its last stop.
            const AxisResult& feed = r.axes.at(cardreader::axis_index(h.axis));
            const bool feed_warned =
                feed.last_stop_in && std::abs(feed.counter_in - *feed.last_stop_in) >= 0.001;
            if (!h.completed && !r.stop && !feed_warned && !hole_warned) {
                fail_invariant(
                    "tap-within-a-thousandth",
                    fmt::format("card {}: not completed, and the run has no stop", h.card));
            }
        }
    }
    if (!r.press || !p.press_sync) {
        return;
    }
    // The position loop within half the speed: no command faster than 1 + kLoopShare times the
    // fastest the press can turn by the fastest per-pulse travel, or the drive's least speed.
    const axes::PressProfile& press = p.press;
    const double rated = press.strokes_per_min * 6.0 * press.pulses_per_degree;
    // The drift compounds once a revolution turned, |r - 1| (a press turning backwards counts
    // its revolutions 0, -1, ...), up to motor 22's governor; a press that drifts slower never
    // turns faster than at its first revolution (docs/machine-profile.md, "How the speed is
    // made"). The crank turns one way, so the last revolution has turned the most.
    const double turned = std::abs(r.press->revolution - 1);
    const double drift =
        std::clamp(std::pow(1 + press.drift_per_cycle, turned), 1.0, kGovernorMost);
    const double fastest =
        rated * std::max(1.0, press.change_factor) * (1 + press.variation) * drift +
        1.0 / p.speed_sample_s;
    for (std::size_t i = 0; i < r.axes.size(); ++i) {
        const auto& speeds = p.axes.at(i).speed_in_per_min;
        const double per_pulse =
            std::max({loop.most_feed.at(i), speeds.at(1) / 60 / rated, speeds.at(2) / 60 / rated});
        const double bound = std::max(cardreader::kLeastTapFeedInPerMin / 60.0,
                                      (1 + kLoopShare) * per_pulse * fastest) +
                             1e-6;
        if (loop.most_command.at(i) > bound) {
            fail_invariant(
                "position-loop-within-half-the-speed",
                fmt::format("{}: {:.1f} thousandths/min at {:.3f} s, past {:.1f} (F {:.5f} in a "
                            "pulse, the press at most {:.1f} pulses/s)",
                            axis_name(cardreader::kAxes.at(i)), loop.most_command.at(i) * 60000,
                            loop.when.at(i), bound * 60000, per_pulse, fastest));
        }
    }
    // Within the documented lag of the crank on position-sync cards: one reference block of
    // delay at the drive's top speed, the start's run-up, and a pulse's travel.
    if (p.sync_drive.position_gain_per_s > 0) {
        const double v = p.sync_drive.max_in_per_min / 60.0;
        double per_pulse = 0;
        for (double f : loop.most_feed) {
            per_pulse = std::max(per_pulse, f);
        }
        // A slip fault (docs/faults.md) stands the part while the screw turns: an axis that
        // slips falls behind by as much as the slip before the loop makes it up.
        double slipped = 0;
        for (const relaylogic::Fault& f : c.deck.faults) {
            slipped += f.kind == relaylogic::FaultKind::slip ? f.count * 0.001 : 0.0;
        }
        // Backlash in nut 78, where the counters measure the part (the patent's chain): on a
        // reversal the screw takes it up with the part standing, so the axis falls behind by
        // at most the backlash before the loop makes it up.
        double backlash = 0;
        if (p.measuring_chain == axes::MeasuringChain::instrument_shaft_74) {
            for (const axes::AxisProfile& a : p.axes) {
                backlash = std::max(backlash, a.backlash_in);
            }
        }
        const double lag = 2 * v * p.speed_sample_s +
                           v * v / (2 * p.sync_drive.acceleration_in_per_s2) + per_pulse + 0.001 +
                           slipped + backlash;
        // The drive asked past its top speed falls behind for as long as that lasts: no bound
        // holds, and the summary must say so (outputs/report/run_report.hpp,
        // press_drive_warning).
        const bool saturation_told =
            r.press->drive_saturated &&
            cli::summary_text(r, "deck", "profile")
                    .find("warning: " + cli::press_drive_warning(r)) != std::string::npos;
        if (r.press->drive_saturated && !saturation_told) {
            fail_invariant("sync-within-its-lag",
                           fmt::format("the drive was asked past its top speed and the summary "
                                       "does not say so ({})",
                                       run_figures(r)));
        }
        if (!saturation_told && r.press->max_lag_position_sync_in > lag + 1e-9) {
            fail_invariant("sync-within-its-lag",
                           fmt::format("position sync lagged {:.4f} in, past {:.4f} in (the "
                                       "least F, {:.5f} in a pulse, asks {:.3f} in/min at the "
                                       "press's rated speed; the drive's least is {} in/min)",
                                       r.press->max_lag_position_sync_in, lag, loop.least_feed,
                                       loop.least_feed * rated * 60,
                                       cardreader::kLeastTapFeedInPerMin));
        }
    }
}

} // namespace

std::optional<Violation> check_case(const PropertyCase& c) {
    try {
        TempDir dir;
        write_bytes(dir.path("profile.json"), c.profile.dump(2) + "\n");
        const auto profile = load_drawn_profile(c, dir.str("profile.json"));
        if (!profile) {
            return std::nullopt;
        }
        check_deck(c, dir, *profile);
    } catch (const InvariantFailure& f) {
        return f.v;
    } catch (const std::exception& e) {
        return Violation{"no-internal-error", e.what()};
    }
    return std::nullopt;
}

} // namespace parsons::test
