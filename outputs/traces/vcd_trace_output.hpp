// --trace FILE: the VCD trace, written while the machine runs (the file takes its name only when
// whole, OutputFile), and then the GTKWave save file beside it (outputs/traces/gtkwave_save.hpp),
// made from the variables the trace declared. The save file is written after the trace is in
// place, through the same writer, so a failed run leaves neither.
#pragma once

#include "outputs/output.hpp"
#include "outputs/output_file.hpp"
#include "outputs/traces/trace_outputs.hpp"

#include <array>
#include <memory>
#include <string>

namespace parsons::cli {

class VcdTraceOutput : public Output {
public:
    // Opens the trace at once (a FIFO waits for its reader here); throws DeckError naming it.
    // save_file: where the GTKWave save file goes, beside the trace; "" for none (a trace on
    // standard output, a device or a FIFO has none). initial_in: the axes' positions at the
    // start of the run.
    VcdTraceOutput(const std::string& trace, std::string save_file,
                   const std::array<double, 5>& initial_in);
    relaylogic::MachineObserver* observer() override { return writer_.get(); }
    std::string gone() const override { return file_.reader_gone() ? file_.name() : ""; }
    void finish(RunEnd& end) override;

private:
    std::string trace_;
    std::string save_file_;
    OutputFile file_;
    std::unique_ptr<VcdWriter> writer_;
};

} // namespace parsons::cli
