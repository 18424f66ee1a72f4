#include "graph/io/LodFile.hpp"

#include "graph/io/AtomicFile.hpp"
#include "graph/io/BinaryReader.hpp"
#include "graph/io/BinaryWriter.hpp"

#include <fstream>
#include <iterator>

namespace arcomp {

namespace {

// Names unique to this format, so that a unity build may join this file
// with the other formats' readers.
constexpr char kLodMagic[8] = {'A', 'R', 'C', 'O', 'M', 'P', 'L', 'D'};
constexpr std::uint32_t kLodHasNormals = 1u, kLodHasTexcoords = 2u, kLodHasTexcoords1 = 4u, kLodHasTangents = 8u,
                        kLodTangentsGenerated = 16u;
constexpr std::uint32_t kLodKnownFlags =
    kLodHasNormals | kLodHasTexcoords | kLodHasTexcoords1 | kLodHasTangents | kLodTangentsGenerated;

bool perVertex(const auto& attribute, const Geometry& g) {
    return !attribute.empty() && attribute.size() == g.positions.size();
}

}  // namespace

void writeLodFile(const std::filesystem::path& file, const std::vector<LodLevel>& levels) {
    BinaryWriter out;
    out.raw(kLodMagic);
    out.u32(kLodFileVersion);
    out.u32(static_cast<std::uint32_t>(levels.size()));
    for (const LodLevel& l : levels) {
        const Geometry& g = l.geometry;
        const bool normals = perVertex(g.normals, g), texcoords = perVertex(g.texcoords, g);
        const bool texcoords1 = perVertex(g.texcoords1, g), tangents = perVertex(g.tangents, g);
        out.f32(l.ratio);
        out.f32(l.error);
        out.u32(static_cast<std::uint32_t>(g.positions.size()));
        out.u32(static_cast<std::uint32_t>(g.indices.size()));
        out.u32((normals ? kLodHasNormals : 0u) | (texcoords ? kLodHasTexcoords : 0u) |
                (texcoords1 ? kLodHasTexcoords1 : 0u) | (tangents ? kLodHasTangents : 0u) |
                (tangents && g.tangentsGenerated ? kLodTangentsGenerated : 0u));
        out.vec3s(g.positions);
        if (normals) out.vec3s(g.normals);
        if (texcoords) out.vec2s(g.texcoords);
        if (texcoords1) out.vec2s(g.texcoords1);
        if (tangents) out.vec4s(g.tangents);
        out.u32s(g.indices);
    }
    writeFileAtomically(file, out.bytes());
}

std::vector<LodLevel> parseLodFile(std::span<const unsigned char> bytes, const std::string& name) {
    BinaryReader r(bytes, name);
    r.magic(kLodMagic, "the header", "not an arcomp LOD file (expected \"ARCOMPLD\")");
    const auto version = r.u32("the header");
    if (version != kLodFileVersion)
        r.fail("version " + std::to_string(version) + ", expected " + std::to_string(kLodFileVersion));
    const auto count = r.u32("the header");
    if (count < 1 || count > kMaxLodLevels) r.fail("level count " + std::to_string(count) + ", expected 1 to 8");

    std::vector<LodLevel> levels(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        LodLevel& l = levels[i];
        const std::string where = "level " + std::to_string(i);
        l.ratio = r.finite("ratio");
        if (!(l.ratio > 0.0f && l.ratio <= 1.0f)) r.fail(where + ": ratio must be in (0, 1]");
        l.error = r.finite("error");
        if (l.error < 0.0f) r.fail(where + ": negative error");
        const auto vertices = r.u32("a level header");
        const auto indices = r.u32("a level header");
        const auto flags = r.u32("a level header");
        if (flags & ~kLodKnownFlags) r.fail(where + ": unknown flags " + std::to_string(flags));
        if ((flags & kLodTangentsGenerated) && !(flags & kLodHasTangents))
            r.fail(where + ": flags " + std::to_string(flags) + " mark generated tangents but hold none");
        if (indices % 3 != 0) r.fail(where + ": index count " + std::to_string(indices) + " is not a multiple of 3");
        Geometry& g = l.geometry;
        g.positions = r.vec3s(vertices, "positions");
        if (flags & kLodHasNormals) g.normals = r.vec3s(vertices, "normals");
        if (flags & kLodHasTexcoords) g.texcoords = r.vec2s(vertices, "texcoords");
        if (flags & kLodHasTexcoords1) g.texcoords1 = r.vec2s(vertices, "texcoords1");
        if (flags & kLodHasTangents) {
            g.tangents = r.vec4s(vertices, "tangents");
            g.tangentsGenerated = (flags & kLodTangentsGenerated) != 0;
        }
        r.needItems(indices, 4, "indices");
        g.indices.resize(indices);
        for (std::uint32_t& index : g.indices) {
            index = r.u32("indices");
            if (index >= vertices)
                r.failAt(r.position() - 4, where + ": index " + std::to_string(index) + " not below vertex count " +
                                               std::to_string(vertices));
        }
        g.finalize();
    }
    if (r.remaining() != 0) r.fail(std::to_string(r.remaining()) + " bytes after the last level");
    return levels;
}

std::vector<LodLevel> readLodFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ModelError(file.string(), "", "cannot open");
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parseLodFile(bytes, file.string());
}

namespace {

bool madeFrom(const std::vector<LodLevel>& levels, const Geometry& mesh, std::span<const float> ratios) {
    if (levels.size() != ratios.size()) return false;
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i].ratio != ratios[i]) return false;
    // A file from before the mesh had some attribute would load the levels
    // without it; the attributes the format holds must match too.
    const Geometry& full = levels[0].geometry;
    return full.positions == mesh.positions && full.indices == mesh.indices && full.texcoords == mesh.texcoords &&
           full.texcoords1 == mesh.texcoords1 && full.tangents == mesh.tangents;
}

}  // namespace

LoadedOrSimplified loadOrSimplifyLevels(const std::filesystem::path& baked, const Geometry& mesh,
                                        std::span<const float> ratios) {
    if (ratios.empty() || ratios[0] != 1.0f)
        return {simplifyLevels(mesh, ratios), false, "no ratio 1 first: not cached"};
    if (!mesh.colors.empty())
        return {simplifyLevels(mesh, ratios), false, "vertex colours, which .lod does not hold: not cached"};
    if (!mesh.joints.empty())
        return {simplifyLevels(mesh, ratios), false, "skin joints and weights, which .lod does not hold: not cached"};
    std::string note;
    std::error_code ec;
    if (std::filesystem::exists(baked, ec)) {
        try {
            std::vector<LodLevel> levels = readLodFile(baked);
            if (madeFrom(levels, mesh, ratios)) return {std::move(levels), true, baked.string() + ": loaded"};
            note = baked.string() + ": made for another mesh or other ratios; simplified again";
        } catch (const ModelError& e) {
            note = std::string(e.what()) + "; simplified again";
        }
    } else {
        note = baked.string() + ": not found; simplified";
    }
    std::vector<LodLevel> levels = simplifyLevels(mesh, ratios);
    try {
        writeLodFile(baked, levels);
    } catch (const std::exception& e) {
        note += std::string("; not saved: ") + e.what();
    }
    return {std::move(levels), false, std::move(note)};
}

}  // namespace arcomp
