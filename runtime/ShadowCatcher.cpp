#include "runtime/ShadowCatcher.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

using namespace gl;

namespace {

// Drawn over the viewport (the scissor keeps it to the shadows' rectangle).
// The quarter-size mask is blurred by four bilinear taps, a texel apart: a
// soft edge about eight output pixels wide, for four fetches a pixel (nine cost llvmpipe a millisecond more at 768x576).
const char* const kApplyShader = R"(
out vec4 fragColor;
uniform sampler2D uMask;
uniform vec2 uTexel;
uniform vec2 uOutputSize;
uniform float uStrength;
void main() {
    vec2 uv = gl_FragCoord.xy / uOutputSize;
    float covered = texture(uMask, uv + vec2(-0.5, -0.5) * uTexel).a + texture(uMask, uv + vec2(0.5, -0.5) * uTexel).a +
                    texture(uMask, uv + vec2(-0.5, 0.5) * uTexel).a + texture(uMask, uv + vec2(0.5, 0.5) * uTexel).a;
    fragColor = vec4(vec3(1.0 - uStrength * covered / 4.0), 1.0);
}
)";

constexpr int kBlurMarginPx = 12;

} // namespace

glm::mat4 floorShadowMatrix(const glm::vec3& light) {
    // p' = p - light * (p.y / light.y): column 1 holds what y contributes.
    glm::mat4 m(1.0f);
    m[1] = glm::vec4(-light.x / light.y, 0.0f, -light.z / light.y, 0.0f);
    return m;
}

ShadowCatcher::ApplyProgram::ApplyProgram()
    : program(fullScreenTriangle(kApplyShader)), mask(program.requiredLocation("uMask")), texel(program.requiredLocation("uTexel")),
      outputSize(program.requiredLocation("uOutputSize")), strength(program.requiredLocation("uStrength")) {}

ShadowCatcher::ShadowCatcher(glm::ivec2 size)
    : mask_(glm::max((size + 3) / 4, glm::ivec2(1))), emptyVao_(GlVertexArray::generate()) {
    glBindTexture(GL_TEXTURE_2D, mask_.colorTexture());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void ShadowCatcher::cast(const Scene& scene, const DrawList& cg, const View& view, const ShadowConfig& shadow,
                         Renderer& renderer, const RenderTarget& output) {
    pixels_ = 0;
    if (cg.items.empty() || shadow.strength <= 0.0f) return;
    const glm::mat4 flatten = floorShadowMatrix(shadow.light);
    const glm::mat4 viewProjection = view.viewProjection();
    const glm::vec2 size(output.size());

    // The shadows' rectangle on screen: each item's bounding cube flattened
    // and projected. A corner behind the eye makes it the whole screen.
    glm::vec2 lo(size), hi(0.0f);
    models_.resize(cg.items.size());  // sized before any pointer into it is taken
    flattened_.clear();
    for (std::size_t i = 0; i < cg.items.size(); ++i) {
        const DrawItem& item = cg.items[i];
        const Sphere& b = scene.worldBound(item.node);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 offset((corner & 1) ? b.radius : -b.radius, (corner & 2) ? b.radius : -b.radius,
                                   (corner & 4) ? b.radius : -b.radius);
            const glm::vec4 clip = viewProjection * flatten * glm::vec4(b.center + offset, 1.0f);
            if (clip.w <= 1e-6f) {
                lo = glm::vec2(0.0f);
                hi = size;
                continue;
            }
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
            lo = glm::min(lo, pixel);
            hi = glm::max(hi, pixel);
        }
        models_[i] = flatten * (item.model ? *item.model : scene.world(item.node));
        DrawItem flat = item;
        flat.model = &models_[i];
        flattened_.items.push_back(flat);
    }
    const glm::ivec2 from = glm::clamp(glm::ivec2(glm::floor(lo)) - kBlurMarginPx, glm::ivec2(0), output.size());
    const glm::ivec2 to = glm::clamp(glm::ivec2(glm::ceil(hi)) + kBlurMarginPx, glm::ivec2(0), output.size());
    if (to.x <= from.x || to.y <= from.y) return;
    pixels_ = static_cast<std::size_t>(to.x - from.x) * static_cast<std::size_t>(to.y - from.y);

    // The same objects in the same places under the same view cast the same
    // mask: a static installation draws it once.
    std::vector<MaskKey> key;
    key.reserve(flattened_.items.size());
    for (std::size_t i = 0; i < flattened_.items.size(); ++i)
        key.push_back({flattened_.items[i].part.geometry, flattened_.items[i].part.material, flattened_.items[i].firstIndex,
                       flattened_.items[i].indexCount, flattened_.items[i].fade, models_[i]});
    if (key != maskKey_ || viewProjection != maskViewProjection_) {
        mask_.bind();
        renderer.draw(scene, flattened_, view, {.clearColor = glm::vec4(0.0f), .coverageOnly = true});
        maskKey_ = std::move(key);
        maskViewProjection_ = viewProjection;
        ++masksDrawn_;
    }

    output.bind();
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(from.x, from.y, to.x - from.x, to.y - from.y);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);  // colour x shade, alpha kept
    apply_.program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mask_.colorTexture());
    glUniform1i(apply_.mask, 0);
    glUniform2f(apply_.texel, 1.0f / static_cast<float>(mask_.size().x), 1.0f / static_cast<float>(mask_.size().y));
    glUniform2f(apply_.outputSize, size.x, size.y);
    glUniform1f(apply_.strength, shadow.strength);
    glBindVertexArray(emptyVao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
}

} // namespace arcomp
