// arcomp bake lod <model> --ratios 1,0.25,0.05 [--out <file>]: simplified
// LOD levels of a model's meshes, merged into one mesh in model space,
// with the triangle counts reached and the geometric error of each.

#include "graph/io/LodFile.hpp"
#include "graph/io/ModelLoader.hpp"
#include "tools/cli/Command.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

namespace arcomp {

namespace {

// The model's parts placed by their nodes' matrices, as one geometry.
// An attribute survives only when every part has it: a merged array must
// cover every vertex. Vertex colours are not merged: the .lod file does not
// hold them.
Geometry mergedModel(const ParsedModel& m) {
    std::vector<glm::mat4> world(m.nodes.size(), glm::mat4(1.0f));
    bool allUv = true, allUv1 = true, allTangents = true, anyGenerated = false;
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
        const ModelNode& node = m.nodes[n];
        world[n] = node.parent < 0 ? node.local : world[static_cast<std::size_t>(node.parent)] * node.local;
        for (const MeshPart& p : node.parts) {
            const Geometry& g = m.geometries[p.geometry];
            allUv = allUv && !g.texcoords.empty();
            allUv1 = allUv1 && !g.texcoords1.empty();
            allTangents = allTangents && !g.tangents.empty();
            anyGenerated = anyGenerated || g.tangentsGenerated;
        }
    }
    Geometry out;
    for (std::size_t n = 0; n < m.nodes.size(); ++n) {
        const glm::mat3 linear(world[n]);
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(linear));
        // A mirroring matrix turns the frame's handedness: the bitangent,
        // cross(normal, tangent) * w, keeps its direction only if w flips.
        const float handedness = glm::determinant(linear) < 0.0f ? -1.0f : 1.0f;
        for (const MeshPart& p : m.nodes[n].parts) {
            const Geometry& g = m.geometries[p.geometry];
            const auto base = static_cast<std::uint32_t>(out.positions.size());
            for (std::size_t v = 0; v < g.positions.size(); ++v) {
                out.positions.push_back(glm::vec3(world[n] * glm::vec4(g.positions[v], 1.0f)));
                out.normals.push_back(glm::normalize(normalMatrix * g.normals[v]));
                if (allUv) out.texcoords.push_back(g.texcoords[v]);
                if (allUv1) out.texcoords1.push_back(g.texcoords1[v]);
                if (allTangents)
                    out.tangents.push_back(
                        glm::vec4(glm::normalize(linear * glm::vec3(g.tangents[v])), g.tangents[v].w * handedness));
            }
            for (std::uint32_t i : g.indices) out.indices.push_back(base + i);
        }
    }
    out.tangentsGenerated = allTangents && anyGenerated;
    out.finalize();
    return out;
}

std::string jsonString(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;  // control characters have no place in a path here
        out += c;
    }
    return out + "\"";
}

std::vector<float> parseRatios(const std::string& text) {
    std::vector<float> ratios;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        char* end = nullptr;
        const float r = std::strtof(item.c_str(), &end);
        if (item.empty() || *end != '\0' || !(r > 0.0f && r <= 1.0f))
            throw InputError("--ratios: \"" + item + "\" is not a number in (0, 1]");
        if (!ratios.empty() && r > ratios.back()) throw InputError("--ratios must be finest first (non-increasing)");
        ratios.push_back(r);
    }
    if (ratios.empty() || ratios.size() > kMaxLodLevels) throw InputError("--ratios: give 1 to 8 ratios");
    return ratios;
}

int bakeLod(const std::string& model, const std::string& ratioText, const std::string& outFile) {
    const std::vector<float> ratios = parseRatios(ratioText);
    const std::filesystem::path path(model);
    if (!std::filesystem::exists(path)) throw InputError(model + ": no such file");
    const std::string ext = path.extension().string();
    const ParsedModel parsed = ext == ".obj" || ext == ".OBJ" ? parseObj(path) : parseGltf(path);
    for (const std::string& w : parsed.warnings) std::cerr << "warning: " << w << "\n";
    const Geometry merged = mergedModel(parsed);
    if (merged.triangleCount() == 0) throw InputError(model + ": no triangles to simplify");

    const std::vector<LodLevel> levels = simplifyLevels(merged, ratios);
    const double original = static_cast<double>(merged.triangleCount());
    std::ostringstream json;
    json << "{\"bake\":\"lod\",\"model\":" << jsonString(model) << ",\"triangles\":" << merged.triangleCount()
         << ",\"extent\":" << 2.0f * merged.bound.radius << ",\"levels\":[";
    bool allWithin = true;
    std::printf("level  ratio  requested  achieved  deviation   error\n");
    for (std::size_t i = 0; i < levels.size(); ++i) {
        const double requested = std::round(original * levels[i].ratio);
        const double achieved = static_cast<double>(levels[i].geometry.triangleCount());
        const double deviation = (achieved - requested) / requested;
        allWithin = allWithin && std::abs(deviation) <= 0.10;
        std::printf("%5zu  %5.3f  %9.0f  %8.0f  %+8.1f%%  %.6g\n", i, levels[i].ratio, requested, achieved,
                    deviation * 100.0, levels[i].error);
        json << (i ? "," : "") << "{\"ratio\":" << levels[i].ratio << ",\"requested_triangles\":" << requested
             << ",\"triangles\":" << achieved << ",\"deviation\":" << deviation << ",\"error\":" << levels[i].error
             << ",\"vertices\":" << levels[i].geometry.positions.size() << "}";
    }
    json << "],\"all_within_10_percent\":" << (allWithin ? "true" : "false");
    if (!outFile.empty()) {
        writeLodFile(outFile, levels);
        json << ",\"out\":" << jsonString(outFile);
    }
    json << "}";
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerBake(
    {"lod", "Simplified LOD levels of a model (meshoptimizer)", [](CommandLine& line) {
         auto model = std::make_shared<std::string>();
         auto ratios = std::make_shared<std::string>("1,0.25,0.05");
         auto out = std::make_shared<std::string>();
         line.option("model", *model, "Model file (.obj, .gltf, .glb)").required();
         line.option("--ratios", *ratios, "Fractions of the triangles per level, finest first").showDefault();
         line.option("--out", *out, "LOD file to write (graph/io/LodFile.hpp)");
         return [=] { return bakeLod(*model, *ratios, *out); };
     }});

}  // namespace

}  // namespace arcomp
