// End to end: the parsons executable as a user types it.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>

using parsons::test::kSample;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::source_path;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::string without_comments(const std::string& listing) {
    std::istringstream in(listing);
    std::string line;
    std::string out;
    while (std::getline(in, line)) {
        if (!line.empty() && line[0] != '#') {
            out += line + "\n";
        }
    }
    return out;
}

} // namespace

TEST_CASE("CLI: punch, convert to .cbn and back to a listing gives the sample listing", "[cli]") {
    TempDir dir;
    auto punched = run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.cbn")));
    REQUIRE(punched.exit_code == 0);
    CHECK(punched.output.find("punched 4 cards") != std::string::npos);
    CHECK(std::filesystem::file_size(dir.path("s.cbn")) == 4 * 160);
    REQUIRE(
        run_parsons("convert " + q(dir.str("s.cbn")) + " -o " + q(dir.str("s.bin"))).exit_code ==
        0);
    REQUIRE(
        run_parsons("convert " + q(dir.str("s.bin")) + " -o " + q(dir.str("s2.cbn"))).exit_code ==
        0);
    CHECK(read_bytes(dir.path("s2.cbn")) == read_bytes(dir.path("s.cbn")));
    REQUIRE(run_parsons("convert " + q(dir.str("s2.cbn")) + " -o " + q(dir.str("back.csv")))
                .exit_code == 0);
    CHECK(read_bytes(dir.path("back.csv")) == without_comments(read_bytes(source_path(kSample))));
}

TEST_CASE("CLI: show prints every field of every card of the sample deck", "[cli]") {
    TempDir dir;
    auto shown = run_parsons("show " + q(source_path(kSample)) + " --svg " + q(dir.str("cards")));
    REQUIRE(shown.exit_code == 0);
    const std::string& out = shown.output;
    for (const char* expected :
         {"card 1 · card number 0001 (columns 77-80) · spindle forward (column 1)",
          "card 3 · card number 0003 (columns 77-80) · spindle reverse (column 1)",
          "card 4 · card number 0004 (columns 77-80) · spindle off (column 1)",
          "  table     2-19     + forward    1      8.785        8.885        8.985  8.985  1,2",
          "  cross     20-33    + forward    2      2.300        (no field)   2.500  2.500  1,2",
          "  tilt      62-75    + forward    3      -            (no field)   0.125  0.125  5",
          "  table     2-19     - reverse    1      8.585        8.485        8.385  0.600  1,2",
          "4 cards read, 0 notes, 0 with bad punches; the machine runs it through"}) {
        INFO(expected);
        CHECK(out.find(expected) != std::string::npos);
    }
    for (int i = 1; i <= 4; ++i) {
        auto svg = dir.path("cards/card-000" + std::to_string(i) + ".svg");
        REQUIRE(std::filesystem::exists(svg));
        CHECK(read_bytes(svg).find("</svg>") != std::string::npos);
    }
}

TEST_CASE("CLI: show tells, from a run, the shared-bank equality and the stop it leads to",
          "[cli]") {
    TempDir dir;
    write_bytes(dir.path("hazard.csv"),
                "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n"
                "1,0,table,+,1,8.850,8.950,9.050,9.000,1\n"
                "1,0,cross,+,3,,,0.000,0.000,2\n"
                "1,0,vertical,+,3,,,0.000,0.000,3\n"
                "1,0,swivel,+,3,,,0.000,0.000,4\n"
                "1,0,tilt,+,3,,,0.000,0.000,5\n");
    auto shown = run_parsons("show " + q(dir.str("hazard.csv")));
    CHECK(shown.exit_code == 0);
    CHECK(shown.output.find("observed in the run: table: the absolute comparer 122' met 8.050, "
                            "which no field of the card punches (the banks 350-356 that "
                            "slow-downs and stop share compare equal there)") != std::string::npos);
    CHECK(shown.output.find("the machine stops here: check_mismatch: card 1 (number 0001), table: "
                            "at the stop only the absolute comparer 122' conducted: absolute "
                            "counter 8.950 (stop 9.050)") != std::string::npos);
    CHECK(
        shown.output.find("1 card read, 1 note, 0 with bad punches; the machine stops at card 1") !=
        std::string::npos);
}

TEST_CASE("CLI: a bad punch is named by card and column: show tells the reader's stop (exit 0), "
          "check and run stop (exit 3), a listing cannot hold it (exit 2)",
          "[cli][bad-input]") {
    TempDir dir;
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.bin"))).exit_code ==
        0);
    std::string bytes = read_bytes(dir.path("s.bin"));
    // Card 2, column 13 (table stop, digit 3): add a 5 punch -> double punch.
    const std::size_t i = 160 + 2 * 12 + 1;
    bytes[i] = static_cast<char>(bytes[i] | 0x01); // word bit 4 = row 5
    write_bytes(dir.path("bad.bin"), bytes);
    // parsons-safe's reader refuses a double punch: a machine stop (bad_punch). show tells it
    // and exits 0 (it shows; docs/stop-codes.md), check and run exit 3, never 2 (the file was
    // read).
    auto shown = run_parsons("show " + q(dir.str("bad.bin")) + " --profile parsons-safe");
    CHECK(shown.exit_code == 0);
    CHECK(shown.output.find("BAD PUNCH: column 13: double punch (rows 3 and 5) in table stop (the "
                            "reader stops the machine here)") != std::string::npos);
    CHECK(shown.output.find("1 with bad punches; the machine stops at card 2") !=
          std::string::npos);
    CHECK(shown.output.find("parsons: error:") == std::string::npos);
    for (const char* judge : {"check", "run"}) {
        INFO(judge);
        const auto judged = run_parsons(std::string(judge) + " " + q(dir.str("bad.bin")) +
                                        " --profile parsons-safe");
        CHECK(judged.exit_code == 3);
        CHECK(judged.output.find("bad_punch: card 2, column 13: double punch") !=
              std::string::npos);
    }
    // parsons-1952's reader closes two relays, as run does (rule 12): no bad punch.
    auto read = run_parsons("show " + q(dir.str("bad.bin")));
    CHECK(read.exit_code == 0);
    CHECK(read.output.find("double punch: column 13: the reader closes two relays of the bank") !=
          std::string::npos);
    CHECK(read.output.find("BAD PUNCH") == std::string::npos);
    auto converted = run_parsons("convert " + q(dir.str("bad.bin")) + " -o " + q(dir.str("x.csv")));
    CHECK(converted.exit_code == 2);
    CHECK(converted.output.find(": card 2, column 13: double punch (rows 3 and 5) in table stop") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("x.csv")));
}

TEST_CASE("CLI: bad input files give exit 2, a message naming where, and no output file",
          "[cli][bad-input]") {
    TempDir dir;
    struct Case {
        std::string name;
        std::string bytes;
        std::string message;
    };
    const std::string header = "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq\n";
    const std::vector<Case> cases = {
        {"short.cbn", std::string("\xC0\x40\x40", 3),
         "short.cbn: card 1, byte 4 (offset 0x3): truncated card: the file ends after 3 of its "
         "160 bytes"},
        {"nomark.cbn", std::string(160, '\x40'),
         "nomark.cbn: card 1, byte 1 (offset 0x0): no card-start mark"},
        {"long.txt", std::string(4097, 'A') + "\n", "long.txt:1: line is longer than 4096 bytes"},
        {"odd.txt", "AB{\n", "odd.txt:1:3: '{' is not a character of the IBM 029 keypunch"},
        {"empty.cbn", "", "empty.cbn: empty file: the deck has no cards"},
        {"axis.csv", header + "1,0,tabel,+,3,,,1.000,1.000,1\n",
         "axis.csv:2: unknown axis 'tabel'"},
        {"big.csv", header + "1,0,table,+,3,,,12.000,1.000,1\n",
         "big.csv:2: stop '12.000': over 9.999 inches"},
        {"decimals.csv", header + "1,0,table,+,3,,,1.5,1.000,1\n",
         "decimals.csv:2: stop '1.5': needs exactly three decimals"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        write_bytes(dir.path(c.name), c.bytes);
        auto r =
            run_parsons("convert " + q(dir.str(c.name)) + " --to cbn -o " + q(dir.str("out.cbn")));
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("parsons: error: " + dir.str(c.message)) != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir.path("out.cbn")));
        // No partial file left beside the output either.
        for (const auto& entry : std::filesystem::directory_iterator(dir.path(""))) {
            CHECK(entry.path().filename().string().find("partial") == std::string::npos);
        }
    }
}

TEST_CASE("CLI: a fig8 deck goes into a text deck as SIMH ~raw cards and comes back the same",
          "[cli][simh]") {
    TempDir dir;
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.cbn"))).exit_code ==
        0);
    auto r = run_parsons("convert " + q(dir.str("s.cbn")) + " -o " + q(dir.str("s.txt")));
    REQUIRE(r.exit_code == 0);
    const std::string text = read_bytes(dir.path("s.txt"));
    CHECK(std::count(text.begin(), text.end(), '\n') == 4);
    CHECK(text.starts_with("~raw"));
    REQUIRE(
        run_parsons("convert " + q(dir.str("s.txt")) + " -o " + q(dir.str("back.cbn"))).exit_code ==
        0);
    CHECK(read_bytes(dir.path("back.cbn")) == read_bytes(dir.path("s.cbn")));
}

TEST_CASE("CLI: a SIMH ~eof inside a text deck is passed over with one warning naming the line, "
          "and every card after it runs",
          "[cli][simh]") {
    TempDir dir;
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.txt"))).exit_code ==
        0);
    const std::string text = read_bytes(dir.path("s.txt"));
    const std::size_t second = text.find('\n', text.find('\n') + 1) + 1;
    write_bytes(dir.path("e.txt"),
                text.substr(0, second) + "~eof\n" + text.substr(second) + "~eoi\n");
    const std::string warning = "parsons: warning: " + dir.str("e.txt") +
                                ":3: '~eof' is SIMH's end-of-file card (rows 6-7-9), for a monitor "
                                "program the 1952 machine does not have: it is passed over";
    // run reads the deck twice (a look for condition, sync and tap cards first): one warning.
    const auto run =
        run_parsons("run " + q(dir.str("e.txt")) + " -q --report " + q(dir.str("r.json")));
    INFO(run.output);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.output, Catch::Contains(warning));
    CHECK(run.output.find(warning) == run.output.rfind(warning));
    CHECK(read_bytes(dir.path("r.json")).find("\"cards_read\": 4") != std::string::npos);
    const auto shown = run_parsons("show " + q(dir.str("e.txt")));
    CHECK_THAT(shown.output, Catch::Contains(warning));
    CHECK_THAT(shown.output, Catch::Contains("card 4"));
    // The same deck without the mark: no warning; a mark at the end says nothing.
    CHECK(run_parsons("show " + q(dir.str("s.txt"))).output.find("warning") == std::string::npos);
}

TEST_CASE("CLI: usage errors exit 2, --help exits 0 with an example", "[cli]") {
    CHECK(run_parsons("").exit_code == 2);
    auto unknown_command = run_parsons("frobnicate");
    CHECK(unknown_command.exit_code == 2);
    CHECK(unknown_command.output.find("parsons: error: unknown command 'frobnicate' (one of: "
                                      "punch, show, convert, run, check, profile, gen, demo, "
                                      "bench, sweep;") != std::string::npos);
    CHECK(run_parsons("punch").exit_code == 2);
    auto missing = run_parsons("show /nonexistent/deck.cbn");
    CHECK(missing.exit_code == 2);
    CHECK(missing.output.find("/nonexistent/deck.cbn: cannot open") != std::string::npos);
    TempDir dir;
    write_bytes(dir.path("deck.xyz"), std::string("\x01\x02\x03\x04", 4));
    auto unknown = run_parsons("show " + q(dir.str("deck.xyz")));
    CHECK(unknown.exit_code == 2);
    CHECK(unknown.output.find("deck.xyz: cannot tell the deck format from the extension or its "
                              "first bytes; give --format cbn, bin, text, listing, tape or five") !=
          std::string::npos);
    auto unknown_out =
        run_parsons("convert " + q(source_path(kSample)) + " -o " + q(dir.str("out.xyz")));
    CHECK(unknown_out.exit_code == 2);
    CHECK(unknown_out.output.find("out.xyz: cannot tell the deck format from the extension; give "
                                  "--to cbn") != std::string::npos);
    for (const char* cmd : {"punch", "show", "convert"}) {
        INFO(cmd);
        auto help = run_parsons(std::string(cmd) + " --help");
        CHECK(help.exit_code == 0);
        CHECK(help.output.find(std::string("parsons ") + cmd) != std::string::npos);
        CHECK(help.output.find("Example") != std::string::npos);
    }
}

TEST_CASE("CLI: show judges the card after a bad one against the bad card's numbers",
          "[cli][bad-input]") {
    TempDir dir;
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.bin"))).exit_code ==
        0);
    std::string bytes = read_bytes(dir.path("s.bin"));
    const std::size_t i = 160 + 2 * 12 + 1; // card 2, column 13: double punch
    bytes[i] = static_cast<char>(bytes[i] | 0x01);
    write_bytes(dir.path("bad.bin"), bytes);
    // parsons-safe's reader refuses the card: the run stops there, and card 3's advice is not
    // judged from numbers nobody read.
    auto shown = run_parsons("show " + q(dir.str("bad.bin")) + " --profile parsons-safe");
    CHECK(shown.exit_code == 0);
    CHECK(shown.output.find("4 cards read, 0 notes, 1 with bad punches; the machine stops at card "
                            "2") != std::string::npos);
}

TEST_CASE("Suite: no test name holds a semicolon (ctest would split it and run no test)",
          "[suite]") {
    const auto& tests = Catch::getRegistryHub().getTestCaseRegistry().getAllTests();
    REQUIRE(tests.size() > 100);
    for (const auto& t : tests) {
        INFO(t.getTestCaseInfo().name);
        CHECK(t.getTestCaseInfo().name.find(';') == std::string::npos);
    }
}

TEST_CASE("CLI: a listing of nothing but its header says no cards, an empty file says empty",
          "[cli][bad-input]") {
    TempDir dir;
    write_bytes(dir.path("header.csv"),
                "# a job not yet written\ncard,spindle,axis,motion,speed,slow1,slow2,stop,check,"
                "seq\n\n");
    write_bytes(dir.path("empty.csv"), "");
    auto header = run_parsons("show " + q(dir.str("header.csv")));
    CHECK(header.exit_code == 2);
    CHECK(header.output.find("header.csv: no cards: the file holds nothing but a header, "
                             "comments, blank lines or blank tape") != std::string::npos);
    auto empty = run_parsons("show " + q(dir.str("empty.csv")));
    CHECK(empty.exit_code == 2);
    CHECK(empty.output.find("empty.csv: empty file: the deck has no cards") != std::string::npos);
}

TEST_CASE("CLI: --plot x.png and --trace x.fst say the file is SVG or VCD", "[cli]") {
    TempDir dir;
    auto r = run_parsons("run " + q(source_path(kSample)) + " -q --plot " + q(dir.str("p.PNG")) +
                         " --trace " + q(dir.str("t.fst")));
    CHECK(r.exit_code == 0);
    CHECK(r.output.find("parsons: warning: --plot writes SVG: " + dir.str("p.PNG") +
                        " will hold SVG") != std::string::npos);
    CHECK(r.output.find("parsons: warning: --trace writes VCD: " + dir.str("t.fst") +
                        " will hold VCD") != std::string::npos);
    CHECK(read_bytes(dir.path("p.PNG")).find("<svg") != std::string::npos);
    auto plain = run_parsons("run " + q(source_path(kSample)) + " -q --plot " +
                             q(dir.str("p.svg")) + " --trace " + q(dir.str("t.vcd")));
    CHECK(plain.exit_code == 0);
    CHECK(plain.output.find("warning") == std::string::npos);
}

TEST_CASE("CLI: --job with neither --cut nor --html (nothing reads it) is refused, naming --job",
          "[cli][bad-input]") {
    TempDir dir;
    REQUIRE(run_parsons("gen airfoil --chord 2 --stations 10 --naca 0012 -o " + q(dir.str("a.cbn")))
                .exit_code == 0);
    const std::string run =
        "run " + q(dir.str("a.cbn")) + " -q --job " + q(dir.str("a.cbn.job.json"));
    const auto alone = run_parsons(run + " --report " + q(dir.str("r.json")));
    INFO(alone.output);
    CHECK(alone.exit_code == 2);
    CHECK_THAT(alone.output, Catch::Contains("parsons: error: --job: the job description is read "
                                             "only for --cut"));
    CHECK_FALSE(std::filesystem::exists(dir.path("r.json")));
    // With either reader of it, the same --job is taken.
    CHECK(run_parsons(run + " --cut " + q(dir.str("c.svg"))).exit_code == 0);
    CHECK(std::filesystem::exists(dir.path("c.svg")));
    CHECK(run_parsons(run + " --html " + q(dir.str("p.html"))).exit_code == 0);
    CHECK(std::filesystem::exists(dir.path("p.html")));
}

TEST_CASE("CLI: a --job written for another deck is refused, whatever format the deck is in",
          "[cli][bad-input]") {
    TempDir dir;
    const std::string gen = "gen airfoil --chord 2 --stations 10 ";
    REQUIRE(run_parsons(gen + "--naca 0012 -o " + q(dir.str("a.cbn"))).exit_code == 0);
    REQUIRE(run_parsons(gen + "--naca 2412 -o " + q(dir.str("b.cbn"))).exit_code == 0);
    auto wrong = run_parsons("run " + q(dir.str("a.cbn")) + " -q --cut " + q(dir.str("c.svg")) +
                             " --job " + q(dir.str("b.cbn.job.json")));
    CHECK(wrong.exit_code == 2);
    CHECK(wrong.output.find("b.cbn.job.json: this job description was written for another deck") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path("c.svg")));
    // The deck's own job, and the same cards in another format, are accepted.
    REQUIRE(
        run_parsons("convert " + q(dir.str("a.cbn")) + " -o " + q(dir.str("a.bin"))).exit_code ==
        0);
    for (const char* deck : {"a.cbn", "a.bin"}) {
        INFO(deck);
        CHECK(run_parsons("run " + q(dir.str(deck)) + " -q --cut " + q(dir.str("c.svg")) +
                          " --job " + q(dir.str("a.cbn.job.json")))
                  .exit_code == 0);
    }
}

TEST_CASE("CLI: a deck whose content plainly is another format than its extension says is read "
          "as what it is, with one warning naming file, both formats and why",
          "[cli][deck-io]") {
    TempDir dir;
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.cbn"))).exit_code ==
        0);
    for (const std::string ext : {"txt", "bin", "tape", "csv"}) {
        REQUIRE(run_parsons("convert " + q(dir.str("s.cbn")) + " -o " + q(dir.str("s." + ext)))
                    .exit_code == 0);
    }
    struct Case {
        std::string from; // the deck's true file
        std::string name; // the name it is given
        std::string extension_says;
        std::string found;
        std::string why;
    };
    const std::vector<Case> cases = {
        {"s.txt", "t.cbn", "cbn", "text", "its first "},
        {"s.cbn", "c.txt", "text", "cbn", "its first 640 bytes are 4 whole column-binary cards"},
        {"s.bin", "b.cbn", "cbn", "bin", "its first 640 bytes are 4 whole IBM 1130 binary cards"},
        {"s.cbn", "c.bin", "bin", "cbn", "its first 640 bytes are 4 whole column-binary cards"},
        {"s.tape", "p.cbn", "cbn", "tape", "160 frames with channel 8 clear and odd parity"},
        {"s.csv", "l.txt", "text", "listing", "line 1 is the listing's header"},
        {"s.txt", "t.csv", "listing", "text", "and none holds a comma, as every listing row does"},
        {"s.cbn", "c.tape", "tape", "cbn", "4 whole column-binary cards"},
    };
    const std::string deck = read_bytes(dir.path("s.cbn"));
    for (const Case& c : cases) {
        INFO(c.name);
        write_bytes(dir.path(c.name), read_bytes(dir.path(c.from)));
        const auto r = parsons::test::run_shell("PARSONS convert " + q(dir.str(c.name)) + " -o " +
                                                q(dir.str("out.cbn")) + " >/dev/null");
        CHECK(r.exit_code == 0);
        const std::string start = "parsons: warning: " + dir.str(c.name) + ": the extension says " +
                                  c.extension_says + ", but the content is " + c.found + ": ";
        CHECK(r.output.rfind(start, 0) == 0);
        CHECK_THAT(r.output, Catch::Matchers::Contains(c.why));
        CHECK_THAT(r.output, Catch::Matchers::EndsWith("; read as " + c.found + " (--format " +
                                                       c.extension_says +
                                                       " reads it as the extension says)\n"));
        CHECK(parsons::test::lines_of(r.output).size() == 1);
        CHECK(read_bytes(dir.path("out.cbn")) == deck);
    }
    SECTION("run reads such a deck the same way, with the one warning") {
        REQUIRE(run_parsons("convert " + q(dir.str("s.cbn")) + " -o " + q(dir.str("t.cbn")) +
                            " --to text")
                    .exit_code == 0);
        const auto r =
            parsons::test::run_shell("PARSONS run " + q(dir.str("t.cbn")) + " --report " +
                                     q(dir.str("r.json")) + " -q >/dev/null");
        CHECK(r.exit_code == 0);
        CHECK(parsons::test::lines_of(r.output).size() == 1);
    }
    SECTION("a deck that fits its extension: no warning") {
        for (const std::string name : {"s.cbn", "s.txt", "s.bin", "s.tape", "s.csv"}) {
            INFO(name);
            const auto r = parsons::test::run_shell("PARSONS convert " + q(dir.str(name)) + " -o " +
                                                    q(dir.str("out.cbn")) + " >/dev/null");
            CHECK(r.exit_code == 0);
            CHECK(r.output.empty());
        }
    }
    SECTION("no format or several, or --format given: the extension's reader, its error, exit 2") {
        write_bytes(dir.path("c.five"), deck); // column binary: a .five's own bytes
        auto r = run_parsons("convert " + q(dir.str("c.five")) + " -o " + q(dir.str("x.cbn")));
        CHECK(r.exit_code == 2);
        CHECK(r.output.rfind("parsons: error: " + dir.str("c.five") + ": card 1, column 76", 0) ==
              0);
        write_bytes(dir.path("comma.csv"), "HELLO, 1952\n");
        r = run_parsons("convert " + q(dir.str("comma.csv")) + " -o " + q(dir.str("x.cbn")));
        CHECK(r.exit_code == 2);
        CHECK(r.output.rfind("parsons: error: " + dir.str("comma.csv") + ":1: expected the header",
                             0) == 0);
        write_bytes(dir.path("t.cbn"), read_bytes(dir.path("s.txt")));
        r = run_parsons("convert " + q(dir.str("t.cbn")) + " --format cbn -o " +
                        q(dir.str("x.cbn")));
        CHECK(r.exit_code == 2);
        CHECK(r.output.rfind("parsons: error: " + dir.str("t.cbn") + ": card 1, byte 1", 0) == 0);
        CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn")));
    }
}
