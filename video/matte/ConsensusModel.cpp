#include "video/matte/ConsensusModel.hpp"

#include "video/matte/Remainder.hpp"
#include "video/pixels/VideoError.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace arcomp {

namespace {

void checkConsensus(bool ok, const std::string& what) {
    if (!ok) throw VideoError("consensus matte", "settings", what);
}

// xorshift32: the model needs cheap, repeatable coin flips, not good statistics.
inline std::uint32_t nextRandom(std::uint32_t& state) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
}

inline int l1(const std::uint8_t* a, const std::uint8_t* b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

// Horprasert's brightness distortion alpha (the gain that brings the
// background nearest to the pixel) and chromaticity distortion (what is left
// once that gain is applied), the latter relative to the background's norm.
bool looksLikeShadow(const std::uint8_t* pixel, const std::uint8_t* background, const ConsensusSpec& spec) {
    const double b0 = background[0], b1 = background[1], b2 = background[2];
    const double norm2 = b0 * b0 + b1 * b1 + b2 * b2;
    if (norm2 < 30.0 * 30.0) return false;  // too dark for the chromaticity to mean anything
    const double alpha = (pixel[0] * b0 + pixel[1] * b1 + pixel[2] * b2) / norm2;
    if (alpha < spec.shadowDarkest || alpha > spec.shadowLightest) return false;
    const double d0 = pixel[0] - alpha * b0, d1 = pixel[1] - alpha * b1, d2 = pixel[2] - alpha * b2;
    return d0 * d0 + d1 * d1 + d2 * d2 <= spec.shadowChroma * spec.shadowChroma * norm2;
}

}  // namespace

ConsensusModel::ConsensusModel(const ConsensusSpec& spec) : spec_(spec) {
    checkConsensus(spec.samples >= 2 && spec.samples <= 64, "samples must lie in 2..64");
    checkConsensus(spec.matches >= 1 && spec.matches <= spec.samples, "matches must lie in 1..samples");
    checkConsensus(spec.colourRadius > 0.0 && spec.colourRadius <= 765.0, "colour_radius must lie in (0, 765]");
    checkConsensus(spec.shadowDarkest > 0.0 && spec.shadowDarkest < spec.shadowLightest && spec.shadowLightest <= 1.0,
                   "shadow brightness must satisfy 0 < darkest < lightest <= 1");
    checkConsensus(spec.shadowChroma >= 0.0 && spec.shadowChroma < 1.0, "shadow_chroma must lie in 0..1");
    checkConsensus(spec.updateOdds >= 1, "update_odds must be >= 1");
    checkConsensus(spec.absorbSeconds > 0.0, "absorb_s must be > 0");
    checkConsensus(spec.warmupSeconds >= 0.0, "warmup_s must be >= 0");
    checkConsensus(spec.fps > 0.0 && spec.fps <= 1000.0, "fps must lie in (0, 1000]");
    checkConsensus(spec.lightChangeFraction > 0.0 && spec.lightChangeFraction <= 1.0,
                   "light_change_fraction must lie in (0, 1]");
}

void ConsensusModel::setPlate(const cv::Mat& plate) {
    CV_Assert(plate.type() == CV_8UC3 && !plate.empty());
    warmup_.assign(1, plate.clone());
    plateGiven_ = true;
    seeded_ = false;
}

void ConsensusModel::seed(const cv::Mat& empty) {
    size_ = empty.size();
    const int n = spec_.samples;
    samples_.assign(static_cast<std::size_t>(size_.area()) * n * 3, 0);
    // The first sample is the pixel itself, the others its neighbours: the
    // spread of a 3x3 neighbourhood stands in for the noise not yet seen.
    for (int y = 0; y < size_.height; ++y)
        for (int x = 0; x < size_.width; ++x) {
            std::uint8_t* s = &samples_[(static_cast<std::size_t>(y) * size_.width + x) * n * 3];
            for (int k = 0; k < n; ++k) {
                int nx = x, ny = y;
                if (k > 0) {
                    const std::uint32_t r = nextRandom(random_);
                    nx = std::clamp(x + static_cast<int>(r % 3) - 1, 0, size_.width - 1);
                    ny = std::clamp(y + static_cast<int>((r / 3) % 3) - 1, 0, size_.height - 1);
                }
                const std::uint8_t* p = empty.ptr<std::uint8_t>(ny) + nx * 3;
                std::copy(p, p + 3, s + k * 3);
            }
        }
    empty.copyTo(background_);
    stillFrames_ = cv::Mat::zeros(size_, CV_16UC1);
    seeded_ = true;
}

void ConsensusModel::relearn(const cv::Mat& where) {
    CV_Assert(where.type() == CV_8UC1 && where.size() == size_ && !previous_.empty());
    const int n = spec_.samples;
    for (int y = 0; y < size_.height; ++y) {
        const std::uint8_t* w = where.ptr<std::uint8_t>(y);
        for (int x = 0; x < size_.width; ++x) {
            if (!w[x]) continue;
            // As at the start: the pixel and its neighbours stand in for the noise.
            std::uint8_t* s = &samples_[(static_cast<std::size_t>(y) * size_.width + x) * n * 3];
            for (int k = 0; k < n; ++k) {
                const std::uint32_t r = k > 0 ? nextRandom(random_) : 4;  // 4: the centre of the 3x3
                const int nx = std::clamp(x + static_cast<int>(r % 3) - 1, 0, size_.width - 1);
                const int ny = std::clamp(y + static_cast<int>((r / 3) % 3) - 1, 0, size_.height - 1);
                const std::uint8_t* p = previous_.ptr<std::uint8_t>(ny) + nx * 3;
                std::copy(p, p + 3, s + k * 3);
            }
            const std::uint8_t* p = previous_.ptr<std::uint8_t>(y) + x * 3;
            std::copy(p, p + 3, background_.ptr<std::uint8_t>(y) + x * 3);
            stillFrames_.at<std::uint16_t>(y, x) = 0;
        }
    }
}

void ConsensusModel::finishWarmup() {
    // Per-pixel, per-channel median of the kept images: a person passing
    // through covers any one pixel in fewer than half of them.
    const int count = static_cast<int>(warmup_.size());
    cv::Mat median(size_, CV_8UC3);
    std::vector<std::uint8_t> values(count);
    for (int y = 0; y < size_.height; ++y) {
        std::uint8_t* out = median.ptr<std::uint8_t>(y);
        for (int x = 0; x < size_.width * 3; ++x) {
            for (int i = 0; i < count; ++i) values[i] = warmup_[i].ptr<std::uint8_t>(y)[x];
            std::nth_element(values.begin(), values.begin() + count / 2, values.end());
            out[x] = values[count / 2];
        }
    }
    warmup_.clear();
    seed(median);
}

void ConsensusModel::apply(const cv::Mat& image, cv::Mat& labels) {
    CV_Assert(image.type() == CV_8UC3 && !image.empty());
    if (!seeded_ || image.size() != size_) {
        if (plateGiven_) {
            cv::Mat plate;
            cv::resize(warmup_.front(), plate, image.size(), 0, 0, cv::INTER_AREA);
            seed(plate);
            warmupFrames_ = -1;  // no warm-up: the plate is the empty place
        } else {
            seed(image);
            warmup_.clear();
            warmupFrames_ = 0;
        }
        image.copyTo(previous_);
    }
    if (warmupFrames_ >= 0) {
        // Keep about 15 images spread over the warm-up, then start from their median.
        const int total = std::max(1, static_cast<int>(std::lround(spec_.warmupSeconds * spec_.fps)));
        const int every = std::max(1, total / 15);
        if (warmupFrames_ % every == 0) warmup_.push_back(image.clone());
        if (++warmupFrames_ >= total) {
            finishWarmup();
            warmupFrames_ = -1;
        }
    }
    classify(image, labels);
    if (correctLightChange(image, labels)) classify(image, labels);
    update(image, labels);
    image.copyTo(previous_);
}

void ConsensusModel::classify(const cv::Mat& image, cv::Mat& labels) {
    labels.create(size_, CV_8UC1);
    const int n = spec_.samples, need = spec_.matches;
    const int radius = static_cast<int>(spec_.colourRadius);
    cv::parallel_for_(cv::Range(0, size_.height), [&](const cv::Range& rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            const std::uint8_t* in = image.ptr<std::uint8_t>(y);
            const std::uint8_t* bg = background_.ptr<std::uint8_t>(y);
            std::uint8_t* out = labels.ptr<std::uint8_t>(y);
            const std::uint8_t* s = &samples_[static_cast<std::size_t>(y) * size_.width * n * 3];
            for (int x = 0; x < size_.width; ++x, in += 3, bg += 3, s += n * 3) {
                int found = 0;
                for (int k = 0; k < n && found < need; ++k) found += l1(in, s + k * 3) < radius;
                out[x] = found >= need ? 0 : looksLikeShadow(in, bg, spec_) ? kShadow : kPerson;
            }
        }
    });
}

bool ConsensusModel::correctLightChange(const cv::Mat& image, const cv::Mat& labels) {
    const int changed = cv::countNonZero(labels);
    if (changed < spec_.lightChangeFraction * size_.area()) return false;
    // One gain per channel, the median of image / background over a grid of
    // pixels. A person covering the frame gives gains that disagree; a light
    // change gives one gain that explains most pixels.
    std::array<std::vector<float>, 3> ratios;
    const int step = std::max(1, static_cast<int>(std::sqrt(size_.area() / 2000.0)));
    for (int y = 0; y < size_.height; y += step)
        for (int x = 0; x < size_.width; x += step) {
            const std::uint8_t* p = image.ptr<std::uint8_t>(y) + x * 3;
            const std::uint8_t* b = background_.ptr<std::uint8_t>(y) + x * 3;
            for (int c = 0; c < 3; ++c)
                if (b[c] >= 16 && p[c] < 250) ratios[c].push_back(static_cast<float>(p[c]) / b[c]);
        }
    std::array<float, 3> gain{};
    for (int c = 0; c < 3; ++c) {
        if (ratios[c].size() < 16) return false;
        std::nth_element(ratios[c].begin(), ratios[c].begin() + ratios[c].size() / 2, ratios[c].end());
        gain[c] = ratios[c][ratios[c].size() / 2];
    }
    int explained = 0, total = 0;
    for (int y = 0; y < size_.height; y += step)
        for (int x = 0; x < size_.width; x += step, ++total) {
            const std::uint8_t* p = image.ptr<std::uint8_t>(y) + x * 3;
            const std::uint8_t* b = background_.ptr<std::uint8_t>(y) + x * 3;
            int d = 0;
            for (int c = 0; c < 3; ++c) d += std::abs(p[c] - static_cast<int>(std::lround(gain[c] * b[c])));
            explained += d < spec_.colourRadius;
        }
    if (explained < spec_.lightChangeFraction * total) return false;

    std::array<std::uint8_t, 256 * 3> lut{};
    for (int c = 0; c < 3; ++c)
        for (int v = 0; v < 256; ++v) lut[c * 256 + v] = cv::saturate_cast<std::uint8_t>(gain[c] * v);
    for (std::size_t i = 0; i < samples_.size(); ++i) samples_[i] = lut[(i % 3) * 256 + samples_[i]];
    for (int y = 0; y < size_.height; ++y) {
        std::uint8_t* b = background_.ptr<std::uint8_t>(y);
        for (int x = 0; x < size_.width * 3; ++x) b[x] = lut[(x % 3) * 256 + b[x]];
    }
    ++lightChanges_;
    return true;
}

void ConsensusModel::update(const cv::Mat& image, const cv::Mat& labels) {
    const int n = spec_.samples;
    const Remainder odds(static_cast<std::uint32_t>(spec_.updateOdds)), sample(static_cast<std::uint32_t>(n));
    // In a register, not re-read after every store into the samples.
    std::uint32_t random = random_;
    const int stillRadius = static_cast<int>(spec_.colourRadius / 2);
    const double absorb = std::min(65000.0, spec_.absorbSeconds * spec_.fps);
    const auto absorbFrames = static_cast<std::uint16_t>(absorb);
    const int w = size_.width, h = size_.height;
    for (int y = 0; y < h; ++y) {
        const std::uint8_t* in = image.ptr<std::uint8_t>(y);
        const std::uint8_t* last = previous_.ptr<std::uint8_t>(y);
        const std::uint8_t* label = labels.ptr<std::uint8_t>(y);
        std::uint8_t* bg = background_.ptr<std::uint8_t>(y);
        std::uint16_t* still = stillFrames_.ptr<std::uint16_t>(y);
        for (int x = 0; x < w; ++x, in += 3, last += 3, bg += 3) {
            std::uint8_t* own = &samples_[(static_cast<std::size_t>(y) * w + x) * n * 3];
            if (label[x] != 0) {
                // Foreground (or shadow): not learnt, unless it has stayed
                // unchanged for absorbSeconds; then it is learnt at the
                // background's own pace, a sample at a time.
                still[x] =
                    l1(in, last) < stillRadius ? static_cast<std::uint16_t>(std::min<int>(still[x] + 1, 65535)) : 0;
                if (still[x] >= absorbFrames && odds(nextRandom(random)) == 0)
                    std::copy(in, in + 3, own + sample(nextRandom(random)) * 3);
                continue;
            }
            still[x] = 0;
            for (int c = 0; c < 3; ++c) bg[c] = static_cast<std::uint8_t>((bg[c] * 15 + in[c] + 8) >> 4);
            if (odds(nextRandom(random)) == 0) std::copy(in, in + 3, own + sample(nextRandom(random)) * 3);
            if (odds(nextRandom(random)) == 0) {
                // Spatial diffusion, but only into a neighbour that is
                // background too: spreading into a person would eat them.
                const std::uint32_t r = nextRandom(random);
                const int nx = std::clamp(x + static_cast<int>(r % 3) - 1, 0, w - 1);
                const int ny = std::clamp(y + static_cast<int>((r / 3) % 3) - 1, 0, h - 1);
                if (labels.ptr<std::uint8_t>(ny)[nx] == 0)
                    std::copy(in, in + 3,
                              &samples_[(static_cast<std::size_t>(ny) * w + nx) * n * 3 + sample(r >> 8) * 3]);
            }
        }
    }
    random_ = random;
}

}  // namespace arcomp
