#include "runtime/render/ImageBasedLight.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace arcomp {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Van der Corput's radical inverse in base 2 paired with k/n: the
// Hammersley point set, low-discrepancy and the same on every run.
glm::vec2 hammersley(std::uint32_t k, std::uint32_t n) {
    std::uint32_t bits = k;
    bits = (bits << 16u) | (bits >> 16u);
    bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
    bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
    bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
    bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
    return {static_cast<float>(k) / static_cast<float>(n), static_cast<float>(bits) * 2.3283064365386963e-10f};
}

// A half vector drawn with density D(h) (n.h) for GGX's D with alpha =
// roughness^2 (Walter et al. 2007, eq. 35-36), in the frame where n = +Z.
glm::vec3 sampleGgxHalfVector(glm::vec2 xi, float alpha) {
    const float phi = 2.0f * kPi * xi.x;
    const float cosTheta = std::sqrt((1.0f - xi.y) / (1.0f + (alpha * alpha - 1.0f) * xi.y));
    const float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// The GGX distribution and the height-correlated Smith visibility of glTF
// 2.0 Appendix B, as the renderer's shader evaluates them for direct light;
// here they weight the samples of the precomputed integrals.
float ggxDistribution(float nh, float alpha) {
    const float a2 = alpha * alpha;
    const float d = nh * nh * (a2 - 1.0f) + 1.0f;
    return a2 / (kPi * d * d);
}
float smithVisibility(float nl, float nv, float alpha) {
    const float a2 = alpha * alpha;
    const float ggxV = nl * std::sqrt(nv * nv * (1.0f - a2) + a2);
    const float ggxL = nv * std::sqrt(nl * nl * (1.0f - a2) + a2);
    const float sum = ggxV + ggxL;
    return sum > 0.0f ? 0.5f / sum : 0.0f;
}

Environment resized(const Environment& source, int width, int height) {
    Environment out{width, height, std::vector<glm::vec3>(static_cast<std::size_t>(width * height))};
    // Area averaging when shrinking, so that every source texel counts once
    // (a small sun in a large panorama keeps its energy); bilinear when
    // growing a small image.
    const cv::Mat from(source.height, source.width, CV_32FC3, const_cast<glm::vec3*>(source.radiance.data()));
    cv::Mat to(height, width, CV_32FC3, out.radiance.data());
    const bool shrinking = width <= source.width && height <= source.height;
    cv::resize(from, to, to.size(), 0, 0, shrinking ? cv::INTER_AREA : cv::INTER_LINEAR);
    return out;
}

glm::vec3 tangentToWorld(const glm::vec3& v, const glm::vec3& n) {
    const glm::vec3 up = std::abs(n.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(up, n));
    const glm::vec3 b = glm::cross(n, t);
    return t * v.x + b * v.y + n * v.z;
}

// One prefiltered direction: the GGX lobe around n, with v = n (Karis's
// simplification), each sample weighted by n.l. Each sample reads the
// source pyramid at the level whose texels cover about the sample's share
// of the lobe (Colbert & Krivanek 2007, "GPU-based importance sampling"),
// which removes the noise a few samples would otherwise leave.
glm::vec3 prefiltered(const std::vector<Environment>& pyramid, const glm::vec3& n, float alpha, std::uint32_t samples) {
    const float texelSolidAngle = 4.0f * kPi / static_cast<float>(pyramid[0].width * pyramid[0].height);
    const float maxLevel = static_cast<float>(pyramid.size() - 1);
    glm::vec3 sum(0.0f);
    float weight = 0.0f;
    for (std::uint32_t k = 0; k < samples; ++k) {
        const glm::vec3 h = tangentToWorld(sampleGgxHalfVector(hammersley(k, samples), alpha), n);
        const float nh = glm::dot(n, h);
        const glm::vec3 l = 2.0f * nh * h - n;
        const float nl = glm::dot(n, l);
        if (nl <= 0.0f) continue;
        // With v = n, the density of l is D(n.h) / 4.
        const float pdf = ggxDistribution(nh, alpha) / 4.0f;
        const float sampleSolidAngle = 1.0f / (static_cast<float>(samples) * pdf + 1e-6f);
        const float level = std::clamp(0.5f * std::log2(sampleSolidAngle / texelSolidAngle) + 1.0f, 0.0f, maxLevel);
        const auto lower = static_cast<std::size_t>(level);
        const std::size_t upper = std::min(lower + 1, pyramid.size() - 1);
        const float t = level - static_cast<float>(lower);
        sum += nl * glm::mix(pyramid[lower].sample(l), pyramid[upper].sample(l), t);
        weight += nl;
    }
    return weight > 0.0f ? sum / weight : glm::vec3(0.0f);
}

}  // namespace

ImageBasedLight prefilterEnvironment(const Environment& environment, int size, int levels) {
    ImageBasedLight light;

    // Diffuse: project onto the nine spherical harmonics up to order 2,
    // each texel weighted by its solid angle (equirectangular texels shrink
    // towards the poles by cos(elevation)).
    const Environment small = resized(environment, 2 * size, size);
    std::array<glm::vec3, 9> L{};
    const float texelArea = (2.0f * kPi / static_cast<float>(small.width)) * (kPi / static_cast<float>(small.height));
    for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x) {
            const glm::vec2 uv{(static_cast<float>(x) + 0.5f) / static_cast<float>(small.width),
                               (static_cast<float>(y) + 0.5f) / static_cast<float>(small.height)};
            const glm::vec3 d = equirectangularDirection(uv);
            const float solidAngle = texelArea * std::sqrt(std::max(0.0f, 1.0f - d.y * d.y));
            const glm::vec3 c = small.at(x, y) * solidAngle;
            // Real spherical harmonics (Ramamoorthi & Hanrahan 2001, eq. 3).
            const std::array<float, 9> basis{0.282095f,
                                             0.488603f * d.y,
                                             0.488603f * d.z,
                                             0.488603f * d.x,
                                             1.092548f * d.x * d.y,
                                             1.092548f * d.y * d.z,
                                             0.315392f * (3.0f * d.z * d.z - 1.0f),
                                             1.092548f * d.x * d.z,
                                             0.546274f * (d.x * d.x - d.y * d.y)};
            for (std::size_t i = 0; i < 9; ++i) L[i] += c * basis[i];
        }
    // Ramamoorthi & Hanrahan 2001, eq. 12: the cosine-convolved irradiance
    // as a quadratic form; divided by pi here so the shader multiplies the
    // diffuse colour directly (Lambert's BRDF is colour / pi).
    const float c1 = 0.429043f, c2 = 0.511664f, c3 = 0.743125f, c4 = 0.886227f, c5 = 0.247708f;
    for (int ch = 0; ch < 3; ++ch) {
        auto l = [&](std::size_t i) { return L[i][ch] / kPi; };
        // Index order of L: 00, 1-1, 10, 11, 2-2, 2-1, 20, 21, 22.
        glm::mat4 m;
        m[0] = {c1 * l(8), c1 * l(4), c1 * l(7), c2 * l(3)};
        m[1] = {c1 * l(4), -c1 * l(8), c1 * l(5), c2 * l(1)};
        m[2] = {c1 * l(7), c1 * l(5), c3 * l(6), c2 * l(2)};
        m[3] = {c2 * l(3), c2 * l(1), c2 * l(2), c4 * l(0) - c5 * l(6)};
        light.irradiance[static_cast<std::size_t>(ch)] = m;
    }

    // Specular: a pyramid of the source by 2x2 averages, for the filtered
    // importance sampling, then one level per roughness.
    std::vector<Environment> pyramid{small};
    while (pyramid.back().height > 1) {
        const Environment& last = pyramid.back();
        pyramid.push_back(resized(last, last.width / 2, last.height / 2));
    }
    light.specular.push_back(resized(small, size, size / 2));
    const std::uint32_t samples = 128;
    for (int i = 1; i < levels; ++i) {
        const int w = std::max(size >> i, 2), h = std::max(w / 2, 1);
        const float roughness = static_cast<float>(i) / static_cast<float>(levels - 1);
        Environment level{w, h, std::vector<glm::vec3>(static_cast<std::size_t>(w * h))};
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::vec2 uv{(static_cast<float>(x) + 0.5f) / static_cast<float>(w),
                                   (static_cast<float>(y) + 0.5f) / static_cast<float>(h)};
                level.radiance[static_cast<std::size_t>(y * w + x)] =
                    prefiltered(pyramid, equirectangularDirection(uv), roughness * roughness, samples);
            }
        light.specular.push_back(std::move(level));
    }
    return light;
}

glm::vec3 diffuseRadiance(const ImageBasedLight& light, const glm::vec3& n) {
    const glm::vec4 n4(n, 1.0f);
    return {glm::dot(n4, light.irradiance[0] * n4), glm::dot(n4, light.irradiance[1] * n4),
            glm::dot(n4, light.irradiance[2] * n4)};
}

// Karis 2013, split sum, second factor: the GGX BRDF integrated against a
// white environment, split by Schlick's Fresnel into F0 * scale + bias.
SplitSumTable splitSumTable(int size) {
    SplitSumTable table{size, std::vector<glm::vec2>(static_cast<std::size_t>(size * size))};
    const std::uint32_t samples = 256;
    for (int row = 0; row < size; ++row) {
        const float roughness = (static_cast<float>(row) + 0.5f) / static_cast<float>(size);
        const float alpha = roughness * roughness;
        for (int col = 0; col < size; ++col) {
            const float nv = (static_cast<float>(col) + 0.5f) / static_cast<float>(size);
            const glm::vec3 v{std::sqrt(1.0f - nv * nv), 0.0f, nv};
            glm::vec2 sum(0.0f);
            for (std::uint32_t k = 0; k < samples; ++k) {
                const glm::vec3 h = sampleGgxHalfVector(hammersley(k, samples), alpha);
                const float vh = glm::dot(v, h);
                const glm::vec3 l = 2.0f * vh * h - v;
                const float nl = l.z, nh = h.z;
                if (nl <= 0.0f || vh <= 0.0f) continue;
                // f * n.l / pdf with pdf(l) = D n.h / (4 v.h): D cancels.
                const float w = smithVisibility(nl, nv, alpha) * 4.0f * nl * vh / nh;
                const float fc = std::pow(1.0f - vh, 5.0f);
                sum += glm::vec2((1.0f - fc) * w, fc * w);
            }
            table.scaleBias[static_cast<std::size_t>(row * size + col)] = sum / static_cast<float>(samples);
        }
    }
    return table;
}

}  // namespace arcomp
