// arcomp inspect-video <file|/dev/videoN|/dev/v4l/by-id/...|pattern|libcamera>:
// what a video input offers. Files: codec, size, fps, frame count. V4L2
// devices: every format with its sizes and rates. libcamera: the cameras it
// lists. pattern[:WxH@fps]: the generated source's settings.

#include "tools/cli/Command.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/LibcameraSource.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/sources/V4l2Source.hpp"

#include <cstdio>

namespace arcomp {
namespace {

void printDevice(const std::string& path) {
    auto dev = systemV4l2Device();
    std::printf("device: %s -> %s\n", path.c_str(), dev->resolve(path).c_str());
    for (const V4l2FormatInfo& f : listV4l2Formats(*dev, path)) {
        std::printf("  format %s (%s)\n", fourccString(f.fourcc).c_str(), f.description.c_str());
        for (const auto& s : f.sizes) {
            std::printf("    %s%dx%d", s.stepwise ? "up to " : "", s.width, s.height);
            for (double fps : s.fps) std::printf(" %.3g", fps);
            std::printf(s.fps.empty() ? "\n" : " fps\n");
        }
    }
}

void printPattern(const std::string& arg) {
    TestPatternOptions o;
    if (arg.size() > 8 && std::sscanf(arg.c_str() + 8, "%dx%d@%lf", &o.width, &o.height, &o.fps) < 2)
        throw InputError("pattern: expected pattern:WIDTHxHEIGHT[@FPS], got '" + arg + "'");
    const TestPatternSource p(o);
    std::printf("pattern: %s (BGR, generated, deterministic)\n", p.name().c_str());
}

// A VideoError (no such file, a device that will not open) is BadInput: exit 2.
int inspectVideo(const std::string& source) {
    if (source.rfind("/dev/", 0) == 0) {
        printDevice(source);
    } else if (source == "pattern" || source.rfind("pattern:", 0) == 0) {
        printPattern(source);
    } else if (source == "libcamera") {
        const auto cams = listLibcameraCameras();
        std::printf("libcamera: %zu camera(s)\n", cams.size());
        for (const auto& id : cams) std::printf("  %s\n", id.c_str());
    } else {
        const VideoFileInfo i = probeVideoFile(source);
        std::printf("file: %s\n  codec %s\n  size %dx%d\n  fps %.3f\n  frames %lld\n", source.c_str(), i.codec.c_str(),
                    i.width, i.height, i.fps, static_cast<long long>(i.frameCount));
    }
    return kExitOk;
}

const bool registered = registerCommand(
    {"inspect-video", "List a video file's or camera's formats, sizes and rates", [](CommandLine& line) {
         auto source = std::make_shared<std::string>();
         line.option("source", *source, "File, /dev/videoN, /dev/v4l/by-id/..., pattern[:WxH@fps] or libcamera")
             .required();
         return [source] { return inspectVideo(*source); };
     }});

}  // namespace
}  // namespace arcomp
