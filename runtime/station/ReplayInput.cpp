#include "runtime/station/ReplayInput.hpp"

#include "video/pixels/VideoError.hpp"
#include "video/sources/FileSource.hpp"
#include "video/sources/TestPatternSource.hpp"

namespace arcomp {

namespace {

StationInput pattern(const SourceSpec& spec) {
    return StationInput::fromReplay(
        std::make_unique<TestPatternSource>(TestPatternOptions{spec.width, spec.height, spec.fps, false}), spec.fps);
}

}  // namespace

StationInput openReplayInput(const SourceSpec& spec, std::vector<std::string>& warnings) {
    switch (spec.kind) {
    case SourceKind::Pattern: return pattern(spec);
    case SourceKind::File:
        try {
            auto file = std::make_unique<FileSource>(
                FileOptions{.path = spec.path, .paced = false, .loop = spec.loop, .onDamage = spec.onDamage});
            const double fps = file->info().fps > 0.0 ? file->info().fps : spec.fps;
            return StationInput::fromReplay(std::move(file), fps);
        } catch (const VideoError& e) {
            if (spec.fallback.kind == FallbackKind::None) throw;
            warnings.push_back(std::string(e.what()) + "; replaying the generated test pattern (" +
                               std::to_string(spec.width) + "x" + std::to_string(spec.height) + ") instead");
            return pattern(spec);
        }
    case SourceKind::V4l2:
    case SourceKind::Libcamera: break;
    }
    throw VideoError(spec.path, "replay", "replay needs a file or pattern source, not a camera; give --video FILE");
}

}  // namespace arcomp
