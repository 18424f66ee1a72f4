#pragma once
// Everything needed to build a person matte, as plain data. The station's
// config loader fills it from the `matte` section; tests fill it directly.
//
//   MatteSpec spec{.kind = MatteKind::Chroma, .chroma = {.keyBgr = {0, 177, 64}}};
//   std::unique_ptr<PersonMatte> matte = makeMatte(spec);
//
// MatteKind::None gives a matte with alpha 0 everywhere: no person layer,
// the video is only the backdrop (plain AR overlay).

#include "video/matte/MaskFolderMatte.hpp"
#include "video/matte/PersonMatte.hpp"

#include <opencv2/core/types.hpp>

#include <memory>
#include <string>

namespace arcomp {

enum class MatteKind { None, Chroma, Background, Masks };

// Keying on the distance in the CbCr plane from the key colour.
struct ChromaKeySpec {
    cv::Vec3b keyBgr{64, 177, 0};  // studio green
    float similarity = 0.08f;      // CbCr distance (0..~0.7) below which a pixel is fully keyed out
    float smoothness = 0.06f;      // width of the ramp from transparent to opaque above `similarity`
    float spill = 0.10f;           // width above `similarity` over which key-coloured spill is desaturated; 0 = off
};

enum class BackgroundMethod { Consensus, Mog2, Knn, Cnt, CleanPlate };

// The consensus model (video/matte/ConsensusModel.hpp): every parameter is a
// physical quantity, in 8-bit levels, ratios or seconds, not a per-sequence tuning.
struct ConsensusSpec {
    int samples = 20;              // background colours remembered per pixel
    int matches = 2;               // samples a pixel must be near to be background
    double colourRadius = 24.0;    // L1 distance over B, G, R (levels) within which a sample is near: 3 x 8, the noise
    double shadowDarkest = 0.4;    // a shadow keeps at least this fraction of the background's brightness
    double shadowLightest = 0.92;  // ... and at most this (above: noise, already background)
    double shadowChroma =
        0.05;  // largest colour change of a shadow, relative to the background's brightness (about 3 degrees)
    int updateOdds = 16;               // a background pixel refreshes one of its samples with odds 1 in this
    double absorbSeconds = 180.0;      // a still, unchanging foreground pixel joins the background after this long
    double warmupSeconds = 2.0;        // busy-scene start: the first background is the median of this many seconds
    double fps = 25.0;                 // frames per second of the video, to turn seconds into frames
    double lightChangeFraction = 0.5;  // share of the frame that must change at once to count as a light change
    double minBlobArea = 0.001;        // foreground blobs smaller than this share of the frame are noise
    double maxHoleArea = 0.004;  // background holes smaller than this share of the frame, inside a person, are filled
    int gapPx = 6;               // gaps narrower than this (frame pixels) between parts of a person are closed
    int edgeRadiusPx = 4;  // guided filter window radius in frame pixels: how far the edge may move to the image's
};

// Foreground from a background model, cleaned up for a person layer.
// Consensus (the default) uses `consensus`, `cleanPlate`, `scale` and
// `temporal`; the other methods use the rest.
struct BackgroundSpec {
    BackgroundMethod method = BackgroundMethod::Consensus;
    ConsensusSpec consensus{};
    std::string cleanPlate{};  // CleanPlate: an image of the empty place; empty = the first frame seen
    double threshold = 30.0;   // CleanPlate: per-channel difference that counts as foreground; MOG2: variance threshold
    double learningRate = -1.0;  // -1: the model's own schedule; 0: frozen after the first frame
    int history = 300;           // frames the model remembers (MOG2, KNN) / stability (CNT, in frames)
    double scale = 0.5;          // the model runs at this fraction of the frame size (0.1..1), alpha is scaled back
    int openPx = 3;              // opening: removes specks smaller than this (pixels of the scaled mask); 0 = off
    int closePx = 9;             // closing: fills holes smaller than this; 0 = off
    int featherPx = 5;           // soft edge width in frame pixels (a blur at model scale); 0 = hard edges
    double temporal = 0.5;       // weight of the previous alpha (0..0.95) against flicker; 0 = off
};

struct MatteSpec {
    MatteKind kind = MatteKind::None;
    ChromaKeySpec chroma;
    BackgroundSpec background;
    MaskFolderSpec masks;
};

// Throws VideoError when the spec cannot be built (a clean plate that cannot
// be read, a value out of range).
std::unique_ptr<PersonMatte> makeMatte(const MatteSpec& spec);

}  // namespace arcomp
