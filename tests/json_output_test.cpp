// --json on show, check, gen and punch (the issue "--json for scripts"): one document on
// standard output that a script can parse, with the values the text prints, the same exit
// codes, errors on standard error and no document; and docs/json-output.md names every field.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using nlohmann::json;
using parsons::test::idle_rest;
using parsons::test::kHeader;
using parsons::test::kSample;
using parsons::test::lines_of;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::run_shell;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

// A run with standard output and standard error apart.
struct Split {
    int exit_code = -1;
    std::string out;
    std::string err;
    json doc() const { return json::parse(out); }
};

Split run_split(const TempDir& dir, const std::string& args) {
    const std::string err = dir.str("stderr.txt");
    const auto r = run_shell("PARSONS " + args + " 2>" + q(err));
    return {r.exit_code, r.output, read_bytes(err)};
}

// The sample deck with a 5 punched in (card, column), as .bin: a double punch in a digit
// column, or a stray hole in an unused one.
std::string sample_with_row5(const TempDir& dir, long card, int column) {
    const std::string deck = dir.str("s.bin");
    REQUIRE(run_parsons("punch " + q(source_path(kSample)) + " -o " + q(deck)).exit_code == 0);
    std::string bytes = read_bytes(deck);
    const auto i = static_cast<std::size_t>(160 * (card - 1) + 2 * (column - 1) + 1);
    bytes.at(i) = static_cast<char>(bytes.at(i) | 0x01); // word bit 4 = row 5
    const std::string name = fmt::format("bad{}_{}.bin", card, column);
    write_bytes(dir.path(name), bytes);
    return dir.str(name);
}

// Table and cross both moving, both punched at position 1 only: a certain sequence stall.
std::string stall_deck(const TempDir& dir) {
    write_bytes(dir.path("stall.csv"),
                std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" +
                    "1,0,cross,+,3,,,0.200,0.200,1\n1,0,vertical,+,3,,,0.000,0.000,3\n"
                    "1,0,swivel,+,3,,,0.000,0.000,4\n1,0,tilt,+,3,,,0.000,0.000,5\n");
    return dir.str("stall.csv");
}

std::vector<std::string> lines_with(const std::string& text, const std::string& what) {
    std::vector<std::string> found;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.find(what) != std::string::npos) {
            found.push_back(line);
        }
    }
    return found;
}

std::size_t count_kind(const json& findings, const std::string& kind) {
    std::size_t n = 0;
    for (const auto& f : findings) {
        n += f["kind"] == kind ? 1 : 0;
    }
    return n;
}

// Every key of every object in a document, at any depth.
void collect_keys(const json& j, std::set<std::string>& keys) {
    if (j.is_object()) {
        for (const auto& [key, value] : j.items()) {
            keys.insert(key);
            collect_keys(value, keys);
        }
    } else if (j.is_array()) {
        for (const auto& value : j) {
            collect_keys(value, keys);
        }
    }
}

void check_head(const json& doc, const std::string& command) {
    CHECK(doc["command"] == command);
    CHECK(doc["schema_version"] == 1);
}

} // namespace

TEST_CASE("Show --json: the sample deck's cards, field by field, pretty-printed on standard "
          "output",
          "[cli][json][show]") {
    TempDir dir;
    const std::string sample = source_path(kSample);
    const auto r = run_split(dir, "show " + q(sample) + " --json");
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    const json doc = r.doc();
    check_head(doc, "show");
    // One document, indented by two spaces, then a newline: nothing else on standard output.
    CHECK(r.out == nlohmann::ordered_json::parse(r.out).dump(2) + "\n");
    CHECK(r.out.rfind("{\n  \"command\": \"show\",\n  \"schema_version\": 1,\n", 0) == 0);
    CHECK(doc["deck"] == sample);
    CHECK(doc["format"] == "listing");
    CHECK(doc["layout"] == "fig8");
    CHECK(doc["cards_read"] == 4);
    CHECK(doc["warning_count"] == 0);
    CHECK(doc["bad_punch_cards"] == 0);
    CHECK(doc["svg_dir"].is_null());
    const json& cards = doc["cards"];
    REQUIRE(cards.size() == 4);
    for (std::size_t i = 0; i < cards.size(); ++i) {
        CHECK(cards[i]["index"] == i + 1);
        CHECK(cards[i]["number"] == i + 1);
        CHECK(cards[i]["axes"].size() == 5);
        CHECK(cards[i]["warnings"].empty());
    }
    // Card 1 is the patent's example for the table: 8.785, 8.885, stop 8.985.
    const json& table = cards[0]["axes"]["table"];
    CHECK(cards[0]["spindle"] == "forward");
    CHECK(table["motion"] == "+");
    CHECK(table["speed"] == 1);
    CHECK(table["slow_down_1"] == 8.785);
    CHECK(table["slow_down_2"] == 8.885);
    CHECK(table["stop"] == 8.985);
    CHECK(table["check"] == 8.985);
    CHECK(table["sequence"] == json::array({1, 2}));
    CHECK(table["slow_down_fields"] == 2);
    CHECK(table["columns"] == json{{"first", 2}, {"last", 19}});
    const json& cross = cards[0]["axes"]["cross"];
    CHECK(cross["speed"] == 2);
    CHECK(cross["slow_down_1"] == 2.3);
    CHECK(cross["slow_down_2"].is_null()); // fig8 has one slow-down field for the cross
    CHECK(cross["slow_down_fields"] == 1);
    CHECK(cross["stop"] == 2.5);
    CHECK(cross["columns"] == json{{"first", 20}, {"last", 33}});
    const json& vertical = cards[0]["axes"]["vertical"];
    CHECK(vertical["slow_down_1"].is_null()); // speed 3: no slow-down punched
    CHECK(vertical["sequence"] == json::array({3, 4}));
    CHECK(cards[0]["axes"]["tilt"]["stop"] == 0.125);
    CHECK(cards[0]["axes"]["tilt"]["sequence"] == json::array({5}));
    // Card 2 backs off: the table in reverse to 8.385, a check of 0.600.
    CHECK(cards[1]["axes"]["table"]["motion"] == "-");
    CHECK(cards[1]["axes"]["table"]["stop"] == 8.385);
    CHECK(cards[1]["axes"]["table"]["check"] == 0.6);
    CHECK(cards[1]["axes"]["tilt"]["check"] == 0.025);
    CHECK(cards[2]["spindle"] == "reverse");
    CHECK(cards[2]["axes"]["cross"]["check"] == 0.0);
    CHECK(cards[3]["spindle"] == "off");
    CHECK(cards[3]["axes"]["table"]["check"] == 8.885);
}

TEST_CASE("Show --json: each note of the text is in the document, on its card, with its kind "
          "and axis, and the run's stop on its card",
          "[cli][json][show]") {
    TempDir dir;
    // A sequence stall on card 1; slow-downs so close to the stop that the table runs on to its
    // limit switch and coasts there, on card 1 of the other deck.
    const std::string stall = stall_deck(dir);
    write_bytes(dir.path("close.csv"), std::string(kHeader) +
                                           "1,0,table,+,1,8.983,8.984,8.985,"
                                           "8.985,1\n" +
                                           idle_rest(1) + "2,0,table,+,3,,,9.085,0.100,1\n" +
                                           idle_rest(2));
    for (const std::string& deck : {stall, dir.str("close.csv")}) {
        INFO(deck);
        const auto text = run_parsons("show " + q(deck));
        const auto r = run_split(dir, "show " + q(deck) + " --json");
        INFO(text.output << r.out << r.err);
        REQUIRE(r.exit_code == text.exit_code);
        const json doc = r.doc();
        // The text's note lines, in order, from every card: "  KIND: [AXIS: ]MESSAGE".
        std::vector<std::string> from_text;
        for (const std::string& line : lines_of(text.output)) {
            for (const char* kind : {"advice", "observed in the run", "double punch"}) {
                const std::string head = std::string("  ") + kind + ": ";
                if (line.rfind(head, 0) == 0) {
                    from_text.push_back(std::string(kind) + ": " + line.substr(head.size()));
                }
            }
        }
        std::vector<std::string> from_json;
        for (const auto& card : doc["cards"]) {
            for (const auto& w : card["warnings"]) {
                CHECK(w["card"] == card["index"]);
                from_json.push_back(
                    w["kind"].get<std::string>() + ": " +
                    (w["axis"].is_null() ? "" : w["axis"].get<std::string>() + ": ") +
                    w["message"].get<std::string>());
            }
        }
        CHECK(from_text.empty() == (deck == stall)); // the stall deck has nothing to note
        CHECK(from_json == from_text);
        CHECK(doc["warning_count"] == from_text.size());
        // The run stops on card 1 of both decks: the stop is on that card, as the text says.
        CHECK(doc["runs_through"] == false);
        REQUIRE(doc["cards"][0].contains("stop"));
        const json& stop = doc["cards"][0]["stop"];
        CHECK(text.output.find("  the machine stops here: " + stop["reason"].get<std::string>() +
                               ": " + stop["message"].get<std::string>()) != std::string::npos);
        for (std::size_t i = 1; i < doc["cards"].size(); ++i) {
            CHECK_FALSE(doc["cards"][i].contains("stop")); // only the stop's card has one
        }
    }
    const auto r = run_split(dir, "show " + q(stall) + " --json");
    CHECK(r.doc()["cards"][0]["stop"]["reason"] == "sequence_stall");
    const auto close = run_split(dir, "show " + q(dir.str("close.csv")) + " --json");
    CHECK(close.doc()["cards"][0]["stop"]["axis"] == "table");
    CHECK(close.doc()["cards"][0]["warnings"][0]["kind"] == "observed in the run");
}

TEST_CASE("Show --json: a card with a bad punch is given by its column, the reader's stop told, "
          "exit 0",
          "[cli][json][show][bad-punch]") {
    TempDir dir;
    const std::string bad = sample_with_row5(dir, 2, 13); // table stop: rows 3 and 5
    const auto r = run_split(dir, "show " + q(bad) + " --json --profile parsons-safe");
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0); // as the text: shown, the stop told; check judges (exit 3)
    CHECK(r.err.empty());
    const json doc = r.doc();
    CHECK(doc["runs_through"] == false);
    CHECK(doc["cards"][1]["stop"]["reason"] == "bad_punch");
    CHECK(doc["cards_read"] == 4);
    CHECK(doc["bad_punch_cards"] == 1);
    const json& card = doc["cards"][1];
    CHECK(card["index"] == 2);
    CHECK(card["bad_punch"]["column"] == 13);
    CHECK(card["bad_punch"]["what"] == "double punch (rows 3 and 5) in table stop");
    CHECK_FALSE(card.contains("axes"));
    CHECK_FALSE(doc["cards"][0].contains("bad_punch"));
    CHECK(doc["cards"][2]["axes"]["table"]["stop"] == 8.985);
}

TEST_CASE("Check --json: a move past a soft limit is a finding of kind limit, with from, to and "
          "the limit, exit 3",
          "[cli][json][check]") {
    TempDir dir;
    const auto r =
        run_split(dir, "check " + q(source_path(kSample)) + " --limit table=0:8.9 --json");
    INFO(r.out << r.err);
    CHECK(r.exit_code == 3);
    const json doc = r.doc();
    check_head(doc, "check");
    CHECK(doc["deck"] == source_path(kSample));
    CHECK(doc["profile"] == "parsons-1952");
    CHECK(doc["cards_checked"] == 4);
    CHECK(doc["will_run_through"] == false);
    // The table passes 8.9 twice: card 1 (0 -> 8.985) and card 3 (8.385 -> 8.985).
    CHECK(doc["past_limit"] == 2);
    CHECK(doc["observed"] == 0);
    CHECK(doc["advice"] == 0);
    CHECK(doc["double_punches"] == 0);
    // The machine's verdict, from the run: it stops on card 1 at the soft limit.
    CHECK(doc["verdict"]["runs_through"] == false);
    CHECK(doc["verdict"]["cards_run"] == 1);
    CHECK(doc["verdict"]["stop"]["card"] == 1);
    CHECK(doc["verdict"]["stop"]["reason"] == "soft_limit");
    CHECK(doc["verdict"]["stop"]["axis"] == "table");
    const json& findings = doc["findings"];
    REQUIRE(findings.size() == 2);
    const json& first = findings[0];
    CHECK(first["card"] == 1);
    CHECK(first["number"] == 1);
    CHECK(first["kind"] == "limit");
    CHECK(first["axis"] == "table");
    CHECK(first["from_in"] == 0.0);
    CHECK(first["to_in"] == 8.985);
    CHECK(first["limit_in"] == 8.9);
    CHECK(first["limit_kind"] == "soft_limit");
    CHECK(first["message"].get<std::string>().find("table moves +8.985 in, from 0.000 to 8.985") ==
          0);
    const json& second = findings[1];
    CHECK(second["card"] == 3);
    CHECK(second["number"] == 3);
    CHECK(second["from_in"] == 8.385); // rounded to the thousandth, not 8.384999...
    CHECK(second["to_in"] == 8.985);
    // The text says the same.
    const auto text = run_parsons("check " + q(source_path(kSample)) + " --limit table=0:8.9");
    CHECK(text.exit_code == 3);
    CHECK(text.output.find("card 3 (number 0003): past a limit: " +
                           second["message"].get<std::string>()) != std::string::npos);

    // Positions summed in binary floating point (0.1 + 0.2) still read as the counters would.
    write_bytes(dir.path("steps.csv"), std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" +
                                           idle_rest(1) + "2,0,table,+,3,,,0.300,0.200,1\n" +
                                           idle_rest(2) + "3,0,table,+,3,,,0.700,0.400,1\n" +
                                           idle_rest(3));
    const auto steps =
        run_split(dir, "check " + q(dir.str("steps.csv")) + " --limit table=0:0.5 --json");
    INFO(steps.out << steps.err);
    CHECK(steps.exit_code == 3);
    const json past = steps.doc()["findings"];
    REQUIRE(past.size() == 1);
    CHECK(past[0]["card"] == 3);
    CHECK(past[0]["from_in"] == 0.3);
    CHECK(past[0]["to_in"] == 0.7);
    CHECK(past[0]["limit_in"] == 0.5);
}

TEST_CASE("Check --json: a deck that runs through has no findings and exit 0",
          "[cli][json][check]") {
    TempDir dir;
    const auto r = run_split(dir, "check " + q(source_path(kSample)) + " --json");
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    const json doc = r.doc();
    CHECK(doc["will_run_through"] == true);
    CHECK(doc["findings"] == json::array());
    CHECK(doc["cards_checked"] == 4);
    for (const char* count : {"past_limit", "observed", "double_punches", "advice"}) {
        CHECK(doc[count] == 0);
    }
    CHECK(doc["verdict"]["runs_through"] == true);
    CHECK(doc["verdict"]["cards_run"] == 4);
    CHECK(doc["verdict"]["machine_seconds"] == 841.871222);
    CHECK(doc["verdict"]["stop"].is_null());
    CHECK(doc["verdict"]["chain"] == json::array());
}

TEST_CASE("Check --json: a bad punch and a sequence stall are the run's stop, a double punch a "
          "finding of its kind, counted as the text counts them",
          "[cli][json][check][bad-punch]") {
    TempDir dir;
    SECTION("a stray hole in column 76: the reader stops the machine, exit 3") {
        const auto r = run_split(dir, "check " + q(sample_with_row5(dir, 2, 76)) + " --json");
        INFO(r.out << r.err);
        CHECK(r.exit_code == 3);
        const json doc = r.doc();
        CHECK(doc["will_run_through"] == false);
        const json& stop = doc["verdict"]["stop"];
        CHECK(stop["reason"] == "bad_punch");
        CHECK(stop["card"] == 2);
        CHECK(stop["number"].is_null()); // the card was not read
        CHECK(stop["axis"].is_null());
        CHECK(stop["message"].get<std::string>().find("card 2, column 76: ") == 0);
        CHECK(doc["verdict"]["chain"].back().get<std::string>().find(
                  "the machine stopped: bad_punch: card 2, column 76") == 0);
    }
    SECTION("a double punch in parsons-1952 is a finding of kind double_punch") {
        const std::string twice = sample_with_row5(dir, 2, 13);
        const auto r = run_split(dir, "check " + q(twice) + " --json");
        const auto text = run_parsons("check " + q(twice));
        INFO(r.out << r.err);
        const json doc = r.doc();
        REQUIRE(count_kind(doc["findings"], "double_punch") == 1);
        for (const auto& f : doc["findings"]) {
            if (f["kind"] == "double_punch") {
                CHECK(f["card"] == 2);
                CHECK(f["number"] == 2);
                CHECK(f["column"] == 13);
            }
        }
        CHECK(doc["double_punches"] == 1);
        CHECK(doc["double_punches"].get<std::size_t>() ==
              lines_with(text.output, ": double punch: ").size());
        CHECK(doc["observed"] == count_kind(doc["findings"], "observed"));
        CHECK(doc["past_limit"] == count_kind(doc["findings"], "limit"));
        CHECK(doc["will_run_through"] == (r.exit_code == 0));
        // parsons-safe refuses the card: the reader stops the machine there.
        const auto safe = run_split(dir, "check " + q(twice) + " --profile parsons-safe --json");
        CHECK(safe.exit_code == 3);
        CHECK(safe.doc()["profile"] == "parsons-safe");
        CHECK(safe.doc()["verdict"]["stop"]["reason"] == "bad_punch");
        CHECK(count_kind(safe.doc()["findings"], "double_punch") == 0);
    }
    SECTION("a sequence stall is the run's stop: exit 3, with the relay events before it") {
        const std::string stall = stall_deck(dir);
        const auto r = run_split(dir, "check " + q(stall) + " --json");
        const auto text = run_parsons("check " + q(stall));
        INFO(r.out << r.err << text.output);
        CHECK(r.exit_code == 3);
        const json doc = r.doc();
        CHECK(doc["will_run_through"] == false);
        CHECK(doc["verdict"]["stop"]["reason"] == "sequence_stall");
        CHECK(doc["verdict"]["stop"]["card"] == 1);
        CHECK(doc["verdict"]["stop"]["number"] == 1);
        // Every line of the chain is in the text, in order.
        std::size_t at = 0;
        for (const auto& line : doc["verdict"]["chain"]) {
            at = text.output.find("    " + line.get<std::string>(), at);
            CHECK(at != std::string::npos);
        }
        CHECK(doc["verdict"]["chain"].size() >= 3); // table, cross, the stop
    }
}

TEST_CASE("Gen --json: the template deck written, with the numbers the text prints",
          "[cli][json][gen]") {
    TempDir dir;
    const std::string deck = dir.str("n.cbn");
    const std::string args = "gen airfoil --naca 2412 --chord 6 --cutter-radius 0.25 --stations 30 "
                             "-o " +
                             q(deck);
    const auto r = run_split(dir, args + " --json --centres " + q(dir.str("c.csv")));
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    const json doc = r.doc();
    check_head(doc, "gen");
    CHECK(doc["generator"] == "airfoil");
    CHECK(doc["job"] == "template");
    CHECK(doc["deck"] == deck);
    CHECK(doc["format"] == "cbn");
    CHECK(doc["job_file"] == deck + ".job.json");
    CHECK(doc["centres"] == dir.str("c.csv"));
    CHECK(std::filesystem::exists(deck + ".job.json"));
    CHECK(doc["airfoil"] == "naca 2412");
    CHECK(doc["chord_in"] == 6.0);
    CHECK(doc["cutter_radius_in"] == 0.25);
    CHECK(doc["surface"] == "upper");
    CHECK(doc["female"] == false);
    // 160 bytes a card in .cbn.
    CHECK(doc["cards"].get<std::size_t>() * 160 == std::filesystem::file_size(deck));
    CHECK(doc["stations"] == 30); // --stations: per surface, one surface
    CHECK(doc["approach_cards"] == doc["cards"].get<int>() + 1 - doc["stations"].get<int>());
    // The same figures as the text summary.
    const auto text = run_parsons(args);
    INFO(text.output);
    REQUIRE(text.exit_code == 0);
    CHECK(text.output.find(fmt::format("  stations         {}\n", doc["stations"].get<int>())) !=
          std::string::npos);
    CHECK(text.output.find(fmt::format("  cards            {} ({} to approach, {} slowed",
                                       doc["cards"].get<int>(), doc["approach_cards"].get<int>(),
                                       doc["corner_cards"].get<int>())) != std::string::npos);
    CHECK(text.output.find(fmt::format("  largest scallop  {:.5f} in",
                                       doc["largest_scallop_in"].get<double>())) !=
          std::string::npos);
    CHECK(text.output.find(fmt::format("  largest dip      {:.5f} in",
                                       doc["largest_dip_in"].get<double>())) != std::string::npos);
    CHECK(text.output.find(fmt::format("  work zero        table {:.3f} in, cross slide {:.3f} in",
                                       doc["work_zero_in"]["table"].get<double>(),
                                       doc["work_zero_in"]["cross"].get<double>())) !=
          std::string::npos);
    CHECK(doc["largest_scallop_in"].get<double>() > 0);
}

TEST_CASE("Gen --json: the wing job, with span, taper, sweep and the zero", "[cli][json][gen]") {
    TempDir dir;
    const std::string deck = dir.str("w.cbn");
    const std::string args = "gen airfoil --naca 0012 --job wing --chord 4 --span 5 --taper 0.6 "
                             "--sweep 10 --stations 12 -o " +
                             q(deck);
    const auto r = run_split(dir, args + " --json");
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    const json doc = r.doc();
    CHECK(doc["job"] == "wing");
    CHECK(doc["span_in"] == 5.0);
    CHECK(doc["taper"] == 0.6);
    CHECK(doc["sweep_deg"] == 10.0);
    CHECK(doc["chord_in"] == 4.0);
    CHECK(doc["centres"].is_null());
    CHECK_FALSE(doc.contains("surface"));
    CHECK(doc["cards"].get<std::size_t>() * 160 == std::filesystem::file_size(deck));
    const auto text = run_parsons(args);
    INFO(text.output);
    CHECK(text.output.find(fmt::format("  stations         {} (one cut",
                                       doc["stations"].get<int>())) != std::string::npos);
    CHECK(text.output.find(fmt::format(
              "  zero             cross {:.3f}, table {:.3f}, vertical "
              "{:.3f} in",
              doc["zero_in"]["cross"].get<double>(), doc["zero_in"]["table"].get<double>(),
              doc["zero_in"]["vertical"].get<double>())) != std::string::npos);
}

TEST_CASE("Punch --json: the listing, the deck, its format and layout and the cards punched",
          "[cli][json][punch]") {
    TempDir dir;
    for (const auto& [name, format, bytes_per_card] :
         {std::tuple{"deck.cbn", "cbn", 160}, std::tuple{"deck.bin", "bin", 160}}) {
        const auto r = run_split(dir, "punch " + q(source_path(kSample)) + " -o " +
                                          q(dir.str(name)) + " --json");
        INFO(r.out << r.err);
        REQUIRE(r.exit_code == 0);
        const json doc = r.doc();
        check_head(doc, "punch");
        CHECK(doc["listing"] == source_path(kSample));
        CHECK(doc["deck"] == dir.str(name));
        CHECK(doc["format"] == format);
        CHECK(doc["layout"] == "fig8");
        CHECK(doc["code"] == "029");
        CHECK(doc["cards"] == 4);
        CHECK(std::filesystem::file_size(dir.path(name)) == 4U * bytes_per_card);
    }
    const auto text = run_split(dir, "punch " + q(source_path(kSample)) + " -o " +
                                         q(dir.str("deck.txt")) + " --code 026 --json");
    CHECK(text.doc()["format"] == "text");
    CHECK(text.doc()["code"] == "026");
}

TEST_CASE("CLI --json: with the deck on standard output (-o -), --json is refused, exit 2, before "
          "anything is written",
          "[cli][json][gen][punch]") {
    TempDir dir;
    // Without --json, a deck on standard output is supported.
    REQUIRE(run_split(dir, "punch " + q(source_path(kSample)) + " --to cbn -o -").exit_code == 0);
    for (const std::string& args :
         {"punch " + q(source_path(kSample)) + " --to cbn -o - --json",
          std::string("gen airfoil --naca 2412 --to cbn -o - --json"),
          "gen airfoil --naca 2412 -o " + q(dir.str("g.cbn")) + " --centres - --json"}) {
        const auto r = run_split(dir, args);
        INFO(args << "\n" << r.out << r.err);
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty()); // neither the deck nor a document
        CHECK(r.err.rfind("parsons: error: ", 0) == 0);
        CHECK(r.err.find("--json and ") != std::string::npos);
        CHECK(r.err.find("cannot both go to standard output") != std::string::npos);
    }
    CHECK_FALSE(std::filesystem::exists(dir.path("g.cbn")));
}

TEST_CASE(
    "CLI --json: unreadable input and bad usage are the usual error on standard error, exit 2, "
    "and no document",
    "[cli][json]") {
    TempDir dir;
    write_bytes(dir.path("broken.csv"), std::string(kHeader) + "1,0,table,+,9,,,1.000,1.000,1\n");
    for (const std::string& args :
         {"show " + q(dir.str("missing.cbn")) + " --json",
          "check " + q(dir.str("broken.csv")) + " --json",
          "punch " + q(dir.str("broken.csv")) + " -o " + q(dir.str("x.cbn")) + " --json",
          std::string("gen airfoil --naca 2412 --dat x.dat -o y.cbn --json"),
          std::string("show --json")}) {
        const auto r = run_split(dir, args);
        INFO(args << "\n" << r.out << r.err);
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty());
        CHECK(r.err.rfind("parsons: error: ", 0) == 0);
    }
}

TEST_CASE("CLI --json: each command's --help shows --json, and its --json example runs as written",
          "[cli][json][help]") {
    TempDir dir;
    // The examples name files of the source tree: run them in a copy of it.
    std::filesystem::create_directories(dir.path("decks/samples"));
    std::filesystem::copy_file(source_path(kSample), dir.path(kSample));
    const std::string cd = "cd " + q(dir.str("")) + " && ";
    const std::vector<std::pair<std::string, std::string>> commands = {
        {"show", "show"}, {"check", "check"}, {"punch", "punch"}, {"gen airfoil", "gen"}};
    for (const auto& [command, name] : commands) {
        const auto help = run_parsons(command + " --help");
        INFO(command << ":\n" << help.output);
        REQUIRE(help.exit_code == 0);
        CHECK(help.output.find("--json") != std::string::npos);
        const auto examples = lines_with(help.output, "  parsons " + command + " ");
        std::vector<std::string> with_json;
        for (const std::string& line : examples) {
            if (line.find(" --json") != std::string::npos) {
                const std::string example = line.substr(line.find("parsons ") + 8);
                with_json.push_back(example.substr(0, example.find("   ("))); // not its comment
            }
        }
        REQUIRE(with_json.size() == 1);
        const std::string err = dir.str("stderr.txt");
        const auto r = run_shell(cd + "PARSONS " + with_json.front() + " 2>" + q(err));
        INFO(with_json.front() << "\n" << r.output << read_bytes(err));
        CHECK((r.exit_code == 0 || (name == "check" && r.exit_code == 3)));
        const json doc = json::parse(r.output);
        CHECK(doc["command"] == name);
    }
}

TEST_CASE("CLI --json: docs/json-output.md names every field the commands emit",
          "[cli][json][docs]") {
    TempDir dir;
    const std::string sample = q(source_path(kSample));
    // Documents that between them carry every field: warnings, bad punches, every kind of
    // finding, both airfoil jobs and the tapping job.
    const std::string stall = q(stall_deck(dir));
    const std::string bad = q(sample_with_row5(dir, 2, 13));
    const std::vector<std::string> runs = {
        "show " + sample + " --json",
        "show " + stall + " --json",
        "show " + bad + " --json --svg " + q(dir.str("svg")),
        "show " + bad + " --json --profile parsons-safe",
        "check " + sample + " --limit table=0:8.9 --json",
        "check " + bad + " --json",
        "check " + bad + " --profile parsons-safe --json",
        "check " + stall + " --json",
        "punch " + sample + " -o " + q(dir.str("d.cbn")) + " --json",
        "gen airfoil --naca 2412 --stations 10 -o " + q(dir.str("t.cbn")) + " --json",
        "gen airfoil --naca 0012 --job wing --stations 8 -o " + q(dir.str("w.cbn")) + " --json",
        "gen tapping -o " + q(dir.str("p.csv")) + " --json"};
    std::set<std::string> keys;
    for (const std::string& args : runs) {
        const auto r = run_split(dir, args);
        INFO(args << "\n" << r.out << r.err);
        REQUIRE_FALSE(r.out.empty());
        collect_keys(r.doc(), keys);
    }
    for (const char* key : {"from_in", "limit_in", "bad_punch", "column", "verdict", "chain",
                            "lamps", "kind", "runs_through", "zero_in", "work_zero_in",
                            "slow_down_2", "will_run_through", "profile_file", "feed_in_per_min"}) {
        CHECK(keys.count(key) == 1); // the runs above do reach every kind of field
    }
    const std::string doc = read_bytes(source_path("docs/json-output.md"));
    for (const std::string& key : keys) {
        INFO("key " << key);
        CHECK(doc.find("`" + key + "`") != std::string::npos);
    }
    // And the README's list of docs links it.
    CHECK(read_bytes(source_path("README.md")).find("docs/json-output.md") != std::string::npos);
}
