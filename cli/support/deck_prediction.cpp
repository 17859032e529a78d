#include "cli/support/deck_prediction.hpp"

#include "cli/support/applied_profile.hpp"
#include "outputs/report/run_report.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/control_cabinet.hpp"

namespace parsons::cli {

std::vector<relaylogic::Fault> parse_faults(const std::vector<std::string>& specs) {
    std::vector<relaylogic::Fault> faults;
    for (const auto& spec : specs) {
        try {
            faults.push_back(relaylogic::parse_fault(spec));
        } catch (const relaylogic::FaultSpecError& e) {
            throw cardreader::DeckError(e.what());
        }
    }
    return faults;
}

namespace {

// What the run's result says that the story, told from the relay events, does not: an axis that
// ends whole turns of its counters from where its cards put it, and a tap that bottomed farther
// from its depth than the NC resolves or did not come back out (on the tap's card). The turns' note
// goes on the last card, its number from the card times the prediction records for it (the run's
// summary says the same, outputs/report/run_report.hpp).
void add_result_notes(Prediction& p) {
    const relaylogic::RunResult& r = p.result;
    for (cardreader::Axis a : cardreader::kAxes) {
        std::string turns = counter_turns_warning(r, a);
        if (!turns.empty()) {
            const int number = r.cards.empty() ? -1 : r.cards.back().number;
            p.notes.push_back({r.cards_read, number, a, std::move(turns)});
        }
    }
    if (r.tapping) {
        for (std::size_t i = 0; i < r.tapping->holes.size(); ++i) {
            std::string miss = tap_hole_warning(r, i);
            if (!miss.empty()) {
                const relaylogic::HoleRecord& h = r.tapping->holes.at(i);
                p.notes.push_back({h.card, h.number, h.axis, std::move(miss)});
            }
        }
    }
    if (std::string drive = press_drive_warning(r, false); !drive.empty()) {
        const relaylogic::DriveSaturation& s = *r.press->drive_saturated;
        p.notes.push_back({s.card, s.number, s.axis, std::move(drive)});
    }
}

} // namespace

Prediction predict_deck(const PredictionRequest& request, InputDeck& deck) {
    AppliedProfile applied = AppliedProfile::load(request.profile);
    applied.apply_limits(request.limits);
    const std::vector<relaylogic::Fault> faults = parse_faults(request.faults);
    axes::MachineProfile& profile = applied.profile();
    apply_feed(profile, request.feed, deck.options());
    refuse_deck_errors(deck, profile); // what run refuses before any motion, refused alike

    relaylogic::ControlCabinet cabinet(profile, *deck.options().layout);
    for (const auto& fault : faults) {
        cabinet.add_fault(fault);
    }
    cabinet.set_pace(relaylogic::Pace::fast_forward);
    cabinet.record_card_times(true);
    MachineStory story;
    cabinet.attach(&story);
    Prediction p;
    p.result = cabinet.run(deck.cards());
    p.profile = profile;
    p.format = std::string(cardreader::format_name(deck.options().format));
    p.layout = deck.options().layout->name;
    p.chain = story.stop_chain();
    p.notes = story.notes();
    add_result_notes(p);
    deck.rewind();
    return p;
}

} // namespace parsons::cli
