#pragma once
// The station config's `point_clouds` section (configs/README.md):
// translucent point clouds, each from a voxel file or the procedural tree,
// split into LDIs and placed in the scene. Absent: no clouds.
//
//   readPointCloudConfig(root, cfg.pointClouds);   // from loadStationConfig
//   addPointClouds(cfg.pointClouds, scene, clouds, warnings);

#include "graph/points/PointCloudNodes.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp {

class YamlMap;

struct PointCloudObject {
    std::string name;
    std::filesystem::path voxels;  // an .arvox file; empty: the procedural tree
    std::uint32_t seed = 2009;     // procedural tree
    int resolution = 120;          // procedural tree's voxel grid
    int ldis = 6;                  // LDI cameras placed around the cloud
    glm::vec3 position{0.0f};
    float rotationYDegrees = 0.0f;
    float scale = 1.0f;  // uniform: the renderer's layer needs it so
    int line = 0;
};

struct PointCloudConfig {
    std::vector<PointCloudObject> clouds;
};

void readPointCloudConfig(YamlMap& root, PointCloudConfig& out);

// Voxelizes or reads each cloud, builds its LDIs and adds it under a
// transform below the root; a cloud that cannot be loaded becomes a warning.
void addPointClouds(const PointCloudConfig& cfg, const std::filesystem::path& configFile, Scene& scene,
                    PointCloudNodes& clouds, std::vector<std::string>& warnings);

}  // namespace arcomp
