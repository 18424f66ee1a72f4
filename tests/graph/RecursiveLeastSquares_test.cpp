// Recursive least squares with forgetting: the online re-fit of the
// frame-time cost model.
#include "graph/budget/RecursiveLeastSquares.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>

using namespace arcomp;

TEST(RecursiveLeastSquares, convergesToKnownSlopeAndIntercept) {
    // t = A·pixels + B with A = 3e-5 ms/px, B = 0.8 ms, measured with noise.
    RecursiveLeastSquares rls(2, 1.0);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pixels(0.0, 9e5);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (int i = 0; i < 400; ++i) {
        const double x = pixels(rng);
        rls.add(std::array{x, 1.0}, 3e-5 * x + 0.8 + noise(rng));
    }
    EXPECT_NEAR(rls.parameters()[0], 3e-5, 3e-7);
    EXPECT_NEAR(rls.parameters()[1], 0.8, 0.02);
}

TEST(RecursiveLeastSquares, forgettingFollowsAChangedMachine) {
    RecursiveLeastSquares rls(2, 0.95);
    for (int i = 0; i < 200; ++i) {
        const double x = 10.0 + (i % 17);
        rls.add(std::array{x, 1.0}, 1.0 * x + 2.0);
    }
    EXPECT_NEAR(rls.parameters()[0], 1.0, 1e-3);
    // The machine gets busy: everything costs 1.5 times as much.
    for (int i = 0; i < 200; ++i) {
        const double x = 10.0 + (i % 17);
        rls.add(std::array{x, 1.0}, 1.5 * x + 2.0);
    }
    EXPECT_NEAR(rls.parameters()[0], 1.5, 1e-2);
    EXPECT_NEAR(rls.parameters()[1], 2.0, 0.1);
}

TEST(RecursiveLeastSquares, withoutForgettingOldSamplesKeepTheirWeight) {
    RecursiveLeastSquares rls(2, 1.0);
    for (int i = 0; i < 200; ++i) rls.add(std::array{10.0 + (i % 17), 1.0}, 1.0 * (10.0 + (i % 17)) + 2.0);
    for (int i = 0; i < 200; ++i) rls.add(std::array{10.0 + (i % 17), 1.0}, 1.5 * (10.0 + (i % 17)) + 2.0);
    EXPECT_NEAR(rls.parameters()[0], 1.25, 0.05);  // the average of both machines
}

TEST(RecursiveLeastSquares, covarianceStaysBoundedWhenTheInputNeverChanges) {
    // The windup case: a steady controller feeds the same x every frame.
    RecursiveLeastSquares rls(2, 0.9, 1.0, 50.0);
    rls.reset(std::array{1.0, 0.0}, std::array{1.0, 1.0});
    for (int i = 0; i < 2000; ++i) rls.add(std::array{30.0, 1.0}, 33.0);
    EXPECT_NEAR(rls.predict(std::array{30.0, 1.0}), 33.0, 1e-6);
    // A single outlier moves the fit, but not to absurd values.
    rls.add(std::array{30.0, 1.0}, 60.0);
    EXPECT_LT(rls.predict(std::array{30.0, 1.0}), 60.0);
    EXPECT_GT(rls.parameters()[0], 0.0);
    EXPECT_LT(rls.parameters()[0], 3.0);
}
