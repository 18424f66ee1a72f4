#include "graph/scenes/PaperForest.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

namespace arcomp {

namespace {

constexpr float kCrownRadius = 100.0f;
constexpr float kCrownHeight = 200.0f;  // of its centre
constexpr float kTrunkRadius = 15.0f;
constexpr float kTrunkTop = 110.0f;  // inside the crown
constexpr int kColumns = 8;
constexpr int kRows = 4;

// A prism of `sides` sides from y = 0 to `top`, open below; with `cap`, a
// fan closes the top.
Geometry makePrism(int sides, float radius, float top, bool cap) {
    Geometry g;
    for (int i = 0; i < sides; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(sides);
        g.positions.push_back({radius * std::cos(a), 0.0f, radius * std::sin(a)});
        g.positions.push_back({radius * std::cos(a), top, radius * std::sin(a)});
    }
    const auto n = static_cast<std::uint32_t>(sides);
    for (std::uint32_t i = 0; i < n; ++i) {
        const std::uint32_t j = (i + 1) % n;
        g.indices.insert(g.indices.end(), {2 * i, 2 * i + 1, 2 * j, 2 * j, 2 * i + 1, 2 * j + 1});
    }
    if (cap)
        for (std::uint32_t i = 1; i + 1 < n; ++i) g.indices.insert(g.indices.end(), {1, 2 * (i + 1) + 1, 2 * i + 1});
    g.finalize();
    return g;
}

const std::array<std::pair<int, int>, 5> kRedTrees{{{1, 0}, {6, 1}, {3, 2}, {0, 3}, {5, 3}}};  // column, row

}  // namespace

// Full: a 7 × 8 UV sphere (98 triangles). Simplified: a bipyramid over a
// triangle (6 triangles).
Geometry makeTreeCrown(bool simplified) {
    Geometry g;
    if (!simplified) {
        g = makeUvSphere(kCrownRadius, 7, 8);
    } else {
        for (int i = 0; i < 3; ++i) {
            const float a = 2.0f * std::numbers::pi_v<float> * float(i) / 3.0f;
            g.positions.push_back({kCrownRadius * std::cos(a), 0.0f, kCrownRadius * std::sin(a)});
        }
        g.positions.push_back({0.0f, kCrownRadius, 0.0f});
        g.positions.push_back({0.0f, -kCrownRadius, 0.0f});
        g.indices = {0, 3, 1, 1, 3, 2, 2, 3, 0, 0, 1, 4, 1, 2, 4, 2, 0, 4};
    }
    for (glm::vec3& p : g.positions) p.y += kCrownHeight;
    g.normals.clear();
    g.finalize();
    return g;
}

// Full: a capped triangular prism (7 triangles). Simplified: its open sides (6).
Geometry makeTreeTrunk(bool simplified) { return makePrism(3, kTrunkRadius, kTrunkTop, !simplified); }

PaperForest addPaperForest(Scene& scene, NodeId parent, GroupingNodes& grouping, LodTable& lods,
                           ForestColouring colouring) {
    return addPaperForestTo(scene, addGroupingNode(scene, parent, grouping, "forest"), lods, colouring);
}

PaperForest addPaperForestTo(Scene& scene, NodeId groupingNode, LodTable& lods, ForestColouring colouring) {
    PaperForest f;
    f.grouping = groupingNode;
    const Geometry crown = makeTreeCrown(false);
    const std::uint32_t crowns[2] = {scene.addGeometry(crown), scene.addGeometry(makeTreeCrown(true))};
    const std::uint32_t trunks[2] = {scene.addGeometry(makeTreeTrunk(false)), scene.addGeometry(makeTreeTrunk(true))};
    Material bark{.name = "bark", .baseColor = {0.35f, 0.22f, 0.1f, 1.0f}};
    Material leaves{.name = "leaves", .baseColor = {0.12f, 0.45f, 0.12f, 1.0f}};
    Material red{.name = "red leaves", .baseColor = {0.75f, 0.1f, 0.08f, 1.0f}};
    const std::uint32_t barkId = scene.addMaterial(bark), greenId = scene.addMaterial(leaves),
                        redId = scene.addMaterial(red);
    // The crown's box sets the spacing, so that neighbours' boxes tile and
    // the shape term Ms of two neighbours is 0.
    const glm::vec3 cell = crown.box.size();
    for (int row = 0; row < kRows; ++row)
        for (int col = 0; col < kColumns; ++col) {
            bool isRed = false;
            if (colouring == ForestColouring::Mixed)
                for (auto [c, r] : kRedTrees) isRed = isRed || (c == col && r == row);
            const glm::vec3 at{(float(col) - 0.5f * float(kColumns - 1)) * cell.x, 0.0f,
                               -(float(row) - 0.5f * float(kRows - 1)) * cell.z};
            const NodeId place = scene.addTransform(f.grouping, glm::translate(glm::mat4(1.0f), at),
                                                    "tree" + std::to_string(f.trees.size()));
            LodNode lod;
            lod.policy = LodPolicy::Distance;
            lod.setThresholds({kForestLodDistance});
            lod.hysteresis = 0.0f;
            const NodeId lodNode = scene.addNode(place, NodeKind::Lod, lods.add(lod));
            for (int level = 0; level < 2; ++level) {
                const NodeId levelNode = scene.addGroup(lodNode, level == 0 ? "full" : "simplified");
                scene.addMesh(levelNode, {trunks[level], barkId});
                scene.addMesh(levelNode, {crowns[level], isRed ? redId : greenId});
            }
            f.trees.push_back(place);
            f.red.push_back(isRed);
        }
    return f;
}

View paperForestView(glm::ivec2 viewport) {
    return View::lookAt({300.0f, 1500.0f, 4300.0f}, {0.0f, 150.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 16.0f, viewport, 100.0f,
                        20000.0f);
}

}  // namespace arcomp
