#include "runtime/render/PointCloudLayer.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace arcomp {

using namespace gl;

namespace {

// Drawn over the whole screen: each fragment fetches the layer pixel under
// it (the image's rows run top down).
const char* const kLayerShader = R"(
uniform sampler2D uColor;
uniform sampler2D uDepth;
out vec4 fragColor;
void main() {
    ivec2 size = textureSize(uColor, 0);
    ivec2 texel = ivec2(int(gl_FragCoord.x), size.y - 1 - int(gl_FragCoord.y));
    vec4 c = texelFetch(uColor, texel, 0);
    if (c.a <= 0.0) discard;
    // The points' colours are display values, composited as they are: the
    // same encoding the CG's output has, so "over" needs no conversion.
    fragColor = c;
    gl_FragDepth = texelFetch(uDepth, texel, 0).r;
}
)";

// The world transform's uniform scale (the length of its first axis).
float uniformScale(const glm::mat4& world) { return glm::length(glm::vec3(world[0])); }

// The view as seen from a node's local space, so the LdiRenderer can work on
// the cloud's own points; depths come out in local units (world / scale).
View localView(const View& view, const glm::mat4& world) {
    const float s = uniformScale(world);
    View local = view;
    local.view = view.view * world;
    local.eye = glm::vec3(glm::inverse(world) * glm::vec4(view.eye, 1.0f));
    local.forward = glm::normalize(glm::transpose(glm::mat3(world)) * view.forward);
    local.near = view.near / s;
    local.far = view.far / s;
    return local;
}

}  // namespace

PointCloudLayer::LayerProgram::LayerProgram()
    : program(fullScreenTriangle(kLayerShader)), color(program.requiredLocation("uColor")),
      depth(program.requiredLocation("uDepth")) {}

PointCloudLayer::PointCloudLayer(int threads) : threads_(threads), vao_(GlVertexArray::generate()) {}

LdiRenderer& PointCloudLayer::rendererFor(const LdiSet& set) {
    for (auto& [s, r] : renderers_)
        if (s == &set) return *r;
    renderers_.emplace_back(&set, std::make_unique<LdiRenderer>(set, threads_));
    return *renderers_.back().second;
}

void PointCloudLayer::draw(const Scene& scene, const PointCloudNodes& clouds, std::span<const PointCloudItem> visible,
                           const View& view) {
    cloudsDrawn_ = splatsDrawn_ = 0;
    if (visible.empty()) return;
    farthestFirst_.assign(visible.begin(), visible.end());
    std::sort(farthestFirst_.begin(), farthestFirst_.end(),
              [](const PointCloudItem& a, const PointCloudItem& b) { return a.viewDistance > b.viewDistance; });

    const glm::ivec2 size = view.viewport;
    if (size != textureSize_) {
        for (GlTexture* t : {&color_, &depth_}) {
            *t = GlTexture::generate();  // the old one, if any, goes
            glBindTexture(GL_TEXTURE_2D, t->get());
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        glBindTexture(GL_TEXTURE_2D, color_.get());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glBindTexture(GL_TEXTURE_2D, depth_.get());
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, size.x, size.y, 0, GL_RED, GL_FLOAT, nullptr);
        textureSize_ = size;
    }

    program_.program.use();
    glUniform1i(program_.color, 0);
    glUniform1i(program_.depth, 1);
    glBindVertexArray(vao_.get());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (const auto& [node, distance] : farthestFirst_) {
        const glm::mat4& world = scene.world(node);
        LdiRenderer& renderer = rendererFor(clouds.at(scene, node));
        const PointImage& img = renderer.render(localView(view, world));
        splatsDrawn_ += renderer.lastSplatCount();
        // View depth (local units) to window depth of the world view's projection.
        const float s = uniformScale(world);
        const glm::mat4& p = view.projection;
        ndcDepth_.resize(img.depth.size());
        for (std::size_t i = 0; i < img.depth.size(); ++i) {
            const float z = img.depth[i] * s;
            const float ndc = std::isinf(z) ? 1.0f : (p[2][2] * -z + p[3][2]) / z;
            ndcDepth_[i] = std::clamp(ndc * 0.5f + 0.5f, 0.0f, 1.0f);
        }
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, color_.get());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, depth_.get());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size.x, size.y, GL_RED, GL_FLOAT, ndcDepth_.data());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        ++cloudsDrawn_;
    }
    glActiveTexture(GL_TEXTURE0);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
}

}  // namespace arcomp
