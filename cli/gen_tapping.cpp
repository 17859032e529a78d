// parsons gen tapping: a plate of tapped holes with two taps on two spindle heads
// (decks/tapping_job.hpp), its job file and its profile (cli/gen_tapping.hpp).
#include "cli/gen_tapping.hpp"
#include "cli/support/value_names.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/json_output.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"
#include "outputs/output_file.hpp"
#include "outputs/report/figures.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <memory>

namespace parsons::cli {
using cardreader::DeckError;

GeneratedTappingJob generate_tapping_job(const decks::TappingOptions& options,
                                         const axes::MachineProfile& base,
                                         const std::string& output, const std::string& to,
                                         const std::string& job_out) {
    GeneratedTappingJob g;
    try {
        g.deck = decks::make_tapping_deck(options, base);
    } catch (const decks::JobError& e) {
        throw DeckError(e.what());
    } catch (const decks::PlanError& e) {
        throw DeckError(fmt::format("gen tapping: {}", e.what()));
    }
    g.profile = decks::tapping_profile(options, base);
    decks::TappingJob& job = g.job;
    job.ratio_source = options.ratio_source;
    job.rows = options.rows;
    job.holes_per_row = options.holes_per_row;
    job.clearance_in = options.clearance_in;
    job.thread_depth_in = options.thread_depth_in;
    job.tolerance_percent = options.tolerance_percent;
    job.chamfer_revs = g.profile.spindle.chamfer_revs;
    job.holes = g.deck.holes;
    job.deck_cards = static_cast<std::int64_t>(g.deck.cards.size());
    if (output.empty()) {
        return g;
    }
    g.job_file = job_file_for(output, job_out);
    job.profile_file = profile_file_for(g.job_file);
    write_cards(g.deck.cards, output, to, nullptr, "gen tapping");
    if (!g.job_file.empty()) {
        write_file(g.job_file, decks::tapping_job_to_json(job));
    }
    if (!job.profile_file.empty()) {
        write_file(job.profile_file, axes::profile_to_json(g.profile));
    }
    return g;
}

namespace {

struct TappingFlags {
    decks::TappingOptions o;
    std::string ratio_source = "transferred";
    int rpm = 0;
    bool rpm_given = false; // no --rpm: the fastest each tap allows
    std::string output;
    std::string to;
    std::string job_out;
    std::string profile = "parsons-extended";
    bool json = false;
};

Json tapping_json(const TappingFlags& f, const GeneratedTappingJob& g) {
    Json doc = json_document("gen");
    doc["generator"] = "tapping";
    doc["job"] = "tapping";
    doc["ratio_source"] = decks::ratio_source_name(g.job.ratio_source);
    doc["deck"] = f.output;
    doc["job_file"] = file_or_null(g.job_file);
    doc["profile_file"] = file_or_null(g.job.profile_file);
    doc["cards"] = g.deck.cards.size();
    Json holes = Json::array();
    for (const auto& h : g.deck.holes) {
        holes.push_back({{"hole", h.hole},
                         {"card", h.card},
                         {"table_in", h.x_in},
                         {"cross_in", h.y_in},
                         {"tool", h.tool},
                         {"tap_pitch_in", h.tap_pitch_in},
                         {"head_ratio", decimals(h.head_ratio, 6)},
                         {"rpm", h.rpm},
                         {"feed_in_per_min", decimals(h.feed_in_per_min, 4)}});
    }
    doc["holes"] = holes;
    return doc;
}

void print_tapping(const TappingFlags& f, const GeneratedTappingJob& g) {
    std::FILE* out = message_stream();
    const auto& o = f.o;
    fmt::print(out, "tapping job: {} hole{} in {} row{}, the ratio into memory 12a {} ({} cards)\n",
               g.deck.holes.size(), g.deck.holes.size() == 1 ? "" : "s", o.rows,
               o.rows == 1 ? "" : "s", decks::ratio_source_name(g.job.ratio_source),
               g.deck.cards.size());
    fmt::print(out,
               "  vertical       tap from {:.3f} ({:.3f} in above the surface at {:.3f}) to a "
               "thread {:.3f} in deep; tolerance {:g} % of the pitch\n",
               o.surface_in + o.clearance_in, o.clearance_in, o.surface_in, o.thread_depth_in,
               o.tolerance_percent);
    if (o.retract > 1) {
        fmt::print(out,
                   "  retract        every tap comes out at {} x S, the feed following (column "
                   "20; an addition after rigid tapping)\n",
                   o.retract);
    }
    if (o.peck_in > 0) {
        fmt::print(out,
                   "  peck           every tap goes in {:.3f} in a pass, out to its start between "
                   "(columns 21-24; an addition after rigid peck tapping)\n",
                   o.peck_in);
    }
    if (o.index_wait) {
        fmt::print(out, "  index wait     every tap's feed waits for encoder 32's index (column "
                        "19; an addition after rigid tapping)\n");
    }
    for (const auto& h : g.deck.holes) {
        fmt::print(out,
                   "  hole {:<9} card {:04}: table {:.3f}, cross {:.3f}; tool {} (pitch {:.5f} "
                   "in, ratio {:.4f}) at S {} rev/min, feed {:.2f} in/min\n",
                   h.hole, h.card, h.x_in, h.y_in, h.tool, h.tap_pitch_in, h.head_ratio, h.rpm,
                   h.feed_in_per_min);
    }
    fmt::print(out, "  wrote          {}\n",
               files_written(f.output, g.job_file, g.job.profile_file));
}

ExitCode run_tapping(TappingFlags f) {
    refuse_json_beside_standard_output("gen tapping", f.json, "-o", f.output);
    const auto source = decks::ratio_source_named(f.ratio_source);
    if (!source) {
        throw DeckError(fmt::format("gen tapping: --ratio-source {}: give transferred or stored",
                                    f.ratio_source));
    }
    f.o.ratio_source = *source;
    if (f.rpm_given) { // --rpm 0 is judged as any S, not taken as not given
        f.o.rpm = f.rpm;
    }
    refuse_json_beside_standard_output("gen tapping", f.json, "--job-out", f.job_out);
    generator_plan(f.profile, f.output, f.job_out, true).check();
    const auto profile = load_profile(f.profile);
    const GeneratedTappingJob g = generate_tapping_job(f.o, profile, f.output, f.to, f.job_out);
    if (f.json) {
        print_json_document(tapping_json(f, g));
    } else {
        print_tapping(f, g);
    }
    return ExitCode::ok;
}

} // namespace

void add_tapping_command(CLI::App& gen, Command& selected) {
    auto flags = std::make_shared<TappingFlags>();
    auto& o = flags->o;
    CLI::App* cmd = gen.add_subcommand(
        "tapping", "A plate of tapped holes, two taps of different pitch on two spindle heads: "
                   "the feed in step with the tool through the gear ratio (spindle "
                   "synchronisation after EP 0360190, an addition)");
    cmd->add_option("--rows", o.rows, "Rows of holes (each row one tool, in turn)")
        ->capture_default_str();
    cmd->add_option("--holes-per-row", o.holes_per_row, "Holes in a row")->capture_default_str();
    cmd->add_option("--first-x", o.first_x_in, "The first hole's table position, inches")
        ->capture_default_str();
    cmd->add_option("--first-y", o.first_y_in, "The first row's cross-slide position, inches")
        ->capture_default_str();
    cmd->add_option("--spacing-x", o.spacing_x_in, "Between the holes of a row, inches")
        ->capture_default_str();
    cmd->add_option("--spacing-y", o.spacing_y_in, "Between the rows, inches")
        ->capture_default_str();
    cmd->add_option("--surface", o.surface_in,
                    "The plate's surface on the vertical (the feed axis), inches")
        ->capture_default_str();
    cmd->add_option("--clearance", o.clearance_in,
                    "The tap starts this far above the surface (motor 27 runs up), inches")
        ->capture_default_str();
    cmd->add_option("--thread-depth", o.thread_depth_in, "The thread's depth, inches")
        ->capture_default_str();
    cmd->add_option("--tools", o.tools, "The tools of the rows, in turn (each a head with a tap)")
        ->delimiter(',')
        ->capture_default_str();
    const CLI::Option* rpm =
        cmd->add_option("--rpm", flags->rpm,
                        "Motor 27's speed S for every hole, 1 to 9999 rev/min (default: the "
                        "fastest each tap allows)");
    cmd->add_option("--tolerance", o.tolerance_percent,
                    "The thread proof's tolerance, percent of the pitch")
        ->capture_default_str();
    cmd->add_option("--ratio-source", flags->ratio_source,
                    "How the gear ratio reaches memory 12a in the job's profile: transferred (PC "
                    "130 sends it after each head exchange) or stored (per tool, in advance)")
        ->type_name(one_of({decks::ratio_source_name(axes::RatioSource::transferred),
                            decks::ratio_source_name(axes::RatioSource::stored)}))
        ->capture_default_str();
    cmd->add_flag("--index-wait", o.index_wait,
                  "Every tap waits for encoder 32's index before its feed starts, so that "
                  "every pass starts at one tool angle (rigid tapping, an addition)");
    cmd->add_option("--retract", o.retract,
                    "Every tap comes out at this multiple of S, the feed following so the pitch "
                    "holds (rigid tapping's faster retract, an addition; 1 = out at S)")
        ->check(CLI::Range(1, cardreader::kMaxTapRetract))
        ->capture_default_str();
    cmd->add_option("--peck", o.peck_in,
                    "Every tap pecks: in this far (inches) a pass, out to its start, in again, "
                    "the feed on one helix (rigid peck tapping, an addition; 0 = one pass)")
        ->capture_default_str();
    cmd->add_option("-o,--output", flags->output, "The deck to write (.cbn .bin .csv)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Deck format: cbn, bin or listing")
        ->type_name(deck_formats());
    add_job_out_option(*cmd, flags->job_out);
    cmd->add_option("--profile", flags->profile,
                    "Machine profile the job's profile starts from (one with spindle heads)")
        ->type_name(std::string(kProfileValue))
        ->capture_default_str();
    add_json_flag(*cmd, flags->json);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was written"}}) +
                "Examples:\n"
                "  parsons gen tapping -o plate.csv\n"
                "  parsons run plate.csv --thread-proof plate.csv.job.json\n"
                "  parsons gen tapping --ratio-source stored -o plate-stored.csv");
    cmd->callback([&selected, flags, rpm] {
        flags->rpm_given = rpm->count() > 0;
        selected = [flags] { return run_tapping(*flags); };
    });
}

} // namespace parsons::cli
