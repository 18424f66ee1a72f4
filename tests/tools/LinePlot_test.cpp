#include "tools/bench/report/LinePlot.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>

namespace arcomp {

TEST(LinePlot, drawsEachSeriesInItsPaletteColour) {
    const auto file = std::filesystem::path(ARCOMP_TEST_OUTPUT) / "LinePlot" / "two-series.png";
    std::filesystem::remove(file);
    LinePlot plot("test", "x", "y");
    plot.addSeries("rising", {0, 1, 2, 3}, {0, 1, 2, 3});
    plot.addSeries("flat", {0, 1, 2, 3}, {1, 1, 1, 1});
    plot.addLevel("limit", 2.5);
    plot.writePng(file, 400, 300);

    const cv::Mat image = cv::imread(file.string());
    ASSERT_FALSE(image.empty());
    EXPECT_EQ(image.cols, 400);
    EXPECT_EQ(image.rows, 300);
    auto count = [&](cv::Vec3b bgr) {
        int n = 0;
        for (auto it = image.begin<cv::Vec3b>(); it != image.end<cv::Vec3b>(); ++it) n += *it == bgr;
        return n;
    };
    EXPECT_GT(count({200, 90, 40}), 50);  // first series
    EXPECT_GT(count({40, 60, 210}), 50);  // second series
}

TEST(LinePlot, refusesSeriesOfUnequalLength) {
    LinePlot plot("test", "x", "y");
    EXPECT_THROW(plot.addSeries("bad", {0, 1}, {0}), std::invalid_argument);
}

}  // namespace arcomp
