#include "graph/core/Shading.hpp"

#include <array>

namespace arcomp {

namespace {
constexpr std::array<std::string_view, kShadingCount> kNames{"unlit", "flat", "gouraud", "phong"};
}

std::string_view toString(Shading s) { return kNames[static_cast<int>(s)]; }

std::optional<Shading> parseShading(std::string_view text) {
    for (int i = 0; i < kShadingCount; ++i)
        if (kNames[i] == text) return static_cast<Shading>(i);
    return std::nullopt;
}

}  // namespace arcomp
