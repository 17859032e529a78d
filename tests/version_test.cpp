// `parsons --version`: the project's version (CMakeLists.txt's project()) and the git
// description of the source it was built from, written at every build by
// cmake/git_version.cmake.
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <string>

using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::run_shell;

TEST_CASE("CLI --version: prints parsons, the project's version and the source's git "
          "description, and exits 0",
          "[cli][version]") {
    const auto r = run_parsons("--version");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    const std::string head = std::string("parsons ") + PARSONS_PROJECT_VERSION + " (";
    REQUIRE(r.output.rfind(head, 0) == 0);
    REQUIRE(r.output.size() > head.size() + 2);
    CHECK(r.output.substr(r.output.size() - 2) == ")\n");
    const std::string description = r.output.substr(head.size(), r.output.size() - head.size() - 2);
    CHECK_FALSE(description.empty());
    CHECK(description.find('\n') == std::string::npos);
    // Built from a git clone with git at hand: git's own description of the source (the
    // build writes it at every build, so it is the tree's as it was built).
    const auto git = run_shell("git -C " + q(PARSONS_SOURCE_DIR) +
                               " describe --always --dirty --tags 2>/dev/null");
    if (git.exit_code == 0 && !git.output.empty()) {
        CHECK(description + "\n" == git.output);
    } else {
        CHECK(description == "no git description");
    }
    // The flag is listed in the top-level help, and a command's help does not take it for
    // an option of its own.
    CHECK_THAT(run_parsons("--help").output, Catch::Contains("--version"));
    CHECK(run_parsons("run --version").exit_code == 2);
}
