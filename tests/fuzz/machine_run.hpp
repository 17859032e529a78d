// Running a deck on the whole machine for the fuzz targets, and what every run must satisfy.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/card.hpp"
#include "relaylogic/faults.hpp"

#include <vector>

namespace parsons::fuzz {

// Writes the cards as a .cbn deck, reads it back through the card reader and runs it on a
// control cabinet with `profile`, fast-forward and again at impulse level, with an observer
// attached when `observe` is set. Throws Finding unless each run ends completed, or stopped
// with a reason, having read no more cards than the deck holds, in finite machine time that
// never runs backwards, and the two runs end the same.
void run_machine(const std::vector<cardreader::Card>& cards, const axes::MachineProfile& profile,
                 bool observe, const std::vector<relaylogic::Fault>& faults = {});

} // namespace parsons::fuzz
