#pragma once
// The four shading levels, cheapest first, as the frame-time controller
// (paper: uniform-frame-time) steps through them.

#include <cstdint>
#include <optional>
#include <string_view>

namespace arcomp {

enum class Shading : std::uint8_t { Unlit, Flat, Gouraud, Phong };
inline constexpr int kShadingCount = 4;

std::string_view toString(Shading s);
std::optional<Shading> parseShading(std::string_view text);

}  // namespace arcomp
