// The two-tool job (decks/two_tool_job.hpp): the job that shows the point of EP 0640901
// (condition cards, an addition). Both variants run through under parsons-extended at both
// paces and leave the same part; the boundary deck takes exactly as much longer as the tripped
// deck's tool change overlapped its return move.
//
// Mutation check, kept in mind when writing "the difference is the overlap": a cabinet that fed
// the next card without waiting for the acknowledgement would run both decks in the same time
// (difference 0, overlap about 6 s); one that started the change late (at the card's end) would
// make the tripped deck as slow as the boundary one and its overlap 0. Either fails the test.
#include "tests/machine_support.hpp"

#include "outputs/proofs/two_tool_proof.hpp"

#include "decks/job_file.hpp"
#include "decks/two_tool_job.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace parsons;
using namespace parsons::decks;
using parsons::test::run_orders;

namespace {

constexpr double kTwoToolQuantisation = 0.0007 + 0.00025; // as template_job_test.cpp

struct Job {
    TwoToolDeck deck;
    JobDescription description;
};

Job make_job(ChangeVariant variant) {
    const auto profile = axes::extended_profile();
    TwoToolOptions o;
    o.pass.chord_in = 6.0;
    o.pass.scallop_in = 0.002;
    o.variant = variant;
    Job job;
    const auto airfoil = naca4("2412");
    job.deck = make_two_tool_deck(*airfoil, o, profile);
    JobDescription& d = job.description;
    d.airfoil = "naca 2412";
    d.options = o.pass;
    d.options.cutter_radius_in = job.deck.passes[1].radius_in;
    d.work_zero_in = job.deck.work_zero_in;
    d.allowance_in = o.allowance_in;
    d.variant = std::string(variant_name(variant));
    for (const TwoToolPass& p : job.deck.passes) {
        d.passes.push_back({p.tool, p.radius_in, p.offset_in});
    }
    return job;
}

const Job& job_of(ChangeVariant v) {
    static const std::map<ChangeVariant, Job> jobs = {
        {ChangeVariant::boundary, make_job(ChangeVariant::boundary)},
        {ChangeVariant::tripped, make_job(ChangeVariant::tripped)}};
    return jobs.at(v);
}

relaylogic::RunResult run(ChangeVariant v, relaylogic::Pace pace,
                          relaylogic::MachineObserver* observer = nullptr) {
    return run_orders(job_of(v).deck.cards, axes::extended_profile(), observer, {}, pace);
}

} // namespace

TEST_CASE("Two-tool job: the deck is pass 1, lift, condition card, return move, pass 2, cards "
          "numbered from 1, every check the travel since the card before",
          "[two-tool][decks]") {
    const Job& tripped = job_of(ChangeVariant::tripped);
    const Job& boundary = job_of(ChangeVariant::boundary);
    const TwoToolDeck& d = tripped.deck;
    REQUIRE(d.cards.size() == boundary.deck.cards.size());
    CHECK(d.passes[0].card_count == d.lift_card);
    CHECK(d.condition_card == d.lift_card + 1);
    CHECK(d.return_card == d.condition_card + 1);
    CHECK(d.passes[1].first_card == d.return_card + 1);
    CHECK(d.passes[1].first_card + d.passes[1].card_count == d.cards.size());
    CHECK(d.passes[0].tool == 1);
    CHECK(d.passes[0].offset_in == Approx(0.26));
    CHECK(d.passes[1].tool == 2);
    CHECK(d.passes[1].offset_in == Approx(0.125));

    std::array<int, 5> at{};
    for (std::size_t i = 0; i < d.cards.size(); ++i) {
        const auto& c = d.cards[i];
        INFO("card " << i + 1);
        CHECK(c.number == static_cast<int>(i + 1));
        if (i != d.condition_card) { // the two variants differ only on the condition card
            CHECK(c == boundary.deck.cards[i]);
        }
        if (c.kind == cardreader::CardKind::condition) {
            CHECK(i == d.condition_card);
            continue;
        }
        for (cardreader::Axis a : cardreader::kAxes) {
            const auto& o = c.axis(a);
            CHECK(o.check == std::abs(o.stop - at.at(cardreader::axis_index(a))));
            at.at(cardreader::axis_index(a)) = o.stop;
        }
    }
    // The return move: the table alone, last in the sequence, back to the change position.
    const auto& back = d.cards[d.return_card];
    CHECK(back.axis(cardreader::Axis::table).stop == 0);
    CHECK(back.axis(cardreader::Axis::table).check == d.return_from);
    CHECK(back.axis(cardreader::Axis::table).sequence == 0b10000);
    CHECK(back.axis(cardreader::Axis::cross).check == 0);
    CHECK(back.axis(cardreader::Axis::cross).stop == d.clearance);
    // Pass 2 starts from where the machine stands after the change.
    const auto& first2 = d.cards[d.passes[1].first_card];
    CHECK(first2.axis(cardreader::Axis::table).check == first2.axis(cardreader::Axis::table).stop);
    CHECK(first2.axis(cardreader::Axis::cross).check ==
          std::abs(first2.axis(cardreader::Axis::cross).stop - d.clearance));

    const auto& cond = d.cards[d.condition_card];
    REQUIRE(cond.kind == cardreader::CardKind::condition);
    REQUIRE(cond.condition_count == 1);
    CHECK(cond.conditions[0].axis == cardreader::Axis::table);
    CHECK(cond.conditions[0].sense == cardreader::PassingSense::reverse);
    CHECK(cond.conditions[0].action == cardreader::ActionKind::tool_change);
    CHECK(cond.conditions[0].parameter == 2);
    CHECK(cond.conditions[0].position == d.trip_position);
    CHECK(d.trip_position > 0);
    CHECK(d.trip_position < d.return_from);
    CHECK(d.planned_lead_s == Approx(6.0).margin(0.2));
    CHECK(boundary.deck.cards[d.condition_card].conditions[0].position == 0);
}

TEST_CASE("Two-tool job: both variants complete under parsons-extended at both paces with the "
          "same end positions, and boundary - tripped machine time is the tripped change's "
          "overlap with the return move",
          "[two-tool][condition]") {
    using relaylogic::Pace;
    std::map<std::pair<ChangeVariant, Pace>, relaylogic::RunResult> runs;
    for (ChangeVariant v : {ChangeVariant::boundary, ChangeVariant::tripped}) {
        for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
            const auto r = run(v, pace);
            INFO(variant_name(v) << (pace == Pace::fast_forward ? " fast-forward" : " impulse"));
            REQUIRE(r.completed);
            REQUIRE_FALSE(r.stop);
            CHECK(r.cards_read == static_cast<long>(job_of(v).deck.cards.size()));
            CHECK(r.tool_in_spindle == 2);
            REQUIRE(r.actions.size() == 1);
            CHECK(r.actions[0].action == cardreader::ActionKind::tool_change);
            CHECK(r.actions[0].motion_card == static_cast<long>(job_of(v).deck.return_card + 1));
            for (const auto& axis : r.axes) {
                CHECK(axis.lost_steps == 0);
                CHECK(std::abs(axis.error_in) < 0.0005);
            }
            runs[{v, pace}] = r;
        }
    }
    const auto& reference = runs.begin()->second;
    for (const auto& [key, r] : runs) {
        for (std::size_t a = 0; a < r.axes.size(); ++a) {
            CHECK(r.axes[a].counter_in == reference.axes[a].counter_in);
            CHECK(r.axes[a].real_in == reference.axes[a].real_in);
        }
    }
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        INFO((pace == Pace::fast_forward ? "fast-forward" : "impulse level"));
        const auto& b = runs.at({ChangeVariant::boundary, pace});
        const auto& t = runs.at({ChangeVariant::tripped, pace});
        // Boundary: tripped by the impulse that reaches the stop, so nothing overlaps.
        CHECK(b.actions[0].tripped_s == b.actions[0].motion_end_s);
        CHECK(b.actions[0].overlap_s() == 0);
        // Tripped: the change began during the move and ended after it.
        const auto& a = t.actions[0];
        CHECK(a.tripped_s < a.motion_end_s);
        CHECK(a.acknowledged_s > a.motion_end_s);
        const double overlap = a.motion_end_s - a.tripped_s;
        CHECK(overlap == a.overlap_s());
        const double saved = b.machine_seconds - t.machine_seconds;
        INFO("boundary " << b.machine_seconds << " s, tripped " << t.machine_seconds
                         << " s, overlap " << overlap << " s");
        CHECK(std::abs(saved - overlap) < 1e-9);
        CHECK(overlap > 1.0);
        // The same moves up to the return move: both trip times lie on one motion.
        CHECK(a.motion_end_s == b.actions[0].motion_end_s);
    }
    for (ChangeVariant v : {ChangeVariant::boundary, ChangeVariant::tripped}) {
        CHECK(std::abs(runs.at({v, Pace::fast_forward}).machine_seconds -
                       runs.at({v, Pace::impulse_level}).machine_seconds) < 1e-9);
    }
}

TEST_CASE("Two-tool job: the cut proof, each pass with the radius of the tool that cut it, is "
          "the same for both variants: tool 1 leaves the allowance, tool 2 finishes the design",
          "[two-tool][cut]") {
    const auto profile = axes::extended_profile();
    std::vector<cli::TwoToolCut> cuts;
    for (ChangeVariant v : {ChangeVariant::boundary, ChangeVariant::tripped}) {
        cli::ToolPaths paths(profile.first_tool);
        const auto r = run(v, relaylogic::Pace::fast_forward, &paths);
        REQUIRE(r.completed);
        REQUIRE(paths.stretches.size() == 2);
        CHECK(paths.stretches[0].tool == 1);
        CHECK(paths.stretches[1].tool == 2);
        cuts.push_back(cli::prove_two_tool_cut(paths, job_of(v).description, profile));
    }
    const cli::TwoToolCut& b = cuts[0];
    const cli::TwoToolCut& t = cuts[1];
    REQUIRE(b.passes.size() == 2);
    REQUIRE(t.passes.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
        CHECK(b.passes[k].tool == t.passes[k].tool);
        CHECK(b.passes[k].radius_in == t.passes[k].radius_in);
        CHECK(b.passes[k].path == t.passes[k].path);
        CHECK(b.passes[k].proof.max_gouge_in == t.passes[k].proof.max_gouge_in);
        CHECK(b.passes[k].proof.max_leftover_in == t.passes[k].proof.max_leftover_in);
        CHECK(b.passes[k].proof.max_scallop_in == t.passes[k].proof.max_scallop_in);
        CHECK(b.passes[k].proof.machined_points == t.passes[k].proof.machined_points);
    }
    CHECK(b.combined.max_gouge_in == t.combined.max_gouge_in);
    CHECK(b.combined.max_leftover_in == t.combined.max_leftover_in);
    CHECK(b.combined.max_scallop_in == t.combined.max_scallop_in);
    CHECK(b.combined.machined_points == t.combined.machined_points);

    const TwoToolDeck& deck = job_of(ChangeVariant::tripped).deck;
    const auto& rough = t.passes[0];
    const auto& finish = t.passes[1];
    INFO("pass 1: gouge " << rough.proof.max_gouge_in << " leftover " << rough.proof.max_leftover_in
                          << "; pass 2: gouge " << finish.proof.max_gouge_in << " leftover "
                          << finish.proof.max_leftover_in << " (planned dip "
                          << deck.passes[1].deck.planned_gouge_in << ")");
    CHECK(rough.radius_in == 0.25);
    CHECK(finish.radius_in == 0.125);
    CHECK(rough.proof.machined_points == t.design.points.size());
    CHECK(finish.proof.machined_points == t.design.points.size());
    // Tool 1, its cards offset by r1 + 0.010: no gouge, the allowance left standing.
    CHECK(rough.proof.max_gouge_in == 0);
    CHECK(rough.proof.max_leftover_in > 0.010 - kTwoToolQuantisation);
    CHECK(rough.proof.max_leftover_in <=
          0.010 + deck.passes[0].deck.planned_leftover_in + kTwoToolQuantisation);
    // Tool 2 on the design: its staircase dip and scallop as planned, within quantisation
    // (measured: gouge 0.00142 in, leftover 0.00269 in).
    CHECK(finish.proof.max_gouge_in <= deck.passes[1].deck.planned_gouge_in + kTwoToolQuantisation);
    CHECK(finish.proof.max_gouge_in < 0.0015);
    CHECK(finish.proof.max_leftover_in <=
          deck.passes[1].deck.planned_leftover_in + kTwoToolQuantisation);
    // Together: per design point the least deviation, here everywhere the finish's.
    CHECK(t.combined.deviation_in == finish.proof.deviation_in);
    CHECK(t.combined.max_gouge_in == finish.proof.max_gouge_in);
}

TEST_CASE("Two-tool job: combining proofs takes the least deviation per design point, a gouge "
          "by any pass stays, a point no pass machined stays unmachined",
          "[two-tool][cut]") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    DesignContour design;
    for (int i = 0; i < 5; ++i) {
        design.points.emplace_back(i * 0.1, 0.0);
        design.normals.emplace_back(0.0, 1.0);
    }
    CutProof a;
    a.deviation_in = {0.010, 0.012, nan, 0.011, nan};
    CutProof b;
    b.deviation_in = {0.002, 0.020, 0.001, -0.001, nan};
    const CutProof c = cli::combine_proofs({a, b}, design);
    REQUIRE(c.deviation_in.size() == 5);
    CHECK(c.deviation_in[0] == 0.002);
    CHECK(c.deviation_in[1] == 0.012);
    CHECK(c.deviation_in[2] == 0.001);
    CHECK(c.deviation_in[3] == -0.001);
    CHECK(std::isnan(c.deviation_in[4]));
    CHECK(c.machined_points == 4);
    CHECK(c.max_gouge_in == 0.001);
    CHECK(c.max_leftover_in == 0.012);
    CHECK(c.max_scallop_in == 0.012);
    CHECK(c.cut_contour[3].y() == Approx(-0.001));
}

TEST_CASE("Two-tool job: the job file lists the passes, reads back, and a one-tool job file "
          "of before reads as one tool",
          "[two-tool][job]") {
    const JobDescription& d = job_of(ChangeVariant::tripped).description;
    const std::string text = job_to_json(d);
    CHECK(text.find("\"job\": \"two-tool\"") != std::string::npos);
    const JobDescription back = job_from_json(text);
    REQUIRE(back.passes.size() == 2);
    CHECK(back.passes[0].tool == 1);
    CHECK(back.passes[0].radius_in == 0.25);
    CHECK(back.passes[0].offset_in == Approx(0.26));
    CHECK(back.passes[1].tool == 2);
    CHECK(back.allowance_in == d.allowance_in);
    CHECK(back.variant == "tripped");
    CHECK(back.work_zero_in == d.work_zero_in);
    CHECK(back.options.cutter_radius_in == 0.125);

    const JobDescription old = job_from_json(
        R"({"airfoil": "naca 2412", "closed_trailing_edge": false, "job": "template",
            "chord_in": 6.0, "cutter_radius_in": 0.25, "surface": "upper", "female": false,
            "work_zero_in": [0.749, 0.525]})");
    CHECK(old.passes.empty());
    CHECK(old.kind == JobKind::template_2d);
    CHECK(old.options.cutter_radius_in == 0.25);
}

TEST_CASE("Two-tool job: refused for a tool the profile lacks, one tool for both passes, or a "
          "surface the cutter cannot leave by rising",
          "[two-tool][decks]") {
    const auto profile = axes::extended_profile();
    const auto airfoil = naca4("2412");
    TwoToolOptions o;
    o.pass.stations = 10;
    o.finish_tool = 7;
    CHECK_THROWS_AS(make_two_tool_deck(*airfoil, o, profile), JobError);
    o.finish_tool = 1;
    CHECK_THROWS_AS(make_two_tool_deck(*airfoil, o, profile), JobError);
    o.finish_tool = 2;
    o.pass.surface = Surface::lower;
    CHECK_THROWS_AS(make_two_tool_deck(*airfoil, o, profile), JobError);
    o.pass.surface = Surface::upper;
    CHECK_NOTHROW(make_two_tool_deck(*airfoil, o, profile));
}

TEST_CASE("Two-tool job: the two passes and the tool change together make at most 9,999 cards: "
          "9,999 are punched, 10,000 are refused before a card is punched",
          "[two-tool][decks][limits]") {
    using Catch::Matchers::Contains;
    const auto profile = axes::extended_profile();
    const auto airfoil = naca4("2412");
    TwoToolOptions o;
    // The passes leave out the moves that go nowhere (neighbouring stations on the same
    // thousandth), so the count is the deck's own: these two were found by trying.
    o.pass.stations = 5717;
    o.allowance_in = 0.011;
    REQUIRE_THROWS_WITH(make_two_tool_deck(*airfoil, o, profile),
                        Contains("--stations 5717: the deck would need 10,000 cards (pass 1 ") &&
                            Contains(", the tool change 3, pass 2 ") &&
                            Contains("more than the 9,999 a deck can number"));
    o.pass.stations = 5693;
    o.allowance_in = 0.010;
    const TwoToolDeck deck = make_two_tool_deck(*airfoil, o, profile);
    CHECK(deck.cards.size() == 9999);
    CHECK(deck.cards.back().number == 9999);
    // Each pass is a template deck: ten million stations are refused before the first.
    o.pass.stations = 10000000;
    CHECK_THROWS_WITH(make_two_tool_deck(*airfoil, o, profile),
                      Contains("--stations 10000000: the deck would need at least 10,000,002 "
                               "cards"));
}

TEST_CASE("Two-tool job: a tool of the profile with a radius under one impulse is refused",
          "[two-tool][decks][limits]") {
    auto profile = axes::extended_profile();
    for (axes::Tool& t : profile.tools) {
        if (t.number == 2) {
            t.radius_in = 1e-300;
        }
    }
    TwoToolOptions o;
    o.pass.stations = 10;
    CHECK_THROWS_WITH(make_two_tool_deck(*naca4("2412"), o, profile),
                      Catch::Matchers::Contains("gives tool 2 a radius of 1e-300 in: a cutter "
                                                "radius under 0.001 in is less than one impulse"));
}
