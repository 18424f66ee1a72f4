#include "tools/bench/scenes/FlightScene.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace arcomp {

namespace {

// A unit mountain: height 1 at the centre falling to 0 at radius 1, with
// ridges so that shading shows; cells × cells quads over [-1, 1]².
Geometry mountainMesh(int cells, float ridgePhase) {
    Geometry g;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const float x = -1.0f + 2.0f * static_cast<float>(i) / static_cast<float>(cells);
            const float z = -1.0f + 2.0f * static_cast<float>(j) / static_cast<float>(cells);
            const float r = std::min(1.0f, std::sqrt(x * x + z * z));
            const float angle = std::atan2(z, x);
            const float ridges = 1.0f + 0.18f * std::sin(5.0f * angle + ridgePhase) * r + 0.06f * std::sin(13.0f * r);
            g.positions.push_back({x, std::pow(1.0f - r, 1.4f) * ridges, z});
        }
    const auto row = static_cast<std::uint32_t>(cells + 1);
    for (std::uint32_t j = 0; j < static_cast<std::uint32_t>(cells); ++j)
        for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(cells); ++i) {
            const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
            g.indices.insert(g.indices.end(), {a, c, b, b, c, d});
        }
    g.finalize();
    return g;
}

}  // namespace

FlightScene buildFlightScene(const FlightOptions& o) {
    FlightScene f;
    Scene& s = f.world.scene;
    // A fine level 0: the controller's room is what levels save, and the
    // pixels of the range seen close up cost the same at every level; with a
    // coarse level 0 that floor would lie above the open-country frames'
    // full-detail time, and no target could be held along the whole path.
    const int cells[3] = {72, 20, 8};
    std::array<std::uint32_t, 3> geometry{};
    for (int l = 0; l < 3; ++l) {
        Geometry g = mountainMesh(cells[l], 0.7f);
        f.trianglesPerLevel[static_cast<std::size_t>(l)] = g.triangleCount();
        geometry[static_cast<std::size_t>(l)] = s.addGeometry(std::move(g));
    }
    std::uint32_t materials[4];
    const glm::vec4 colors[4] = {
        {0.32f, 0.45f, 0.22f, 1}, {0.45f, 0.40f, 0.30f, 1}, {0.38f, 0.42f, 0.30f, 1}, {0.55f, 0.52f, 0.48f, 1}};
    for (int i = 0; i < 4; ++i) {
        Material m;
        m.baseColor = colors[i];
        m.roughness = 0.6f;
        materials[i] = s.addMaterial(m);
    }
    // Most mountains in one dense range north-east of the origin; the rest
    // scattered thinly over the plain.
    std::mt19937 rng(o.seed);
    std::normal_distribution<float> range(0.0f, 90.0f);
    std::uniform_real_distribution<float> plain(-450.0f, 450.0f), radius(18.0f, 55.0f), height(0.5f, 1.1f), u(0, 1);
    for (int k = 0; k < o.mountains; ++k) {
        const bool dense = k < o.mountains * 2 / 3;
        const glm::vec3 at = dense ? glm::vec3(150.0f + range(rng), 0.0f, -150.0f + range(rng))
                                   : glm::vec3(plain(rng), 0.0f, plain(rng));
        const float r = radius(rng);
        const glm::mat4 m =
            glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), at), u(rng) * glm::two_pi<float>(), {0, 1, 0}),
                       {r, r * height(rng), r});
        const NodeId t = s.addTransform(s.root(), m);
        const NodeId lod = s.addNode(t, NodeKind::Lod, f.world.lods.add(LodNode{}));
        const std::uint32_t material = materials[k % 4];
        std::array<NodeId, 3> levels{};
        for (std::size_t l = 0; l < 3; ++l) levels[l] = s.addMesh(lod, {geometry[l], material});
        f.mountains.push_back(levels);
    }
    s.update();
    return f;
}

View flightView(double t, glm::ivec2 viewport) {
    // One loop around the range, a wide ellipse, flying low.
    const double a = glm::two_pi<double>() * t;
    const glm::vec3 centre(100.0f, 0.0f, -100.0f);
    auto at = [&](double phase) {
        return centre + glm::vec3(static_cast<float>(380.0 * std::cos(phase)), 0.0f,
                                  static_cast<float>(260.0 * std::sin(phase)));
    };
    glm::vec3 eye = at(a);
    eye.y = 45.0f + 25.0f * static_cast<float>(std::sin(3.0 * a));
    // Looking ahead and well towards the range near its eastern end, close
    // by; ahead and only a little towards it from the far side.
    glm::vec3 tangent = at(a + 0.01) - at(a);
    tangent.y = 0.0f;
    glm::vec3 toRange = glm::vec3(150.0f, 0.0f, -150.0f) - glm::vec3(eye.x, 0.0f, eye.z);
    const glm::vec3 dir = glm::normalize(glm::normalize(tangent) +
                                         (1.5f + 0.7f * static_cast<float>(std::cos(a))) * glm::normalize(toRange));
    glm::vec3 target = eye + 100.0f * dir;
    target.y = eye.y - 25.0f;
    return View::lookAt(eye, target, {0, 1, 0}, 55.0f, viewport, 1.0f, 2000.0f);
}

}  // namespace arcomp
