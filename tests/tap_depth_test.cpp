// A tap that bottoms farther from its depth than the NC resolves is told, never "completed" and
// nothing more (issue 53; docs/tapping.md, "Near the depth"): the summary and `check` name the
// hole, its card and how far, from relaylogic::depth_miss_in, once for both.
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include "relaylogic/tapping/tapping_units.hpp"

#include <catch2/catch.hpp>

namespace test = parsons::test;
namespace cardreader = parsons::cardreader;
namespace relaylogic = parsons::relaylogic;

namespace {

relaylogic::HoleRecord hole(double depth, double deepest, double pitch, double ratio) {
    relaylogic::HoleRecord h;
    h.completed = true;
    h.depth_in = depth;
    h.deepest_in = deepest;
    h.pitch_ordered_in = pitch;
    h.ratio_used = ratio;
    return h;
}

} // namespace

TEST_CASE("Tap depth: a miss within a thousandth, or within one encoder edge's feed where that "
          "is coarser, is none, past either it is the signed miss, and a hole not completed has none",
          "[tapping]") {
    // Tool 1's tap: 0.05 in a turn, ratio 1/4, 24 edges: an edge feeds 0.00052 in, so the
    // thousandth rules.
    CHECK(relaylogic::depth_miss_in(hole(0.300, 0.3010, 0.05, 0.25), 24) == 0);
    CHECK(relaylogic::depth_miss_in(hole(0.300, 0.2990, 0.05, 0.25), 24) == 0);
    CHECK(relaylogic::depth_miss_in(hole(0.300, 0.3012, 0.05, 0.25), 24) == Approx(0.0012));
    CHECK(relaylogic::depth_miss_in(hole(0.300, 0.2988, 0.05, 0.25), 24) == Approx(-0.0012));
    // A coarse pitch: 0.4 in a turn at ratio 1 over 72 edges feeds 0.00556 in an edge.
    CHECK(relaylogic::depth_miss_in(hole(0.015, 0.0205, 0.4, 1.0), 72) == 0);
    CHECK(relaylogic::depth_miss_in(hole(0.015, 0.0210, 0.4, 1.0), 72) == Approx(0.006));
    relaylogic::HoleRecord stopped = hole(0.300, 0.100, 0.05, 0.25);
    stopped.completed = false; // the machine stopped first: the stop says why
    CHECK(relaylogic::depth_miss_in(stopped, 24) == 0);
}

TEST_CASE("Tap depth: a tap the NC cannot bring within a thousandth or an encoder edge of its "
          "depth is told by the summary and by check, naming the hole, its card and how far",
          "[tapping][cli]") {
    // The property test's seed 471 (parsons-extended as built): a tap 0.015 in deep at a pitch
    // of 0.39776 in a turn and S 36 is 0.04 of a turn: the NC measures no speed before the
    // tool is at its depth, and the tap bottoms at 0.0239 in.
    test::TempDir dir;
    test::write_bytes(dir.path("shallow.csv"), std::string(cardreader::kListingHeader) + "\n" +
                                                   "1,tap,2,swivel,reverse,0.015,0.39776,36\n");
    const auto ran = test::run_parsons("run " + test::q(dir.str("shallow.csv")) +
                                       " --profile parsons-extended");
    CHECK(ran.exit_code == 0);
    CHECK_THAT(ran.output, Catch::Contains("warning: hole 1 (card 1, tool 2, S 36) bottomed at "
                                           "0.0239 in, 0.0089 in past its depth 0.015 in"));
    const auto checked = test::run_parsons("check " + test::q(dir.str("shallow.csv")) +
                                           " --profile parsons-extended");
    CHECK(checked.exit_code == 0);
    CHECK_THAT(checked.output,
               Catch::Contains("card 1 (number 0001): observed: swivel: hole 1 (card 1, tool 2, "
                               "S 36) bottomed at 0.0239 in, 0.0089 in past its depth"));

    // The job's own tap, 0.600 in deep at S 240, bottoms within an edge: no warning.
    test::write_bytes(dir.path("good.csv"),
                      test::deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n"));
    const auto good =
        test::run_parsons("run " + test::q(dir.str("good.csv")) + " --profile parsons-extended");
    CHECK(good.exit_code == 0);
    CHECK_THAT(good.output, Catch::Contains("1 hole tapped"));
    CHECK_THAT(good.output, !Catch::Contains("warning: hole"));
}
