// glTF metallic-roughness shading in the Renderer, judged by statistics of
// small headless renders: emission and unlit materials, the BRDF's
// highlight, image-based light, normal and occlusion maps, alpha modes,
// texture slots (sampler, transform, TEXCOORD_1), vertex colours, sides.

#include "graph/core/SelectPass.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/ImageBasedLight.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"
#include "tests/support/ImagePixels.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

using namespace arcomp;

namespace {

constexpr glm::ivec2 kPbrSize{96, 96};

int brightness(const test::Pixel& p) { return (p.r + p.g + p.b) / 3; }

// The sRGB encoding of a linear value, as 0..255.
int encoded(float linear) {
    const float c = linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
}

// A unit square in the XY plane facing +Z, texture coordinates 0..1 from
// the bottom left (u along +X); `uvScale` stretches them.
Geometry makeSquare(float uvScale = 1.0f) {
    Geometry g;
    g.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    g.normals.assign(4, {0, 0, 1});
    g.texcoords = {{0, 1}, {uvScale, 1}, {uvScale, 1 - uvScale}, {0, 1 - uvScale}};
    g.indices = {0, 1, 2, 0, 2, 3};
    g.finalize();
    return g;
}

Image makeImage(int w, int h, const std::function<glm::u8vec4(int, int)>& texel) {
    Image img{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w * h * 4))};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::u8vec4 c = texel(x, y);
            std::copy(&c[0], &c[0] + 4, img.rgba.begin() + (y * w + x) * 4);
        }
    return img;
}

// The square seen head-on, filling the middle of the image (48x48 of 96x96
// at distance 4.83 with 45 degrees).
const View kFront = View::lookAt({0, 0, 4.828f}, {0, 0, 0}, {0, 1, 0}, 45.0f, kPbrSize);

// The API the running test renders with: every test runs on both.
GlRequest g_api = GlRequest::Gl33;

struct Render {
    std::optional<GlRequest> api = std::nullopt;  // default: g_api
    Shading shading = Shading::Phong;
    RenderSettings settings{};
    const ImageBasedLight* environment = nullptr;
    View view = kFront;
};

Image render(const std::function<void(Scene&)>& build, const Render& r = {}) {
    auto ctx = HeadlessContext::create(r.api.value_or(g_api));
    World world;
    build(world.scene);
    world.scene.update();
    RenderTarget target(r.view.viewport);
    target.bind();
    Renderer renderer;
    if (r.environment) renderer.setEnvironment(*r.environment);
    DrawList list;
    select(world, r.view, {.shading = r.shading}, list);
    renderer.draw(world.scene, list, r.view, r.settings);
    return target.read();
}

void addAt(Scene& scene, const glm::vec3& position, Geometry g, Material m) {
    const NodeId t = scene.addTransform(scene.root(), glm::translate(glm::mat4(1), position));
    scene.addMesh(t, {scene.addGeometry(std::move(g)), scene.addMaterial(std::move(m))});
}

void savePbrOnFailure(const Image& img, const std::string& name) {
    if (::testing::Test::HasFailure())
        writePng(std::string(ARCOMP_TEST_OUTPUT) + "/" + name + (g_api == GlRequest::Es3 ? "-es3" : "-gl33") + ".png",
                 img);
}

const Sampler kNearest{.magFilter = TextureFilter::Nearest, .minFilter = TextureFilter::Nearest};

TextureRef slot(int image, const Sampler& sampler, int texCoord = 0, const TextureTransform& transform = {}) {
    TextureRef ref;
    ref.image = image;
    ref.texCoord = texCoord;
    ref.sampler = sampler;
    ref.transform = transform;
    return ref;
}

class PbrShading : public ::testing::TestWithParam<GlRequest> {
protected:
    void SetUp() override { g_api = GetParam(); }
};

constexpr Shading kLevels[] = {Shading::Unlit, Shading::Flat, Shading::Gouraud, Shading::Phong};

}  // namespace

// The third-party car: black base colours, the colours in emission. A lit
// material shows its emission at every level; a KHR_materials_unlit one
// shows its base colour alone, as the extension says and three.js draws it.
TEST_P(PbrShading, blackBaseWithEmissionDrawsTheEmissiveColourUnlessUnlit) {
    const glm::vec3 emissive{0.2f, 0.6f, 1.0f};
    for (Shading level : kLevels) {
        for (bool unlit : {false, true}) {
            const Image img = render(
                [&](Scene& s) {
                    addAt(s, {}, makeSquare(),
                          {.name = "test", .baseColor = {0, 0, 0, 1}, .emissive = emissive, .unlit = unlit});
                },
                {.shading = level, .settings = {.lightIntensity = 0.0f, .environmentIntensity = 0.0f}});
            const test::Pixel p = test::pixelAt(img, 48, 48);
            const glm::vec3 expected = unlit ? glm::vec3(0.0f) : emissive;
            EXPECT_NEAR(p.r, encoded(expected.r), 2) << toString(level) << (unlit ? ", unlit" : "");
            EXPECT_NEAR(p.g, encoded(expected.g), 2) << toString(level) << (unlit ? ", unlit" : "");
            EXPECT_NEAR(p.b, encoded(expected.b), 2) << toString(level) << (unlit ? ", unlit" : "");
            EXPECT_EQ(p.a, 255);
            savePbrOnFailure(img, unlit ? "pbr-unlit-emissive" : "pbr-lit-emissive");
        }
    }
}

TEST_P(PbrShading, emissionTimesStrengthAndTextureShowsAtEveryLevel) {
    for (Shading level : kLevels) {
        const Image img = render(
            [&](Scene& s) {
                // Emissive texture: the left half white, the right half black.
                const int image = static_cast<int>(s.addImage(
                    makeImage(2, 1, [](int x, int) { return x == 0 ? glm::u8vec4(255) : glm::u8vec4(0, 0, 0, 255); })));
                Material m{
                    .name = "test", .baseColor = {0, 0, 0, 1}, .emissive = {0, 0.25f, 0}, .emissiveStrength = 4.0f};
                m.emissiveTexture = slot(image, kNearest);
                addAt(s, {}, makeSquare(), m);
            },
            {.shading = level, .settings = {.lightIntensity = 0.0f, .environmentIntensity = 0.0f}});
        EXPECT_EQ(test::pixelAt(img, 36, 48).g, 255) << toString(level) << ": 0.25 * 4 is full green";
        EXPECT_LT(test::pixelAt(img, 36, 48).r, 10) << toString(level);
        EXPECT_LT(test::pixelAt(img, 60, 48).g, 10) << toString(level) << ": the texture's black half emits nothing";
        savePbrOnFailure(img, "pbr-emission-levels");
    }
}

// A black dielectric in the dark shows only the directional light's GGX
// highlight: rougher, it is dimmer and wider.
TEST_P(PbrShading, highlightPeakFallsAndSpreadsAsRoughnessRises) {
    int lastPeak = 256;
    std::size_t lastSpread = 0;
    for (float roughness : {0.25f, 0.45f, 0.7f}) {
        const Image img = render(
            [&](Scene& s) {
                addAt(s, {}, makeUvSphere(1.0f, 64, 32),
                      {.name = "test", .baseColor = {0, 0, 0, 1}, .metallic = 0.0f, .roughness = roughness});
            },
            {.settings = {.lightDirection = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f)),
                          .lightIntensity = 1.0f,
                          .environmentIntensity = 0.0f}});
        int peak = 0;
        for (int y = 0; y < kPbrSize.y; ++y)
            for (int x = 0; x < kPbrSize.x; ++x) peak = std::max(peak, brightness(test::pixelAt(img, x, y)));
        std::size_t spread = 0;
        for (int y = 0; y < kPbrSize.y; ++y)
            for (int x = 0; x < kPbrSize.x; ++x) spread += brightness(test::pixelAt(img, x, y)) * 2 > peak;
        EXPECT_LT(peak, 255) << "roughness " << roughness << ": a clipped peak hides the fall";
        EXPECT_LT(peak, lastPeak) << "roughness " << roughness;
        EXPECT_GT(spread, lastSpread) << "roughness " << roughness;
        lastPeak = peak;
        lastSpread = spread;
        savePbrOnFailure(img, "pbr-roughness");
    }
}

// Metals reflect in their own colour (F0 = base colour); a dielectric's
// reflection (F0 = 0.04) is the light's own colour: white here.
TEST_P(PbrShading, metalReflectionsTakeTheBaseColourDielectricOnesStayWhite) {
    auto highlight = [](const glm::vec4& base, float metallic) {
        const Image img = render(
            [&](Scene& s) {
                addAt(s, {}, makeUvSphere(1.0f, 64, 32),
                      {.name = "test", .baseColor = base, .metallic = metallic, .roughness = 0.5f});
            },
            {.settings = {.lightIntensity = 0.4f, .environmentIntensity = 0.2f}});
        test::Pixel best{0, 0, 0, 0};
        for (int y = 0; y < kPbrSize.y; ++y)
            for (int x = 0; x < kPbrSize.x; ++x)
                if (brightness(test::pixelAt(img, x, y)) > brightness(best)) best = test::pixelAt(img, x, y);
        return best;
    };
    const test::Pixel metal = highlight({1.0f, 0.4f, 0.1f, 1}, 1.0f), plastic = highlight({0, 0, 0, 1}, 0.0f);
    EXPECT_LT(metal.b, metal.r * 6 / 10) << "metal highlight " << metal.r << "," << metal.g << "," << metal.b;
    EXPECT_GT(plastic.r, 20) << "the dielectric reflects something";
    EXPECT_NEAR(plastic.b, plastic.r, plastic.r / 10 + 1)
        << "plastic highlight " << plastic.r << "," << plastic.g << "," << plastic.b;
}

// A white furnace: under an environment of the same radiance everywhere,
// a white surface that absorbs nothing reflects exactly that radiance from
// every point, whatever its roughness, and disappears into its surround.
// A rough metal drawn with single scattering alone would keep about a
// third of it head-on and less at the rim.
TEST_P(PbrShading, aWhiteSurfaceInAWhiteFurnaceReflectsAllItsLightAtAnyRoughness) {
    const ImageBasedLight furnace =
        prefilterEnvironment(Environment{64, 32, std::vector<glm::vec3>(64 * 32, glm::vec3(0.5f))}, 32, 5);
    for (const float metallic : {1.0f, 0.0f})
        for (const float roughness : {0.3f, 0.6f, 1.0f}) {
            const Image img = render(
                [&](Scene& s) {
                    addAt(s, {}, makeUvSphere(1.0f, 64, 32),
                          {.name = "test", .baseColor = {1, 1, 1, 1}, .metallic = metallic, .roughness = roughness});
                },
                {.settings = {.lightIntensity = 0.0f, .environmentIntensity = 1.0f}, .environment = &furnace});
            int darkest = 255, brightest = 0;
            for (int y = 0; y < kPbrSize.y; ++y)
                for (int x = 0; x < kPbrSize.x; ++x) {
                    const test::Pixel p = test::pixelAt(img, x, y);
                    if (p.a != 255) continue;
                    darkest = std::min({darkest, p.r, p.g, p.b});
                    brightest = std::max({brightest, p.r, p.g, p.b});
                }
            EXPECT_GT(test::coveredPixels(img), 1000u);
            EXPECT_NEAR(darkest, encoded(0.5f), 4) << "metallic " << metallic << ", roughness " << roughness;
            EXPECT_NEAR(brightest, encoded(0.5f), 4) << "metallic " << metallic << ", roughness " << roughness;
            savePbrOnFailure(img, "pbr-furnace");
        }
}

namespace {

// A square under a light that grazes it from +X, with a normal map of
// vertical stripes whose normals lean alternately towards and away from it.
Image grazingSquare(bool withMap, bool withTangents) {
    return render(
        [&](Scene& s) {
            Geometry g = makeSquare();
            if (withTangents) g.tangents.assign(4, {1, 0, 0, 1});
            Material m{.name = "test", .baseColor = {0.8f, 0.8f, 0.8f, 1}, .roughness = 0.8f};
            if (withMap) {
                const int image = static_cast<int>(s.addImage(makeImage(8, 8, [](int x, int) {
                    return x % 2 ? glm::u8vec4(218, 128, 218, 255) : glm::u8vec4(38, 128, 218, 255);
                })));
                m.normalTexture = slot(image, kNearest);
            }
            addAt(s, {}, std::move(g), m);
        },
        {.settings = {.lightDirection = glm::normalize(glm::vec3(1.0f, 0.0f, 0.25f)),
                      .lightIntensity = 3.0f,
                      .environmentIntensity = 0.0f}});
}

// Spread of brightness over the square's middle.
int brightnessRange(const Image& img) {
    int lo = 255, hi = 0;
    for (int y = 30; y < 66; ++y)
        for (int x = 30; x < 66; ++x) {
            lo = std::min(lo, brightness(test::pixelAt(img, x, y)));
            hi = std::max(hi, brightness(test::pixelAt(img, x, y)));
        }
    return hi - lo;
}

}  // namespace

TEST_P(PbrShading, normalMapShowsItsPatternUnderAGrazingLight) {
    const Image plain = grazingSquare(false, true);
    const Image mapped = grazingSquare(true, true);
    const Image derived = grazingSquare(true, false);
    EXPECT_LT(brightnessRange(plain), 6) << "a flat square under a directional light is uniform";
    EXPECT_GT(brightnessRange(mapped), 60) << "the stripes lean towards and away from the light";
    EXPECT_GT(brightnessRange(derived), 60) << "without tangents, the frame from derivatives shows them too";
    // The stripes are 6 pixels wide: neighbouring columns three apart differ.
    EXPECT_GT(std::abs(brightness(test::pixelAt(mapped, 45, 48)) - brightness(test::pixelAt(mapped, 51, 48))), 40);
    savePbrOnFailure(mapped, "pbr-normal-map");
}

TEST_P(PbrShading, occlusionDarkensTheAmbientOnly) {
    auto squareWithOcclusion = [](float light, float environment) {
        return render(
            [&](Scene& s) {
                // Occlusion texture (R): left half fully occluded, right half open.
                const int image = static_cast<int>(s.addImage(
                    makeImage(2, 1, [](int x, int) { return x == 0 ? glm::u8vec4(0, 0, 0, 255) : glm::u8vec4(255); })));
                Material m{.name = "test", .baseColor = {0.8f, 0.8f, 0.8f, 1}, .roughness = 0.9f};
                m.occlusionTexture = slot(image, kNearest);
                addAt(s, {}, makeSquare(), m);
            },
            {.settings = {.lightDirection = {0, 0, 1}, .lightIntensity = light, .environmentIntensity = environment}});
    };
    const Image direct = squareWithOcclusion(1.5f, 0.0f);
    const Image ambient = squareWithOcclusion(0.0f, 1.0f);
    EXPECT_GT(brightness(test::pixelAt(direct, 36, 48)), 100);
    EXPECT_NEAR(brightness(test::pixelAt(direct, 36, 48)), brightness(test::pixelAt(direct, 60, 48)), 2)
        << "direct light is not occluded";
    EXPECT_GT(brightness(test::pixelAt(ambient, 60, 48)), 60);
    EXPECT_LT(brightness(test::pixelAt(ambient, 36, 48)), 5) << "the occluded half gets no environment light";
    savePbrOnFailure(ambient, "pbr-occlusion");
}

TEST_P(PbrShading, maskCutoffKeepsTheTexelsAboveIt) {
    std::size_t counts[2]{};
    int i = 0;
    for (float cutoff : {0.25f, 0.75f}) {
        const Image img = render(
            [&](Scene& s) {
                // Alpha rises across the texture: 0.5/16 .. 15.5/16.
                const int image = static_cast<int>(s.addImage(makeImage(16, 1, [](int x, int) {
                    return glm::u8vec4(255, 255, 255, static_cast<std::uint8_t>((x * 16 + 8)));
                })));
                Material m{
                    .name = "test", .baseColor = {1, 1, 1, 1}, .alphaMode = AlphaMode::Mask, .alphaCutoff = cutoff};
                m.baseColorTexture = slot(image, kNearest);
                addAt(s, {}, makeSquare(), m);
            },
            {.shading = Shading::Unlit, .settings = {.clearColor = glm::vec4(0)}});
        counts[i++] = test::coveredPixels(img);
        for (int y = 0; y < kPbrSize.y; ++y)
            for (int x = 0; x < kPbrSize.x; ++x) {
                const test::Pixel p = test::pixelAt(img, x, y);
                ASSERT_TRUE(p.a == 0 || p.a == 255) << "a masked texel is opaque or gone";
            }
    }
    const double square = 48.0 * 48.0;
    EXPECT_NEAR(static_cast<double>(counts[0]) / square, 0.75, 0.04);
    EXPECT_NEAR(static_cast<double>(counts[1]) / square, 0.25, 0.04);
}

TEST_P(PbrShading, blendedSquareMixesWithTheOpaqueOneBehind) {
    const Image img = render(
        [&](Scene& s) {
            addAt(s, {0, 0, -0.5f}, makeSquare(), {.name = "test", .baseColor = {1, 0, 0, 1}});
            addAt(s, {0, 0, 0.5f}, makeSquare(),
                  {.name = "test", .baseColor = {0, 0, 1, 0.5f}, .alphaMode = AlphaMode::Blend});
        },
        {.shading = Shading::Unlit});
    const test::Pixel p = test::pixelAt(img, 48, 48);
    // Premultiplied "over" of the encoded colours: half blue, half red.
    EXPECT_NEAR(p.r, 128, 3);
    EXPECT_NEAR(p.b, 128, 3);
    EXPECT_EQ(p.a, 255);
    savePbrOnFailure(img, "pbr-blend");
}

namespace {

Image checker(int cells) {
    return makeImage(cells, cells,
                     [](int x, int y) { return (x + y) % 2 ? glm::u8vec4(255) : glm::u8vec4(0, 0, 0, 255); });
}

Image texturedSquare(const Image& texture, const Sampler& sampler, TextureTransform transform = {},
                     float uvScale = 1.0f) {
    return render(
        [&](Scene& s) {
            Material m{.name = "test", .baseColor = {1, 1, 1, 1}};
            m.baseColorTexture = slot(static_cast<int>(s.addImage(texture)), sampler, 0, transform);
            addAt(s, {}, makeSquare(uvScale), m);
        },
        {.shading = Shading::Unlit});
}

double fractionDiffering(const Image& a, const Image& b) {
    std::size_t differ = 0, inside = 0;
    for (int y = 26; y < 70; ++y)
        for (int x = 26; x < 70; ++x) {
            ++inside;
            differ += std::abs(brightness(test::pixelAt(a, x, y)) - brightness(test::pixelAt(b, x, y))) > 128;
        }
    return static_cast<double>(differ) / static_cast<double>(inside);
}

}  // namespace

TEST_P(PbrShading, textureTransformMovesTheCheckerByItsOffset) {
    const Image plain = texturedSquare(checker(8), kNearest);
    const Image byOneCell = texturedSquare(checker(8), kNearest, {.offset = {0.125f, 0}});
    const Image byTwoCells = texturedSquare(checker(8), kNearest, {.offset = {0.25f, 0}});
    EXPECT_GT(fractionDiffering(plain, byOneCell), 0.8) << "one cell over swaps black and white";
    EXPECT_LT(fractionDiffering(plain, byTwoCells), 0.1) << "two cells over is the same pattern";
    savePbrOnFailure(byOneCell, "pbr-transform");
}

TEST_P(PbrShading, nearestSamplingKeepsEdgesSharpLinearBlursThem) {
    auto midTones = [](const Image& img) {
        std::size_t n = 0;
        for (int y = 26; y < 70; ++y)
            for (int x = 26; x < 70; ++x)
                n += brightness(test::pixelAt(img, x, y)) > 40 && brightness(test::pixelAt(img, x, y)) < 215;
        return static_cast<double>(n) / (44.0 * 44.0);
    };
    const Image nearest = texturedSquare(checker(2), kNearest);
    const Image linear =
        texturedSquare(checker(2), {.magFilter = TextureFilter::Linear, .minFilter = TextureFilter::Linear});
    EXPECT_LT(midTones(nearest), 0.02);
    EXPECT_GT(midTones(linear), 0.3);
}

// The default sampler minifies through mipmaps, and a colour texture is
// decoded from sRGB and averaged as light: a fine checker of sRGB 128
// (linear 0.216) and black seen small is linear 0.108, sRGB 92, and even.
// Without the decode it would read 137; averaged as sRGB codes, 64.
TEST_P(PbrShading, aMinifiedColourTextureAveragesInLinearLight) {
    const Image greyChecker = makeImage(256, 256, [](int x, int y) {
        return (x + y) % 2 ? glm::u8vec4(128, 128, 128, 255) : glm::u8vec4(0, 0, 0, 255);
    });
    const Image img = texturedSquare(greyChecker, Sampler{});
    int lo = 255, hi = 0, sum = 0;
    for (int y = 30; y < 66; ++y)
        for (int x = 30; x < 66; ++x) {
            const int b = brightness(test::pixelAt(img, x, y));
            lo = std::min(lo, b);
            hi = std::max(hi, b);
            sum += b;
        }
    EXPECT_NEAR(sum / (36 * 36), encoded(0.5f * 0.2158f), 8);
    EXPECT_LT(hi - lo, 16);
    savePbrOnFailure(img, "pbr-minified");
}

TEST_P(PbrShading, clampRepeatsTheEdgeTexelRepeatWrapsAround) {
    // Red | green, with u running 0..2 across the square.
    const Image redGreen =
        makeImage(2, 1, [](int x, int) { return x == 0 ? glm::u8vec4(255, 0, 0, 255) : glm::u8vec4(0, 255, 0, 255); });
    Sampler repeat = kNearest, clamp = kNearest;
    clamp.wrapS = TextureWrap::ClampToEdge;
    const Image repeated = texturedSquare(redGreen, repeat, {}, 2.0f);
    const Image clamped = texturedSquare(redGreen, clamp, {}, 2.0f);
    const int thirdQuarter = 24 + 48 * 5 / 8;  // u = 1.25
    EXPECT_GT(test::pixelAt(repeated, thirdQuarter, 48).r, 200);
    EXPECT_LT(test::pixelAt(repeated, thirdQuarter, 48).g, 50);
    EXPECT_GT(test::pixelAt(clamped, thirdQuarter, 48).g, 200);
    EXPECT_LT(test::pixelAt(clamped, thirdQuarter, 48).r, 50);
}

TEST_P(PbrShading, aSlotReadsTheTexcoordSetItNames) {
    auto square = [](int texCoord) {
        return render(
            [&](Scene& s) {
                Geometry g = makeSquare();
                g.texcoords1 = g.texcoords;
                g.texcoords.assign(4, {0.25f, 0.5f});  // TEXCOORD_0 reads red everywhere
                const Image redGreen = makeImage(2, 1, [](int x, int) {
                    return x == 0 ? glm::u8vec4(255, 0, 0, 255) : glm::u8vec4(0, 255, 0, 255);
                });
                Material m{.name = "test", .baseColor = {1, 1, 1, 1}};
                m.baseColorTexture = slot(static_cast<int>(s.addImage(redGreen)), kNearest, texCoord);
                addAt(s, {}, std::move(g), m);
            },
            {.shading = Shading::Unlit});
    };
    const Image first = square(0), second = square(1);
    EXPECT_GT(test::pixelAt(first, 60, 48).r, 200);
    EXPECT_GT(test::pixelAt(second, 36, 48).r, 200);
    EXPECT_GT(test::pixelAt(second, 60, 48).g, 200) << "TEXCOORD_1 spans the texture";
}

TEST_P(PbrShading, vertexColoursMultiplyTheBaseColour) {
    const Image img = render(
        [&](Scene& s) {
            Geometry g = makeSquare();
            g.colors = {{1, 0, 0, 1}, {0, 0, 1, 1}, {0, 0, 1, 1}, {1, 0, 0, 1}};  // red left, blue right
            addAt(s, {}, std::move(g), {.name = "test", .baseColor = {1, 1, 0.5f, 1}});
        },
        {.shading = Shading::Unlit});
    const test::Pixel left = test::pixelAt(img, 24, 48), right = test::pixelAt(img, 71, 48);
    EXPECT_GT(left.r, 240);
    EXPECT_LT(left.b, 40);
    EXPECT_NEAR(right.b, encoded(0.5f * 47.5f / 48.0f), 6) << "blue times the factor's 0.5";
    EXPECT_LT(right.r, 50);
}

TEST_P(PbrShading, singleSidedBacksAreCulledDoubleSidedOnesLitWithTheNormalFlipped) {
    const View behind = View::lookAt({0, 0, -4.828f}, {0, 0, 0}, {0, 1, 0}, 45.0f, kPbrSize);
    auto back = [&](Shading level, bool doubleSided, const glm::vec3& light) {
        return render(
            [&](Scene& s) {
                addAt(s, {}, makeSquare(),
                      {.name = "test",
                       .baseColor = {0.8f, 0.8f, 0.8f, 1},
                       .roughness = 1.0f,
                       .doubleSided = doubleSided});
            },
            {.shading = level,
             .settings = {.lightDirection = light, .lightIntensity = 2.0f, .environmentIntensity = 0.0f},
             .view = behind});
    };
    for (Shading level : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
        EXPECT_EQ(test::coveredPixels(back(level, false, {0, 0, -1})), 0u) << toString(level);
        const Image litFromViewerSide = back(level, true, {0, 0, -1});
        const Image litFromFront = back(level, true, {0, 0, 1});
        EXPECT_EQ(test::coveredPixels(litFromViewerSide), 48u * 48u) << toString(level);
        EXPECT_GT(brightness(test::pixelAt(litFromViewerSide, 48, 48)), 150) << toString(level);
        EXPECT_LT(brightness(test::pixelAt(litFromFront, 48, 48)), 10)
            << toString(level) << ": the back's normal points away from a light in front";
    }
}

TEST_P(PbrShading, unlitLevelIgnoresTheLightTopLevelFollowsTheEnvironment) {
    auto sphere = [](Shading level, const RenderSettings& settings, const ImageBasedLight* environment) {
        return render(
            [&](Scene& s) {
                addAt(s, {}, makeUvSphere(1.0f, 48, 24),
                      {.name = "test", .baseColor = {0.9f, 0.9f, 0.9f, 1}, .roughness = 0.5f});
            },
            {.shading = level, .settings = settings, .environment = environment});
    };
    const Image dim = sphere(Shading::Unlit, {.lightIntensity = 0.2f, .environmentIntensity = 0.1f}, nullptr);
    const Image bright = sphere(Shading::Unlit, {.lightIntensity = 5.0f, .environmentIntensity = 3.0f}, nullptr);
    EXPECT_EQ(dim.rgba, bright.rgba);

    Environment red{64, 32, std::vector<glm::vec3>(64 * 32, glm::vec3(1, 0, 0))};
    const ImageBasedLight redLight = prefilterEnvironment(red, 32, 4);
    const Image neutral = sphere(Shading::Phong, {.lightIntensity = 0.0f}, nullptr);
    const Image reddish = sphere(Shading::Phong, {.lightIntensity = 0.0f}, &redLight);
    const test::Pixel n = test::pixelAt(neutral, 48, 48), r = test::pixelAt(reddish, 48, 48);
    EXPECT_NEAR(n.r, n.b, 4) << "the neutral studio is grey";
    EXPECT_GT(n.r, 80);
    EXPECT_GT(r.r, 150);
    EXPECT_LT(r.g, 20);
    EXPECT_LT(r.b, 20);
    savePbrOnFailure(reddish, "pbr-red-environment");
}

// A mirror sphere shows the environment the right way round: what lies
// behind the camera (+Z) in its middle, +X on its right.
TEST_P(PbrShading, aMirrorSphereReflectsTheEnvironmentTheRightWayRound) {
    auto mirror = [](const std::function<bool(const glm::vec3&)>& bright) {
        Environment env{64, 32, std::vector<glm::vec3>(64 * 32)};
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x)
                env.radiance[static_cast<std::size_t>(y * 64 + x)] =
                    glm::vec3(bright(equirectangularDirection({(x + 0.5f) / 64.0f, (y + 0.5f) / 32.0f})) ? 1.0f : 0.0f);
        const ImageBasedLight light = prefilterEnvironment(env, 64, 5);
        return render(
            [&](Scene& s) {
                addAt(s, {}, makeUvSphere(1.0f, 64, 32),
                      {.name = "mirror", .baseColor = {1, 1, 1, 1}, .metallic = 1.0f, .roughness = 0.0f});
            },
            {.settings = {.lightIntensity = 0.0f}, .environment = &light});
    };
    const Image behindCamera = mirror([](const glm::vec3& d) { return d.z > 0.0f; });
    const Image ahead = mirror([](const glm::vec3& d) { return d.z < 0.0f; });
    const Image right = mirror([](const glm::vec3& d) { return d.x > 0.0f; });
    EXPECT_GT(brightness(test::pixelAt(behindCamera, 48, 48)), 200);
    EXPECT_LT(brightness(test::pixelAt(ahead, 48, 48)), 30);
    EXPECT_GT(brightness(test::pixelAt(right, 60, 48)), 200);
    EXPECT_LT(brightness(test::pixelAt(right, 36, 48)), 30);
    savePbrOnFailure(right, "pbr-mirror-right");
}

TEST(PbrShadingApis, desktopAndEsAgreeOnTheFullModel) {
    auto scene = [](Scene& s) {
        Geometry g = makeUvSphere(1.0f, 48, 24);
        addAt(s, {}, std::move(g),
              {.name = "test", .baseColor = {0.9f, 0.5f, 0.2f, 1}, .metallic = 0.5f, .roughness = 0.4f});
    };
    const Image gl = render(scene, {.api = GlRequest::Gl33});
    const Image es = render(scene, {.api = GlRequest::Es3});
    double sum = 0;
    for (std::size_t i = 0; i < gl.rgba.size(); ++i) sum += std::abs(int(gl.rgba[i]) - int(es.rgba[i]));
    EXPECT_LT(sum / static_cast<double>(gl.rgba.size()), 0.5);
    EXPECT_GT(test::coveredPixels(es), 1000u);
}

INSTANTIATE_TEST_SUITE_P(Apis, PbrShading, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });
