// `arcomp inspect` lists a model's animations and skins; `arcomp check`
// fails on an object that names an animation its model does not have.

#include "../support/GltfFile.hpp"
#include "../support/Shell.hpp"
#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using arcomp::test::arcompCommand;
using arcomp::test::GltfFile;
using arcomp::test::TempDir;

namespace {

// Two clips on a triangle node: "wave" (LINEAR translation and STEP scale,
// 2 s) and "turn" (CUBICSPLINE rotation, 1 s); skinned or not. The skinned
// mesh has no JOINTS_0 and WEIGHTS_0, so it is drawn in its bind pose with a
// warning, which `check` counts.
std::string animatedModel(bool skinned) {
    GltfFile f;
    f.nodes = skinned ? R"([{"name": "arm", "mesh": 0, "skin": 0, "children": [1]}, {"name": "bone"}])"
                      : R"([{"name": "arm", "mesh": 0, "children": [1]}, {"name": "bone"}])";
    if (skinned) f.skins = R"([{"name": "rig", "joints": [1]}])";
    const int twoSeconds = f.add({0, 2}, "SCALAR");
    const int oneSecond = f.add({0, 1}, "SCALAR");
    const int move = f.add({0, 0, 0, 1, 0, 0}, "VEC3");
    const int grow = f.add({1, 1, 1, 2, 2, 2}, "VEC3");
    const int spin = f.add({0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0}, "VEC4");
    const auto s = [](int input, int output, const char* interpolation) {
        return R"({"input": )" + std::to_string(input) + R"(, "output": )" + std::to_string(output) +
               R"(, "interpolation": ")" + interpolation + "\"}";
    };
    f.animations = R"([{"name": "wave", "samplers": [)" + s(twoSeconds, move, "LINEAR") + ", " +
                   s(twoSeconds, grow, "STEP") +
                   R"(], "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}},
                                      {"sampler": 1, "target": {"node": 0, "path": "scale"}}]},
                      {"name": "turn", "samplers": [)" +
                   s(oneSecond, spin, "CUBICSPLINE") +
                   R"(], "channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}}]}])";
    return f.json();
}

}  // namespace

TEST(ModelAnimationCommands, inspectListsAnimationsAndSkins) {
    TempDir dir;
    const auto r = arcompCommand("inspect " + dir.write("arm.gltf", animatedModel(true)).string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("animation 0 'wave': 2 channels, 2 s, LINEAR, STEP\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("animation 1 'turn': 1 channel, 1 s, CUBICSPLINE\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("skin 'rig': 1 joints"), std::string::npos) << r.out;
    EXPECT_NE(
        r.out.find("warning: /meshes/0/primitives/0: skinned by skin 0 'rig' (/nodes/0) but has no skin influences"),
        std::string::npos)
        << r.out;
}

TEST(ModelAnimationCommands, checkFailsOnAnAnimationTheModelLacks) {
    TempDir dir;
    dir.write("arm.gltf", animatedModel(false));
    const std::string object = "scene:\n  objects:\n    - name: greeter\n      model: arm.gltf\n      animation: ";
    const auto bad = arcompCommand("check " + dir.write("bad.yaml", object + "dance\n").string());
    EXPECT_EQ(bad.code, 2) << bad.out;
    EXPECT_NE(bad.out.find("object 'greeter' skipped: model '"), std::string::npos) << bad.out;
    EXPECT_NE(bad.out.find("arm.gltf' has no animation 'dance'; its animations: 0 'wave', 1 'turn'"), std::string::npos)
        << bad.out;
    const auto good = arcompCommand("check " + dir.write("good.yaml", object + "turn\n").string());
    EXPECT_EQ(good.code, 0) << good.out;
}
