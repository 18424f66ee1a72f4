// BenchJson's lines parse as JSON (read back here with yaml-cpp, whose
// parser takes JSON) and say what was written: strings with quotes,
// backslashes and control characters intact, numbers as the same doubles.
#include "tools/bench/report/BenchJson.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace arcomp {
namespace {

// The text as a JSON parser reads it back (from_chars: no locale, every digit).
double parsed(const std::string& number) {
    double x = 0.0;
    const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), x);
    EXPECT_EQ(error, std::errc{}) << number;
    EXPECT_EQ(end, number.data() + number.size()) << number;
    return x;
}

}  // namespace

TEST(BenchJson, stringsWithQuotesBackslashesAndControlCharactersParseBackUnchanged) {
    const std::string nasty = "out/\"quoted\" dir\\sub\n\ttab\x01\x1f end \xc3\xa9";
    BenchJson j;
    j.field("path", nasty).field("bench", "load");
    const std::string line = j.str();
    EXPECT_EQ(line.find('\n'), std::string::npos) << "one line: " << line;
    const YAML::Node back = YAML::Load(line);
    EXPECT_EQ(back["path"].as<std::string>(), nasty);
    EXPECT_EQ(back["bench"].as<std::string>(), "load");
}

TEST(BenchJson, stringsEscapeOnlyWhatJsonRequires) {
    BenchJson j;
    j.field("a", "plain /path.avi").field("b", "a\"b\\c").field("c", "\n\x1f").field("d", "\xc3\xa9");
    EXPECT_EQ(j.str(), "{\"a\":\"plain /path.avi\",\"b\":\"a\\\"b\\\\c\",\"c\":\"\\n\\u001f\",\"d\":\"\xc3\xa9\"}");
}

// A path from the command line need not be UTF-8: its bytes become U+FFFD
// and the bench still prints its line.
TEST(BenchJson, bytesThatAreNotUtf8DoNotCostTheLine) {
    BenchJson j;
    j.field("path", "clip\xff.avi").field("frames", 3);
    EXPECT_EQ(j.str(), "{\"path\":\"clip\xef\xbf\xbd.avi\",\"frames\":3}");
}

TEST(BenchJson, numbersReadBackAsTheSameDoubleAndStayReadable) {
    EXPECT_EQ(BenchJson::number(0.1), "0.1");
    EXPECT_EQ(BenchJson::number(5.0), "5");
    EXPECT_EQ(BenchJson::number(20000.0), "20000");  // not "2e+04"
    EXPECT_EQ(BenchJson::number(-2.5), "-2.5");
    EXPECT_EQ(BenchJson::number(1e-6), "1e-06");
    EXPECT_EQ(BenchJson::number(0.011f), "0.011");  // the float's digits, not its double's
    for (const double x : {1.0 / 3.0, std::numbers::pi, 123456.789, 58.82352941176471, 1e-6, 2.5e-300, 1e17,
                           std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min()})
        EXPECT_EQ(parsed(BenchJson::number(x)), x) << BenchJson::number(x);
}

TEST(BenchJson, nonFiniteNumbersAreNull) {
    EXPECT_EQ(BenchJson::number(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(BenchJson::number(std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(BenchJson::number(-std::numeric_limits<double>::infinity()), "null");
    EXPECT_EQ(BenchJson::number(Fixed{std::numeric_limits<double>::quiet_NaN(), 3}), "null");
    BenchJson j;
    j.field("psnr_db", std::numeric_limits<double>::infinity());
    EXPECT_EQ(j.str(), "{\"psnr_db\":null}");
}

TEST(BenchJson, fixedDecimalsRoundAsPrintfDoes) {
    EXPECT_EQ(BenchJson::number(Fixed{12.34567, 3}), "12.346");
    EXPECT_EQ(BenchJson::number(Fixed{2.0, 3}), "2.000");
    EXPECT_EQ(BenchJson::number(Fixed{0.86, 4}), "0.8600");
    EXPECT_EQ(BenchJson::number(Fixed{-0.0004, 3}), "-0.000");  // printf("%.3f") reads the same
    EXPECT_EQ(BenchJson::number(Fixed{41.96, 0}), "42");
}

TEST(BenchJson, integersBoolsAndNullAreWrittenExactly) {
    BenchJson j;
    j.field("frames", 300)
        .field("offset", -7)
        .field("triangles", std::size_t{27864})
        .field("drops", std::numeric_limits<std::uint64_t>::max())
        .field("ok", true)
        .field("met", false)
        .null("vtest");
    EXPECT_EQ(j.str(), "{\"frames\":300,\"offset\":-7,\"triangles\":27864,\"drops\":18446744073709551615,"
                       "\"ok\":true,\"met\":false,\"vtest\":null}");
}

TEST(BenchJson, nestsObjectsAndArraysAsTheBenchesDo) {
    BenchJson j;
    j.field("bench", "composite");
    j.beginArray("size").value(768).value(576).end();
    j.beginObject("median_ms").field("capture", 0.5).field("total", 12.25).end();
    j.beginArray("ldi");
    for (int n : {1, 7}) j.beginObject().field("ldis", n).field("build_s", Fixed{0.25 * n, 3}).end();
    j.end();
    j.beginArray("strips").value("a.png").value("b \"c\".png").end();
    j.beginArray("empty").end();
    const std::string line = j.str();
    EXPECT_EQ(line, "{\"bench\":\"composite\",\"size\":[768,576],\"median_ms\":{\"capture\":0.5,\"total\":12.25},"
                    "\"ldi\":[{\"ldis\":1,\"build_s\":0.25},{\"ldis\":7,\"build_s\":1.75}],"
                    "\"strips\":[\"a.png\",\"b \\\"c\\\".png\"],\"empty\":[]}");
    const YAML::Node back = YAML::Load(line);
    EXPECT_EQ(back["size"][1].as<int>(), 576);
    EXPECT_EQ(back["median_ms"]["total"].as<double>(), 12.25);
    EXPECT_EQ(back["ldi"][1]["ldis"].as<int>(), 7);
    EXPECT_EQ(back["strips"][1].as<std::string>(), "b \"c\".png");
    EXPECT_EQ(back["empty"].size(), 0u);
}

TEST(BenchJson, strCanBeAskedTwice) {
    BenchJson j;
    j.field("a", 1);
    EXPECT_EQ(j.str(), j.str());
    EXPECT_EQ(BenchJson().str(), "{}");
}

TEST(BenchJson, misuseIsALogicError) {
    BenchJson j;
    EXPECT_THROW(j.value(1), std::logic_error);  // an element in an object
    EXPECT_THROW(j.end(), std::logic_error);     // the outer object closes in str()
    j.beginArray("list");
    EXPECT_THROW(j.field("key", 1), std::logic_error);  // a key in an array
    EXPECT_THROW((void)j.str(), std::logic_error);      // the array still open
    j.end();
    EXPECT_EQ(j.str(), "{\"list\":[]}");
}

}  // namespace arcomp
