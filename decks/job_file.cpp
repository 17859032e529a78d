#include "decks/job_file.hpp"

#include "axes/json_text.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace parsons::decks {

using nlohmann::json;

namespace {

std::string surface_name(Surface s) {
    return s == Surface::upper ? "upper" : s == Surface::lower ? "lower" : "both";
}

} // namespace

std::string job_to_json(const JobDescription& job) {
    json j{{"airfoil", job.airfoil}, {"closed_trailing_edge", job.closed_trailing_edge}};
    if (job.kind == JobKind::wing) {
        const WingOptions& w = job.wing;
        j["job"] = "wing";
        j["root_chord_in"] = w.root_chord_in;
        j["span_in"] = w.span_in;
        j["taper"] = w.taper;
        j["sweep_deg"] = w.sweep_deg;
        j["cutter_radius_in"] = w.cutter_radius_in;
        j["zero_in"] = {job.wing_zero_in.x(), job.wing_zero_in.y(), job.wing_zero_in.z()};
    } else {
        const TemplateOptions& o = job.options;
        j["job"] = job.passes.empty() ? "template" : "two-tool";
        j["chord_in"] = o.chord_in;
        j["cutter_radius_in"] = o.cutter_radius_in;
        j["surface"] = surface_name(o.surface);
        j["female"] = o.female;
        j["work_zero_in"] = {job.work_zero_in.x(), job.work_zero_in.y()};
        if (!job.passes.empty()) {
            json passes = json::array();
            for (const PassDescription& p : job.passes) {
                passes.push_back(
                    {{"tool", p.tool}, {"radius_in", p.radius_in}, {"offset_in", p.offset_in}});
            }
            j["passes"] = passes;
            j["allowance_in"] = job.allowance_in;
            j["variant"] = job.variant;
        }
    }
    if (!job.deck_fingerprint.empty()) {
        j["deck"] = {{"cards", job.deck_cards}, {"fingerprint", job.deck_fingerprint}};
    }
    return axes::json_text(j, 2) + "\n";
}

JobDescription job_from_json(const std::string& text) {
    JobDescription job;
    try {
        const json j = json::parse(text);
        const std::string kind = j.at("job").get<std::string>();
        if (j.contains("deck")) { // written since the check that a job matches its deck
            job.deck_cards = j.at("deck").at("cards").get<std::int64_t>();
            job.deck_fingerprint = j.at("deck").at("fingerprint").get<std::string>();
        }
        job.airfoil = j.at("airfoil").get<std::string>();
        job.closed_trailing_edge = j.at("closed_trailing_edge").get<bool>();
        if (kind == "wing") {
            job.kind = JobKind::wing;
            WingOptions& w = job.wing;
            w.root_chord_in = j.at("root_chord_in").get<double>();
            w.span_in = j.at("span_in").get<double>();
            w.taper = j.at("taper").get<double>();
            w.sweep_deg = j.at("sweep_deg").get<double>();
            w.cutter_radius_in = j.at("cutter_radius_in").get<double>();
            const auto& zero = j.at("zero_in");
            job.wing_zero_in = Eigen::Vector3d(zero.at(0).get<double>(), zero.at(1).get<double>(),
                                               zero.at(2).get<double>());
            return job;
        }
        if (kind != "template" && kind != "two-tool") {
            throw JobError(fmt::format("job: '{}' is not template, two-tool or wing", kind));
        }
        if (kind == "two-tool") {
            for (const json& p : j.at("passes")) {
                job.passes.push_back({p.at("tool").get<int>(), p.at("radius_in").get<double>(),
                                      p.at("offset_in").get<double>()});
            }
            if (job.passes.empty()) {
                throw JobError("passes: a two-tool job lists its passes");
            }
            job.allowance_in = j.at("allowance_in").get<double>();
            job.variant = j.at("variant").get<std::string>();
        }
        job.options.chord_in = j.at("chord_in").get<double>();
        job.options.cutter_radius_in = j.at("cutter_radius_in").get<double>();
        const std::string surface = j.at("surface").get<std::string>();
        if (surface != "upper" && surface != "lower" && surface != "both") {
            throw JobError(fmt::format("surface: '{}' is not upper, lower or both", surface));
        }
        job.options.surface = surface == "upper"   ? Surface::upper
                              : surface == "lower" ? Surface::lower
                                                   : Surface::both;
        job.options.female = j.at("female").get<bool>();
        const auto& zero = j.at("work_zero_in");
        job.work_zero_in = Eigen::Vector2d(zero.at(0).get<double>(), zero.at(1).get<double>());
    } catch (const json::exception& e) {
        throw JobError(fmt::format("not a parsons job description: {}", e.what()));
    }
    return job;
}

std::unique_ptr<Airfoil> open_airfoil(const JobDescription& job) {
    if (job.airfoil.rfind("naca ", 0) == 0) {
        try {
            return naca4(job.airfoil.substr(5), job.closed_trailing_edge);
        } catch (const std::invalid_argument& e) {
            throw JobError(e.what());
        }
    }
    if (job.airfoil.rfind("dat ", 0) == 0) {
        return read_dat(job.airfoil.substr(4));
    }
    throw JobError(fmt::format("airfoil: '{}' is neither 'naca NNNN' nor 'dat PATH'", job.airfoil));
}

} // namespace parsons::decks
