#include "runtime/operator/HttpRequest.hpp"

#include <gtest/gtest.h>

namespace arcomp {

using namespace std::string_view_literals;

TEST(HttpRequest, aScrapersRequestGivesItsMethodPathAndToken) {
    const auto head = parseHttpRequestHead(
        "GET /metrics?name=x HTTP/1.1\r\nHost: 127.0.0.1\r\nauthorization:  Bearer abc123 \r\nAccept: */*\r\n\r\n");
    ASSERT_EQ(head.state, HttpRequestHead::Complete) << head.error;
    EXPECT_EQ(head.method, "GET");
    EXPECT_EQ(head.path, "/metrics");
    EXPECT_EQ(head.authorization, "Bearer abc123");
}

TEST(HttpRequest, bareLineFeedsEndAHeadToo) {
    const auto head = parseHttpRequestHead("GET /status HTTP/1.0\nHost: x\n\n");
    ASSERT_EQ(head.state, HttpRequestHead::Complete) << head.error;
    EXPECT_EQ(head.path, "/status");
    EXPECT_TRUE(head.authorization.empty());
}

TEST(HttpRequest, aHeadStillArrivingIsIncompleteAtEveryByte) {
    const std::string whole = "GET /status HTTP/1.1\r\nHost: x\r\n\r\n";
    for (std::size_t n = 0; n < whole.size(); ++n)
        EXPECT_EQ(parseHttpRequestHead(whole.substr(0, n)).state, HttpRequestHead::Incomplete) << n;
    EXPECT_EQ(parseHttpRequestHead(whole).state, HttpRequestHead::Complete);
}

TEST(HttpRequest, aHeadOverTheLimitIsTooLargeWhetherOrNotItEnded) {
    const std::string endless = "GET /status HTTP/1.1\r\nX: " + std::string(kMaxHttpHeadBytes, 'a');
    EXPECT_EQ(parseHttpRequestHead(endless).state, HttpRequestHead::TooLarge);
    EXPECT_EQ(parseHttpRequestHead(endless + "\r\n\r\n").state, HttpRequestHead::TooLarge);
    EXPECT_EQ(parseHttpRequestHead(std::string(kMaxHttpHeadBytes, 'a')).state, HttpRequestHead::Incomplete);
}

struct BadHead {
    std::string_view text;
    const char* error;
};

class HttpRequestRefuses : public ::testing::TestWithParam<BadHead> {};

TEST_P(HttpRequestRefuses, withTheReason) {
    const auto head = parseHttpRequestHead(GetParam().text);
    EXPECT_EQ(head.state, HttpRequestHead::Bad);
    EXPECT_NE(head.error.find(GetParam().error), std::string::npos) << head.error;
}

INSTANTIATE_TEST_SUITE_P(
    Garbage, HttpRequestRefuses,
    ::testing::Values(BadHead{"\x16\x03\x01\x02\x00\x01\x00\r\n\r\n"sv, "request line"},
                      BadHead{"GET\r\n\r\n", "request line"}, BadHead{"G(T /status HTTP/1.1\r\n\r\n", "method"},
                      BadHead{"GET status HTTP/1.1\r\n\r\n", "target"},
                      BadHead{"GET /st\x01tus HTTP/1.1\r\n\r\n", "target"},
                      BadHead{"GET /status HTTP/2\r\n\r\n", "version"},
                      BadHead{"GET /status HTTP/1.1\r\nno colon here\r\n\r\n", "header line"},
                      BadHead{"GET /status HTTP/1.1\r\nBad Name: x\r\n\r\n", "header line"},
                      BadHead{"GET /status HTTP/1.1\r\nX: a\x01z\r\n\r\n", "control character"},
                      BadHead{"GET /status HTTP/1.1\r\nAuthorization: Bearer a\r\nAuthorization: Bearer b\r\n\r\n",
                              "more than one Authorization"}));

}  // namespace arcomp
