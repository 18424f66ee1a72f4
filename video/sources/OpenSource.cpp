#include "video/sources/OpenSource.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"
#include "video/sources/CaptureThread.hpp"
#include "video/sources/FallbackSource.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/LibcameraSource.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/sources/V4l2Source.hpp"

#include <opencv2/imgcodecs.hpp>

namespace arcomp {

namespace {

std::unique_ptr<FrameSource> openPrimary(const SourceSpec& spec) {
    if (spec.width <= 0 || spec.height <= 0 || !(spec.fps > 0.0))
        throw VideoError(
            spec.path.empty() ? "source" : spec.path, "spec",
            joinText("size ", spec.width, "x", spec.height, " at ", spec.fps, " fps: expected positive values"));
    CaptureThread::GrabberFactory factory;
    std::string name = spec.path;
    switch (spec.kind) {
    case SourceKind::File:
        factory = [spec] {
            return std::make_unique<FileSource>(
                FileOptions{.path = spec.path, .paced = spec.paced, .loop = spec.loop, .onDamage = spec.onDamage});
        };
        break;
    case SourceKind::V4l2:
        factory = [spec] {
            V4l2Options o;
            o.device = spec.path;
            o.width = spec.width;
            o.height = spec.height;
            o.fps = spec.fps;
            if (!spec.formats.empty()) o.preference = spec.formats;
            return std::make_unique<V4l2Source>(o);
        };
        break;
    case SourceKind::Libcamera:
        factory = [spec] {
            LibcameraOptions o;
            o.cameraId = spec.path;
            o.width = spec.width;
            o.height = spec.height;
            o.fps = spec.fps;
            if (!spec.formats.empty()) o.preference = spec.formats;
            return std::make_unique<LibcameraSource>(o);
        };
        name = "libcamera " + spec.path;
        break;
    case SourceKind::Pattern: {
        const TestPatternOptions o{.width = spec.width, .height = spec.height, .fps = spec.fps, .paced = spec.paced};
        TestPatternSource check(o);  // reject a bad size here, not on the capture thread
        name = check.name();
        factory = [o] { return std::make_unique<TestPatternSource>(o); };
        break;
    }
    }
    return std::make_unique<CaptureThread>(name, std::move(factory));
}

}  // namespace

std::unique_ptr<FrameSource> openSource(const SourceSpec& spec) {
    std::unique_ptr<FrameSource> primary = openPrimary(spec);
    const FallbackSpec& fb = spec.fallback;
    std::unique_ptr<FrameSource> fallback;
    cv::Mat still;
    switch (fb.kind) {
    case FallbackKind::None: primary->open(); return primary;
    case FallbackKind::File: {
        SourceSpec file;
        file.kind = SourceKind::File;
        file.path = fb.path;
        file.loop = true;
        fallback = openPrimary(file);
        break;
    }
    case FallbackKind::Pattern: {
        SourceSpec pattern = spec;
        pattern.kind = SourceKind::Pattern;
        pattern.paced = true;
        pattern.fallback = {};
        fallback = openPrimary(pattern);
        break;
    }
    case FallbackKind::Image:
        still = cv::imread(fb.path, cv::IMREAD_COLOR);
        if (still.empty()) throw VideoError(fb.path, "fallback image", "missing or not a readable image");
        break;
    case FallbackKind::LastGoodFrame: break;
    }
    auto out = std::make_unique<FallbackSource>(std::move(primary), fb.kind, std::move(fallback), std::move(still));
    out->open();
    return out;
}

}  // namespace arcomp
