#include "runtime/composite/ShadowCatcher.hpp"

#include "runtime/composite/TileQuads.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

using namespace gl;

namespace {

// Drawn over the tiles that the shadows' rectangles cover, each pixel once.
// The quarter-size mask is blurred by four bilinear taps, a texel apart: a
// soft edge about eight output pixels wide, for four fetches a pixel (nine cost llvmpipe a millisecond more at
// 768x576).
const char* const kApplyShader = R"(
#ifdef VERTEX
layout(location = 0) in vec2 aPosition;
void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }
#else
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
#endif
)";

constexpr int kBlurMarginPx = 12;
constexpr int kTilePx = 8;

}  // namespace

glm::mat4 floorShadowMatrix(const glm::vec3& light) {
    // p' = p - light * (p.y / light.y): column 1 holds what y contributes.
    glm::mat4 m(1.0f);
    m[1] = glm::vec4(-light.x / light.y, 0.0f, -light.z / light.y, 0.0f);
    return m;
}

ShadowCatcher::ApplyProgram::ApplyProgram()
    : program(kApplyShader), mask(program.requiredLocation("uMask")), texel(program.requiredLocation("uTexel")),
      outputSize(program.requiredLocation("uOutputSize")), strength(program.requiredLocation("uStrength")) {}

ShadowCatcher::ShadowCatcher(glm::ivec2 size, Tiles tiles)
    : mask_(glm::max((size + 3) / 4, glm::ivec2(1))),
      tilesFromMask_(tiles == Tiles::Mask || (tiles == Tiles::Auto && isSoftwareRasterizer())),
      tileVao_(GlVertexArray::generate()), tileBuffer_(GlBuffer::generate()) {
    glBindVertexArray(tileVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindVertexArray(0);
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

    // Each item's shadow rectangle on screen: its bounding cube flattened and
    // projected, widened by the blur. A corner behind the eye makes it the
    // whole screen.
    models_.resize(cg.items.size());  // sized before any pointer into it is taken
    flattened_.clear();
    rectangles_.clear();
    for (std::size_t i = 0; i < cg.items.size(); ++i) {
        const DrawItem& item = cg.items[i];
        const Sphere& b = scene.worldBound(item.node);
        glm::vec2 lo(size), hi(0.0f);
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 offset((corner & 1) ? b.radius : -b.radius, (corner & 2) ? b.radius : -b.radius,
                                   (corner & 4) ? b.radius : -b.radius);
            const glm::vec4 clip = viewProjection * flatten * glm::vec4(b.center + offset, 1.0f);
            if (clip.w <= 1e-6f) {
                lo = glm::vec2(0.0f);
                hi = size;
                break;
            }
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
            lo = glm::min(lo, pixel);
            hi = glm::max(hi, pixel);
        }
        const glm::ivec2 from = glm::clamp(glm::ivec2(glm::floor(lo)) - kBlurMarginPx, glm::ivec2(0), output.size());
        const glm::ivec2 to = glm::clamp(glm::ivec2(glm::ceil(hi)) + kBlurMarginPx, glm::ivec2(0), output.size());
        if (to.x > from.x && to.y > from.y) rectangles_.push_back({from, to});
        models_[i] = flatten * (item.model ? *item.model : scene.world(item.node));
        DrawItem flat = item;
        flat.model = &models_[i];
        flattened_.items.push_back(flat);
    }
    coverRectangles(output.size());
    if (rectangles_.empty()) return;  // no shadow reaches the screen

    // The same objects in the same places under the same view cast the same
    // mask: a static installation draws it once.
    std::vector<MaskKey> key;
    key.reserve(flattened_.items.size());
    for (std::size_t i = 0; i < flattened_.items.size(); ++i)
        key.push_back({flattened_.items[i].part.geometry, flattened_.items[i].part.material,
                       flattened_.items[i].firstIndex, flattened_.items[i].indexCount, flattened_.items[i].fade,
                       models_[i]});
    if (key != maskKey_ || viewProjection != maskViewProjection_) {
        mask_.bind();
        renderer.draw(scene, flattened_, view, {.clearColor = glm::vec4(0.0f), .coverageOnly = true});
        maskKey_ = std::move(key);
        maskViewProjection_ = viewProjection;
        ++masksDrawn_;
        maskTiles_.clear();
    }
    if (tilesFromMask_ && maskTiles_.size() != covered_.size()) findMaskTiles(output.size());
    if (tilesFromMask_)
        for (std::size_t t = 0; t < covered_.size(); ++t) covered_[t] &= maskTiles_[t];
    buildQuads(output.size());
    if (pixels_ == 0) return;

    output.bind();
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);  // colour x shade, alpha kept
    apply_.program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, mask_.colorTexture());
    glUniform1i(apply_.mask, 0);
    glUniform2f(apply_.texel, 1.0f / static_cast<float>(mask_.size().x), 1.0f / static_cast<float>(mask_.size().y));
    glUniform2f(apply_.outputSize, size.x, size.y);
    glUniform1f(apply_.strength, shadow.strength);
    glBindVertexArray(tileVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(tiles_.size() * sizeof(float)), tiles_.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tiles_.size() / 2));
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

void ShadowCatcher::coverRectangles(glm::ivec2 size) {
    // Tiles, not the rectangles themselves: the pass multiplies, so a pixel
    // under two rectangles must still be drawn once. Window coordinates,
    // rows from the bottom, as the rectangles are.
    const glm::ivec2 grid = tileGrid(size, kTilePx);
    const int tx = grid.x, ty = grid.y;
    covered_.assign(static_cast<std::size_t>(tx * ty), 0);
    for (const Rectangle& r : rectangles_)
        for (int j = r.from.y / kTilePx; j <= (r.to.y - 1) / kTilePx; ++j)
            for (int i = r.from.x / kTilePx; i <= (r.to.x - 1) / kTilePx; ++i)
                covered_[static_cast<std::size_t>(j * tx + i)] = 1;
}

void ShadowCatcher::findMaskTiles(glm::ivec2 size) {
    const glm::ivec2 grid = tileGrid(size, kTilePx);
    const int tx = grid.x, ty = grid.y;
    maskTiles_.assign(static_cast<std::size_t>(tx * ty), 0);
    mask_.read(maskImage_);  // rows top to bottom
    const glm::ivec2 m = mask_.size();
    const glm::vec2 scale = glm::vec2(size) / glm::vec2(m);
    // Output pixel p samples the mask at texel coordinate (p + 1/2) / scale,
    // four taps half a texel to each side, each bilinear: texels
    // floor(c - 1) .. floor(c) + 1. So texel k reaches the pixels whose
    // c lies in [k - 1, k + 2), widened by a pixel against rounding.
    const auto pixels = [](int k, float s, int extent) {
        return glm::ivec2(std::clamp(static_cast<int>(std::floor(static_cast<float>(k - 1) * s - 1.5f)), 0, extent - 1),
                          std::clamp(static_cast<int>(std::ceil(static_cast<float>(k + 2) * s + 0.5f)), 0, extent - 1));
    };
    for (int row = 0; row < m.y; ++row) {
        const std::uint8_t* texels =
            &maskImage_.rgba[static_cast<std::size_t>(row) * static_cast<std::size_t>(m.x) * 4];
        const glm::ivec2 ys = pixels(m.y - 1 - row, scale.y, size.y);  // window rows count from the bottom
        for (int k = 0; k < m.x; ++k) {
            if (texels[k * 4 + 3] == 0) continue;
            const glm::ivec2 xs = pixels(k, scale.x, size.x);
            for (int j = ys.x / kTilePx; j <= ys.y / kTilePx; ++j)
                for (int i = xs.x / kTilePx; i <= xs.y / kTilePx; ++i)
                    maskTiles_[static_cast<std::size_t>(j * tx + i)] = 1;
        }
    }
}

void ShadowCatcher::buildQuads(glm::ivec2 size) {
    tiles_.clear();
    pixels_ = appendTileQuads(covered_, size, kTilePx, TileRows::FromBottom, tiles_);
}

}  // namespace arcomp
