// parsons gen airfoil: the 1952 arithmetic. Compute closely spaced points on an airfoil,
// offset each by the cutter radius to the cutter-centre locus, and punch one card per station.
// With --json, what it prints about the deck is one document for scripts (docs/json-output.md).
// parsons gen two-tool: the template roughed with one tool and finished with another, the tool
// change tripped by a condition card during the return move (decks/two_tool_job.hpp; an
// addition after EP 0640901, run under --profile parsons-extended). parsons gen press-feeder and
// parsons gen tapping: the jobs of the press and spindle synchronisations
// (cli/gen_press_feeder.hpp, cli/gen_tapping.hpp).
#include "cli/commands.hpp"
#include "cli/gen_press_feeder.hpp"
#include "cli/gen_tapping.hpp"
#include "cli/support/applied_profile.hpp"
#include "cli/support/data_files.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/json_output.hpp"
#include "cli/support/progress_line.hpp"
#include "cli/support/value_names.hpp"
#include "outputs/output_file.hpp"
#include "outputs/proofs/two_tool_proof.hpp"
#include "outputs/report/figures.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/layout.hpp"
#include "decks/job_file.hpp"
#include "decks/move_planner.hpp"
#include "decks/number_text.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <memory>

namespace parsons::cli {
namespace {

// The source a job is computed from: "naca DIGITS", or "dat FILE" with FILE found as given or
// among the bundled airfoil files (cli/support/data_files.hpp). A file that cannot be found is
// named, with the bundled ones a bare name could have given.
std::string airfoil_source(const std::string& naca, const std::string& dat) {
    if (!naca.empty()) {
        return "naca " + naca;
    }
    const std::string file = resolve_airfoil_file(dat);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) {
        throw cardreader::DeckError::in_file(dat, "cannot open the airfoil file" +
                                                      bundled_airfoils_hint());
    }
    return "dat " + file;
}

using cardreader::DeckError;

struct GenFlags {
    std::string naca;
    std::string dat;
    bool closed_te = false;
    double chord_in = 6.0;
    double radius_in = 0.25;
    int stations = 60;
    std::string spacing = "cosine";
    double scallop_in = 0;
    bool scallop_given = false;
    std::string surface = "upper";
    bool female = false;
    bool no_corner_slowdown = false;
    std::string job = "template";
    double span_in = 5.0;
    double taper = 0.8;
    double sweep_deg = 5.0;
    std::string output;
    std::string to;
    std::string centres;
    std::string job_out;
    std::string profile;
    bool json = false;
};

decks::TemplateOptions options_from(const GenFlags& f) {
    decks::TemplateOptions o;
    o.chord_in = f.chord_in;
    o.cutter_radius_in = f.radius_in;
    o.stations = f.stations;
    o.spacing = f.spacing == "uniform" ? decks::Spacing::uniform : decks::Spacing::cosine;
    o.scallop_in = f.scallop_in;
    o.surface = f.surface == "lower"  ? decks::Surface::lower
                : f.surface == "both" ? decks::Surface::both
                                      : decks::Surface::upper;
    o.female = f.female;
    o.corner_slowdown = !f.no_corner_slowdown;
    return o;
}

} // namespace

FilePlan generator_plan(const std::string& profile, const std::string& output,
                        const std::string& job_out, bool writes_profile) {
    FilePlan plan;
    plan.read("--profile", AppliedProfile::file_read(profile));
    plan.write("-o", output);
    const std::string job_file = job_file_for(output, job_out);
    plan.write(job_option(job_out), job_file);
    if (writes_profile) {
        plan.write("the profile beside the job description", profile_file_for(job_file));
    }
    return plan;
}

void add_job_out_option(CLI::App& cmd, std::string& job_out) {
    cmd.add_option("--job-out", job_out,
                   "Write the job description (for run --cut and the proofs) to this file "
                   "instead of beside the deck (DECK.job.json); a deck to standard output or a "
                   "device has none unless this is given")
        ->type_name(file_value({"json"}));
}

std::string files_written(const std::string& deck, const std::string& job_file,
                          const std::string& also, const std::string& and_also) {
    std::vector<std::string> names{deck == "-" ? std::string("standard output") : deck};
    for (const std::string* name : {&job_file, &also, &and_also}) {
        if (!name->empty()) {
            names.push_back(*name);
        }
    }
    std::string text = names.front();
    for (std::size_t i = 1; i < names.size(); ++i) {
        text += (i + 1 == names.size() ? " and " : ", ") + names[i];
    }
    if (job_file.empty()) {
        text += " (no job description beside a deck that is not a file: give --job-out FILE "
                "for one)";
    }
    return text;
}

cardreader::DeckFingerprint write_cards(const std::vector<cardreader::CardOrders>& cards,
                                        const std::string& output, const std::string& to,
                                        ProgressLine* progress, const char* command) {
    cardreader::DeckFingerprint fingerprint;
    DeckFlags flags;
    const auto options = deck_options(output, to, flags, "--to");
    OutputFile deck_file(output);
    auto sink = cardreader::open_card_sink(deck_file.stream(), options);
    for (const auto& card : cards) {
        if (progress != nullptr) {
            progress->show(
                static_cast<double>(fingerprint.cards()) / static_cast<double>(cards.size()),
                fmt::format("punching card {} of {}", fingerprint.cards() + 1, cards.size()),
                fingerprint.cards() == 0); // a new stage: drawn at once
        }
        auto punched = cardreader::encode(card, cardreader::fig8_layout());
        if (!punched) {
            throw DeckError(fmt::format("{}: card {}: {}", command, card.number, *punched.error));
        }
        sink->write(punched.card);
        fingerprint.add(punched.card);
    }
    deck_file.commit();
    return fingerprint;
}

namespace {

// A scallop target finer than the finest stations the generator makes is refused, with the
// smallest scallop the job can have, rather than a deck that misses it.
void refuse_unreachable_scallop(double target_in, double planned_in, const char* finest) {
    if (target_in > 0 && planned_in > target_in + 1e-9) {
        throw DeckError(fmt::format("gen airfoil: --scallop {}: this job cannot hold a scallop "
                                    "that small; with the finest stations the generator makes "
                                    "({}) the smallest possible is {:.5f} in",
                                    target_in, finest, std::ceil(planned_in * 1e5) / 1e5));
    }
}

} // namespace

GeneratedJob generate_job(const decks::JobDescription& description,
                          const axes::MachineProfile& profile, const std::string& output,
                          const std::string& to, const std::string& centres, ProgressLine* progress,
                          const std::string& job_out) {
    GeneratedJob job{description, {}, {}, 0, job_file_for(output, job_out)};
    if (progress != nullptr) {
        progress->show(0, fmt::format("{}: computing the stations", description.airfoil), true);
    }
    cardreader::DeckFingerprint fingerprint;
    std::string csv = "x,y,cx,cy\n";
    try {
        const auto airfoil = decks::open_airfoil(description);
        if (description.kind == decks::JobKind::wing) {
            job.wing = decks::make_wing_deck(*airfoil, description.wing, profile);
            job.description.wing_zero_in = job.wing.zero;
            refuse_unreachable_scallop(description.wing.scallop_in, job.wing.planned_leftover_in,
                                       "at most 400 stations along the chord");
            fingerprint = write_cards(job.wing.cards, output, to, progress);
            job.cards = job.wing.cards.size();
            csv = "u,root_cx,root_cy,root_cz,tip_cx,tip_cy,tip_cz,tilt_deg,swivel_deg\n";
            for (const auto& s : job.wing.stations) {
                csv += fmt::format(
                    "{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.5f},{:.5f}\n", s.u,
                    s.root_centre.x(), s.root_centre.y(), s.root_centre.z(), s.tip_centre.x(),
                    s.tip_centre.y(), s.tip_centre.z(), s.tilt_rad * 180 / 3.14159265358979,
                    s.swivel_rad * 180 / 3.14159265358979);
            }
        } else {
            job.deck = decks::make_template_deck(*airfoil, description.options, profile);
            job.description.work_zero_in = job.deck.work_zero_in;
            refuse_unreachable_scallop(description.options.scallop_in, job.deck.planned_leftover_in,
                                       "at least 0.0001 of the path apart");
            fingerprint = write_cards(job.deck.cards, output, to, progress);
            job.cards = job.deck.cards.size();
            for (const auto& s : job.deck.stations) {
                csv += fmt::format("{:.6f},{:.6f},{:.6f},{:.6f}\n", s.work.x(), s.work.y(),
                                   s.centre.x(), s.centre.y());
            }
        }
    } catch (const decks::JobError& e) {
        throw DeckError(fmt::format("gen airfoil: {}", e.what()));
    } catch (const decks::PlanError& e) {
        throw DeckError(fmt::format("gen airfoil: {}", e.what()));
    }
    job.description.deck_cards = fingerprint.cards();
    job.description.deck_fingerprint = fingerprint.hex();
    if (!job.job_file.empty()) { // a deck on standard output or a device has none beside it
        write_file(job.job_file, decks::job_to_json(job.description));
    }
    if (!centres.empty()) {
        write_file(centres, csv);
    }
    return job;
}

GeneratedTwoToolJob generate_two_tool_job(const std::string& airfoil_source, bool closed_te,
                                          const decks::TwoToolOptions& options,
                                          const axes::MachineProfile& profile,
                                          const std::string& output, const std::string& to,
                                          const std::string& job_out) {
    if (!profile.condition_cards) {
        throw DeckError(fmt::format("gen two-tool: the machine profile '{}' takes no condition "
                                    "cards (an addition after EP 0640901): give --profile "
                                    "parsons-extended",
                                    profile.name));
    }
    GeneratedTwoToolJob job;
    job.job_file = job_file_for(output, job_out);
    decks::JobDescription& d = job.description;
    d.airfoil = airfoil_source;
    d.closed_trailing_edge = closed_te;
    d.options = options.pass;
    d.allowance_in = options.allowance_in;
    d.variant = std::string(decks::variant_name(options.variant));
    cardreader::DeckFingerprint fingerprint;
    try {
        const auto airfoil = decks::open_airfoil(d);
        job.deck = decks::make_two_tool_deck(*airfoil, options, profile);
        fingerprint = write_cards(job.deck.cards, output, to, nullptr, "gen two-tool");
    } catch (const decks::JobError& e) {
        throw DeckError(fmt::format("gen two-tool: {}", e.what()));
    } catch (const decks::PlanError& e) {
        throw DeckError(fmt::format("gen two-tool: {}", e.what()));
    }
    for (const decks::TwoToolPass& p : job.deck.passes) {
        d.passes.push_back({p.tool, p.radius_in, p.offset_in});
    }
    d.options.cutter_radius_in = job.deck.passes.back().radius_in; // the finish
    d.work_zero_in = job.deck.work_zero_in;
    d.deck_cards = fingerprint.cards();
    d.deck_fingerprint = fingerprint.hex();
    if (!job.job_file.empty()) {
        write_file(job.job_file, decks::job_to_json(d));
    }
    return job;
}

namespace {

// What print_summary says, for --json.
Json summary_json(const GenFlags& f, const GeneratedJob& job) {
    const auto& description = job.description;
    Json doc = json_document("gen");
    doc["generator"] = "airfoil";
    doc["job"] = description.kind == decks::JobKind::wing ? "wing" : "template";
    doc["deck"] = f.output;
    doc["format"] = std::string(
        cardreader::format_name(deck_options(f.output, f.to, DeckFlags{}, "--to").format));
    doc["job_file"] = file_or_null(job.job_file);
    doc["centres"] = file_or_null(f.centres);
    doc["airfoil"] = description.airfoil;
    doc["chord_in"] = f.chord_in;
    doc["cutter_radius_in"] = f.radius_in;
    if (description.kind == decks::JobKind::wing) {
        const auto& w = job.wing;
        doc["span_in"] = f.span_in;
        doc["taper"] = f.taper;
        doc["sweep_deg"] = f.sweep_deg;
        doc["cards"] = w.cards.size();
        doc["stations"] = w.stations.size();
        doc["largest_scallop_in"] = fine_length(w.planned_leftover_in);
        doc["zero_in"] = {{"cross", fine_length(w.zero.x())},
                          {"table", fine_length(w.zero.y())},
                          {"vertical", fine_length(w.zero.z())}};
    } else {
        const auto& d = job.deck;
        doc["surface"] = f.surface;
        doc["female"] = f.female;
        doc["cards"] = d.cards.size();
        doc["stations"] = d.stations.size();
        doc["approach_cards"] = d.cards.size() + 1 - d.stations.size();
        doc["corner_cards"] = d.corner_cards;
        doc["largest_scallop_in"] = fine_length(d.planned_leftover_in);
        doc["largest_dip_in"] = fine_length(d.planned_gouge_in);
        doc["work_zero_in"] = {{"table", fine_length(d.work_zero_in.x())},
                               {"cross", fine_length(d.work_zero_in.y())}};
    }
    return doc;
}

void print_summary(const GenFlags& f, const GeneratedJob& job) {
    const auto& description = job.description;
    std::FILE* out = message_stream();
    if (description.kind == decks::JobKind::wing) {
        const auto& w = job.wing;
        fmt::print(out,
                   "{} tapered wing, root chord {:.3f} in, span {:.3f} in, taper {:.3f}, sweep "
                   "{:.1f} deg, cutter radius {:.3f} in\n",
                   description.airfoil, f.chord_in, f.span_in, f.taper, f.sweep_deg, f.radius_in);
        fmt::print(out, "  stations         {} (one cut along the span each)\n", w.stations.size());
        fmt::print(out, "  cards            {} (set the section, then plunge and traverse)\n",
                   w.cards.size());
        fmt::print(out, "  largest scallop  {:.5f} in (planned, root and tip sections)\n",
                   w.planned_leftover_in);
        fmt::print(out, "  zero             cross {:.3f}, table {:.3f}, vertical {:.3f} in\n",
                   w.zero.x(), w.zero.y(), w.zero.z());
    } else {
        const auto& d = job.deck;
        fmt::print(out, "{} template, chord {:.3f} in, cutter radius {:.3f} in, {} surface{}\n",
                   description.airfoil, f.chord_in, f.radius_in, f.surface,
                   f.female ? ", female" : "");
        fmt::print(out, "  stations         {}\n", d.stations.size());
        fmt::print(out, "  cards            {} ({} to approach, {} slowed for a corner)\n",
                   d.cards.size(), d.cards.size() + 1 - d.stations.size(), d.corner_cards);
        fmt::print(out, "  largest scallop  {:.5f} in (planned, before quantising to 0.001 in)\n",
                   d.planned_leftover_in);
        fmt::print(out, "  largest dip      {:.5f} in (staircase traverse into the design)\n",
                   d.planned_gouge_in);
        fmt::print(out,
                   "  work zero        table {:.3f} in, cross slide {:.3f} in (the leading edge)\n",
                   d.work_zero_in.x(), d.work_zero_in.y());
    }
    fmt::print(out, "  wrote            {}\n", files_written(f.output, job.job_file, f.centres));
}

ExitCode run_gen(const GenFlags& f) {
    if (f.naca.empty() == f.dat.empty()) {
        throw DeckError("gen airfoil: give exactly one of --naca DIGITS or --dat FILE");
    }
    decks::JobDescription description;
    description.airfoil = airfoil_source(f.naca, f.dat);
    description.closed_trailing_edge = f.closed_te;
    description.options = options_from(f);
    if (f.job == "wing") {
        if (f.surface != "upper" || f.female) {
            throw DeckError("gen airfoil: the wing job cuts the upper surface of a male wing (Fig. "
                            "5); turn the wing over for the lower surface");
        }
        description.kind = decks::JobKind::wing;
        description.wing.root_chord_in = f.chord_in;
        description.wing.span_in = f.span_in;
        description.wing.taper = f.taper;
        description.wing.sweep_deg = f.sweep_deg;
        description.wing.cutter_radius_in = f.radius_in;
        description.wing.stations = f.stations;
        description.wing.spacing = description.options.spacing;
        description.wing.scallop_in = f.scallop_in;
    }
    if (f.scallop_given && !(f.scallop_in > 0 && std::isfinite(f.scallop_in))) {
        throw DeckError(fmt::format("gen airfoil: --scallop {}: the scallop (the cusp left "
                                    "standing between two passes) must be a positive number of "
                                    "inches, e.g. 0.002",
                                    f.scallop_in));
    }
    refuse_json_beside_standard_output("gen airfoil", f.json, "-o", f.output);
    refuse_json_beside_standard_output("gen airfoil", f.json, "--centres", f.centres);
    refuse_json_beside_standard_output("gen airfoil", f.json, "--job-out", f.job_out);
    FilePlan plan = generator_plan(f.profile, f.output, f.job_out, false);
    plan.read("--dat", airfoil_file_read(description.airfoil));
    plan.write("--centres", f.centres);
    plan.check();
    const auto profile = load_profile(f.profile);
    ProgressLine progress; // on a terminal only
    const GeneratedJob job =
        generate_job(description, profile, f.output, f.to, f.centres, &progress, f.job_out);
    progress.clear();
    if (f.json) {
        print_json_document(summary_json(f, job));
    } else {
        print_summary(f, job);
    }
    return ExitCode::ok;
}

} // namespace

namespace {

struct TwoToolFlags {
    std::string naca;
    std::string dat;
    bool closed_te = false;
    double chord_in = 6.0;
    int stations = 60;
    std::string spacing = "cosine";
    double scallop_in = 0;
    bool scallop_given = false;
    double allowance_in = 0.010;
    std::string variant = "tripped";
    int rough_tool = 0;  // 0: the profile's first tool
    int finish_tool = 0; // 0: the profile's next tool after the rough one
    bool no_corner_slowdown = false;
    std::string output;
    std::string to;
    std::string job_out;
    std::string profile = "parsons-extended";
    bool json = false;
};

std::string card_range(const decks::TwoToolPass& p) {
    return fmt::format("cards {}-{}", p.first_card + 1, p.first_card + p.card_count);
}

Json two_tool_json(const TwoToolFlags& f, const GeneratedTwoToolJob& job) {
    const decks::TwoToolDeck& d = job.deck;
    Json doc = json_document("gen");
    doc["generator"] = "two-tool";
    doc["job"] = "two-tool";
    doc["deck"] = f.output;
    doc["format"] = std::string(
        cardreader::format_name(deck_options(f.output, f.to, DeckFlags{}, "--to").format));
    doc["job_file"] = file_or_null(job.job_file);
    doc["airfoil"] = job.description.airfoil;
    doc["chord_in"] = f.chord_in;
    doc["variant"] = job.description.variant;
    doc["allowance_in"] = f.allowance_in;
    doc["cards"] = d.cards.size();
    Json passes = Json::array();
    for (const decks::TwoToolPass& p : d.passes) {
        passes.push_back({{"tool", p.tool},
                          {"radius_in", p.radius_in},
                          {"offset_in", p.offset_in},
                          {"stations", p.deck.stations.size()},
                          {"first_card", p.first_card + 1},
                          {"cards", p.card_count}});
    }
    doc["passes"] = passes;
    doc["lift_card"] = d.lift_card + 1;
    doc["condition_card"] = d.condition_card + 1;
    doc["return_card"] = d.return_card + 1;
    doc["clearance_in"] = d.clearance / 1000.0;
    doc["return_from_in"] = d.return_from / 1000.0;
    doc["trip_position_in"] = d.trip_position / 1000.0;
    doc["return_move_seconds"] = time_s(d.return_move_s);
    doc["planned_lead_seconds"] = time_s(d.planned_lead_s);
    doc["work_zero_in"] = {{"table", fine_length(d.work_zero_in.x())},
                           {"cross", fine_length(d.work_zero_in.y())}};
    return doc;
}

void print_two_tool(const TwoToolFlags& f, const GeneratedTwoToolJob& job,
                    const axes::MachineProfile& profile) {
    const decks::TwoToolDeck& d = job.deck;
    std::FILE* out = message_stream();
    const auto& rough = d.passes[0];
    const auto& finish = d.passes[1];
    fmt::print(out, "{} two-tool template, chord {:.3f} in, upper surface, tool change {}\n",
               job.description.airfoil, f.chord_in,
               job.description.variant == "tripped" ? "tripped during the return move"
                                                    : "at the change position");
    fmt::print(out,
               "  pass 1           tool {} (radius {:.4f} in + allowance {:.4f} in): {} "
               "stations, {}\n",
               rough.tool, rough.radius_in, f.allowance_in, rough.deck.stations.size(),
               card_range(rough));
    fmt::print(out, "  lift             card {}: cross slide to {:.3f} in (the clearance)\n",
               d.lift_card + 1, d.clearance / 1000.0);
    fmt::print(out,
               "  condition card   card {}: table passing {:.3f} in counting down: tool "
               "change to tool {}\n",
               d.condition_card + 1, d.trip_position / 1000.0, finish.tool);
    fmt::print(out,
               "  return move      card {}: table {:.3f} -> 0.000 in (the change position), "
               "about {:.1f} s\n",
               d.return_card + 1, d.return_from / 1000.0, d.return_move_s);
    if (job.description.variant == "tripped") {
        fmt::print(out,
                   "  tool change      {:.1f} s, begun about {:.1f} s before the table stops "
                   "(planned)\n",
                   profile.actions.tool_change_s, d.planned_lead_s);
    } else {
        fmt::print(out, "  tool change      {:.1f} s, begun as the table stops\n",
                   profile.actions.tool_change_s);
    }
    fmt::print(out, "  pass 2           tool {} (radius {:.4f} in): {} stations, {}\n", finish.tool,
               finish.radius_in, finish.deck.stations.size(), card_range(finish));
    fmt::print(out,
               "  work zero        table {:.3f} in, cross slide {:.3f} in (the leading edge)\n",
               d.work_zero_in.x(), d.work_zero_in.y());
    fmt::print(out, "  wrote            {}\n", files_written(f.output, job.job_file));
}

int other_tool(const axes::MachineProfile& profile, int rough) {
    for (const axes::Tool& t : profile.tools) {
        if (t.number != rough) {
            return t.number;
        }
    }
    return rough; // refused by the generator: one tool for both passes
}

ExitCode run_two_tool(const TwoToolFlags& f) {
    if (f.naca.empty() == f.dat.empty()) {
        throw DeckError("gen two-tool: give exactly one of --naca DIGITS or --dat FILE");
    }
    if (f.scallop_given && !(f.scallop_in > 0 && std::isfinite(f.scallop_in))) {
        throw DeckError(fmt::format("gen two-tool: --scallop {}: give a positive number of "
                                    "inches, e.g. 0.002",
                                    f.scallop_in));
    }
    refuse_json_beside_standard_output("gen two-tool", f.json, "-o", f.output);
    refuse_json_beside_standard_output("gen two-tool", f.json, "--job-out", f.job_out);
    const std::string airfoil = airfoil_source(f.naca, f.dat);
    FilePlan plan = generator_plan(f.profile, f.output, f.job_out, false);
    plan.read("--dat", airfoil_file_read(airfoil));
    plan.check();
    const auto profile = load_profile(f.profile);
    decks::TwoToolOptions o;
    o.pass.chord_in = f.chord_in;
    o.pass.stations = f.stations;
    o.pass.spacing = f.spacing == "uniform" ? decks::Spacing::uniform : decks::Spacing::cosine;
    o.pass.scallop_in = f.scallop_in;
    o.pass.corner_slowdown = !f.no_corner_slowdown;
    o.allowance_in = f.allowance_in;
    o.variant =
        f.variant == "boundary" ? decks::ChangeVariant::boundary : decks::ChangeVariant::tripped;
    o.rough_tool = f.rough_tool != 0 ? f.rough_tool : profile.first_tool;
    o.finish_tool = f.finish_tool != 0 ? f.finish_tool : other_tool(profile, o.rough_tool);
    if (o.rough_tool != profile.first_tool) {
        throw DeckError(fmt::format("gen two-tool: --rough-tool {}: the machine starts with tool "
                                    "{} in the spindle (profile key first_tool), and the deck "
                                    "changes tools only between the passes",
                                    o.rough_tool, profile.first_tool));
    }
    const GeneratedTwoToolJob job =
        generate_two_tool_job(airfoil, f.closed_te, o, profile, f.output, f.to, f.job_out);
    if (f.json) {
        print_json_document(two_tool_json(f, job));
    } else {
        print_two_tool(f, job, profile);
    }
    return ExitCode::ok;
}

// --dat: a coordinate file, or a bundled airfoil by name (both offered by the completion).
void add_dat_option(CLI::App& cmd, std::string& dat) {
    std::string names;
    for (std::string_view name : kBundledAirfoils) {
        names += (names.empty() ? "" : ", ") + std::string(name);
    }
    cmd.add_option("--dat", dat,
                   "Airfoil coordinate file (Selig or Lednicer .dat), or a bundled one by name: " +
                       names)
        ->type_name(file_value({"dat"}) + "|" + std::string(kAirfoilValue));
}

void add_two_tool_command(CLI::App& gen, Command& selected) {
    auto flags = std::make_shared<TwoToolFlags>();
    CLI::App* cmd = gen.add_subcommand(
        "two-tool", "A template roughed with one tool and finished with another; the tool "
                    "change tripped by a condition card (an addition after EP 0640901)");
    cmd->add_option("--naca", flags->naca, "NACA 4-digit section, e.g. 2412");
    add_dat_option(*cmd, flags->dat);
    cmd->add_flag("--closed-te", flags->closed_te, "NACA: closed trailing edge (a4 = 0.1036)");
    cmd->add_option("--chord", flags->chord_in, "Chord, inches")->capture_default_str();
    cmd->add_option("--stations", flags->stations, "Stations per pass")->capture_default_str();
    cmd->add_option("--spacing", flags->spacing, "Station spacing along the chord")
        ->check(CLI::IsMember({"cosine", "uniform"}))
        ->capture_default_str();
    CLI::Option* scallop =
        cmd->add_option("--scallop", flags->scallop_in,
                        "Instead of --stations: keep each pass's scallop under this many inches");
    cmd->add_option("--allowance", flags->allowance_in,
                    "What the first tool leaves standing for the second, inches")
        ->capture_default_str();
    cmd->add_option("--variant", flags->variant,
                    "tripped: the change begins during the return move (the seed's point); "
                    "boundary: as the table reaches the change position")
        ->check(CLI::IsMember({"tripped", "boundary"}))
        ->capture_default_str();
    cmd->add_option("--rough-tool", flags->rough_tool,
                    "Tool of the first pass (default: the profile's first tool)");
    cmd->add_option("--finish-tool", flags->finish_tool,
                    "Tool of the second pass (default: the profile's next tool)");
    cmd->add_flag("--no-corner-slowdown", flags->no_corner_slowdown,
                  "Do not slow down at sharp turns of the path");
    cmd->add_option("-o,--output", flags->output, "The deck to write (.cbn .bin .csv)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Deck format: cbn, bin or listing")
        ->type_name(deck_formats());
    add_job_out_option(*cmd, flags->job_out);
    cmd->add_option("--profile", flags->profile,
                    "Machine profile (its tools and tool-change time); one that takes condition "
                    "cards")
        ->type_name(std::string(kProfileValue))
        ->capture_default_str();
    add_json_flag(*cmd, flags->json);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was written"}}) +
                "Examples:\n"
                "  parsons gen two-tool --naca 2412 --chord 6 --scallop 0.002 -o two-tool.csv\n"
                "  parsons run two-tool.csv --profile parsons-extended --cut cut.svg\n"
                "  parsons gen two-tool --naca 2412 --variant boundary -o boundary.cbn --json");
    cmd->callback([&selected, flags, scallop] {
        flags->scallop_given = scallop->count() > 0;
        selected = [flags] { return run_two_tool(*flags); };
    });
}

} // namespace

void add_gen_command(CLI::App& app, Command& selected) {
    auto flags = std::make_shared<GenFlags>();
    CLI::App* gen = app.add_subcommand("gen", "Generate a deck by the 1952 arithmetic");
    gen->require_subcommand(1);
    gen->footer(exit_codes_help({{ExitCode::ok, "the deck was written"}}));
    CLI::App* cmd = gen->add_subcommand(
        "airfoil", "A template deck for an airfoil: stations, cutter offset, one card a station");
    cmd->add_option("--naca", flags->naca, "NACA 4-digit section, e.g. 2412");
    add_dat_option(*cmd, flags->dat);
    cmd->add_flag("--closed-te", flags->closed_te, "NACA: closed trailing edge (a4 = 0.1036)");
    cmd->add_option("--chord", flags->chord_in, "Chord (the wing's root chord), inches")
        ->capture_default_str();
    cmd->add_option("--cutter-radius", flags->radius_in, "Cutter radius, inches")
        ->capture_default_str();
    cmd->add_option("--stations", flags->stations, "Stations per surface")->capture_default_str();
    cmd->add_option("--spacing", flags->spacing, "Station spacing along the chord")
        ->check(CLI::IsMember({"cosine", "uniform"}))
        ->capture_default_str();
    CLI::Option* scallop =
        cmd->add_option("--scallop", flags->scallop_in,
                        "Instead of --stations: keep the scallop under this many inches");
    cmd->add_option("--surface", flags->surface, "Which surface to cut")
        ->check(CLI::IsMember({"upper", "lower", "both"}))
        ->capture_default_str();
    cmd->add_flag("--female", flags->female, "The patent's Fig. 4 female template (other side)");
    cmd->add_option("--job", flags->job, "template (Fig. 4) or wing (Fig. 5, tapered)")
        ->check(CLI::IsMember({"template", "wing"}))
        ->capture_default_str();
    cmd->add_option("--span", flags->span_in, "Wing: span, inches")->capture_default_str();
    cmd->add_option("--taper", flags->taper, "Wing: tip chord / root chord")->capture_default_str();
    cmd->add_option("--sweep", flags->sweep_deg, "Wing: leading-edge sweep, degrees")
        ->capture_default_str();
    cmd->add_flag("--no-corner-slowdown", flags->no_corner_slowdown,
                  "Do not slow down at sharp turns of the path (to see why one should)");
    cmd->add_option("-o,--output", flags->output, "The deck to write (.cbn .bin .csv)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Deck format: cbn, bin or listing")
        ->type_name(deck_formats());
    cmd->add_option("--centres", flags->centres,
                    "Write x,y,cx,cy per station (work point and cutter centre, inches)")
        ->type_name(file_value({"csv"}));
    add_job_out_option(*cmd, flags->job_out);
    cmd->add_option("--profile", flags->profile, "Machine profile JSON")
        ->type_name(std::string(kProfileValue));
    add_json_flag(*cmd, flags->json);
    cmd->footer(
        exit_codes_help({{ExitCode::ok, "the deck was written"}}) +
        "Examples:\n"
        "  parsons gen airfoil --naca 2412 --chord 6 --cutter-radius 0.25 -o naca2412.cbn\n"
        "  parsons gen airfoil --dat decks/airfoils/clarky.dat --scallop 0.002 --surface both "
        "-o y.cbn\n"
        "  parsons gen airfoil --naca 0012 --job wing --chord 4 --span 5 --taper 0.6 "
        "--sweep 10 --scallop 0.002 -o wing.cbn\n"
        "  parsons gen airfoil --naca 2412 --scallop 0.002 -o naca2412.cbn --json\n"
        "  parsons run naca2412.cbn --cut cut.svg");
    cmd->callback([&selected, flags, scallop] {
        flags->scallop_given = scallop->count() > 0;
        selected = [flags] { return run_gen(*flags); };
    });
    add_two_tool_command(*gen, selected);
    add_press_feeder_command(*gen, selected);
    add_tapping_command(*gen, selected);
    add_gen_gcode_command(*gen, selected);
}

} // namespace parsons::cli
