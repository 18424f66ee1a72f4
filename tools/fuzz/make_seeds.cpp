// Writes small valid inputs for the binary, CSV and HTTP fuzz targets into
// <out>/<target>/, from the project's own writers, so that each fuzzer
// starts from a file its parser accepts and mutates inward from there.
//
//   build-fuzz/make_seeds build-fuzz/seeds

#include "graph/budget/CostModel.hpp"
#include "graph/io/LodFile.hpp"
#include "graph/io/SilhouetteFile.hpp"
#include "graph/io/VoxelFile.hpp"
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/CameraFile.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

Geometry tetrahedron() {
    Geometry g;
    g.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    g.texcoords = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    g.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    g.finalize();
    return g;
}

void writeText(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_seeds <folder>\n";
        return 2;
    }
    const fs::path out = argv[1];
    for (const char* t : {"lod", "silhouette", "voxel", "calibration", "camera", "gaze", "obj", "http"})
        fs::create_directories(out / t);

    const Geometry g = tetrahedron();
    std::vector<LodLevel> levels(2);
    levels[0].geometry = g;
    levels[1].geometry = g;
    levels[1].geometry.normals.clear();
    levels[1].geometry.texcoords.clear();
    levels[1].ratio = 0.5f;
    levels[1].error = 0.01f;
    writeLodFile(out / "lod/tetra.lod", levels);
    // The optional attributes' flags, so that mutations reach their branches.
    levels[0].geometry.texcoords1 = g.texcoords;
    levels[0].geometry.tangents = computeTangents(g.positions, g.normals, g.texcoords, g.indices);
    levels[0].geometry.tangentsGenerated = true;
    writeLodFile(out / "lod/tetra-tangents.lod", levels);

    SilhouetteMesh sil;
    sil.positions = g.positions;
    sil.indices = g.indices;
    sil.full = {0, 12};
    Box box;
    box.min = glm::vec3(2.0f);
    box.max = glm::vec3(3.0f);
    sil.regions.push_back(ViewRegion::fromBox(box));
    sil.ranges.push_back({0, 6});
    writeSilhouetteFile(out / "silhouette/tetra.sil", sil);

    VoxelGrid grid;
    grid.resolution = 4;
    grid.origin = {-1, -1, -1};
    grid.voxelSize = 0.5f;
    grid.cells = {{0, 0, 0}, {1, 0, 0}, {3, 3, 3}};
    grid.colors = {{255, 0, 0, 255}, {0, 255, 0, 128}, {0, 0, 255, 0}};
    writeVoxelFile(out / "voxel/small.arvox", grid);

    CostModel model(2);
    model.set(0, Shading::Phong, {3.2e-6, 0.5});
    model.set(1, Shading::Flat, {2.0e-6, 0.4});
    writeCalibration(out / "calibration/calib.yaml", model, {"gl33: fuzz seed", {1280, 720}});

    CalibratedCamera camera;
    camera.intrinsics = {.imageSize = {640, 480},
                         .fx = 500.0,
                         .fy = 500.0,
                         .cx = 319.5,
                         .cy = 239.5,
                         .distortion = {-0.1, 0.01, 0.0, 0.0, 0.0}};
    camera.translation = {0.0, -3.0, 8.0};
    writeCameraFile(out / "camera/camera.yaml", camera, "fuzz seed");

    writeText(out / "http/scrape.txt", "GET /metrics HTTP/1.1\r\nHost: 127.0.0.1:9464\r\nAccept: text/plain\r\n\r\n");
    writeText(out / "http/token.txt", "GET /status?x=1 HTTP/1.0\nAuthorization: Bearer 0123456789abcdef\n\n");

    writeText(out / "gaze/track.csv", "time,eye_x,eye_y,eye_z,gaze_x,gaze_y,gaze_z\n"
                                      "# a comment\n"
                                      "0.0,0,1.6,5,0,0,-1\n\n"
                                      "0.5,0.1,1.6,5,0.1,0,-1\n"
                                      "1.25,0.2,1.6,4.9,0.2,-0.1,-1\n");
    writeText(out / "obj/cube.obj",
              "mtllib cube.mtl\no cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
              "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 -1\nvn 0 0 1\ng front\nusemtl red\n"
              "f 1/1/1 2/2/1 3/3/1 4/1/1\nf 5//2 6//2 7//2\nf -1 -2 -3\nl 1 2\np 3\n");
    return 0;
}
