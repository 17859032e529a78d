// A trace written to a file while the machine runs (--trace, --events, --path, convert -o):
// the writer is the run's observer, and the file takes its name only when complete
// (OutputFile), so a failed run leaves none.
#pragma once

#include "outputs/output.hpp"
#include "outputs/output_file.hpp"

#include <memory>
#include <string>
#include <utility>

namespace parsons::cli {

template <typename Writer>
class TraceOutput : public Output {
public:
    // Opens the file at once (a FIFO waits for its reader here); throws DeckError naming it.
    template <typename... Args>
    explicit TraceOutput(const std::string& path, Args&&... args)
        : file_(path),
          writer_(std::make_unique<Writer>(file_.stream(), std::forward<Args>(args)...)) {}
    relaylogic::MachineObserver* observer() override { return writer_.get(); }
    std::string gone() const override { return file_.reader_gone() ? file_.name() : ""; }
    void finish(RunEnd& /*end*/) override {
        writer_.reset(); // flushes what is buffered
        file_.commit();
    }

private:
    OutputFile file_;
    std::unique_ptr<Writer> writer_;
};

} // namespace parsons::cli
