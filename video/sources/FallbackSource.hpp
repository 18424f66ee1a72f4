#pragma once
// Shows something sensible when a camera is missing or lost: a file, a
// still image, the last good frame or the test pattern. It switches back as
// soon as the camera delivers a frame again, and logs every switch with
// the reason.
//
//   FallbackSource src(std::move(camera), FallbackKind::Pattern, std::move(pattern));
//   src.open();
//   auto f = src.newest();          // camera frames, or fallback frames while it is lost
//   src.showingFallback();          // which one the station is showing
//
// state() is the camera's own state, so the station still knows it is lost.

#include "video/sources/FrameSource.hpp"
#include "video/sources/SourceSpec.hpp"

#include <memory>

namespace arcomp {

class FallbackSource : public FrameSource {
public:
    // `fallback` is the source for File and Pattern (nullptr otherwise);
    // `still` the image for Image.
    FallbackSource(std::unique_ptr<FrameSource> primary, FallbackKind kind, std::unique_ptr<FrameSource> fallback,
                   cv::Mat still = {});
    ~FallbackSource() override;

    void open() override;
    std::optional<Frame> newest() override;
    SourceState state() const override { return primary_->state(); }
    std::uint64_t drops() const override { return primary_->drops(); }
    void close() override;
    std::string name() const override { return primary_->name(); }

    bool showingFallback() const { return showingFallback_; }
    std::uint64_t switches() const { return switches_; }
    const std::string& lastSwitchReason() const { return lastSwitchReason_; }

private:
    void switchTo(bool fallback, const std::string& reason);
    std::optional<Frame> fallbackFrame();

    std::unique_ptr<FrameSource> primary_;
    FallbackKind kind_;
    std::unique_ptr<FrameSource> fallback_;
    cv::Mat still_;
    std::optional<Frame> lastGood_;
    bool showingFallback_ = false;
    bool stillPending_ = false;
    std::uint64_t switches_ = 0;
    std::uint64_t stillSequence_ = 0;
    std::string lastSwitchReason_;
};

std::string_view fallbackKindName(FallbackKind kind);

}  // namespace arcomp
