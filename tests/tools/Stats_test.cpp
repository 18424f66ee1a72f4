#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace arcomp {

TEST(Stats, medianOfAnOddCountIsTheMiddleSample) {
    EXPECT_EQ(median(std::vector<double>{3.0, 1.0, 2.0}), 2.0);
    EXPECT_EQ(median(std::vector<double>{7.5}), 7.5);
    EXPECT_EQ(median(std::vector<double>{9.0, 1.0, 8.0, 2.0, 5.0}), 5.0);
}

TEST(Stats, medianOfAnEvenCountIsTheMeanOfTheMiddleTwo) {
    EXPECT_EQ(median(std::vector<double>{4.0, 1.0, 3.0, 2.0}), 2.5);
    EXPECT_EQ(median(std::vector<double>{10.0, 20.0}), 15.0);
}

TEST(Stats, samplesAreLeftInTheirOrder) {
    const std::vector<double> frameMs{5.0, 1.0, 4.0};
    EXPECT_DOUBLE_EQ(percentile(frameMs, 95), 4.9);
    EXPECT_EQ(frameMs, (std::vector<double>{5.0, 1.0, 4.0}));
}

TEST(Stats, percentileInterpolatesBetweenTheClosestRanks) {
    std::vector<double> v;
    for (int i = 100; i >= 0; --i) v.push_back(i);  // 0..100, reversed
    EXPECT_EQ(percentile(v, 0), 0.0);
    EXPECT_EQ(percentile(v, 100), 100.0);
    EXPECT_DOUBLE_EQ(percentile(v, 95), 95.0);
    EXPECT_DOUBLE_EQ(percentile(std::vector<double>{0.0, 10.0}, 95), 9.5);
    EXPECT_DOUBLE_EQ(percentile(std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0}, 25), 2.0);
    EXPECT_DOUBLE_EQ(percentile(std::vector<double>{1.0, 2.0, 3.0, 4.0}, 50),
                     median(std::vector<double>{1.0, 2.0, 3.0, 4.0}));
}

TEST(Stats, noSamplesHaveNoMedianAndBenchJsonWritesNull) {
    const std::vector<double> none;
    EXPECT_TRUE(std::isnan(median(none)));
    EXPECT_TRUE(std::isnan(percentile(none, 95)));
    BenchJson j;
    j.field("frame_ms_median", median(none));
    EXPECT_EQ(j.str(), "{\"frame_ms_median\":null}");
}

TEST(Stats, percentileOutsideZeroToHundredIsRefused) {
    const std::vector<double> v{1.0, 2.0};
    EXPECT_THROW(percentile(v, -1), std::invalid_argument);
    EXPECT_THROW(percentile(v, 100.5), std::invalid_argument);
    EXPECT_THROW(percentile(v, std::nan("")), std::invalid_argument);
}

}  // namespace arcomp
