#include "runtime/composite/Compositor.hpp"

#include "runtime/composite/TileQuads.hpp"

#include <glm/gtc/type_ptr.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

namespace arcomp {

using namespace gl;

namespace {

// The person layer on the occupied tiles, each pixel at its person's depth
// (the depth test keeps it behind a nearer holdout). Output and video share
// one pixel grid, so the fragment fetches its own texel; video rows arrive
// top first, framebuffer rows count from the bottom.
const char* const kPersonShader = R"(
#ifdef VERTEX
layout(location = 0) in vec2 aPosition;
void main() { gl_Position = vec4(aPosition, 0.0, 1.0); }
#else
out vec4 fragColor;
uniform sampler2D uPerson;
uniform highp usampler2D uSlots;
uniform int uSlotScale;   // 0: no slot image, every pixel is slot 0
uniform int uHeight;
uniform vec3 uDepth[PEOPLE];   // window depth = x fragX + y fragY + z, per slot
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 texel = ivec2(p.x, uHeight - 1 - p.y);
    int slot = uSlotScale > 0 ? int(texelFetch(uSlots, texel / uSlotScale, 0).r) : 0;
    gl_FragDepth = clamp(dot(uDepth[slot], vec3(gl_FragCoord.xy, 1.0)), 0.0, 1.0);
    fragColor = texelFetch(uPerson, texel, 0).bgra;   // uploaded as BGRA bytes
}
#endif
)";

// The OR of `count` words; a whole tile's count is a constant, so that loop
// is vectorized at -O2 too.
std::uint32_t wordsOr(const std::uint32_t* words, int count) {
    std::uint32_t any = 0;
    if (count == Compositor::kTile)
        for (int x = 0; x < Compositor::kTile; ++x) any |= words[x];
    else
        for (int x = 0; x < count; ++x) any |= words[x];
    return any;
}

// A card's window depth as a plane over the fragment's window position:
// (x, y, z) with depth = x fragX + y fragY + z. The projection's depth is
// linear in 1 / eye depth (-P22 + P32 / d in NDC), and the card's 1 / d
// is linear in the video pixel (u, v) = (fragX - 1/2, height - fragY - 1/2).
glm::vec3 windowDepthPlane(const glm::mat4& projection, const glm::vec3& inverseDepth, int height) {
    const float half = 0.5f * projection[3][2];
    const float a = inverseDepth.x, b = inverseDepth.y;
    const float c = inverseDepth.z + a * -0.5f + b * (static_cast<float>(height) - 0.5f);
    return {half * a, -half * b, 0.5f - 0.5f * projection[2][2] + half * c};
}
}  // namespace

Compositor::PersonProgram::PersonProgram()
    : program(kPersonShader, "#define PEOPLE " + std::to_string(PersonDepths::kMaxPeople + 1) + "\n"),
      person(program.requiredLocation("uPerson")), slots(program.requiredLocation("uSlots")),
      slotScale(program.requiredLocation("uSlotScale")), height(program.requiredLocation("uHeight")),
      depth(program.requiredLocation("uDepth")) {}

Compositor::Compositor(glm::ivec2 size)
    : size_(size), output_(size), personTexture_(GlTexture::generate()), tileVao_(GlVertexArray::generate()),
      tileBuffer_(GlBuffer::generate()), slotTexture_(GlTexture::generate()) {
    glBindTexture(GL_TEXTURE_2D, personTexture_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindVertexArray(tileVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindVertexArray(0);
}

void Compositor::makePlate(const cv::Mat& frame, cv::Mat& plate) {
    if (frame.type() != CV_8UC3) throw std::invalid_argument("Compositor::makePlate: expected a BGR frame");
    // RGBA is the fast upload path; rows flipped to GL's bottom-first order.
    // Converted row by row into the flipped position: one pass, not two.
    plate.create(frame.rows, frame.cols, CV_8UC4);
    cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            cv::Mat out = plate.row(frame.rows - 1 - y);
            cv::cvtColor(frame.row(y), out, cv::COLOR_BGR2RGBA);
        }
    });
}

void Compositor::begin(const cv::Mat& frame, const CompositeSettings& settings) {
    if (settings.backdropVideo) makePlate(frame, plate_);
    beginWithPlate(plate_, settings);
}

void Compositor::beginWithPlate(const cv::Mat& plate, const CompositeSettings& settings) {
    output_.bind();
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    if (settings.backdropVideo) {
        if (plate.cols != size_.x || plate.rows != size_.y || plate.type() != CV_8UC4 || !plate.isContinuous())
            throw std::invalid_argument("Compositor::begin: expected a video frame of the output size");
        // Straight into the colour texture: no pass, just the upload.
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glBindTexture(GL_TEXTURE_2D, output_.colorTexture());
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, plate.data);
        glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    } else {
        const glm::vec4 c = settings.backdropColor;
        glClearColor(c.r * c.a, c.g * c.a, c.b * c.a, c.a);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    }
}

void Compositor::beginHoldout() {
    output_.bind();
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // The CG's own depth is done with: from here the depth buffer holds the
    // holdout alone, which lies on (not in front of) its CG surface.
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

void Compositor::endHoldout() { glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); }

void Compositor::findTiles(const cv::Mat& person, PersonTiles& found) {
    found.quads.clear();
    found.count = 0;
    found.rows = glm::ivec2(0);
    found.occupied.clear();
    if (person.type() != CV_8UC4 || person.empty()) return;  // person() says what is wrong
    const glm::ivec2 size(person.cols, person.rows);
    const glm::ivec2 grid = tileGrid(size, kTile);
    const int tx = grid.x, ty = grid.y;
    std::vector<std::uint8_t>& occupied = found.occupied;
    occupied.assign(static_cast<std::size_t>(tx * ty), 0);
    // A pixel's alpha byte as a bit mask over the pixel read as one word:
    // a tile's row segment is then one OR over kTile words, which vectorizes.
    constexpr std::array<std::uint8_t, 4> kAlphaBytes{0, 0, 0, 0xFF};
    std::uint32_t alphaBits = 0;
    std::memcpy(&alphaBits, kAlphaBytes.data(), sizeof alphaBits);
    cv::parallel_for_(cv::Range(0, ty), [&](const cv::Range& rows) {
        for (int j = rows.start; j < rows.end; ++j) {
            std::uint8_t* tileRow = &occupied[static_cast<std::size_t>(j * tx)];
            for (int y = j * kTile; y < std::min(size.y, (j + 1) * kTile); ++y) {
                const auto* p = person.ptr<std::uint32_t>(y);
                for (int i = 0; i < tx; ++i) {
                    if (tileRow[i]) continue;
                    tileRow[i] = (wordsOr(p + i * kTile, std::min(kTile, size.x - i * kTile)) & alphaBits) != 0;
                }
            }
        }
    });
    found.rows = {size.y, 0};
    for (int j = 0; j < ty; ++j)
        for (int i = 0; i < tx; ++i) {
            if (!occupied[static_cast<std::size_t>(j * tx + i)]) continue;
            ++found.count;
            found.rows = {std::min(found.rows.x, j * kTile), std::min(size.y, (j + 1) * kTile)};
        }
    appendTileQuads(occupied, size, kTile, TileRows::FromTop, found.quads);
}

void Compositor::uploadSlots(const PersonDepths& depths) {
    const cv::Mat& s = depths.slots;
    if (s.empty()) return;
    const glm::ivec2 expected = (size_ + depths.slotScale - 1) / depths.slotScale;
    if (s.type() != CV_8UC1 || !s.isContinuous() || s.cols != expected.x || s.rows != expected.y)
        throw std::invalid_argument("Compositor::person: the slot image does not match the output size and its scale");
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, slotTexture_.get());
    if (slotSize_ != expected) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R8UI, s.cols, s.rows, 0, GL_RED_INTEGER, GL_UNSIGNED_BYTE, s.data);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        slotSize_ = expected;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, s.cols, s.rows, GL_RED_INTEGER, GL_UNSIGNED_BYTE, s.data);
    }
}

void Compositor::person(const cv::Mat& person, const PersonDepths& depths, const glm::mat4& projection) {
    findTiles(person, ownTiles_);
    this->person(person, ownTiles_, depths, projection);
}

void Compositor::person(const cv::Mat& person, const PersonTiles& tiles, const PersonDepths& depths,
                        const glm::mat4& projection) {
    if (person.cols != size_.x || person.rows != size_.y || person.type() != CV_8UC4 || !person.isContinuous())
        throw std::invalid_argument("Compositor::person: expected continuous premultiplied BGRA of the output size");
    tileCount_ = tiles.count;
    if (tiles.count == 0) return;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, personTexture_.get());
    // Only the image rows the tiles cover: the draw samples no other texel.
    // Texture rows are image rows, top first.
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, tiles.rows.x, size_.x, tiles.rows.y - tiles.rows.x, GL_RGBA, GL_UNSIGNED_BYTE,
                    person.ptr(tiles.rows.x));
    uploadSlots(depths);
    std::array<glm::vec3, PersonDepths::kMaxPeople + 1> window{};
    for (std::size_t i = 0; i < window.size(); ++i)
        window[i] = windowDepthPlane(projection, depths.inverseDepth[i], size_.y);

    output_.bind();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);  // in front of the holdout, or where there is none
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    program_.program.use();
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, personTexture_.get());
    glUniform1i(program_.person, 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, slotTexture_.get());
    glUniform1i(program_.slots, 1);
    glUniform1i(program_.slotScale, depths.slots.empty() ? 0 : depths.slotScale);
    glUniform1i(program_.height, size_.y);
    glUniform3fv(program_.depth, static_cast<GLsizei>(window.size()), glm::value_ptr(window[0]));
    glBindVertexArray(tileVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, tileBuffer_.get());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(tiles.quads.size() * sizeof(float)), tiles.quads.data(),
                 GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(tiles.quads.size() / 2));
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

}  // namespace arcomp
