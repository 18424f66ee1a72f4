#include "video/matte/MatteSpec.hpp"

#include "video/matte/BackgroundMatte.hpp"
#include "video/matte/ChromaKeyMatte.hpp"
#include "video/matte/ConsensusMatte.hpp"

namespace arcomp {

namespace {

// No person layer: alpha 0 everywhere, so the video is only the backdrop.
class NoMatte final : public PersonMatte {
public:
    void apply(const cv::Mat& frame, cv::Mat& person) override {
        person.create(frame.size(), CV_8UC4);
        person.setTo(cv::Scalar::all(0));
    }
    std::string name() const override { return "none"; }
};

}  // namespace

std::unique_ptr<PersonMatte> makeMatte(const MatteSpec& spec) {
    switch (spec.kind) {
    case MatteKind::None: return std::make_unique<NoMatte>();
    case MatteKind::Chroma: return std::make_unique<ChromaKeyMatte>(spec.chroma);
    case MatteKind::Background:
        if (spec.background.method == BackgroundMethod::Consensus)
            return std::make_unique<ConsensusMatte>(spec.background);
        return std::make_unique<BackgroundMatte>(spec.background);
    case MatteKind::Masks: return std::make_unique<MaskFolderMatte>(spec.masks);
    }
    return std::make_unique<NoMatte>();
}

}  // namespace arcomp
