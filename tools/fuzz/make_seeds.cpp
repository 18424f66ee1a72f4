// Writes small valid inputs for the binary, CSV and HTTP fuzz targets into
// <out>/<target>/, from the project's own writers, so that each fuzzer
// starts from a file its parser accepts and mutates inward from there.
//
//   build-fuzz/make_seeds build-fuzz/seeds

#include "graph/budget/CostModel.hpp"
#include "graph/io/Base64.hpp"
#include "graph/io/GltfWriter.hpp"
#include "graph/io/LodFile.hpp"
#include "graph/io/SilhouetteFile.hpp"
#include "graph/io/VoxelFile.hpp"
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/CameraFile.hpp"

#include <lo/lo_lowlevel.h>
#include <meshoptimizer.h>
#include <nlohmann/json.hpp>

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

std::string le(std::uint32_t v, int bytes) {
    std::string out;
    for (int k = 0; k < bytes; ++k) out += static_cast<char>(v >> (8 * k) & 0xFF);
    return out;
}

// fuzz_draco's input: the declared points and indices, then the stream,
// taken from the Draco primitive GltfWriter makes.
std::string dracoSeed(const Geometry& g, bool sequential) {
    GltfWriter w;
    const auto primitive = nlohmann::json::parse(w.dracoPrimitive(
        g.positions.size(),
        {{.semantic = "POSITION", .data = &g.positions[0].x, .components = 3, .quantizationBits = 11},
         {.semantic = "NORMAL", .data = &g.normals[0].x, .components = 3, .quantizationBits = 8},
         {.semantic = "TEXCOORD_0", .data = &g.texcoords[0].x, .components = 2, .quantizationBits = 10}},
        g.indices, sequential));
    const auto doc = nlohmann::json::parse(w.text());
    const std::string uri = doc["buffers"][0]["uri"];
    const auto bytes = *fromBase64(uri.substr(uri.find(',') + 1));
    const auto& view =
        doc["bufferViews"][primitive["extensions"]["KHR_draco_mesh_compression"]["bufferView"].get<int>()];
    const std::size_t offset = view.value("byteOffset", 0), length = view["byteLength"];
    const auto& accessors = doc["accessors"];
    return le(accessors[primitive["attributes"]["POSITION"].get<int>()]["count"], 4) +
           le(accessors[primitive["indices"].get<int>()]["count"], 4) +
           std::string(bytes.begin() + static_cast<std::ptrdiff_t>(offset),
                       bytes.begin() + static_cast<std::ptrdiff_t>(offset + length));
}

// fuzz_meshopt's input: mode, filter, byteStride / 4, count, then the stream.
std::string meshoptSeed(int mode, int filter, std::size_t stride, std::size_t count,
                        const std::vector<unsigned char>& stream) {
    return std::string{static_cast<char>(mode), static_cast<char>(filter), static_cast<char>(stride / 4)} +
           le(static_cast<std::uint32_t>(count), 2) + std::string(stream.begin(), stream.end());
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: make_seeds <folder>\n";
        return 2;
    }
    const fs::path out = argv[1];
    for (const char* t :
         {"lod", "silhouette", "voxel", "calibration", "camera", "gaze", "obj", "http", "draco", "meshopt", "cue"})
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

    // Cues: the wire's byte (0 OSC, 1 JSON), then the packet.
    const auto oscCue = [&](const char* name, const char* path, std::vector<const char*> strings) {
        lo_message m = lo_message_new();
        for (const char* s : strings) lo_message_add_string(m, s);
        std::size_t size = 0;
        void* bytes = lo_message_serialise(m, path, nullptr, &size);
        std::string text(1, '\0');
        text.append(static_cast<const char*>(bytes), size);
        free(bytes);
        lo_message_free(m);
        writeText(out / "cue" / name, text);
    };
    oscCue("play.osc", "/arcomp/cue/play", {"walker", "hop"});
    oscCue("hide.osc", "/arcomp/cue/hide", {"sign"});
    oscCue("reload.osc", "/arcomp/cue/reload", {});
    writeText(out / "cue/play.json", "\x01{\"cue\": \"play\", \"object\": \"walker\", \"animation\": \"walk\"}");
    writeText(out / "cue/stop.json", "\x01{\"cue\": \"stop\", \"object\": \"walker\"}");

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

    const Geometry sphere = makeUvSphere(1.0f, 8, 4);
    writeText(out / "draco/sphere-edgebreaker.bin", dracoSeed(sphere, false));
    writeText(out / "draco/sphere-sequential.bin", dracoSeed(sphere, true));
    std::vector<unsigned char> stream(meshopt_encodeVertexBufferBound(sphere.positions.size(), 12));
    stream.resize(
        meshopt_encodeVertexBuffer(stream.data(), stream.size(), sphere.positions.data(), sphere.positions.size(), 12));
    writeText(out / "meshopt/positions.bin", meshoptSeed(0, 0, 12, sphere.positions.size(), stream));
    stream.assign(meshopt_encodeIndexBufferBound(sphere.indices.size(), sphere.positions.size()), 0);
    stream.resize(
        meshopt_encodeIndexBuffer(stream.data(), stream.size(), sphere.indices.data(), sphere.indices.size()));
    writeText(out / "meshopt/triangles.bin", meshoptSeed(1, 0, 4, sphere.indices.size(), stream));
    stream.assign(meshopt_encodeIndexSequenceBound(sphere.indices.size(), sphere.positions.size()), 0);
    stream.resize(
        meshopt_encodeIndexSequence(stream.data(), stream.size(), sphere.indices.data(), sphere.indices.size()));
    writeText(out / "meshopt/sequence.bin", meshoptSeed(2, 0, 4, sphere.indices.size(), stream));
    std::vector<glm::vec4> normals;
    for (const glm::vec3& n : sphere.normals) normals.emplace_back(n, 0.0f);
    std::vector<std::int8_t> octahedral(normals.size() * 4);
    meshopt_encodeFilterOct(octahedral.data(), normals.size(), 4, 8, &normals[0].x);
    stream.assign(meshopt_encodeVertexBufferBound(sphere.normals.size(), 4), 0);
    stream.resize(
        meshopt_encodeVertexBuffer(stream.data(), stream.size(), octahedral.data(), sphere.normals.size(), 4));
    writeText(out / "meshopt/octahedral.bin", meshoptSeed(0, 1, 4, sphere.normals.size(), stream));
    return 0;
}
