// parsons gen press-feeder: the seed's Fig. 3 cycle (decks/press_feeder_job.hpp), its job file
// and its profile; the speed-only variant timed by running it (cli/gen_press_feeder.hpp).
#include "cli/gen_press_feeder.hpp"
#include "cli/support/value_names.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"
#include "cli/support/deck_files.hpp"
#include "cli/support/json_output.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"
#include "outputs/output_file.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "outputs/report/figures.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <memory>

namespace parsons::cli {
namespace {

using cardreader::DeckError;

class CardList : public cardreader::CardSource {
public:
    explicit CardList(std::vector<cardreader::Card> cards) : cards_(std::move(cards)) {}
    std::optional<cardreader::Card> next() override {
        if (next_ >= cards_.size()) {
            return std::nullopt;
        }
        return cards_[next_++];
    }

private:
    std::vector<cardreader::Card> cards_;
    std::size_t next_ = 0;
};

std::vector<cardreader::Card> punch(const std::vector<cardreader::CardOrders>& cards) {
    std::vector<cardreader::Card> out;
    for (const auto& c : cards) {
        auto e = cardreader::encode(c, cardreader::fig8_layout());
        if (!e) {
            throw DeckError(fmt::format("gen press-feeder: card {}: {}", c.number, *e.error));
        }
        out.push_back(e.card);
    }
    return out;
}

double wrap(double a) {
    return a - 360.0 * std::floor(a / 360.0);
}

// The feeder's zone entries in a run of two cycles at the nominal press speed.
struct Entries {
    std::vector<double> t;
    double start_deg = 0;
    double w = 0; // deg/s
    double angle(std::size_t i) const { return wrap(start_deg + w * t.at(i)); }
};

Entries entries_of(decks::PressFeederOptions o, const axes::MachineProfile& base) {
    o.cycles = 2;
    const decks::PressFeederDeck deck = decks::make_press_feeder_deck(o, base);
    const axes::MachineProfile profile = decks::press_feeder_profile(o, base);
    PressProof proof(profile.press, o.zone_edge_x_in, o.safe_height_in, deck.cycle_card);
    const relaylogic::RunResult r = run_cards(deck.cards, profile, &proof);
    if (r.stop) {
        throw DeckError(fmt::format("gen press-feeder: the {} deck stopped the machine while "
                                    "being timed: {}",
                                    o.speed_only ? "speed-only" : "position+speed",
                                    r.stop->message));
    }
    if (proof.entries_s().size() < 3) {
        throw DeckError("gen press-feeder: the feeder did not enter the die zone three times in "
                        "two cycles (a bug: please report it)");
    }
    return {proof.entries_s(), o.start_angle_deg, o.strokes_per_min * 6.0};
}

// The speed-only variant's timing: the start angle and the degrees of the retract and the
// carry-out such that at nominal speed its feeder enters the zone at the position deck's
// angles, cycle after cycle.
void time_speed_only(decks::PressFeederOptions& o, const axes::MachineProfile& base,
                     GeneratedPressJob& g) {
    decks::PressFeederOptions p = o;
    p.speed_only = false;
    const Entries pos = entries_of(p, base);
    g.insert_entry_deg = pos.angle(0);
    g.takeout_entry_deg = pos.angle(1);
    g.revolutions_per_cycle =
        std::max(1, static_cast<int>(std::lround((pos.t.at(2) - pos.t.at(0)) * pos.w / 360.0)));
    const double w = pos.w;
    const double gap_out = wrap(g.takeout_entry_deg - g.insert_entry_deg);
    const double gap_in = 360.0 * g.revolutions_per_cycle - gap_out;
    decks::PressFeederOptions s = o;
    s.speed_only = true;
    for (int i = 0; i < 8; ++i) {
        const Entries e = entries_of(s, base);
        const double err_out = gap_out - (e.t.at(1) - e.t.at(0)) * w;
        const double err_in = gap_in - (e.t.at(2) - e.t.at(1)) * w;
        s.start_angle_deg = wrap(g.insert_entry_deg - w * e.t.at(0));
        if (std::abs(err_out) < 0.2 && std::abs(err_in) < 0.2) {
            break;
        }
        s.retract_deg += err_out;
        s.carry_out_deg += err_in;
        if (!(s.retract_deg > 1 && s.carry_out_deg > 1 && s.retract_deg < 359 &&
              s.carry_out_deg < 359)) {
            throw DeckError(fmt::format("gen press-feeder: the speed-only variant cannot be timed "
                                        "to the press: its fixed-speed moves and card cycles "
                                        "take {} the time between the zone entries",
                                        s.retract_deg > 1 ? "less than" : "more than"));
        }
    }
    o.start_angle_deg = s.start_angle_deg;
    if (o.speed_only) {
        o.retract_deg = s.retract_deg;
        o.carry_out_deg = s.carry_out_deg;
    }
}

} // namespace

relaylogic::RunResult run_cards(const std::vector<cardreader::CardOrders>& cards,
                                const axes::MachineProfile& profile,
                                relaylogic::MachineObserver* observer) {
    CardList deck(punch(cards));
    relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
    if (observer != nullptr) {
        cabinet.attach(observer);
    }
    return cabinet.run(deck);
}

GeneratedPressJob generate_press_job(decks::PressFeederOptions options,
                                     const axes::MachineProfile& base, const std::string& output,
                                     const std::string& to, const std::string& job_out) {
    GeneratedPressJob g;
    try {
        decks::make_press_feeder_deck(options, base); // the geometry first: its errors first
        time_speed_only(options, base, g);
        g.deck = decks::make_press_feeder_deck(options, base);
    } catch (const decks::JobError& e) {
        throw DeckError(e.what());
    } catch (const decks::PlanError& e) {
        throw DeckError(fmt::format("gen press-feeder: {}", e.what()));
    }
    g.profile = decks::press_feeder_profile(options, base);
    g.job.options = options;
    g.job.variant = options.speed_only ? "speed-only" : "position+speed";
    g.job.cycle_card = g.deck.cycle_card;
    g.job.deck_cards = static_cast<std::int64_t>(g.deck.cards.size());
    if (output.empty()) {
        return g;
    }
    g.job_file = job_file_for(output, job_out);
    g.job.profile_file = profile_file_for(g.job_file);
    const auto deck_opts = deck_options(output, to, DeckFlags{}, "--to");
    OutputFile deck_file(output);
    auto sink = cardreader::open_card_sink(deck_file.stream(), deck_opts);
    for (const auto& card : punch(g.deck.cards)) {
        sink->write(card);
    }
    deck_file.commit();
    if (!g.job_file.empty()) {
        write_file(g.job_file, decks::press_job_to_json(g.job));
    }
    if (!g.job.profile_file.empty()) {
        write_file(g.job.profile_file, axes::profile_to_json(g.profile));
    }
    return g;
}

namespace {

struct PressFeederFlags {
    decks::PressFeederOptions o;
    std::string output;
    std::string to;
    std::string job_out;
    std::string profile = "parsons-extended";
    bool json = false;
};

Json press_json(const PressFeederFlags& f, const GeneratedPressJob& g) {
    Json doc = json_document("gen");
    doc["generator"] = "press-feeder";
    doc["job"] = "press-feeder";
    doc["variant"] = g.job.variant;
    doc["deck"] = f.output;
    doc["job_file"] = file_or_null(g.job_file);
    doc["profile_file"] = file_or_null(g.job.profile_file);
    doc["cards"] = g.deck.cards.size();
    doc["cycles"] = g.job.options.cycles;
    doc["strokes_per_min"] = g.job.options.strokes_per_min;
    doc["start_angle_deg"] = angle_deg(g.job.options.start_angle_deg);
    doc["insert_entry_deg"] = angle_deg(g.insert_entry_deg);
    doc["takeout_entry_deg"] = angle_deg(g.takeout_entry_deg);
    doc["revolutions_per_cycle"] = g.revolutions_per_cycle;
    Json moves = Json::array();
    for (const auto& m : g.deck.moves) {
        moves.push_back({{"move", m.name},
                         {"sync_card", m.card},
                         {"degrees", angle_deg(m.degrees)},
                         {"travel_per_pulse_in", fine_length(m.travel_per_pulse / 1e5)},
                         {"speed_in_per_min", decimals(m.speed_in_per_min, 4)}});
    }
    doc["moves"] = moves;
    return doc;
}

void print_press(const PressFeederFlags& f, const GeneratedPressJob& g) {
    std::FILE* out = message_stream();
    const auto& o = g.job.options;
    const auto low = axes::Press(g.profile.press).angles_at_height(o.safe_height_in);
    fmt::print(out,
               "press-feeder job ({}), {} cycles, press {:g} strokes a minute from crank {:.1f} "
               "deg\n",
               g.job.variant, o.cycles, o.strokes_per_min, o.start_angle_deg);
    fmt::print(out,
               "  feeder X       retracted {:.3f}, die zone past {:.3f}, insert {:.3f} in; Y "
               "carry-in {:.3f}, press {:.3f}, carry-out {:.3f} in\n",
               o.retracted_x_in, o.zone_edge_x_in, o.insert_x_in, o.carry_in_y_in, o.press_y_in,
               o.carry_out_y_in);
    if (low) {
        fmt::print(out,
                   "  die 20         below its safe height {:.3f} in from {:.1f} to {:.1f} deg\n",
                   o.safe_height_in, low->first, low->second);
    }
    for (const auto& m : g.deck.moves) {
        fmt::print(out,
                   "  {:<14} sync card {}: F {:.5f} in a pulse over {:.1f} deg ({:.2f} in/min)\n",
                   m.name, m.card, m.travel_per_pulse * 1e-5, m.degrees, m.speed_in_per_min);
    }
    fmt::print(out,
               "  zone entries   insert at {:.1f} deg, take-out at {:.1f} deg (position deck, "
               "nominal speed; {} revolution{} a cycle)\n",
               g.insert_entry_deg, g.takeout_entry_deg, g.revolutions_per_cycle,
               g.revolutions_per_cycle == 1 ? "" : "s");
    fmt::print(out, "  wrote          {}\n",
               files_written(f.output, g.job_file, g.job.profile_file));
}

ExitCode run_press_feeder(const PressFeederFlags& f) {
    refuse_json_beside_standard_output("gen press-feeder", f.json, "-o", f.output);
    refuse_json_beside_standard_output("gen press-feeder", f.json, "--job-out", f.job_out);
    generator_plan(f.profile, f.output, f.job_out, true).check();
    const auto profile = load_profile(f.profile);
    const GeneratedPressJob g = generate_press_job(f.o, profile, f.output, f.to, f.job_out);
    if (f.json) {
        print_json_document(press_json(f, g));
    } else {
        print_press(f, g);
    }
    return ExitCode::ok;
}

} // namespace

void add_press_feeder_command(CLI::App& gen, Command& selected) {
    auto flags = std::make_shared<PressFeederFlags>();
    auto& o = flags->o;
    CLI::App* cmd = gen.add_subcommand(
        "press-feeder", "A press feeder synchronised to a rotary press: the cycle of EP "
                        "0436887's Fig. 3 (press synchronisation, an addition)");
    cmd->add_option("--retracted-x", o.retracted_x_in, "Feeder X retracted, inches")
        ->capture_default_str();
    cmd->add_option("--zone-edge-x", o.zone_edge_x_in, "The die zone begins past this X, inches")
        ->capture_default_str();
    cmd->add_option("--insert-x", o.insert_x_in, "Feeder X in the die, inches")
        ->capture_default_str();
    cmd->add_option("--carry-in-y", o.carry_in_y_in, "The carry-in conveyor's Y, inches")
        ->capture_default_str();
    cmd->add_option("--press-y", o.press_y_in, "The press line's Y, inches")->capture_default_str();
    cmd->add_option("--carry-out-y", o.carry_out_y_in, "The carry-out conveyor's Y, inches")
        ->capture_default_str();
    cmd->add_option("--safe-height", o.safe_height_in,
                    "Die 20 clears the feeder above this height over bottom dead centre, inches")
        ->capture_default_str();
    cmd->add_option("--cycles", o.cycles, "Passes of the cycle (the loop card)")
        ->capture_default_str();
    cmd->add_option("--strokes-per-min", o.strokes_per_min, "The press's nominal speed")
        ->capture_default_str();
    cmd->add_option("--insert-angle", o.insert_angle_deg, "R of the insert, crank degrees")
        ->capture_default_str();
    cmd->add_option("--insert-deg", o.insert_deg, "Crank degrees the insert is given")
        ->capture_default_str();
    cmd->add_option("--retract-deg", o.retract_deg, "Crank degrees the retract is given")
        ->capture_default_str();
    cmd->add_option("--takeout-angle", o.takeout_angle_deg, "R of the take-out, crank degrees")
        ->capture_default_str();
    cmd->add_option("--takeout-deg", o.takeout_deg, "Crank degrees the take-out is given")
        ->capture_default_str();
    cmd->add_option("--carry-out-deg", o.carry_out_deg, "Crank degrees the carry-out is given")
        ->capture_default_str();
    cmd->add_flag("--speed-only", o.speed_only,
                  "The seed's Fig. 7 (conventional): no position sync, timed to the nominal press");
    cmd->add_option("-o,--output", flags->output, "The deck to write (.cbn .bin .csv)")
        ->type_name(std::string(kDeckValue))
        ->required();
    cmd->add_option("--to", flags->to, "Deck format: cbn, bin or listing")
        ->type_name(deck_formats());
    add_job_out_option(*cmd, flags->job_out);
    cmd->add_option("--profile", flags->profile,
                    "Machine profile the job's profile starts from (one with press sync)")
        ->type_name(std::string(kProfileValue))
        ->capture_default_str();
    add_json_flag(*cmd, flags->json);
    cmd->footer(exit_codes_help({{ExitCode::ok, "the deck was written"}}) +
                "Examples:\n"
                "  parsons gen press-feeder -o feeder.csv\n"
                "  parsons run feeder.csv --profile feeder.csv.profile.json --press-proof "
                "feeder.csv.job.json\n"
                "  parsons gen press-feeder --speed-only -o conventional.csv");
    cmd->callback([&selected, flags] { selected = [flags] { return run_press_feeder(*flags); }; });
}

} // namespace parsons::cli
