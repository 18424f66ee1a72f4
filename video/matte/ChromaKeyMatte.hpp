#pragma once
// Chroma key for studio stations: a pixel's alpha comes from its distance
// to the key colour in the CbCr plane (BT.709 coefficients on the encoded
// values), so shadows and highlights on the backing, which change luma but
// little chroma, key out alike. Near-key pixels kept in the foreground are
// desaturated towards their luma to remove spill from the backing.
//
//   ChromaKeyMatte key({.keyBgr = {64, 177, 0}, .similarity = 0.08f, .smoothness = 0.06f, .spill = 0.1f});
//   key.apply(frame, person);   // premultiplied BGRA
//
// Per pixel it is two table look-ups indexed by (Cb, Cr): the tables are
// built once from the settings.

#include "video/matte/MatteSpec.hpp"

#include <array>
#include <vector>

namespace arcomp {

// Opacity at CbCr distance `d` from the key: 0 up to `similarity`, a
// smoothstep to 1 over the next `smoothness`.
float chromaKeyAlpha(float d, float similarity, float smoothness);
// How much of a pixel's own chroma survives spill removal (1 = untouched).
float chromaSpillKeep(float d, float similarity, float spill);
// (Cb, Cr) of an encoded BGR colour, each in -0.5..0.5 (BT.709).
cv::Vec2f cbcrOf(cv::Vec3b bgr);

class ChromaKeyMatte final : public PersonMatte {
public:
    explicit ChromaKeyMatte(const ChromaKeySpec& spec);
    void apply(const cv::Mat& frame, cv::Mat& person) override;
    std::string name() const override { return "chroma key"; }

private:
    // Indexed by (Cb + 128) * 256 + (Cr + 128) in 8-bit units.
    std::vector<std::uint8_t> alpha_;
    std::vector<std::uint8_t> keep_;
};

}  // namespace arcomp
