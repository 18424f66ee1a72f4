#pragma once
// The synthetic installation `arcomp-bench ar` and `arcomp-bench people`
// measure the station on: a camera 3.2 m up, tilted 17 degrees, with a
// lens that bends (k1 -0.12); a textured floor; three walkers (boxes
// 0.5 x 1.7 x 0.3 m) going back and forth on known paths: one behind a CG
// box, one in front of it, one walking towards the camera past it; a CG
// sphere further back. The walkers are drawn through the true lens over
// the floor's photograph, a frame at a time, and the station calibrates
// the camera itself from photographs of a chessboard and a floor marker.
//
//   const SyntheticCamera lens(ar::kLens);
//   const ar::Calibration calibration = ar::calibrate(lens, dir);   // writes dir/camera.yaml
//   ar::ObjectPainter walkers(ar::walkers(), ar::trueCamera().view({768, 576}, 0.1f, 100.0f));
//   const cv::Mat frame = ar::over(lens.throughLens(walkers.paint(t, Shading::Phong)), ar::floorPlate(lens));

#include "graph/camera/CalibratedCamera.hpp"
#include "graph/core/SelectPass.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "tools/bench/scenes/SyntheticCamera.hpp"
#include "video/sources/FrameGrabber.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp::ar {

constexpr double kFps = 25.0;
inline const SyntheticLens kLens{
    .size = {768, 576}, .fx = 690, .fy = 686, .cx = 388, .cy = 284, .distortion = {-0.12, 0.02}};
constexpr double kCameraHeight = 3.2, kCameraZ = 9.5, kTiltDegrees = 17.0;

CalibratedCamera trueCamera();

// The CG: blue, so that a pixel showing it is told from a walker (red).
std::vector<ObjectConfig> cgObjects();
// Walkers on known paths, back and forth (graph/core/ObjectMotion.hpp).
std::vector<ObjectConfig> walkers();

// Where one of walkers() stands at video time `seconds`: its middle on the
// floor (x, z) in metres, and its velocity there in metres per second.
struct FloorTruth {
    glm::vec2 position{0.0f}, velocity{0.0f};
};
FloorTruth walkerAt(const ObjectConfig& walker, double seconds);

// The empty floor through `lens`: the clean plate the walkers walk over.
cv::Mat floorPlate(const SyntheticCamera& lens);

cv::Mat bgraOf(const Image& img);
// Premultiplied BGRA over BGR.
cv::Mat over(const cv::Mat& layer, const cv::Mat& under);

// Draws a list of objects at video time `seconds` through `view`.
class ObjectPainter {
public:
    ObjectPainter(std::vector<ObjectConfig> objects, const View& view);
    // Premultiplied BGRA, rows top first.
    cv::Mat paint(double seconds, Shading shading);

private:
    World world_;
    View view_;
    RenderTarget target_;
    Renderer renderer_;
};

// The station's own calibration of the installation's camera (dir/camera.yaml)
// and its errors against the true one.
struct Calibration {
    CalibratedCamera camera;
    double focalErrPct = 0, principalErrPx = 0, rmsPx = 0, heightErrPct = 0, tiltErrDeg = 0;
};
Calibration calibrate(const SyntheticCamera& lens, const std::filesystem::path& dir);

// A station config in `file` for the installation: `matte` and
// `compositor` are those sections' indented lines, `sections` whole
// sections more; the CG is cgObjects() and the camera dir/camera.yaml.
void writeConfig(const std::filesystem::path& file, const std::string& matte, const std::string& compositor,
                 const std::string& sections = "");

// The video the station sees, frame after frame, from memory.
class FramesGrabber : public FrameGrabber {
public:
    explicit FramesGrabber(const std::vector<cv::Mat>& frames) : frames_(frames) {}
    GrabResult grab() override;
    std::string name() const override { return "synthetic installation"; }

private:
    const std::vector<cv::Mat>& frames_;
    std::size_t next_ = 0;
};

}  // namespace arcomp::ar
