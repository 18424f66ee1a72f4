#pragma once
// The light that surrounds the scene, as an equirectangular image of linear
// RGB radiance: the source of the renderer's image-based lighting.
//
//   Environment env = neutralEnvironment();              // built in
//   Environment hdr = loadEnvironment("studio.hdr");     // or .png (sRGB)
//   writeRadianceHdr("neutral.hdr", env);                // for a reference viewer
//
// Layout as three.js reads an equirectangular map (EquirectangularReflection
// Mapping), so that a reference render given the same file lights alike:
// row 0 is straight up (+Y), the last row straight down; across a row the
// azimuth atan2(z, x) runs from -pi (column 0, -X) through -pi/2 (-Z) and 0
// (+X) to pi/2 (+Z).

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp {

struct Environment {
    int width = 0;
    int height = 0;
    std::vector<glm::vec3> radiance;  // linear RGB, row 0 at the top

    const glm::vec3& at(int x, int y) const { return radiance[static_cast<std::size_t>(y * width + x)]; }
    // Bilinear, wrapping in azimuth and clamped at the poles.
    glm::vec3 sample(const glm::vec3& direction) const;
};

// Where `direction` (unit length) falls in the image, in 0..1 both ways.
glm::vec2 equirectangularUv(const glm::vec3& direction);
// The unit direction through image coordinates (u, v) in 0..1.
glm::vec3 equirectangularDirection(glm::vec2 uv);

// A soft studio: a bright overhead panel, two dimmer soft boxes, a light
// horizon and a darker floor. Neutral grey, so it tints nothing;
// deterministic, so tests and reference renders agree.
Environment neutralEnvironment(int width = 256, int height = 128);

// Reads a Radiance .hdr (linear) or a PNG/JPEG (sRGB, decoded to linear).
// Throws BadInput naming the file and what was wrong with it.
Environment loadEnvironment(const std::filesystem::path& file);

// "neutral" gives neutralEnvironment(); anything else is a file path.
Environment environmentFromOption(const std::string& option);

// Writes a Radiance RGBE file (uncompressed scanlines, which every reader
// accepts). Throws std::runtime_error naming the file when it cannot.
void writeRadianceHdr(const std::filesystem::path& file, const Environment& environment);

}  // namespace arcomp
