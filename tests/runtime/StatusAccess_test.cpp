#include "runtime/config/StatusAccess.hpp"

#include "../support/TempDir.hpp"
#include "graph/core/BadInput.hpp"

#include <gtest/gtest.h>

namespace arcomp {

TEST(StatusAccess, loopbackIsAll127ButNotEveryInterface) {
    EXPECT_TRUE(isLoopbackAddress("127.0.0.1"));
    EXPECT_TRUE(isLoopbackAddress("127.1.2.3"));
    EXPECT_FALSE(isLoopbackAddress("0.0.0.0"));
    EXPECT_FALSE(isLoopbackAddress("192.168.1.20"));
    EXPECT_FALSE(isLoopbackAddress("128.0.0.1"));
    EXPECT_FALSE(isLoopbackAddress("localhost"));  // not an address: the config asks for one
}

TEST(StatusAccess, theTokenIsTheFilesFirstLineTrimmed) {
    test::TempDir dir;
    EXPECT_EQ(readBearerToken(dir.write("token", "  0123456789abcdef0123\n# second line ignored\n")),
              "0123456789abcdef0123");
}

TEST(StatusAccess, aMissingEmptyShortOrSpacedTokenIsRefusedNamingTheFile) {
    test::TempDir dir;
    const auto refused = [](const std::filesystem::path& file, const std::string& expected) {
        try {
            readBearerToken(file);
            ADD_FAILURE() << file << " was accepted";
        } catch (const BadInput& e) {
            EXPECT_EQ(e.source, file.string());
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    };
    refused(dir.path() / "absent", "cannot read");
    refused(dir.write("empty", "\n"), "empty");
    refused(dir.write("short", "hunter2\n"), "expected at least 16");
    refused(dir.write("spaced", "0123456789 abcdef\n"), "printable ASCII");
}

TEST(StatusAccess, onlyTheWholeTokenAfterBearerMatches) {
    const std::string token = "0123456789abcdef";
    EXPECT_TRUE(bearerTokenMatches("Bearer 0123456789abcdef", token));
    EXPECT_TRUE(bearerTokenMatches("bearer  0123456789abcdef", token));
    EXPECT_FALSE(bearerTokenMatches("", token));
    EXPECT_FALSE(bearerTokenMatches("0123456789abcdef", token));
    EXPECT_FALSE(bearerTokenMatches("Basic 0123456789abcdef", token));
    EXPECT_FALSE(bearerTokenMatches("Bearer 0123456789abcde", token));    // a prefix
    EXPECT_FALSE(bearerTokenMatches("Bearer 0123456789abcdef0", token));  // longer
    EXPECT_FALSE(bearerTokenMatches("Bearer 0123456789abcdeF", token));
    EXPECT_FALSE(bearerTokenMatches("Bearer ", token));
}

}  // namespace arcomp
