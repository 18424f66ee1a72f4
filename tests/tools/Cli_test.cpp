// The arcomp command line as scripts use it: exit codes, outputs, messages.

#include "runtime/station/ImageFile.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include "tests/support/Shell.hpp"
#include <array>
#include <cstdio>
#include <sys/wait.h>

using arcomp::test::arcompCommand;
using arcomp::test::benchCommand;
using arcomp::test::lastLine;
using arcomp::test::ShellResult;
using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

fs::path bunny() { return arcomp::test::sharedData() / "meshes/bunny.obj"; }

double coverage(const arcomp::Image& img) {
    std::size_t covered = 0;
    for (std::size_t i = 3; i < img.rgba.size(); i += 4) covered += img.rgba[i] > 0;
    return static_cast<double>(covered) / static_cast<double>(img.width * img.height);
}

}  // namespace

TEST(Cli, renderWritesTheBunnyAndShadingChangesTheImage) {
    if (!fs::exists(bunny())) GTEST_SKIP() << "shared test data is absent";
    TempDir dir;
    const ShellResult phong =
        arcompCommand("render " + bunny().string() + " --out " + (dir.path() / "p.png").string() + " --size 640x480");
    ASSERT_EQ(phong.code, 0) << phong.out;
    const ShellResult flat = arcompCommand("render " + bunny().string() + " --out " + (dir.path() / "f.png").string() +
                                           " --size 640x480 --shading flat");
    ASSERT_EQ(flat.code, 0) << flat.out;
    const arcomp::Image p = arcomp::readPng(dir.path() / "p.png");
    const arcomp::Image f = arcomp::readPng(dir.path() / "f.png");
    EXPECT_EQ(p.width, 640);
    EXPECT_EQ(p.height, 480);
    EXPECT_GT(coverage(p), 0.08);  // framed at about 80% of the height
    EXPECT_LT(coverage(p), 0.45);
    EXPECT_NE(p.rgba, f.rgba);
}

TEST(Cli, renderWithEsAndDesktopGlGivesMatchingImages) {
    if (!fs::exists(bunny())) GTEST_SKIP() << "shared test data is absent";
    TempDir dir;
    ASSERT_EQ(arcompCommand("render " + bunny().string() + " --gl gl33 --out " + (dir.path() / "gl.png").string()).code,
              0);
    ASSERT_EQ(arcompCommand("render " + bunny().string() + " --gl es3 --out " + (dir.path() / "es.png").string()).code,
              0);
    const arcomp::Image gl = arcomp::readPng(dir.path() / "gl.png");
    const arcomp::Image es = arcomp::readPng(dir.path() / "es.png");
    double diff = 0;
    for (std::size_t i = 0; i < gl.rgba.size(); ++i) diff += std::abs(int(gl.rgba[i]) - int(es.rgba[i]));
    EXPECT_LT(diff / static_cast<double>(gl.rgba.size()), 0.5);
}

TEST(Cli, badInputExitsTwoWithTheReason) {
    TempDir dir;
    const ShellResult missing = arcompCommand("render " + (dir.path() / "none.obj").string() + " --out x.png");
    EXPECT_EQ(missing.code, 2);
    EXPECT_NE(missing.out.find("none.obj: no such file"), std::string::npos) << missing.out;
    const ShellResult garbage = arcompCommand("inspect " + dir.write("junk.gltf", "not json").string());
    EXPECT_EQ(garbage.code, 2);
    EXPECT_NE(garbage.out.find("junk.gltf"), std::string::npos) << garbage.out;
    const ShellResult size = arcompCommand(
        "render " + dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n").string() + " --out x.png --size 0x10");
    EXPECT_EQ(size.code, 2);
    EXPECT_NE(size.out.find("--size '0x10'"), std::string::npos) << size.out;
    EXPECT_EQ(arcompCommand("render").code, 2);  // usage
    EXPECT_EQ(arcompCommand("no-such-command").code, 2);
}

TEST(Cli, inspectPrintsTheTreeWithCounts) {
    if (!fs::exists(bunny())) GTEST_SKIP() << "shared test data is absent";
    const ShellResult r = arcompCommand("inspect " + bunny().string());
    ASSERT_EQ(r.code, 0) << r.out;
    EXPECT_NE(r.out.find("mesh: 27864 triangles"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("meshes 1, triangles 27864"), std::string::npos) << r.out;
}

TEST(Cli, benchLoadPrintsOneJsonLineLast) {
    if (!fs::exists(bunny())) GTEST_SKIP() << "shared test data is absent";
    const ShellResult r = benchCommand("load --repeats 1 --model " + bunny().string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::string json = lastLine(r.out);
    EXPECT_EQ(json.front(), '{');
    EXPECT_EQ(json.back(), '}');
    EXPECT_NE(json.find("\"triangles\":27864"), std::string::npos) << json;
    EXPECT_NE(json.find("\"load_ms\":"), std::string::npos) << json;
}

// A kiosk's station binary holds what an integrator runs on it; the
// benches, and OpenSceneGraph that the cull bench compares against, are
// arcomp-bench's.
TEST(Cli, theStationBinaryHoldsNoBenchAndNoOpenSceneGraph) {
    const ShellResult bench = arcompCommand("bench load");
    EXPECT_EQ(bench.code, 2);
    EXPECT_NE(bench.out.find("arcomp-bench <name>"), std::string::npos) << bench.out;
    const ShellResult ldd = arcomp::test::shell(std::string("ldd ") + ARCOMP_BINARY);
    ASSERT_EQ(ldd.code, 0) << ldd.out;
    EXPECT_NE(ldd.out.find("libopencv_core"), std::string::npos) << ldd.out;  // ldd lists libraries at all
    EXPECT_EQ(ldd.out.find("libosg"), std::string::npos) << ldd.out;

    const ShellResult help = benchCommand("--help");
    ASSERT_EQ(help.code, 0) << help.out;
    for (const char* bench : {"ar", "budget", "calibrate", "composite", "cull", "gltf-reference", "grouping",
                              "grouping-forest", "ldi", "load", "matte", "silhouette", "soak", "status-load", "video"})
        EXPECT_NE(help.out.find(std::string("\n  ") + bench + " "), std::string::npos) << bench << "\n" << help.out;
}

// What a reference renderer is told must reach arcomp too: the field of view
// (a narrower one fills more of the frame) and the light's direction (a
// quad lit from behind its viewer shows only the environment's light, which
// for the neutral studio is about three quarters of the front-lit quad's).
TEST(Cli, renderTakesFieldOfViewAndLightDirection) {
    TempDir dir;
    const std::string quad = dir.write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n").string();
    const auto render = [&](const std::string& name, const std::string& options) {
        const ShellResult r = arcompCommand("render " + quad + " --out " + (dir.path() / name).string() +
                                            " --size 160x120 --eye 0,0,6 --target 0,0,0 " + options);
        EXPECT_EQ(r.code, 0) << r.out;
        return arcomp::readPng(dir.path() / name);
    };
    const double narrow = coverage(render("narrow.png", "--fovy 20")), wide = coverage(render("wide.png", "--fovy 60"));
    EXPECT_GT(narrow, 2.5 * wide) << narrow << " vs " << wide;
    const auto brightness = [](const arcomp::Image& img) {
        double sum = 0;
        for (std::size_t i = 0; i < img.rgba.size(); i += 4) sum += img.rgba[i];
        return sum;
    };
    const double front = brightness(render("front.png", "--light-direction 0,0,1"));
    const double behind = brightness(render("behind.png", "--light-direction 0,0,-1"));
    EXPECT_GT(front, 1.25 * behind);
    const ShellResult zero = arcompCommand("render " + quad + " --out x.png --light-direction 0,0,0");
    EXPECT_EQ(zero.code, 2);
    EXPECT_NE(zero.out.find("--light-direction"), std::string::npos) << zero.out;
}
