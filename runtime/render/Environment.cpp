#include "runtime/render/Environment.hpp"

#include "graph/core/BadInput.hpp"

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>

namespace arcomp {

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// A soft-edged round light: full inside `radius` (radians) of `centre`,
// fading to nothing over another `radius`.
float softDisc(const glm::vec3& d, const glm::vec3& centre, float radius) {
    const float angle = std::acos(std::clamp(glm::dot(d, centre), -1.0f, 1.0f));
    const float t = std::clamp((angle - radius) / radius, 0.0f, 1.0f);
    return 1.0f - t * t * (3.0f - 2.0f * t);
}

glm::vec3 neutralRadiance(const glm::vec3& d) {
    // Sky and floor: a light band at the horizon, brighter upwards, a dark
    // floor that meets it over a few degrees (a studio's cove, not a cliff).
    const float horizon = 0.4f, zenith = 0.6f, floor = 0.18f;
    float value = d.y >= 0.0f ? horizon + (zenith - horizon) * std::sqrt(d.y)
                              : floor + (horizon - floor) * std::exp(-(-d.y) * 12.0f);
    // Sized so that a white surface facing up gets about 0.8 from the
    // environment (E / pi), one facing sideways about 0.4: bright enough to
    // read shapes, dim enough that the directional light still shows; the
    // floor keeps undersides from going black.
    value += 1.5f * softDisc(d, {0.0f, 1.0f, 0.0f}, glm::radians(15.0f));
    value += 1.2f * softDisc(d, glm::normalize(glm::vec3(0.75f, 0.5f, 0.43f)), glm::radians(12.0f));
    value += 0.8f * softDisc(d, glm::normalize(glm::vec3(-0.75f, 0.4f, 0.43f)), glm::radians(12.0f));
    return glm::vec3(value);
}

}  // namespace

glm::vec2 equirectangularUv(const glm::vec3& d) {
    return {std::atan2(d.z, d.x) / (2.0f * std::numbers::pi_v<float>)+0.5f,
            0.5f - std::asin(std::clamp(d.y, -1.0f, 1.0f)) / std::numbers::pi_v<float>};
}

glm::vec3 equirectangularDirection(glm::vec2 uv) {
    const float azimuth = (uv.x - 0.5f) * 2.0f * std::numbers::pi_v<float>;
    const float elevation = (0.5f - uv.y) * std::numbers::pi_v<float>;
    return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation), std::cos(elevation) * std::sin(azimuth)};
}

glm::vec3 Environment::sample(const glm::vec3& direction) const {
    const glm::vec2 uv = equirectangularUv(direction);
    const float x = uv.x * static_cast<float>(width) - 0.5f;
    const float y = std::clamp(uv.y * static_cast<float>(height) - 0.5f, 0.0f, static_cast<float>(height - 1));
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const int y1 = std::min(y0 + 1, height - 1);
    auto wrap = [&](int xi) { return ((xi % width) + width) % width; };
    const glm::vec3 top = glm::mix(at(wrap(x0), y0), at(wrap(x0 + 1), y0), fx);
    const glm::vec3 bottom = glm::mix(at(wrap(x0), y1), at(wrap(x0 + 1), y1), fx);
    return glm::mix(top, bottom, fy);
}

Environment neutralEnvironment(int width, int height) {
    Environment env{width, height, std::vector<glm::vec3>(static_cast<std::size_t>(width * height))};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec2 uv{(static_cast<float>(x) + 0.5f) / static_cast<float>(width),
                               (static_cast<float>(y) + 0.5f) / static_cast<float>(height)};
            env.radiance[static_cast<std::size_t>(y * width + x)] = neutralRadiance(equirectangularDirection(uv));
        }
    return env;
}

Environment loadEnvironment(const std::filesystem::path& file) {
    const std::string name = file.string();
    if (!std::filesystem::exists(file)) throw BadInput(name, "", "environment file does not exist");
    cv::Mat image;
    try {
        image = cv::imread(name, cv::IMREAD_UNCHANGED);
    } catch (const cv::Exception& e) {
        throw BadInput(name, "", std::string("cannot decode the environment: ") + e.what());
    }
    if (image.empty())
        throw BadInput(name, "", "cannot decode the environment: expected a Radiance .hdr or a PNG/JPEG image");
    if (image.cols != 2 * image.rows)
        throw BadInput(name, "",
                       "environment is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                           ": expected an equirectangular image, twice as wide as high");
    const int channels = image.channels();
    if (channels != 1 && channels != 3 && channels != 4)
        throw BadInput(name, "",
                       "environment has " + std::to_string(channels) + " channels: expected grey, RGB or RGBA");
    cv::Mat values;
    const bool linear = image.depth() == CV_32F || image.depth() == CV_64F;
    const double scale = image.depth() == CV_8U ? 1.0 / 255.0 : image.depth() == CV_16U ? 1.0 / 65535.0 : 1.0;
    image.convertTo(values, CV_MAKETYPE(CV_32F, channels), scale);
    Environment env{values.cols, values.rows, std::vector<glm::vec3>(values.total())};
    for (int y = 0; y < values.rows; ++y) {
        const float* row = values.ptr<float>(y);
        for (int x = 0; x < values.cols; ++x) {
            const float* p = row + x * channels;
            // OpenCV orders colour channels BGR.
            glm::vec3 c = channels == 1 ? glm::vec3(p[0]) : glm::vec3(p[2], p[1], p[0]);
            for (int i = 0; i < 3; ++i) {
                if (!std::isfinite(c[i]) || c[i] < 0.0f) c[i] = 0.0f;
                if (!linear) c[i] = srgbToLinear(c[i]);
            }
            env.radiance[static_cast<std::size_t>(y * values.cols + x)] = c;
        }
    }
    return env;
}

Environment environmentFromOption(const std::string& option) {
    return option == "neutral" ? neutralEnvironment() : loadEnvironment(option);
}

void writeRadianceHdr(const std::filesystem::path& file, const Environment& env) {
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream out(file, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + file.string());
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << env.height << " +X " << env.width << "\n";
    std::vector<unsigned char> row(static_cast<std::size_t>(env.width) * 4);
    for (int y = 0; y < env.height; ++y) {
        for (int x = 0; x < env.width; ++x) {
            // RGBE (Ward, Graphics Gems II): a shared exponent for the
            // largest component, 8-bit mantissas.
            const glm::vec3 c = glm::max(env.at(x, y), glm::vec3(0.0f));
            const float largest = std::max({c.r, c.g, c.b});
            unsigned char* p = &row[static_cast<std::size_t>(x) * 4];
            if (largest < 1e-32f) {
                p[0] = p[1] = p[2] = p[3] = 0;
                continue;
            }
            int exponent = 0;
            const float mantissa = std::frexp(largest, &exponent);
            const float scale = mantissa * 256.0f / largest;
            for (int i = 0; i < 3; ++i) p[i] = static_cast<unsigned char>(std::min(255.0f, c[i] * scale));
            p[3] = static_cast<unsigned char>(exponent + 128);
        }
        out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size()));
    }
    out.close();
    if (!out) throw std::runtime_error("cannot write " + file.string() + ": write failed");
}

}  // namespace arcomp
