#include "runtime/config/PointCloudConfig.hpp"

#include "graph/io/VoxelFile.hpp"
#include "graph/points/LdiCamera.hpp"
#include "graph/points/Voxelizer.hpp"
#include "graph/scenes/ProceduralTree.hpp"
#include "runtime/config/YamlMap.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace arcomp {

void readPointCloudConfig(YamlMap& root, PointCloudConfig& out) {
    if (!root.has("point_clouds")) return;
    std::vector<YamlMap> list = root.list("point_clouds");
    for (std::size_t i = 0; i < list.size(); ++i) {
        YamlMap& m = list[i];
        PointCloudObject c;
        c.name = "cloud" + std::to_string(i);
        c.line = m.mark().line + 1;
        m.text("name", c.name);
        std::string source = "tree";
        m.choice("source", source, {"tree", "voxels"});
        if (source == "voxels") m.path("voxels", c.voxels, true, Required::Yes);
        int seed = static_cast<int>(c.seed);
        m.integer("seed", seed, 0, 1 << 30);
        c.seed = static_cast<std::uint32_t>(seed);
        m.integer("resolution", c.resolution, 8, 400);
        m.integer("ldis", c.ldis, 1, 32);
        m.vec3("position", c.position);
        m.number("rotation_y_deg", c.rotationYDegrees, -360.0, 360.0);
        m.number("scale", c.scale, 1e-4, 1e4);
        m.finish();
        out.clouds.push_back(std::move(c));
    }
}

void addPointClouds(const PointCloudConfig& cfg, const std::filesystem::path& configFile, Scene& scene,
                    PointCloudNodes& clouds, std::vector<std::string>& warnings) {
    for (const PointCloudObject& c : cfg.clouds) {
        PointCloud cloud;
        try {
            if (c.voxels.empty()) {
                const ProceduralTree tree = growTree(c.seed);
                cloud = pointCloudFromVoxels(voxelize(tree.voxelSources(), c.resolution));
            } else {
                cloud = pointCloudFromVoxels(readVoxelFile(c.voxels));
            }
        } catch (const std::exception& e) {  // ModelError, or the file unreadable
            warnings.push_back(configFile.string() + ":" + std::to_string(c.line) + ": point cloud '" + c.name +
                               "' skipped: " + e.what());
            continue;
        }
        if (cloud.size() == 0) {
            warnings.push_back(configFile.string() + ":" + std::to_string(c.line) + ": point cloud '" + c.name +
                               "' skipped: it has no points");
            continue;
        }
        const Sphere bound = sphereAround(cloud.positions);
        std::vector<LdiCamera> cameras = ldiCamerasAround(bound, c.ldis, cloud.pointSize);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), c.position);
        m = glm::rotate(m, glm::radians(c.rotationYDegrees), {0, 1, 0});
        m = glm::scale(m, glm::vec3(c.scale));
        const NodeId place = scene.addTransform(scene.root(), m, c.name);
        clouds.add(scene, place, buildLdis(std::move(cloud), std::move(cameras)), c.name);
    }
}

}  // namespace arcomp
