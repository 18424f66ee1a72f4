#include "tools/bench/scenes/DemoStation.hpp"

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <cstdio>
#include <stdexcept>

namespace arcomp {

std::string demoVideo(const std::filesystem::path& dir, const std::string& bench, const std::string& preferred) {
    if (std::filesystem::exists(preferred)) return preferred;
    std::fprintf(stderr, "%s: %s is absent, generating a clip\n", bench.c_str(), preferred.c_str());
    // Moving blobs over a textured background: enough for the matte to find "people".
    const std::string file = (dir / "generated-clip.avi").string();
    cv::VideoWriter out(file, cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, {640, 480});
    if (!out.isOpened()) throw std::runtime_error(file + ": cannot write the generated clip");
    cv::Mat background(480, 640, CV_8UC3);
    cv::randu(background, cv::Scalar::all(40), cv::Scalar::all(90));
    for (int i = 0; i < 100; ++i) {
        cv::Mat f = background.clone();
        cv::ellipse(f, {80 + i * 5, 260}, {28, 80}, 0, 0, 360, cv::Scalar(30, 60, 200), cv::FILLED);
        cv::ellipse(f, {560 - i * 4, 300}, {24, 70}, 0, 0, 360, cv::Scalar(200, 160, 40), cv::FILLED);
        out.write(f);
    }
    return file;
}

std::string demoStationYaml(const std::string& video) {
    return "video:\n  source: file\n  path: \"" + video +
           "\"\n  loop: true\n"
           "matte:\n  kind: background\n  background:\n    method: mog2\n    scale: 0.5\n    feather_px: 3\n"
           "compositor:\n  person_plane_m: 12\n  backdrop: video\n"
           "scene:\n  objects:\n"
           "    - {name: pillar, shape: box, size: [0.5, 4.6, 0.5], position: [0.6, -0.6, -7.0]}\n"
           "    - {name: globe, shape: sphere, radius: 1.4, position: [5.4, -0.3, -16.0]}\n"
           "    - {name: kiosk, shape: box, size: [2.2, 1.0, 0.8], position: [-4.7, 1.45, -14.0]}\n"
           "camera:\n  eye: [0, 0, 0]\n  target: [0, 0, -10]\n  fovy_deg: 45\n  size: [768, 576]\n"
           "render:\n  shading: phong\n";
}

}  // namespace arcomp
