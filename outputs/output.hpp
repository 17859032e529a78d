// One output of a run: a file `parsons run` writes (report, VCD, events, path, G-code path, plot,
// cut picture, replay page, the proofs' verdicts, saved state) or a recording an embedder keeps
// (the exhibit page's timeline, web/parsons_web.cpp).
//
// An output is made before the first card (by its option's entry in run's table,
// cli/run_outputs.cpp), is attached to the run (observer(): a relaylogic::MachineObserver that
// watches it, or nothing), and is finished with the result. The outputs of a run are finished in
// the order of the table, so an output later in it (the report, the replay page) holds what an
// earlier one (a proof) added to the report.
//
//   made (option's factory) --> observer() attached --> the run --> gone()? --> finish(end)
//                                                                           --> objection()
#pragma once

#include "relaylogic/control_cabinet.hpp"
#include "relaylogic/machine_observer.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::cli {

// What the outputs of a run are finished with.
struct RunEnd {
    const relaylogic::RunResult& result;
    nlohmann::json&
        report;           // the run report (outputs/report/run_report.hpp): a proof adds its block
    std::string& summary; // lines printed after the summary's own (a proof's figures)
};

class Output {
public:
    Output() = default;
    virtual ~Output() = default;
    Output(const Output&) = delete;
    Output& operator=(const Output&) = delete;

    // What watches the run, attached to the cabinet before the first card; null: nothing.
    virtual relaylogic::MachineObserver* observer() { return nullptr; }
    // An output written while the run goes on whose reader went away (a closed pipe): its name,
    // else "". Asked of every output before any is finished.
    virtual std::string gone() const { return {}; }
    // The run is over: write the output, and add to the report and the summary.
    virtual void finish(RunEnd& end) = 0;
    // A proof that found the job wrong though the machine ran as it should: the message for
    // standard error (exit 3), else "". Asked after every output is finished, of a run that
    // did not stop.
    virtual std::string objection() const { return {}; }
};

} // namespace parsons::cli
