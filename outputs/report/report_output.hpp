// run --report FILE: the run report as JSON (outputs/report/run_report.hpp), written with what
// the outputs before it in run's table (the cut, the proofs) added.
#pragma once

#include "axes/json_text.hpp"
#include "outputs/output.hpp"
#include "outputs/output_file.hpp"

#include <string>
#include <utility>

namespace parsons::cli {

class ReportOutput : public Output {
public:
    explicit ReportOutput(std::string file) : file_(std::move(file)) {}
    void finish(RunEnd& end) override {
        // A deck name that is not UTF-8 is written with U+FFFD for its bad bytes, not refused.
        write_file(file_, axes::json_text(end.report, 2) + "\n");
    }

private:
    std::string file_;
};

} // namespace parsons::cli
