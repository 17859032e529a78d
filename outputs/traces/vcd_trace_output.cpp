#include "outputs/traces/vcd_trace_output.hpp"

#include "outputs/traces/gtkwave_save.hpp"

#include <filesystem>
#include <utility>

namespace parsons::cli {

VcdTraceOutput::VcdTraceOutput(const std::string& trace, std::string save_file,
                               const std::array<double, 5>& initial_in)
    : trace_(trace), save_file_(std::move(save_file)), file_(trace),
      writer_(std::make_unique<VcdWriter>(file_.stream(), std::string(), initial_in)) {}

void VcdTraceOutput::finish(RunEnd& /*end*/) {
    const std::vector<VcdVariable> declared = writer_->declared();
    writer_.reset(); // flushes what is buffered
    file_.commit();
    if (save_file_.empty()) {
        return;
    }
    // Both by their names alone: they sit in one folder (gtkwave_save.hpp).
    namespace fs = std::filesystem;
    write_file(save_file_, gtkwave_save_file(declared, fs::path(trace_).filename().string(),
                                             fs::path(save_file_).filename().string()));
}

} // namespace parsons::cli
