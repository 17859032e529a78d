// The registry of attachments: the later systems parsons carries, in the order the cabinet
// calls their hooks (and each defines its trace signals). A fourth system is added here, in a
// folder of its own, and touches no file of the 1952 machine.
//   1. condition cards, EP 0640901 (Siemens) ............ relaylogic/conditions/
//   2. press synchronisation, EP 0436887 (Mitsubishi) ... relaylogic/press/
//   3. tapping, EP 0360190 (Mitsubishi) ................. relaylogic/tapping/
//   4. contouring, EP 0636958 (Black & Decker) .......... relaylogic/contouring/
// Each is built only when the profile asks for it (parsons-extended asks for all four,
// parsons-1952 for none). Here too: the refusal of a card whose system the profile lacks, and
// the saved state's members of the systems a machine does not have.
#include "relaylogic/attachment.hpp"

#include "relaylogic/conditions/conditions_attachment.hpp"
#include "relaylogic/contouring/contouring_attachment.hpp"
#include "relaylogic/control_cabinet.hpp"
#include "relaylogic/press/press_attachment.hpp"
#include "relaylogic/tapping/tapping_attachment.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

namespace {

template <class A>
void keep_if_present(Attachments& list, Tracer& tracer, const axes::MachineProfile& profile) {
    auto a = std::make_unique<A>(tracer, profile);
    if (a->present()) {
        a->record_hooks(hooks_of<A>());
        list.push_back(std::move(a));
    }
}

Attachment* find(const Attachments& present, std::string_view name) {
    for (const auto& a : present) {
        if (a->name() == name) {
            return a.get();
        }
    }
    return nullptr;
}

bool saved(const nlohmann::json& state, const char* key) {
    return state.contains(key) && !state.at(key).is_null();
}

} // namespace

Attachments make_attachments(Tracer& tracer, const axes::MachineProfile& profile) {
    Attachments list;
    keep_if_present<ConditionsAttachment>(list, tracer, profile);
    keep_if_present<PressAttachment>(list, tracer, profile);
    keep_if_present<TappingAttachment>(list, tracer, profile);
    keep_if_present<ContouringAttachment>(list, tracer, profile);
    return list;
}

void refuse_unattached_card(ControlCabinet& cab, cardreader::CardKind kind) {
    const char* card = "";
    const char* patent = "";
    const char* lacks = "";
    StopReason reason = StopReason::condition_refused;
    switch (kind) {
    case cardreader::CardKind::condition:
        card = "condition";
        patent = "EP 0640901, Siemens";
        lacks = "has no condition units; the built-in profile parsons-extended allows them";
        break;
    case cardreader::CardKind::sync:
        card = "sync";
        patent = "EP 0436887, Mitsubishi";
        lacks = "has no press synchronisation; the built-in profile parsons-extended has it";
        reason = StopReason::sync_refused;
        break;
    case cardreader::CardKind::tap:
        card = "tap";
        patent = "EP 0360190, Mitsubishi";
        lacks = "has no spindle synchronisation; the built-in profile parsons-extended has it";
        reason = StopReason::tap_refused;
        break;
    case cardreader::CardKind::segment:
        card = "segment";
        patent = "EP 0636958, Black & Decker";
        lacks = "has no contouring (stepper axes and their interpolator); the built-in profile "
                "parsons-extended has it";
        reason = StopReason::segment_refused;
        break;
    case cardreader::CardKind::motion:
        return; // the 1952 cabinet reads it
    }
    cab.machine_stop(reason, std::nullopt,
                     fmt::format("{}, column {}: a {} card (an addition after {}): profile {} {}",
                                 cab.card_name(), cab.layout().extension_column, card, patent,
                                 cab.profile().name, lacks),
                     "card reader 134 check lamp (an addition)");
}

void save_absent(const Attachments& present, nlohmann::json& state) {
    if (find(present, "conditions") == nullptr) {
        state["conditions"] = nullptr;
        state["actions"] = actions_to_json({});
    }
    if (find(present, "sync") == nullptr) {
        state["sync"] = nullptr;
    }
    if (find(present, "tapping") == nullptr) {
        state["tapping"] = nullptr;
    }
    // A machine without contouring writes no member of it: its state stays as it was before
    // the fourth attachment came.
}

void load_all(ControlCabinet& cab, const Attachments& present, const nlohmann::json& state) {
    if (Attachment* a = find(present, "conditions")) {
        a->load(cab, state);
    } else {
        if (saved(state, "conditions")) {
            throw axes::StateError("the state has condition units, but the profile allows no "
                                   "condition cards");
        }
        // Read, to refuse a malformed list, and set aside: no action of this machine's.
        (void)actions_from_json(state.contains("actions") ? state.at("actions")
                                                          : nlohmann::json::array());
    }
    if (Attachment* a = find(present, "sync")) {
        a->load(cab, state);
    } else if (saved(state, "sync")) {
        throw axes::StateError("the saved machine has a press; this profile has none");
    }
    if (Attachment* a = find(present, "tapping")) {
        a->load(cab, state);
    } else if (saved(state, "tapping")) {
        throw axes::StateError("the saved state has spindle synchronisation and this profile "
                               "has none");
    }
    if (Attachment* a = find(present, "contouring")) {
        // A state from before contouring existed has no member: the axes stood at 0.
        if (state.contains("contouring")) {
            a->load(cab, state);
        }
    } else if (saved(state, "contouring")) {
        throw axes::StateError("the saved state has contouring (stepper axes) and this profile "
                               "has none");
    }
}

} // namespace parsons::relaylogic
