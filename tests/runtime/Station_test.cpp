// End-to-end compositing: the demo installation replayed on vtest.avi and
// checked against masks computed independently (each object rendered alone
// with its full mesh); silhouette against full-mesh holdouts along a camera
// path; replay determinism.

#include "graph/core/SelectPass.hpp"
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/CameraFile.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ImageFile.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/station/Station.hpp"
#include "tests/support/OpencvVideos.hpp"
#include "tests/support/TempDir.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/TestPatternSource.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

// The demo's four standing objects, without its files, its sign and beacon
// and their triggers: the CG stays the same in every frame.
StationConfig demoConfig() {
    StationConfig cfg = loadStationConfig(fs::path(ARCOMP_SOURCE_DIR) / "configs/demo-replay.yaml");
    cfg.compositing.output = {};
    std::erase_if(cfg.objects, [](const ObjectConfig& o) { return !o.visible || !o.animation.empty(); });
    cfg.triggers.clear();
    return cfg;
}

cv::Mat bgrOf(const Image& img) {
    const cv::Mat rgba(img.height, img.width, CV_8UC4, const_cast<std::uint8_t*>(img.rgba.data()));
    cv::Mat bgr;
    cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
    return bgr;
}

// The config's objects drawn by a plain Renderer: all of them shaded (the
// reference CG), or one alone as a coverage mask.
Image renderObjects(const StationConfig& cfg, const std::vector<std::size_t>& which, const View& view,
                    Shading shading) {
    StationConfig some = cfg;
    some.objects.clear();
    for (std::size_t i : which) some.objects.push_back(cfg.objects[i]);
    World world;
    std::vector<std::string> warnings;
    buildScene(some, world, warnings);
    Scene& scene = world.scene;
    scene.update();
    DrawList list;
    select(world, view, {.shading = shading, .lod = false, .grouping = false}, list);
    RenderTarget target(view.viewport);
    target.bind();
    Renderer renderer;
    renderer.draw(scene, list, view,
                  {.clearColor = glm::vec4(0.0f), .lightDirection = cfg.compositing.compositor.shadow.light});
    return target.read();
}

cv::Mat coverageOf(const Image& img) {
    const cv::Mat rgba(img.height, img.width, CV_8UC4, const_cast<std::uint8_t*>(img.rgba.data()));
    cv::Mat a;
    cv::extractChannel(rgba, a, 3);
    return a > 0;
}

// Pixels where BGR image `a` is brighter than `b` by more than 1 in any channel.
cv::Mat brighterThan(const cv::Mat& a, const cv::Mat& b) {
    cv::Mat d;
    cv::subtract(a, b, d);  // 0 where darker
    std::vector<cv::Mat> ch;
    cv::split(d, ch);
    return (ch[0] > 1) | (ch[1] > 1) | (ch[2] > 1);
}

// Largest per-channel difference of two BGR images over a mask (0 if empty).
int maxDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask) {
    if (cv::countNonZero(mask) == 0) return 0;
    cv::Mat d;
    cv::absdiff(a, b, d);
    // Per-channel max over the mask.
    std::vector<cv::Mat> ch;
    cv::split(d, ch);
    double m = 0;
    for (const cv::Mat& c : ch) {
        double v = 0;
        cv::minMaxLoc(c, nullptr, &v, nullptr, nullptr, mask);
        m = std::max(m, v);
    }
    return static_cast<int>(m);
}

// The demo, registered: every walker is cut by exactly the objects nearer
// than their own feet, the same object stands in front of some walkers and
// behind others, and the objects' shadows only darken the video.
TEST(Station, vtestWalkersAreCutOnlyByObjectsNearerThanThemselves) {
    if (!fs::exists(test::kVtest)) GTEST_SKIP() << test::kVtest << " absent (opencv-doc not installed)";
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const StationConfig cfg = demoConfig();
    Station station(cfg,
                    StationInput::fromReplay(std::make_unique<FileSource>(FileOptions{.path = test::kVtest}), 10.0));
    FileSource reference(FileOptions{.path = test::kVtest});
    const View view = station.view();

    const cv::Mat cg = bgrOf(renderObjects(cfg, {0, 1, 2, 3}, view, cfg.render.shading));
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    struct Object {
        cv::Mat inner, outer;
        float nearest, farthest;  // along the view axis
    };
    std::vector<Object> objects;
    cv::Mat anyObject = cv::Mat::zeros(view.viewport.y, view.viewport.x, CV_8UC1);
    for (std::size_t i = 0; i < cfg.objects.size(); ++i) {
        Object o;
        const cv::Mat cover = coverageOf(renderObjects(cfg, {i}, view, Shading::Unlit));
        ASSERT_GT(cv::countNonZero(cover), 300) << cfg.objects[i].name;
        cv::erode(cover, o.inner, k);
        cv::dilate(cover, o.outer, k);
        anyObject |= o.outer;
        const ObjectConfig& c = cfg.objects[i];
        const float radius = c.shape == "sphere" ? c.radius : 0.5f * glm::length(c.size);
        const float depth = -(view.view * glm::vec4(c.position, 1.0f)).z;
        o.nearest = depth - radius;
        o.farthest = depth + radius;
        objects.push_back(o);
    }

    std::map<std::string, int> inFront, behind;  // frames with a walker in front of / behind each object
    std::size_t checked = 0, shadowed = 0;
    for (int f = 0; f < 150; ++f) {
        ASSERT_TRUE(station.frame());
        const cv::Mat video = reference.next()->image;
        const cv::Mat out = bgrOf(station.compositedFrame().read());
        const cv::Mat alpha = alphaOf(station.personLayer());
        const cv::Mat person = alpha == 255, background = alpha == 0;
        const PersonDepths& depths = station.personDepths();

        // A walker away from every object shows the video; so does the
        // background, darkened at most (by a shadow), never lightened.
        EXPECT_LE(maxDifference(out, video, person & ~anyObject), 1) << "frame " << f;
        EXPECT_EQ(cv::countNonZero(brighterThan(out, video) & background & ~anyObject), 0) << "frame " << f;
        shadowed += static_cast<std::size_t>(cv::countNonZero(brighterThan(video, out) & background & ~anyObject));

        // Inside an object's silhouette, each tracked walker by their own depth.
        cv::Mat slots;  // at the frame's size: pixel (x, y) is slot (x, y) / slotScale
        if (depths.people > 0) {
            cv::resize(depths.slots, slots, {}, depths.slotScale, depths.slotScale, cv::INTER_NEAREST);
            slots = slots(cv::Rect(0, 0, person.cols, person.rows));
        }
        for (int slot = 1; slot <= depths.people; ++slot) {
            const float metres = depths.metres[static_cast<std::size_t>(slot)];
            const cv::Mat walker = person & (slots == slot);
            for (std::size_t i = 0; i < objects.size(); ++i) {
                const cv::Mat overlap = walker & objects[i].inner;
                if (cv::countNonZero(overlap) < 30) continue;
                const std::string& name = cfg.objects[i].name;
                if (objects[i].farthest < metres - 0.3f) {
                    EXPECT_LE(maxDifference(out, cg, overlap), 1) << name << " in front, frame " << f;
                    ++behind[name];
                } else if (objects[i].nearest > metres + 0.3f) {
                    EXPECT_LE(maxDifference(out, video, overlap), 1) << name << " behind, frame " << f;
                    ++inFront[name];
                } else {
                    continue;  // the walker stands within the object's depth: either may be right
                }
                ++checked;
            }
        }
    }
    std::cout << "frames with a walker in front of / behind:";
    for (const ObjectConfig& c : cfg.objects)
        std::cout << " " << c.name << " " << inFront[c.name] << "/" << behind[c.name];
    std::cout << "\n";
    EXPECT_GE(checked, 20u);
    EXPECT_GT(shadowed, 150u * 1000u);  // the objects' shadows, every frame
    // The point of the registered demo: one object both in front of a walker and behind another.
    bool both = false;
    for (const ObjectConfig& c : cfg.objects) both = both || (inFront[c.name] >= 3 && behind[c.name] >= 3);
    EXPECT_TRUE(both);
}

// Occluders with many triangles: a dense sphere, and the bunny when the
// shared data is there.
StationConfig occluderConfig(HoldoutMesh holdout) {
    StationConfig cfg;
    cfg.file = "occluders.yaml";
    ObjectConfig sphere;
    sphere.name = "sphere";
    sphere.shape = "sphere";
    sphere.radius = 0.8f;
    sphere.position = {-1.0f, 0.0f, -5.0f};
    cfg.objects.push_back(sphere);
    const fs::path bunny = fs::path(ARCOMP_SHARED_DATA) / "meshes/bunny.obj";
    ObjectConfig other;
    if (fs::exists(bunny)) {
        other.name = "bunny";
        other.model = bunny;
        other.scale = glm::vec3(12.0f);
        other.position = {1.0f, -1.0f, -5.0f};
    } else {
        other.name = "box";
        other.shape = "box";
        other.rotationDegrees = {20.0f, 30.0f, 0.0f};
        other.position = {1.0f, 0.0f, -5.0f};
    }
    cfg.objects.push_back(other);
    cfg.camera.given = true;
    cfg.camera.eye = {0.0f, 0.0f, 0.0f};
    cfg.camera.target = {0.0f, 0.0f, -10.0f};
    cfg.compositing.compositor.personPlaneMetres = 8.0f;
    cfg.compositing.compositor.holdoutRegionMetres = 0.5f;
    cfg.compositing.compositor.holdout = holdout;
    return cfg;
}

StationInput pattern(glm::ivec2 size) {
    return StationInput::fromReplay(
        std::make_unique<TestPatternSource>(TestPatternOptions{.width = size.x, .height = size.y, .paced = false}),
        30.0);
}

cv::Mat holdoutMask(Station& s) { return coverageOf(s.readHoldout()).clone(); }

// The controller sits between select and render: with a target no frame can
// meet, it lowers the objects' shading; with time to spare it keeps the
// finest; without a budget section it does nothing.
TEST(Station, budgetLowersShadingOnlyWhenTheTargetIsTight) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    arcomp::test::TempDir dir;
    CostModel model(1);
    for (int s = 0; s < kShadingCount; ++s) model.set(0, static_cast<Shading>(s), {1e-4 * (s + 1), 2.0 * (s + 1)});
    writeCalibration(dir.path() / "calibration.yaml", model, {"test", {320, 240}});
    auto run = [&](std::optional<double> targetMs) {
        StationConfig cfg = occluderConfig(HoldoutMesh::Full);
        if (targetMs) {
            cfg.budget.enabled = true;
            cfg.budget.calibration = dir.path() / "calibration.yaml";
            cfg.budget.refit = false;
            cfg.budget.targetMs = *targetMs;
        }
        Station station(cfg, pattern({320, 240}));
        for (int i = 0; i < 3; ++i) EXPECT_TRUE(station.frame());
        return station.stats().budget;
    };
    const auto tight = run(1.0);
    ASSERT_TRUE(tight);
    EXPECT_EQ(tight->itemsReduced, 2u);
    EXPECT_LT(tight->quality, 1.0);
    const auto loose = run(10000.0);
    ASSERT_TRUE(loose);
    EXPECT_EQ(loose->itemsReduced, 0u);
    EXPECT_DOUBLE_EQ(loose->quality, 1.0);
    EXPECT_FALSE(run(std::nullopt));
}

TEST(Station, silhouetteHoldoutDiffersFromFullMeshOnlyAtTheOutline) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    const glm::ivec2 size{640, 480};
    Station silhouette(occluderConfig(HoldoutMesh::Silhouette), pattern(size));
    Station full(occluderConfig(HoldoutMesh::Full), pattern(size));
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    std::size_t silhouetteTriangles = 0, fullTriangles = 0;
    // A path through the region (eyes within 0.4 m of the camera position).
    for (int i = 0; i < 12; ++i) {
        const float t = static_cast<float>(i) / 11.0f;
        const glm::vec3 eye(0.4f * std::cos(6.28f * t), 0.35f * std::sin(6.28f * t), 0.4f * (2.0f * t - 1.0f));
        const glm::vec3 target = eye + glm::vec3(0.05f * t, 0.0f, -10.0f);
        silhouette.setCamera(eye, target);
        full.setCamera(eye, target);
        ASSERT_TRUE(silhouette.frame());
        ASSERT_TRUE(full.frame());
        EXPECT_EQ(silhouette.stats().objectsInFront, 2u);
        silhouetteTriangles += silhouette.stats().holdoutTriangles;
        fullTriangles += full.stats().holdoutTriangles;
        const cv::Mat s = holdoutMask(silhouette), f = holdoutMask(full);
        ASSERT_GT(cv::countNonZero(f), 1000);
        cv::Mat inner, outer, differ;
        cv::erode(f, inner, k);
        cv::dilate(f, outer, k);
        cv::bitwise_xor(s, f, differ);
        // Within 1 px of the full mesh's outline: inside the dilated mask and
        // outside the eroded one.
        const cv::Mat farFromOutline = differ & (inner | ~outer);
        EXPECT_EQ(cv::countNonZero(farFromOutline), 0) << "eye " << eye.x << "," << eye.y << "," << eye.z;
    }
    EXPECT_LT(silhouetteTriangles, fullTriangles);
}

std::vector<char> bytesOf(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(Station, replayTwiceGivesIdenticalImages) {
    test::TempDir dir;
    const std::string base =
        std::string(ARCOMP_BINARY) + " replay " + ARCOMP_SOURCE_DIR + "/configs/demo-replay.yaml --frames 12 --out ";
    ASSERT_EQ(std::system((base + (dir.path() / "a").string() + " >/dev/null 2>&1").c_str()), 0);
    ASSERT_EQ(std::system((base + (dir.path() / "b").string() + " >/dev/null 2>&1").c_str()), 0);
    int frames = 0;
    for (const auto& e : fs::directory_iterator(dir.path() / "a")) {
        const fs::path other = dir.path() / "b" / e.path().filename();
        ASSERT_TRUE(fs::exists(other)) << other;
        EXPECT_EQ(bytesOf(e.path()), bytesOf(other)) << e.path().filename();
        frames += e.path().extension() == ".png";
    }
    EXPECT_EQ(frames, 12);
    EXPECT_TRUE(fs::exists(dir.path() / "a" / "events.jsonl")) << "compared with the frames";
}

}  // namespace

// Config movers move their object by video time (deterministic in replay),
// and an object with generated LOD draws a coarser level when small on screen.
TEST(Station, moversFollowVideoTimeAndLodObjectsPickTheirLevel) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    StationConfig cfg;
    cfg.file = "movers.yaml";
    ObjectConfig mover;
    mover.name = "mover";
    mover.shape = "box";
    mover.position = {0.0f, 0.0f, -6.0f};
    mover.velocity = {1.5f, 0.0f, 0.0f};  // 0.05 m a frame at 30 fps
    mover.rangeMetres = 10.0f;
    cfg.objects.push_back(mover);
    ObjectConfig far;
    far.name = "far sphere";
    far.shape = "sphere";
    far.position = {0.0f, 0.0f, -60.0f};
    far.lodRatios = {1.0f, 0.25f, 0.05f};
    far.lodThresholds = {20.0f, 40.0f};  // distance: level 2 beyond 40 m
    cfg.objects.push_back(far);
    cfg.camera.given = true;
    cfg.camera.eye = {0.0f, 0.0f, 0.0f};
    cfg.camera.target = {0.0f, 0.0f, -1.0f};
    Station station(cfg, pattern({160, 120}));
    ASSERT_TRUE(station.frame());
    std::optional<std::uint8_t> farLevel;
    for (const DrawItem& item : station.drawList().items)
        if (item.viewDistance > 50.0f) farLevel = item.level;
    ASSERT_TRUE(farLevel);
    EXPECT_EQ(*farLevel, 2);
    for (int i = 0; i < 20; ++i) ASSERT_TRUE(station.frame());
    // Frame 21 was drawn at video time 20/30 s: the box has moved 1 m along +X.
    bool found = false;
    for (const DrawItem& item : station.drawList().items)
        if (item.viewDistance < 20.0f) {
            found = true;
            EXPECT_NEAR(item.viewDistance, std::sqrt(36.0f + 1.0f), 1e-3f);
        }
    EXPECT_TRUE(found);
}

// The holdout comes from the same select pass as the CG: an LOD object in
// front of the person is cut out with the silhouette of the level drawn.
TEST(Station, holdoutIsTheSilhouetteOfTheLevelTheCgDraws) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    auto run = [](float levelTwoBeyond) {
        StationConfig cfg;
        cfg.file = "lod-holdout.yaml";
        ObjectConfig sphere;
        sphere.name = "sphere";
        sphere.shape = "sphere";
        sphere.position = {0.0f, 0.0f, -30.0f};
        sphere.lodRatios = {1.0f, 0.25f, 0.05f};
        sphere.lodThresholds = {levelTwoBeyond / 2.0f, levelTwoBeyond};
        cfg.objects.push_back(sphere);
        cfg.camera.given = true;
        cfg.camera.eye = {0.0f, 0.0f, 0.0f};
        cfg.camera.target = {0.0f, 0.0f, -1.0f};
        cfg.compositing.compositor.personPlaneMetres = 100.0f;  // everything stands in front
        cfg.compositing.compositor.holdout = HoldoutMesh::Full;
        Station station(cfg, pattern({160, 120}));
        EXPECT_TRUE(station.frame());
        EXPECT_EQ(station.stats().objectsInFront, 1u);
        EXPECT_EQ(station.drawList().holdouts.size(), 1u);
        return std::pair{station.drawList().items.at(0).level, station.stats().holdoutTriangles};
    };
    const auto [fineLevel, fineTriangles] = run(1000.0f);
    const auto [coarseLevel, coarseTriangles] = run(20.0f);
    EXPECT_EQ(fineLevel, 0);
    EXPECT_EQ(coarseLevel, 2);
    EXPECT_GT(coarseTriangles, 0u);
    EXPECT_LT(coarseTriangles * 5, fineTriangles);  // a twentieth of the triangles, as the ratios say
}

// A station that restarts loads yesterday's holdouts and LOD levels instead
// of baking them again, and draws exactly as the station that baked them.
TEST(Station, aRestartLoadsWhatItBakedFromTheCache) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    StationConfig cfg = occluderConfig(HoldoutMesh::Silhouette);
    cfg.compositing.compositor.bakeCache = dir.path() / "cache";
    ObjectConfig far;
    far.name = "far sphere";
    far.shape = "sphere";
    far.position = {0.0f, 0.0f, -30.0f};  // level 1, behind the person plane
    far.lodRatios = {1.0f, 0.25f};
    far.lodThresholds = {20.0f};
    cfg.objects.push_back(far);
    const auto files = [&](const char* extension) {
        std::size_t n = 0;
        for (const fs::directory_entry& e : fs::directory_iterator(dir.path() / "cache"))
            n += e.path().extension() == extension;
        return n;
    };
    Station first(cfg, pattern({320, 240}));
    ASSERT_TRUE(first.frame());
    const std::size_t meshes = first.holdoutBake().baked;
    EXPECT_EQ(first.holdoutBake().loaded, 0u);
    EXPECT_GT(meshes, 0u);
    EXPECT_EQ(files(".sil"), meshes);
    EXPECT_EQ(first.lodBake().baked, 1u);
    EXPECT_EQ(first.lodBake().loaded, 0u);
    EXPECT_EQ(files(".lod"), 1u);

    Station second(cfg, pattern({320, 240}));
    ASSERT_TRUE(second.frame());
    EXPECT_EQ(second.holdoutBake().loaded, meshes);
    EXPECT_EQ(second.holdoutBake().baked, 0u);
    EXPECT_EQ(second.lodBake().loaded, 1u);
    EXPECT_EQ(second.lodBake().baked, 0u);
    EXPECT_EQ(cv::countNonZero(holdoutMask(first) != holdoutMask(second)), 0);
    EXPECT_EQ(cv::norm(bgrOf(first.compositedFrame().read()), bgrOf(second.compositedFrame().read()), cv::NORM_INF),
              0.0);

    // Another region is another bake: the stale files are baked again. So
    // are levels of other ratios.
    cfg.compositing.compositor.holdoutRegionMetres = 0.25f;
    cfg.objects.back().lodRatios = {1.0f, 0.5f};
    Station moved(cfg, pattern({320, 240}));
    EXPECT_EQ(moved.holdoutBake().baked, meshes);
    EXPECT_EQ(moved.holdoutBake().loaded, 0u);
    EXPECT_EQ(moved.lodBake().baked, 1u);

    cfg.compositing.compositor.bakeCache = "none";
    Station uncached(cfg, pattern({320, 240}));
    EXPECT_TRUE(uncached.holdoutBake().folder.empty());
    EXPECT_EQ(uncached.holdoutBake().baked, meshes);
    EXPECT_EQ(uncached.lodBake().baked, 1u);
}

// A calibrated camera is the CG camera: a small ball on the floor is drawn
// where the real camera, at the video's (here halved) size, images its centre.
TEST(Station, aCalibratedCameraDrawsFloorObjectsWhereTheRealCameraSeesThem) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    arcomp::test::TempDir dir;
    CalibratedCamera real;
    real.intrinsics = {.imageSize = {640, 480}, .fx = 560.0, .fy = 556.0, .cx = 331.0, .cy = 228.5, .distortion = {}};
    const double tilt = glm::radians(18.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    real.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    real.translation = -real.rotation * glm::dvec3(-0.5, 3.0, 9.0);
    writeCameraFile(dir.path() / "camera.yaml", real, "");
    const StationConfig cfg = loadStationConfig(dir.write("station.yaml", R"(scene:
  objects:
    - {shape: sphere, radius: 0.08, position: [1.5, 0.08, 1.0], color: [1, 1, 1, 1]}
camera:
  calibration: camera.yaml
)"));
    Station station(cfg, pattern({320, 240}));
    EXPECT_NEAR(station.view().eye.y, 3.0f, 1e-4f);

    const cv::Mat ball = coverageOf(renderObjects(cfg, {0}, station.view(), Shading::Unlit));
    const cv::Moments m = cv::moments(ball, true);
    ASSERT_GT(m.m00, 4.0);
    const glm::dvec2 full = real.project({1.5, 0.08, 1.0});
    // Pixel centres at integers: (u + ½) scales with the image.
    EXPECT_NEAR(m.m10 / m.m00, (full.x + 0.5) / 2.0 - 0.5, 0.5);
    EXPECT_NEAR(m.m01 / m.m00, (full.y + 0.5) / 2.0 - 0.5, 0.5);
}

namespace {

// A studio-green floor scene with two people painted as flat cards standing
// on it, through a real camera: what the matte and the tracker see.
class TwoPeopleCamera : public FrameGrabber {
public:
    TwoPeopleCamera(const CalibratedCamera& camera, std::vector<cv::Rect> people, std::vector<cv::Scalar> colours)
        : size_(camera.intrinsics.imageSize), people_(std::move(people)), colours_(std::move(colours)) {}
    GrabResult grab() override {
        cv::Mat frame(size_.y, size_.x, CV_8UC3, cv::Scalar(64, 177, 0));
        for (std::size_t i = 0; i < people_.size(); ++i) cv::rectangle(frame, people_[i], colours_[i], cv::FILLED);
        return {Frame{frame}, {SourceStatus::Streaming, ""}};
    }
    std::string name() const override { return "two people"; }

private:
    glm::ivec2 size_;
    std::vector<cv::Rect> people_;
    std::vector<cv::Scalar> colours_;
};

// The card of a person 1.7 m tall and 0.5 m wide whose feet are at `floor`.
cv::Rect personCard(const CalibratedCamera& c, const glm::dvec3& floor) {
    const glm::dvec2 feet = c.project(floor), head = c.project(floor + glm::dvec3(0.0, 1.7, 0.0));
    const glm::dvec2 side = c.project(floor + glm::dvec3(0.25, 0.0, 0.0));
    const double halfWidth = side.x - feet.x;
    return cv::Rect(cv::Point(static_cast<int>(feet.x - halfWidth), static_cast<int>(head.y)),
                    cv::Point(static_cast<int>(feet.x + halfWidth), static_cast<int>(feet.y) + 1));
}

}  // namespace

// With a calibrated camera each person stands at their own depth, from
// where their feet meet the floor: a box between a near and a far person
// cuts the far one and is covered by the near one.
TEST(Station, eachPersonIsInFrontOfOrBehindTheCgByTheirOwnDepth) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    arcomp::test::TempDir dir;
    CalibratedCamera real;
    real.intrinsics = {.imageSize = {640, 480}, .fx = 560.0, .fy = 560.0, .cx = 320.0, .cy = 240.0, .distortion = {}};
    const double tilt = glm::radians(18.0);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    real.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    real.translation = -real.rotation * glm::dvec3(0.0, 3.0, 9.0);
    writeCameraFile(dir.path() / "camera.yaml", real, "");
    const glm::dvec3 nearFeet(-0.3, 0.0, 2.0), farFeet(0.4, 0.0, -4.0);
    const cv::Rect nearCard = personCard(real, nearFeet), farCard = personCard(real, farFeet);
    const StationConfig cfg = loadStationConfig(dir.write("station.yaml", R"(matte:
  kind: chroma
compositor:
  person_plane_m: 30
scene:
  objects:
    - {name: box, shape: box, size: [1.6, 1.2, 0.4], position: [0, 0.6, 0], color: [0.2, 0.3, 0.9, 1]}
camera:
  calibration: camera.yaml
)"));
    Station station(cfg, StationInput::fromReplay(std::make_unique<TwoPeopleCamera>(
                                                      real, std::vector{nearCard, farCard},
                                                      std::vector{cv::Scalar(0, 0, 230), cv::Scalar(230, 0, 230)}),
                                                  30.0));
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(station.frame());

    const PersonDepths& depths = station.personDepths();
    ASSERT_EQ(depths.people, 2);
    std::vector<float> metres{depths.metres[1], depths.metres[2]};
    std::sort(metres.begin(), metres.end());
    EXPECT_NEAR(metres[0], real.depthOf(nearFeet), 0.05 * real.depthOf(nearFeet));
    EXPECT_NEAR(metres[1], real.depthOf(farFeet), 0.05 * real.depthOf(farFeet));
    EXPECT_EQ(station.stats().objectsInFront, 1u);

    // The box's front face, where each card overlaps it.
    const glm::dvec2 boxNear = real.project({-0.3, 0.7, 0.2}), boxFar = real.project({0.4, 1.1, 0.2});
    ASSERT_TRUE(nearCard.contains(cv::Point(static_cast<int>(boxNear.x), static_cast<int>(boxNear.y))));
    ASSERT_TRUE(farCard.contains(cv::Point(static_cast<int>(boxFar.x), static_cast<int>(boxFar.y))));
    const Image out = station.compositedFrame().read();
    auto rgb = [&](const glm::dvec2& p) {
        const std::size_t i = (static_cast<std::size_t>(p.y) * 640 + static_cast<std::size_t>(p.x)) * 4;
        return cv::Vec3b(out.rgba[i], out.rgba[i + 1], out.rgba[i + 2]);
    };
    EXPECT_EQ(rgb(boxNear), cv::Vec3b(230, 0, 0));  // the near person over the box
    const cv::Vec3b cut = rgb(boxFar);              // the box over the far person: blue, not magenta
    EXPECT_GT(cut[2], cut[0]) << cut;
    EXPECT_LT(cut[0], 150) << cut;
}

// A station whose environment file went bad after the check still runs: it
// says so and lights with the built-in environment, so its frames are those
// of a station configured with `neutral`.
TEST(Station, anUnreadableEnvironmentAtStartIsAWarningAndTheNeutralOneLights) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    arcomp::test::TempDir dir;
    const fs::path bad = dir.write("broken.hdr", "#?RADIANCE\nnot really\n");
    auto frameWith = [&](const fs::path& environment, std::vector<std::string>& warnings) {
        StationConfig cfg = occluderConfig(HoldoutMesh::Full);
        cfg.render.environment = environment;
        Station station(cfg, pattern({160, 120}));
        EXPECT_TRUE(station.frame());
        warnings = station.warnings();
        return station.compositedFrame().read();
    };
    std::vector<std::string> badWarnings, neutralWarnings;
    const Image withBad = frameWith(bad, badWarnings);
    const Image withNeutral = frameWith({}, neutralWarnings);
    const auto mentions = [](const std::vector<std::string>& lines, const std::string& part) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.find(part) != std::string::npos; });
    };
    EXPECT_TRUE(mentions(badWarnings, "broken.hdr"));
    EXPECT_TRUE(mentions(badWarnings, "neutral environment"));
    EXPECT_FALSE(mentions(neutralWarnings, "environment"));
    EXPECT_EQ(withBad.rgba, withNeutral.rgba);
}
