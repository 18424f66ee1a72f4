#include "video/matte/PersonTracker.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <map>

namespace arcomp {
namespace {

const cv::Size kFrame(640, 360);

// A walker: a body of 30x120 pixels whose feet are at (x, feetY).
void drawWalker(cv::Mat& alpha, float x, int feetY) {
    cv::rectangle(alpha, cv::Rect(static_cast<int>(x) - 15, feetY - 119, 30, 120), cv::Scalar(255), cv::FILLED);
}

const TrackedPerson* byId(const std::vector<TrackedPerson>& people, int id) {
    for (const TrackedPerson& p : people)
        if (p.id == id) return &p;
    return nullptr;
}

}  // namespace

TEST(PersonTracker, theFootPointIgnoresAThinTrailBelowTheFeet) {
    cv::Mat labels(kFrame, CV_32S, cv::Scalar(0));
    labels(cv::Rect(100, 100, 40, 200)).setTo(3);  // feet on row 299
    labels(cv::Rect(130, 300, 1, 20)).setTo(3);    // a shadow's thin line, 20 pixels on
    const cv::Point2f foot = footPoint(labels, 3, cv::Rect(100, 100, 40, 220));
    EXPECT_NEAR(foot.y, 299.0f, 1.0f);
    EXPECT_NEAR(foot.x, 120.0f, 1.0f);
}

TEST(PersonTracker, twoWalkersWhoCrossKeepTheirIds) {
    PersonTracker tracker;
    std::map<int, float> firstX;  // id -> where the walker started
    int merged = 0;
    for (int frame = 0; frame < 60; ++frame) {
        cv::Mat alpha(kFrame, CV_8UC1, cv::Scalar(0));
        const float left = 100.0f + 8.0f * frame, right = 540.0f - 8.0f * frame;  // they meet around frame 27
        drawWalker(alpha, left, 300);
        drawWalker(alpha, right, 310);
        const auto& people = tracker.update(alpha);
        int seen = 0;
        for (const TrackedPerson& p : people) seen += p.missed == 0;
        merged += seen == 1;
        // The one hidden in the merged blob shares its label.
        if (seen == 1 && people.size() == 2u) {
            const TrackedPerson& hidden = people[0].missed ? people[0] : people[1];
            const TrackedPerson& shown = people[0].missed ? people[1] : people[0];
            EXPECT_TRUE(hidden.merged) << "frame " << frame;
            EXPECT_EQ(hidden.label, shown.label) << "frame " << frame;
        }
        for (const TrackedPerson& p : people)
            if (p.missed == 0) {
                EXPECT_FALSE(p.merged);
            }
        if (frame == 5) {
            ASSERT_EQ(people.size(), 2u);
            for (const TrackedPerson& p : people) firstX[p.id] = p.foot.x;
        }
    }
    EXPECT_GT(merged, 0);  // they did become one blob for a while
    // After crossing, the walker who started on the left is on the right, under the same id.
    const auto& people = tracker.people();
    ASSERT_EQ(firstX.size(), 2u);
    for (const auto& [id, x] : firstX) {
        const TrackedPerson* p = byId(people, id);
        ASSERT_NE(p, nullptr) << "id " << id << " was lost";
        EXPECT_EQ(p->missed, 0);
        const bool startedLeft = x < 320.0f;
        EXPECT_EQ(p->foot.x > 320.0f, startedLeft) << "id " << id;
        EXPECT_NEAR(p->foot.y, startedLeft ? 299.0f : 309.0f, 2.0f);
    }
}

TEST(PersonTracker, aFlickeringMatteKeepsTheIdAndTheFootPoint) {
    PersonTracker tracker;
    int id = 0;
    for (int frame = 0; frame < 20; ++frame) {
        cv::Mat alpha(kFrame, CV_8UC1, cv::Scalar(0));
        const bool flicker = frame >= 10 && frame < 13;  // the matte loses the person for three frames
        if (!flicker) drawWalker(alpha, 200.0f + 2.0f * frame, 300);
        const auto& people = tracker.update(alpha);
        ASSERT_EQ(people.size(), 1u) << "frame " << frame;
        if (frame == 0) id = people[0].id;
        EXPECT_EQ(people[0].id, id);
        EXPECT_EQ(people[0].missed, flicker ? frame - 9 : 0);
        EXPECT_NEAR(people[0].foot.y, 299.0f, 1.0f);
    }
}

TEST(PersonTracker, feetBelowTheFrameKeepTheLastFootPoint) {
    PersonTracker tracker;
    for (int frame = 0; frame < 10; ++frame) {
        cv::Mat alpha(kFrame, CV_8UC1, cv::Scalar(0));
        drawWalker(alpha, 300.0f, 330 + 5 * frame);  // walking towards the camera, out through the bottom edge
        tracker.update(alpha);
    }
    const TrackedPerson& p = tracker.people().at(0);
    EXPECT_FALSE(p.feetVisible);
    EXPECT_LT(p.foot.y, static_cast<float>(kFrame.height - 1));  // where the feet were last seen, not the edge
    EXPECT_GT(p.foot.y, 340.0f);
}

TEST(PersonTracker, labelsMarkEachPersonsPixelsAndDropNoise) {
    PersonTracker tracker;
    cv::Mat alpha(kFrame, CV_8UC1, cv::Scalar(0));
    drawWalker(alpha, 100.0f, 300);
    drawWalker(alpha, 400.0f, 300);
    cv::rectangle(alpha, cv::Rect(600, 10, 3, 3), cv::Scalar(255), cv::FILLED);  // 9 pixels: below the minimum area
    const auto& people = tracker.update(alpha);
    ASSERT_EQ(people.size(), 2u);
    for (const TrackedPerson& p : people) {
        EXPECT_GT(p.label, 0);
        EXPECT_EQ(cv::countNonZero(tracker.labels() == p.label), 30 * 120);
    }
    EXPECT_EQ(tracker.labels().at<int>(11, 601), 0);
}

}  // namespace arcomp
