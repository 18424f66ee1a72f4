#pragma once
// A person matte turns one video frame into the person layer: colour and
// alpha, premultiplied (colour already multiplied by alpha), as BGRA bytes in
// the frame's own (sRGB / BT.709-encoded) colour space. The compositor cuts
// this layer with holdouts and lays it over the CG behind the person.
//
//   std::unique_ptr<PersonMatte> matte = makeMatte(spec);   // video/matte/MatteSpec.hpp
//   cv::Mat person;                                         // CV_8UC4, reused
//   matte->apply(frame.image, person);                      // frame: CV_8UC3 BGR
//   cv::Mat a = alphaOf(person);                            // CV_8UC1, for inspection
//
// Mattes with temporal state (background models, smoothing) learn from every
// frame they see, so replay feeds them frames in order from the first.

#include <opencv2/core/mat.hpp>

#include <string>

namespace arcomp {

class PersonMatte {
public:
    virtual ~PersonMatte() = default;
    // `frame` is CV_8UC3 BGR; `person` becomes CV_8UC4 premultiplied BGRA of
    // the same size (its buffer is reused from call to call).
    virtual void apply(const cv::Mat& frame, cv::Mat& person) = 0;
    virtual std::string name() const = 0;
};

// The alpha channel of a person layer, for inspection and tests.
cv::Mat alphaOf(const cv::Mat& person);

// Premultiplies `frame` (CV_8UC3 BGR) by `alpha` (CV_8UC1) into `person`
// (CV_8UC4 BGRA), rounding to nearest: the last step of every matte.
void premultiply(const cv::Mat& frame, const cv::Mat& alpha, cv::Mat& person);

}  // namespace arcomp
