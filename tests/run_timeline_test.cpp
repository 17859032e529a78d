// The run as the exhibit page plays it (outputs/replay/run_timeline.hpp) and `parsons run --html`
// (outputs/replay/replay_page.hpp): the record is the machine's, change for change, and the replay
// page is whole and self-contained whatever the deck is called.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "outputs/replay/replay_page.hpp"
#include "outputs/replay/run_timeline.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/layout.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

using parsons::cli::base64;
using parsons::cli::RunTimeline;
using parsons::test::idle_card;
using parsons::test::order;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_orders;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
namespace cr = parsons::cardreader;
namespace rl = parsons::relaylogic;

namespace {

std::string b64(const std::string& bytes) {
    return base64(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

// Two cards: the table out to 1.507 in and the cross slide to 0.250, then the table back to
// 0.205 with the swivel screw out to 0.5 in (the fixture turns). Each axis keeps the sequence
// position an idle card gives it (table 1, cross 2, swivel 4).
std::vector<cr::CardOrders> two_cards() {
    auto c1 = idle_card(1, {0, 0, 0, 0, 0});
    c1.axis(cr::Axis::table) = order(0, 1507, 1, 1307, 1407, 1);
    c1.axis(cr::Axis::cross) = order(0, 250, 2, 150, {}, 2);
    auto c2 = idle_card(2, {1507, 250, 0, 0, 0});
    c2.axis(cr::Axis::table) = order(1507, 205, 2, 305, {}, 1);
    c2.axis(cr::Axis::swivel) = order(0, 500, 3, {}, {}, 8);
    return {c1, c2};
}

// The signals' values after every recorded change, from their initial values.
std::vector<std::uint32_t> replayed(const RunTimeline& t) {
    const nlohmann::json h = t.header();
    std::vector<std::uint32_t> v(h["signals"].size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!h["signals"][i].is_null()) {
            v[i] = h["signals"][i]["initial"].get<std::uint32_t>();
        }
    }
    for (std::size_t k = 0; k < t.change_ids().size(); ++k) {
        v.at(t.change_ids()[k]) = t.change_values()[k];
    }
    return v;
}

std::uint32_t value_of(const RunTimeline& t, const std::vector<std::uint32_t>& v,
                       const std::string& scope, const std::string& name) {
    const nlohmann::json h = t.header();
    for (std::size_t i = 0; i < h["signals"].size(); ++i) {
        const auto& s = h["signals"][i];
        if (!s.is_null() && s["scope"] == scope && s["name"] == name) {
            return v[i];
        }
    }
    FAIL("no signal " << scope << "." << name);
    return 0;
}

} // namespace

TEST_CASE("Timeline: base64 of the arrays is RFC 4648's, padding included", "[timeline]") {
    CHECK(b64("") == "");
    CHECK(b64("f") == "Zg==");
    CHECK(b64("fo") == "Zm8=");
    CHECK(b64("foo") == "Zm9v");
    CHECK(b64("foob") == "Zm9vYg==");
    CHECK(b64("fooba") == "Zm9vYmE=");
    CHECK(b64("foobar") == "Zm9vYmFy");
    CHECK(b64(std::string("\xff\xfe\x00", 3)) == "//4A");
    CHECK(b64(std::string("\xfb\xff", 2)) == "+/8=");
}

TEST_CASE("Timeline: replaying the record from the initial values ends where the machine ended",
          "[timeline]") {
    const auto profile = parsons::axes::default_profile();
    RunTimeline timeline;
    timeline.set_machine(profile);
    const rl::RunResult result = run_orders(two_cards(), profile, &timeline);
    REQUIRE(result.completed);
    const nlohmann::json h = timeline.header();

    // The absolute counter dials, read as the operator reads them, are the counters' reading.
    const auto v = replayed(timeline);
    for (const cr::Axis axis : {cr::Axis::table, cr::Axis::cross, cr::Axis::swivel}) {
        const std::string scope(cr::axis_name(axis));
        const double dials = value_of(timeline, v, scope, "absolute_counter_104") +
                             value_of(timeline, v, scope, "absolute_counter_106") / 10.0 +
                             value_of(timeline, v, scope, "absolute_counter_108") / 100.0 +
                             value_of(timeline, v, scope, "absolute_counter_110") / 1000.0;
        CHECK(dials == Approx(result.axes[cr::axis_index(axis)].counter_in).margin(1e-9));
    }
    CHECK(value_of(timeline, v, "table", "absolute_counter_110") == 5); // 0.205
    CHECK(h["final_values"] == nlohmann::json(v)); // "to the end" lands where the record ends
    CHECK(value_of(timeline, v, "swivel", "absolute_counter_106") == 5);

    // The last motion record: the five real positions and the fixture's two angles.
    const auto& m = timeline.motion();
    REQUIRE(m.size() % RunTimeline::kMotionRecord == 0);
    REQUIRE(m.size() >= RunTimeline::kMotionRecord);
    const std::size_t last = m.size() - RunTimeline::kMotionRecord;
    for (std::size_t i = 0; i < cr::kAxisCount; ++i) {
        CHECK(m[last + 1 + i] == Approx(result.axes[i].real_in).margin(1e-12));
    }
    const auto swivel = cr::axis_index(cr::Axis::swivel);
    const auto tilt = cr::axis_index(cr::Axis::tilt);
    REQUIRE(result.axes[swivel].fixture_angle_deg);
    CHECK(m[last + 6] == Approx(*result.axes[swivel].fixture_angle_deg).margin(1e-12));
    CHECK(m[last + 7] == Approx(*result.axes[tilt].fixture_angle_deg).margin(1e-12));
    CHECK(m[last + 6] != Approx(0.0).margin(0.1)); // the swivel screw did turn the fixture

    // Cards, finish and time order.
    CHECK(h["cards"].size() == 2);
    CHECK(h["cards"][1]["axes"]["table"]["stop_in"] == Approx(0.205));
    CHECK(h["cards"][1]["axes"]["table"]["held_in"].back() == Approx(0.205));
    CHECK(h["cards"][1]["axes"]["table"]["motion"] == "-");
    CHECK(h["finish"].get<double>() == Approx(result.machine_seconds).margin(1e-12));
    CHECK(h["stop"].is_null());
    CHECK(h["truncated"] == false);
    CHECK(h["changes"] == timeline.change_times().size());
    CHECK(std::is_sorted(timeline.change_times().begin(), timeline.change_times().end()));
    CHECK(h["axes"] == nlohmann::json({"table", "cross", "vertical", "swivel", "tilt"}));

    // The live page's header (nlohmann's number text, not json_text's shortest) holds the same
    // values, number for number, without the signals.
    nlohmann::json without = h;
    without.erase("signals");
    CHECK(nlohmann::json::parse(timeline.page_header_text()) == without);
}

TEST_CASE("Timeline: a stop is recorded with its reason, card and lamps", "[timeline]") {
    RunTimeline timeline;
    const rl::RunResult result = run_orders(two_cards(), parsons::axes::default_profile(),
                                            &timeline, {rl::parse_fault("drop-impulse:table:120")});
    REQUIRE(result.stop);
    const nlohmann::json h = timeline.header();
    CHECK(h["stop"]["reason"] == "missed_impulse");
    CHECK(h["stop"]["card"] == 1);
    CHECK(h["stop"]["axis"] == "table");
    CHECK(h["stop"]["message"] == result.stop->message);
    CHECK(h["stop"]["lamps"].size() == result.stop->lamps.size());
}

TEST_CASE("Timeline: past its limit it records no more changes and says so", "[timeline]") {
    RunTimeline timeline(50);
    run_orders(two_cards(), parsons::axes::default_profile(), &timeline);
    CHECK(timeline.change_times().size() == 50);
    CHECK(timeline.change_ids().size() == 50);
    const nlohmann::json h = timeline.header();
    CHECK(h["truncated"] == true);
    CHECK(h["final_values"] == nlohmann::json(replayed(timeline))); // the record's end
    CHECK(h["cards"].size() == 2); // cards, stop and finish stay whole
}

TEST_CASE("Replay page: every slot filled, the run embedded whole, no name breaks the page",
          "[timeline][html]") {
    RunTimeline timeline;
    run_orders(two_cards(), parsons::axes::default_profile(), &timeline);
    // Typed with its folders: the page carries the file name alone (issue 31), which can hold
    // no '/', so no "</script"; a '<' and a slot's text still must not break the page.
    const std::string name = "<script><!--viewer-->&deck";
    const std::string typed = "/home/visitor/my decks/" + name;
    const std::string page = parsons::cli::replay_page(
        timeline, nlohmann::json{{"status", "completed"}, {"deck", typed}}, typed);
    CHECK(page.find("/home/visitor") == std::string::npos);
    CHECK(page.find("my decks") == std::string::npos);
    for (const char* slot : {"<!--title-->", "/*exhibit-css*/", "<!--viewer-->", "/*parts-js*/",
                             "/*cabinet-js*/", "/*viewer-js*/", "/*tour-js*/", "/*sound-js*/",
                             "<!--timeline-json-->", "<!--run-json-->"}) {
        INFO(slot);
        CHECK(page.find(slot) == std::string::npos);
    }
    CHECK(page.find("parsons replay: &lt;script&gt;&lt;!--viewer--&gt;&amp;deck") !=
          std::string::npos);
    CHECK(page.find(name) == std::string::npos);
    CHECK(page.find("id=\"viewer\"") != std::string::npos);
    CHECK(page.find("ParsonsViewer.replayFromPage(document)") != std::string::npos);
    CHECK(page.find("<script src=") == std::string::npos); // nothing from outside the file
    // Every script element closes where it should: as many closings as openings.
    auto count = [&](const std::string& s) {
        std::size_t n = 0;
        for (auto at = page.find(s); at != std::string::npos; at = page.find(s, at + 1)) {
            ++n;
        }
        return n;
    };
    CHECK(count("<script") == count("</script>"));
    // The embedded timeline reads back as JSON, its arrays the right length.
    const std::string open = "<script type=\"application/json\" id=\"parsons-timeline\">";
    const auto from = page.find(open) + open.size();
    const auto json = nlohmann::json::parse(page.substr(from, page.find("</script>", from) - from));
    CHECK(json["changes"] == timeline.change_times().size());
    const std::string packed =
        parsons::cli::packed_record(timeline.change_times(), timeline.change_ids(),
                                    timeline.change_values(), timeline.motion());
    CHECK(json["arrays"]["encoding"] == "xor1");
    CHECK(json["arrays"]["packed"] == b64(packed));
    // Packed, a few bytes a number: under a third of the raw arrays' 16 bytes a change and 64 a
    // motion record (a quarter on this run, a fifth on the demo deck).
    CHECK(packed.size() * 3 < timeline.change_times().size() * 16 + timeline.motion().size() * 8);
    const std::string run_open = "<script type=\"application/json\" id=\"parsons-run\">";
    const auto run_from = page.find(run_open) + run_open.size();
    const auto run =
        nlohmann::json::parse(page.substr(run_from, page.find("</script>", run_from) - run_from));
    CHECK(run["deck"] == name);
    CHECK(run["report"]["deck"] == name);
}

TEST_CASE("Run --html: the page of a completed run, of a stop, and of a generated deck's cut",
          "[timeline][html][cli]") {
    TempDir dir;
    const std::string sample = source_path("decks/samples/patent-example.csv");
    auto r = run_parsons("run " + q(sample) + " -q --html " + q(dir.str("run.html")));
    REQUIRE(r.exit_code == 0);
    std::string page = read_bytes(dir.path("run.html"));
    CHECK(page.rfind("<!doctype html>", 0) == 0);
    CHECK(page.find("patent-example.csv") != std::string::npos);
    CHECK(page.find("\"status\":\"completed\"") != std::string::npos);

    // A machine stop is exit 3, and its page is written, the stop in it.
    r = run_parsons("run " + q(sample) + " -q --fault drop-impulse:table:120 --html " +
                    q(dir.str("stop.html")));
    CHECK(r.exit_code == 3);
    page = read_bytes(dir.path("stop.html"));
    CHECK(page.find("\"reason\":\"missed_impulse\"") != std::string::npos);

    // A generated airfoil deck: the design the cut grows against comes from its job file.
    r = run_parsons("gen airfoil --naca 2412 --chord 4 --stations 12 -o " + q(dir.str("a.cbn")));
    REQUIRE(r.exit_code == 0);
    r = run_parsons("run " + q(dir.str("a.cbn")) + " -q --html " + q(dir.str("a.html")));
    REQUIRE(r.exit_code == 0);
    page = read_bytes(dir.path("a.html"));
    CHECK(page.find("\"design\":{\"airfoil\":\"naca 2412\"") != std::string::npos);

    // A press-feeder or tapping deck: the job file beside it is its proof's, with no cut to
    // draw; the page is written without a design (it was exit 2, the file taken for a
    // template's job).
    for (const char* gen : {"press-feeder --cycles 1", "tapping"}) {
        INFO(gen);
        r = run_parsons(std::string("gen ") + gen + " -o " + q(dir.str("p.csv")));
        REQUIRE(r.exit_code == 0);
        r = run_parsons("run " + q(dir.str("p.csv")) + " -q --profile " +
                        q(dir.str("p.csv.profile.json")) + " --html " + q(dir.str("p.html")));
        INFO(r.output);
        CHECK(r.exit_code == 0);
        page = read_bytes(dir.path("p.html"));
        CHECK(page.find("\"status\":\"completed\"") != std::string::npos);
        CHECK(page.find("\"design\":null") != std::string::npos);
    }
    // A job file beside the deck that is no JSON is an error still, naming it.
    parsons::test::write_bytes(dir.path("a.cbn.job.json"), "{not json");
    r = run_parsons("run " + q(dir.str("a.cbn")) + " -q --html " + q(dir.str("a2.html")));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("a.cbn.job.json") != std::string::npos);

    // A deck whose name is not UTF-8: the report and the page carry U+FFFD for the bad byte
    // (it was an internal error, exit 1).
    const std::string odd = dir.str("odd\xff.csv");
    parsons::test::write_bytes(odd, read_bytes(sample));
    r = run_parsons("run " + q(odd) + " -q --report " + q(dir.str("odd.json")) + " --html " +
                    q(dir.str("odd.html")));
    CHECK(r.exit_code == 0);
    CHECK(read_bytes(dir.path("odd.json")).find("odd\xef\xbf\xbd.csv") != std::string::npos);
    CHECK(read_bytes(dir.path("odd.html")).find("odd\xef\xbf\xbd.csv") != std::string::npos);

    // A folder that is not there: exit 2 naming the file, and no page.
    r = run_parsons("run " + q(sample) + " -q --html " + q(dir.str("no/such/run.html")));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("no/such/run.html") != std::string::npos);
}

// The header is written as text while the run goes (not a tree of JSON objects): its strings and
// numbers must read back as the machine gave them, a name with quotes, a backslash or a control
// character included, and every card's numbers to the last bit.
TEST_CASE("Timeline: the header written as text reads back exactly", "[timeline]") {
    RunTimeline timeline;
    rl::SignalInfo odd;
    odd.id = 0;
    odd.scope = "table";
    odd.name = "a \"quoted\" \\ name\n\t\x01";
    odd.component = "122\u2032 comparer";
    odd.numeral = "122'";
    odd.width = 4;
    timeline.on_signal_defined(odd, 7);
    rl::SignalInfo plain = odd;
    plain.id = 1;
    plain.name = "relay_0";
    timeline.on_signal_defined(plain, 0);
    const nlohmann::json signals = nlohmann::json::parse(timeline.signals_text());
    REQUIRE(signals.size() == 2);
    CHECK(signals[0]["name"] == odd.name);
    CHECK(signals[0]["component"] == odd.component);
    CHECK(signals[0]["numeral"] == odd.numeral);
    CHECK(signals[0]["initial"] == 7);
    CHECK(signals[0]["width"] == 4);
    CHECK(signals[1]["name"] == "relay_0");
    // The same text nlohmann writes for the same object.
    const nlohmann::json as_object = {{"scope", odd.scope},         {"name", odd.name},
                                      {"component", odd.component}, {"numeral", odd.numeral},
                                      {"width", odd.width},         {"initial", 7}};
    CHECK(timeline.signals_text().substr(1, as_object.dump().size()) == as_object.dump());

    // Cards: times and held numbers bit for bit (0.1 + 0.2 has no short decimal), whole numbers
    // still fractions.
    cr::CardOrders card = idle_card(3, {0, 0, 0, 0, 0});
    card.axis(cr::Axis::table) = order(0, 2000, 1, 1307, 1999, 1);
    card.axis(cr::Axis::cross) = order(0, 1, 2, {}, {}, 2);
    const double t = 0.1 + 0.2;
    timeline.on_card(t, 1, card);
    timeline.on_card(12.0, 2, card);
    const std::string text = timeline.cards_text();
    CHECK(text.find("\"stop_in\":2.0}") != std::string::npos);
    const nlohmann::json cards = nlohmann::json::parse(text);
    REQUIRE(cards.size() == 2);
    CHECK(cards[0]["t"].get<double>() == t); // exact, not Approx
    CHECK(cards[1]["t"].get<double>() == 12.0);
    CHECK(cards[0]["number"] == 3);
    CHECK(cards[0]["kind"] == "motion");
    const auto& table = cards[0]["axes"]["table"];
    CHECK(table["held_in"] == nlohmann::json({1307 / 1000.0, 1999 / 1000.0, 2000 / 1000.0}));
    CHECK(table["check_in"].get<double>() == card.axis(cr::Axis::table).check / 1000.0);
    CHECK(table["speed"] == 1);
    CHECK(cards[0]["axes"]["cross"]["stop_in"].get<double>() == 0.001);
    CHECK(cards[0]["axes"].size() == 5);
    // Every number a card can hold, 0.000 to 9.999 in, reads back as its thousandths / 1000.
    RunTimeline every;
    for (int n = 0; n <= 9999; ++n) {
        cr::CardOrders c = idle_card(n, {0, 0, 0, 0, 0});
        c.axis(cr::Axis::tilt) = order(0, n, 1, {}, {}, 5);
        every.on_card(n * 1e-3, n + 1, c);
    }
    const nlohmann::json all = nlohmann::json::parse(every.cards_text());
    int exact = 0;
    for (int n = 0; n <= 9999; ++n) {
        exact += all[n]["axes"]["tilt"]["stop_in"].get<double>() == n / 1000.0 ? 1 : 0;
    }
    CHECK(exact == 10000);
    // The page's header and the --html record's hold the same cards.
    CHECK(nlohmann::json::parse(timeline.page_header_text())["cards"] == cards);
    CHECK(timeline.header()["cards"] == cards);
}

// Alone, the record takes the tracer's changes in bulk (its change log, no call a change); among
// other observers (a fan-out) it takes them one on_signal() at a time. The record is the same.
TEST_CASE("Timeline: the change log in bulk records what on_signal records", "[timeline]") {
    RunTimeline alone;
    run_orders(two_cards(), parsons::axes::default_profile(), &alone);
    RunTimeline among;
    rl::MachineObserver other; // follows every change and motion, does nothing with them
    rl::ObserverFanOut fan;
    fan.add(&among);
    fan.add(&other);
    run_orders(two_cards(), parsons::axes::default_profile(), &fan);
    REQUIRE(alone.change_times().size() > 1000);
    CHECK(alone.change_times() == among.change_times());
    CHECK(alone.change_ids() == among.change_ids());
    CHECK(alone.change_values() == among.change_values());
    CHECK(alone.motion() == among.motion());
    CHECK(alone.header_text() == among.header_text());
}
