#include "video/sources/FallbackSource.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"

#include <spdlog/spdlog.h>

namespace arcomp {

std::string_view fallbackKindName(FallbackKind kind) {
    switch (kind) {
    case FallbackKind::None: return "none";
    case FallbackKind::File: return "file";
    case FallbackKind::Image: return "still image";
    case FallbackKind::LastGoodFrame: return "last good frame";
    case FallbackKind::Pattern: return "test pattern";
    }
    return "unknown";
}

FallbackSource::FallbackSource(std::unique_ptr<FrameSource> primary, FallbackKind kind,
                               std::unique_ptr<FrameSource> fallback, cv::Mat still)
    : primary_(std::move(primary)), kind_(kind), fallback_(std::move(fallback)), still_(std::move(still)) {
    const bool needsSource = kind_ == FallbackKind::File || kind_ == FallbackKind::Pattern;
    if (!primary_ || (needsSource && !fallback_) || (kind_ == FallbackKind::Image && still_.empty()))
        throw VideoError(primary_ ? primary_->name() : "fallback", "fallback",
                         joinText(fallbackKindName(kind_), " fallback needs its source or image"));
}

FallbackSource::~FallbackSource() { close(); }

void FallbackSource::open() { primary_->open(); }

void FallbackSource::close() {
    primary_->close();
    if (fallback_) fallback_->close();
}

void FallbackSource::switchTo(bool fallback, const std::string& reason) {
    showingFallback_ = fallback;
    ++switches_;
    lastSwitchReason_ = reason;
    if (fallback) {
        spdlog::warn(joinText(primary_->name(), ": showing ", fallbackKindName(kind_), " fallback: ", reason));
        stillPending_ = true;
        if (fallback_) fallback_->open();
    } else {
        spdlog::info(joinText(primary_->name(), ": back from ", fallbackKindName(kind_), " fallback: ", reason));
        if (fallback_) fallback_->close();
    }
}

std::optional<Frame> FallbackSource::fallbackFrame() {
    switch (kind_) {
    case FallbackKind::File:
    case FallbackKind::Pattern: return fallback_->newest();
    case FallbackKind::Image:
    case FallbackKind::LastGoodFrame: {
        // A still is handed over once per switch; the renderer keeps showing it.
        if (!stillPending_) return std::nullopt;
        stillPending_ = false;
        if (kind_ == FallbackKind::LastGoodFrame && !lastGood_) return std::nullopt;
        Frame f = kind_ == FallbackKind::Image ? Frame{still_, {}, {}, 0, PixelFormat::Bgr} : *lastGood_;
        f.captured = std::chrono::steady_clock::now();
        f.sequence = stillSequence_++;
        return f;
    }
    case FallbackKind::None: break;
    }
    return std::nullopt;
}

std::optional<Frame> FallbackSource::newest() {
    std::optional<Frame> f = primary_->newest();
    if (f) {
        if (showingFallback_) switchTo(false, joinText("primary delivers frames again (frame ", f->sequence, ")"));
        if (kind_ == FallbackKind::LastGoodFrame) lastGood_ = f;
        return f;
    }
    if (!showingFallback_) {
        const SourceState s = primary_->state();
        if (kind_ == FallbackKind::None || !isLost(s.status)) return std::nullopt;
        switchTo(true, joinText("primary ", sourceStatusName(s.status), ": ", s.reason));
    }
    return fallbackFrame();
}

}  // namespace arcomp
