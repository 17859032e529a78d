// run --plot FILE: the positions and speed positions against machine time, drawn as SVG
// (outputs/plots/plot_svg.hpp) when the run is over.
#pragma once

#include "outputs/output.hpp"
#include "outputs/output_file.hpp"
#include "outputs/plots/plot_svg.hpp"

#include <string>
#include <utility>

namespace parsons::cli {

class PlotOutput : public Output {
public:
    // `title`: the deck's name.
    PlotOutput(std::string svg, std::string title)
        : svg_(std::move(svg)), recorder_(std::move(title)) {}
    relaylogic::MachineObserver* observer() override { return &recorder_; }
    void finish(RunEnd& /*end*/) override { write_file(svg_, recorder_.svg()); }

private:
    std::string svg_;
    PlotSvgRecorder recorder_;
};

} // namespace parsons::cli
