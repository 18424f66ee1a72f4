#include "graph/grouping/GroupingMeasure.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

int GroupingParams::stepCount() const {
    if (!(omegaStep > 0.0f) || omegaMax < omegaStart) return 1;
    return static_cast<int>(std::floor((double(omegaMax) - double(omegaStart)) / double(omegaStep) + 0.5)) + 1;
}

GroupingItem groupingItem(const Box& box, const glm::vec3& color, const glm::vec3& velocity) {
    return {box, box.volume(), color, velocity};
}

namespace {

// Shape dissimilarity, Kato, Kanoh, Nishihara, "A Realtime Display Method
// for Virtual Environment Using Grouping Operation", eq. (7):
// Ms = (V12 - (V1 + V2)) / V12, V12 the volume of the box enclosing both.
// Overlapping boxes would make it negative; the differing volume d of
// eq. (6) cannot be, so it is held at 0.
float shapeDissimilarity(float v1, float v2, float v12) {
    if (!(v12 > 0.0f)) return 0.0f;
    return std::max(0.0f, (v12 - (v1 + v2)) / v12);
}

}  // namespace

// Kato, Kanoh, Nishihara, eqs. (3)-(5), (9)-(11):
// Ω = αp·L2/Leye + αs·Ms/Leye + αc·Mc/Leye + αf·|v1 - v2|/Leye, with
// Mc = sqrt(ΔR² + ΔG² + ΔB²); Ω0 is Ω at Leye = L0.
float omega0(const GroupingItem& a, const GroupingItem& b, const GroupingParams& p) {
    const float l2 = glm::length(a.box.center() - b.box.center());
    Box both = a.box;
    both.expand(b.box);
    const float ms = shapeDissimilarity(a.volume, b.volume, both.volume());
    const float mc = glm::length(a.color - b.color);
    const float dv = glm::length(a.velocity - b.velocity);
    return (p.alphaP * l2 + p.alphaS * ms + p.alphaC * mc + p.alphaF * dv) / p.l0;
}

// Kato, Kanoh, Nishihara, eq. (11): Ω = Ω0·L0/Leye.
float omegaAt(float omega0, float leye, const GroupingParams& p) { return omega0 * p.l0 / std::max(leye, 1e-6f); }

GroupingItem mergedItem(const GroupingItem& a, const GroupingItem& b) {
    GroupingItem g;
    g.box = a.box;
    g.box.expand(b.box);
    g.volume = g.box.volume();
    const float w = a.volume + b.volume;
    const float wa = w > 0.0f ? a.volume / w : 0.5f;
    const float wb = w > 0.0f ? b.volume / w : 0.5f;
    g.color = a.color * wa + b.color * wb;
    g.velocity = a.velocity * wa + b.velocity * wb;
    return g;
}

}  // namespace arcomp
