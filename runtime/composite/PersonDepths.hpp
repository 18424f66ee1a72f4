#pragma once
// How far away each person pixel is: which person it belongs to, and that
// person's distance along the camera's view axis. The compositor draws a
// person pixel over the CG unless the holdout there is nearer.
//
// A person is a vertical card through their feet, facing the camera, not a
// plane of one depth: the camera looks down, so their head is nearer along
// the view axis than their feet, as the near face of an object beside them
// is. (With one depth per person, someone beside a box at its own distance
// was cut across the middle: the box's top in front, its foot behind.)
// Across a card, 1 / depth is linear in the pixel: `inverseDepth` holds
// (a, b, c) with 1 / depth = a u + b v + c at video pixel (u, v), OpenCV's
// convention (pixel centres at integers, v down).
//
// Slot 0 is everyone not tracked (and every pixel, when `slots` is empty):
// it stands on the config's person plane, one depth. Slots 1..kMaxPeople
// are tracked people. `slots` may be smaller than the frame by an integer
// factor (`slotScale`): the person layer's pixel (x, y) reads slot
// (x, y) / slotScale.

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include <algorithm>
#include <array>

namespace arcomp {

struct PersonDepths {
    static constexpr int kMaxPeople = 63;

    cv::Mat slots;  // CV_8UC1, or empty
    int slotScale = 1;
    std::array<float, kMaxPeople + 1> metres{};  // at the feet
    std::array<glm::vec3, kMaxPeople + 1> inverseDepth{};
    int people = 0;  // slots 1..people are in use

    // A slot standing all at one depth.
    void setFlat(int slot, float depthMetres) {
        metres[static_cast<std::size_t>(slot)] = depthMetres;
        inverseDepth[static_cast<std::size_t>(slot)] = glm::vec3(0.0f, 0.0f, 1.0f / depthMetres);
    }
    static PersonDepths everyoneAt(float depthMetres) {
        PersonDepths d;
        for (int i = 0; i <= kMaxPeople; ++i) d.setFlat(i, depthMetres);
        return d;
    }

    float farthest() const {
        float d = metres[0];
        for (int i = 1; i <= people; ++i) d = std::max(d, metres[static_cast<std::size_t>(i)]);
        return d;
    }
};

}  // namespace arcomp
