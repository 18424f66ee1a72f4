#pragma once
// The budget benchmark's world, after the paper's flight simulator: a field
// of mountains, each an LOD node over three heightfield meshes, and a fixed
// camera path over it along which the amount on screen varies a lot (a
// dense range seen close up, open country, the horizon).
//
//   FlightScene f = buildFlightScene({.mountains = 60});
//   View v = flightView(f, frame / double(frames - 1), {1280, 720});

#include "graph/core/View.hpp"
#include "graph/core/World.hpp"

#include <array>
#include <vector>

namespace arcomp {

struct FlightOptions {
    int mountains = 60;
    unsigned seed = 11;
};

struct FlightScene {
    // Its LOD nodes have one level as far as select is concerned: the
    // budget controller picks each mountain's level.
    World world;
    // Each mountain's level meshes, finest first.
    std::vector<std::array<NodeId, 3>> mountains;
    std::array<std::size_t, 3> trianglesPerLevel{};
};

FlightScene buildFlightScene(const FlightOptions& options);
// The camera at path position t in [0, 1].
View flightView(double t, glm::ivec2 viewport);

}  // namespace arcomp
