#pragma once
// How far away each person pixel is: which person it belongs to, and that
// person's distance along the camera's view axis. The compositor draws a
// person pixel over the CG unless the holdout there is nearer.
//
// Slot 0 is everyone not tracked (and every pixel, when `slots` is empty):
// it stands at the config's person plane. Slots 1..kMaxPeople are tracked
// people. `slots` may be smaller than the frame by an integer factor
// (`slotScale`): the person layer's pixel (x, y) reads slot (x, y) / slotScale.

#include <opencv2/core/mat.hpp>

#include <array>

namespace arcomp {

struct PersonDepths {
    static constexpr int kMaxPeople = 63;

    cv::Mat slots;  // CV_8UC1, or empty
    int slotScale = 1;
    std::array<float, kMaxPeople + 1> metres{};
    int people = 0;  // slots 1..people are in use

    float farthest() const {
        float d = metres[0];
        for (int i = 1; i <= people; ++i) d = std::max(d, metres[static_cast<std::size_t>(i)]);
        return d;
    }
};

} // namespace arcomp
