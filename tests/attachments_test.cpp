// The house (docs/architecture.md): the later systems are attachments of control cabinet 52
// (relaylogic/attachment.hpp), built only when the profile asks for them; the report and the
// summary show one only when the deck used it (tests/house_test.cpp holds the layers).
#include "tests/test_support.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/attachment.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace parsons;
using parsons::test::kHeader;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::vector<std::string> names_of(const relaylogic::ControlCabinet& cabinet) {
    std::vector<std::string> names;
    for (const auto& a : cabinet.attachments()) {
        names.emplace_back(a->name());
    }
    return names;
}

// A motion card alone, and the same card after a sync card that waits for the crank at 30 deg.
const std::string kMotionDeck =
    std::string(kHeader) + "1,0,table,+,1,0.100,0.150,0.200,0.200,1\n" + test::idle_rest(1);
const std::string kSyncDeck = std::string(kHeader) + "1,sync,position,30\n" +
                              "2,0,table,+,1,0.100,0.150,0.200,0.200,1\n" + test::idle_rest(2);

} // namespace

TEST_CASE("Attachments: parsons-1952 and parsons-safe build none, parsons-extended builds "
          "conditions, press, tapping and contouring in that order") {
    const cardreader::CardLayout& layout = cardreader::fig8_layout();
    CHECK(names_of(relaylogic::ControlCabinet(axes::default_profile(), layout)).empty());
    CHECK(names_of(relaylogic::ControlCabinet(axes::safe_profile(), layout)).empty());
    CHECK(names_of(relaylogic::ControlCabinet(axes::extended_profile(), layout)) ==
          std::vector<std::string>{"conditions", "sync", "tapping", "contouring"});
    // One system alone: only its attachment.
    axes::MachineProfile p = axes::default_profile();
    p.condition_cards = true;
    CHECK(names_of(relaylogic::ControlCabinet(p, layout)) ==
          std::vector<std::string>{"conditions"});
}

namespace {

// A made-up attachment that sees impulses before they are counted, and nothing else.
class CountingOnly : public relaylogic::Attachment {
public:
    std::string_view name() const override { return "counting"; }
    void before_count(relaylogic::ControlCabinet& /*cab*/, relaylogic::AxisCircuit& /*c*/,
                      int /*direction*/) override {}
};

} // namespace

TEST_CASE("Attachments: the hot hooks the cabinet calls of an attachment are exactly those its "
          "class overrides") {
    using relaylogic::hooks_of;
    constexpr auto none = hooks_of<relaylogic::Attachment>();
    STATIC_REQUIRE(!none.holding);
    STATIC_REQUIRE(!none.before_count);
    STATIC_REQUIRE(!none.clock);
    constexpr auto counting = hooks_of<CountingOnly>();
    STATIC_REQUIRE(counting.before_count);
    STATIC_REQUIRE(!counting.after_count);
    STATIC_REQUIRE(!counting.before_jump);
    STATIC_REQUIRE(!counting.holds_axis);
    STATIC_REQUIRE(!counting.drive);
    STATIC_REQUIRE(!counting.clock);
    STATIC_REQUIRE(!counting.plants);
    // The registry records them: the press turns a clock and holds a card's motion; the
    // tapping head moves the spindle and sees every impulse; the condition units watch counts.
    const relaylogic::ControlCabinet cabinet(axes::extended_profile(), cardreader::fig8_layout());
    const auto& a = cabinet.attachments();
    REQUIRE(a.size() == 4);
    CHECK(a[0]->hooks().after_count);
    CHECK(a[0]->hooks().holds_axis);
    CHECK_FALSE(a[0]->hooks().clock);
    CHECK(a[1]->hooks().clock);
    CHECK(a[1]->hooks().holding);
    CHECK(a[1]->hooks().drive);
    CHECK_FALSE(a[1]->hooks().before_count);
    CHECK(a[2]->hooks().plants);
    CHECK(a[2]->hooks().before_count);
    CHECK(a[2]->hooks().before_jump);
    CHECK_FALSE(a[2]->hooks().clock);
    // The contouring axes are the attachment's own, moved by its lasting events: no hot hook.
    CHECK_FALSE(a[3]->hooks().plants);
    CHECK_FALSE(a[3]->hooks().before_count);
    CHECK_FALSE(a[3]->hooks().clock);
    CHECK_FALSE(a[3]->hooks().holding);
}

TEST_CASE("Attachments: the report and the summary show the press, the tapping head and the "
          "tool changer only when the deck used them") {
    TempDir dir;
    const auto motion = dir.path("motion.csv");
    const auto sync = dir.path("sync.csv");
    write_bytes(motion, kMotionDeck);
    write_bytes(sync, kSyncDeck);
    const auto report = dir.path("r.json");

    const auto plain = run_parsons("run " + q(motion.string()) +
                                   " --profile parsons-extended --report " + q(report.string()));
    REQUIRE(plain.exit_code == 0);
    const std::string plain_report = read_bytes(report);
    CHECK(plain_report.find("\"press\"") == std::string::npos);
    CHECK(plain_report.find("\"tapping\"") == std::string::npos);
    CHECK(plain_report.find("\"tool_in_spindle\"") == std::string::npos);
    CHECK(plain.output.find("  press ") == std::string::npos);
    CHECK(plain.output.find("  tapping ") == std::string::npos);
    CHECK(plain.output.find("  tool ") == std::string::npos);

    const auto synced = run_parsons("run " + q(sync.string()) +
                                    " --profile parsons-extended --report " + q(report.string()));
    REQUIRE(synced.exit_code == 0);
    const std::string synced_report = read_bytes(report);
    CHECK(synced_report.find("\"press\"") != std::string::npos);
    CHECK(synced_report.find("\"tapping\"") == std::string::npos);
    CHECK(synced.output.find("  press ") != std::string::npos);
    CHECK(synced.output.find("  tapping ") == std::string::npos);
}

TEST_CASE("Attachments: a saved state keeps whether the deck used the press, so a resumed run "
          "reports it as the whole run would") {
    TempDir dir;
    const auto deck = dir.path("sync.csv");
    write_bytes(deck, kSyncDeck);
    const auto state = dir.path("s.json");
    const auto report = dir.path("r.json");
    // The table's movement range stops card 2 (the motion card, after the sync card was read);
    // resumed with a wider range, the run goes on from card 2.
    const auto stopped =
        run_parsons("run " + q(deck.string()) + " --profile parsons-extended --limit " +
                    "table=0:0.15 --save-state " + q(state.string()) + " -q");
    REQUIRE(stopped.exit_code == 3);
    CHECK(read_bytes(state).find("\"used\": true") != std::string::npos);
    const auto resumed = run_parsons("run " + q(deck.string()) + " --resume " + q(state.string()) +
                                     " --limit table=0:1 --report " + q(report.string()) + " -q");
    REQUIRE(resumed.exit_code == 0);
    CHECK(read_bytes(report).find("\"press\"") != std::string::npos);
}
