#include "runtime/config/CameraFile.hpp"

#include "graph/io/AtomicFile.hpp"
#include "runtime/config/YamlMap.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <vector>

namespace arcomp {
namespace {

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", x);
    return text;
}

template <typename Values>
std::string list(const Values& values) {
    std::string text = "[";
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + number(values[i]);
    return text + "]";
}

// The lens, the part a camera file and a lens file share, after `header`.
std::string lensText(const char* header, const CameraIntrinsics& k, const std::string& note) {
    std::string text = header;
    if (!note.empty()) text += "# " + note + "\n";
    text += "image_size: [" + std::to_string(k.imageSize.x) + ", " + std::to_string(k.imageSize.y) + "]\n";
    text += "fx: " + number(k.fx) + "\nfy: " + number(k.fy) + "\ncx: " + number(k.cx) + "\ncy: " + number(k.cy) + "\n";
    text += "distortion: " + list(k.distortion) + "   # k1, k2, p1, p2, k3\n";
    return text;
}

void write(const std::filesystem::path& file, const std::string& text) {
    writeFileAtomically(file, std::as_bytes(std::span(text.data(), text.size())));
}

}  // namespace

void writeCameraFile(const std::filesystem::path& file, const CalibratedCamera& camera, const std::string& note) {
    std::vector<double> rotation;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) rotation.push_back(camera.rotation[column][row]);
    const std::vector<double> translation{camera.translation.x, camera.translation.y, camera.translation.z};
    std::string text = lensText("# arcomp camera calibration: pinhole intrinsics in pixels (OpenCV's axes:\n"
                                "# x right, y down, z forward) and the pose, floor frame to camera, in metres.\n",
                                camera.intrinsics, note);
    text += "rotation: " + list(rotation) + "\ntranslation: " + list(translation) + "\n";
    text += "# camera at " + list(std::vector<double>{camera.position().x, camera.position().y, camera.position().z}) +
            " m in the floor frame, " + number(camera.heightMetres()) + " m above the floor, tilted " +
            number(camera.tiltDegrees()) + " degrees down\n";
    write(file, text);
}

void writeLensFile(const std::filesystem::path& file, const CameraIntrinsics& intrinsics, const std::string& note) {
    write(file, lensText("# arcomp lens calibration: pinhole intrinsics in pixels (OpenCV's axes: x right,\n"
                         "# y down, z forward), no pose; `arcomp calibrate floor --intrinsics` adds it.\n",
                         intrinsics, note));
}

CalibratedCamera readCameraFile(const std::filesystem::path& file) {
    ConfigReport report(file);
    YAML::Node rootNode = loadYamlFile(report);
    if (!rootNode) report.throwIfAny();
    YamlMap root(rootNode, "", report);
    CalibratedCamera camera;
    CameraIntrinsics& k = camera.intrinsics;
    root.vec2i("image_size", k.imageSize, 1, 16384, Required::Yes);
    constexpr double kMaxPixels = 1e6;
    root.number("fx", k.fx, 1e-3, kMaxPixels, Required::Yes);
    root.number("fy", k.fy, 1e-3, kMaxPixels, Required::Yes);
    root.number("cx", k.cx, -kMaxPixels, kMaxPixels, Required::Yes);
    root.number("cy", k.cy, -kMaxPixels, kMaxPixels, Required::Yes);
    std::vector<float> distortion, rotation, translation;
    root.numbers("distortion", distortion, -1e3, 1e3);
    root.numbers("rotation", rotation, -1.0001, 1.0001);
    root.numbers("translation", translation, -1e5, 1e5);
    if (!distortion.empty() && distortion.size() != 4 && distortion.size() != 5)
        report.add(root.mark(), "distortion: expected [k1, k2, p1, p2] or [k1, k2, p1, p2, k3]");
    for (std::size_t i = 0; i < distortion.size() && i < 5; ++i) k.distortion[i] = distortion[i];
    if (root.has("rotation") != root.has("translation"))
        report.add(root.mark(), "rotation and translation: give both (the pose) or neither (intrinsics only)");
    if (!rotation.empty() && rotation.size() != 9)
        report.add(root.mark(), "rotation: expected 9 numbers, a 3x3 matrix row by row");
    if (!translation.empty() && translation.size() != 3) report.add(root.mark(), "translation: expected 3 numbers");
    if (rotation.size() == 9 && translation.size() == 3) {
        for (int row = 0; row < 3; ++row)
            for (int column = 0; column < 3; ++column)
                camera.rotation[column][row] = rotation[static_cast<std::size_t>(row * 3 + column)];
        camera.translation = glm::dvec3(translation[0], translation[1], translation[2]);
        // A rotation is orthonormal with determinant +1; anything else would
        // shear or mirror the CG against the video.
        const glm::dmat3 shouldBeIdentity = glm::transpose(camera.rotation) * camera.rotation;
        double worst = std::abs(glm::determinant(camera.rotation) - 1.0);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                worst = std::max(worst, std::abs(shouldBeIdentity[i][j] - (i == j ? 1.0 : 0.0)));
        if (worst > 1e-3) report.add(root.mark(), "rotation: not a rotation matrix (orthonormal, determinant +1)");
    }
    root.finish();
    report.throwIfAny();
    return camera;
}

}  // namespace arcomp
