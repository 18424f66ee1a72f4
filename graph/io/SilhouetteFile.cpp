#include "graph/io/SilhouetteFile.hpp"

#include "graph/io/AtomicFile.hpp"
#include "graph/io/BinaryReader.hpp"
#include "graph/io/BinaryWriter.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace arcomp {

namespace {

// Names unique to this format, so that a unity build may join this file
// with the other formats' readers.
constexpr char kSilhouetteMagic[8] = {'A', 'R', 'C', 'S', 'I', 'L', '\0', '\0'};

void writeSilhouetteRange(BinaryWriter& w, SilhouetteRange r) {
    w.u32(r.firstIndex);
    w.u32(r.indexCount);
}

SilhouetteRange readSilhouetteRange(BinaryReader& r, std::uint32_t indexCount) {
    const std::uint32_t first = r.u32("range start"), count = r.u32("range count");
    if (first % 3 != 0 || count % 3 != 0 || std::uint64_t{first} + count > indexCount)
        r.fail("index range [" + std::to_string(first) + ", +" + std::to_string(count) +
               ") must be whole triangles inside " + std::to_string(indexCount) + " indices");
    return {first, count};
}

}  // namespace

std::vector<std::byte> encodeSilhouetteMesh(const SilhouetteMesh& mesh) {
    BinaryWriter w;
    w.raw(kSilhouetteMagic);
    w.u32(kSilhouetteFileVersion);
    w.u32(static_cast<std::uint32_t>(mesh.positions.size()));
    w.u32(static_cast<std::uint32_t>(mesh.indices.size()));
    w.u32(static_cast<std::uint32_t>(mesh.regions.size()));
    writeSilhouetteRange(w, mesh.full);
    w.vec3s(mesh.positions);
    w.u32s(mesh.indices);
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
        const auto vertices = mesh.regions[r].vertices();
        w.u32(static_cast<std::uint32_t>(vertices.size()));
        w.vec3s(vertices);
        writeSilhouetteRange(w, mesh.ranges[r]);
    }
    return w.take();
}

SilhouetteMesh decodeSilhouetteMesh(std::span<const std::byte> bytes, const std::string& name) {
    BinaryReader r(bytes, name);
    r.magic(kSilhouetteMagic, "the header", "not a baked silhouette file (bad magic)");
    const std::uint32_t version = r.u32("version");
    if (version != kSilhouetteFileVersion)
        r.fail("version " + std::to_string(version) + " not supported (expected " +
               std::to_string(kSilhouetteFileVersion) + ")");
    const std::uint32_t vertexCount = r.u32("vertex count"), indexCount = r.u32("index count"),
                        regionCount = r.u32("region count");
    SilhouetteMesh m;
    m.full = readSilhouetteRange(r, indexCount);
    // All three at once (at most 2^32 * 28 bytes: no overflow), so that a
    // region count beyond the file is refused before anything is read.
    r.need(std::uint64_t{vertexCount} * 12 + std::uint64_t{indexCount} * 4 + std::uint64_t{regionCount} * 12,
           "vertices, indices and regions");
    m.positions = r.vec3s(vertexCount, "vertex position");
    m.indices.reserve(indexCount);
    for (std::uint32_t i = 0; i < indexCount; ++i) {
        const std::uint32_t index = r.u32("index");
        if (index >= vertexCount)
            r.failAt(r.position() - 4,
                     "index " + std::to_string(index) + " out of range (" + std::to_string(vertexCount) + " vertices)");
        m.indices.push_back(index);
    }
    for (std::uint32_t k = 0; k < regionCount; ++k) {
        const std::uint32_t n = r.u32("region vertex count");
        if (n < 4 || n > kMaxRegionVertices)
            r.fail("region " + std::to_string(k) + " has " + std::to_string(n) + " vertices; expected 4 to " +
                   std::to_string(kMaxRegionVertices));
        const std::vector<glm::vec3> vertices = r.vec3s(n, "region vertex");
        try {
            m.regions.push_back(ViewRegion::fromVertices(vertices));
        } catch (const std::invalid_argument& e) {
            r.fail("region " + std::to_string(k) + ": " + e.what());
        }
        m.ranges.push_back(readSilhouetteRange(r, indexCount));
    }
    if (r.remaining() != 0) r.fail(std::to_string(r.remaining()) + " bytes after the last region");
    return m;
}

void writeSilhouetteFile(const std::filesystem::path& file, const SilhouetteMesh& mesh) {
    writeFileAtomically(file, encodeSilhouetteMesh(mesh));
}

SilhouetteMesh readSilhouetteFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ModelError(file.string(), "", "cannot be read");
    std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return decodeSilhouetteMesh(std::as_bytes(std::span(data)), file.string());
}

namespace {

bool sameRegions(const std::vector<ViewRegion>& a, const std::vector<ViewRegion>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!std::equal(a[i].vertices().begin(), a[i].vertices().end(), b[i].vertices().begin(), b[i].vertices().end()))
            return false;
    return true;
}

}  // namespace

LoadedOrBaked loadOrBakeSilhouetteMesh(const std::filesystem::path& baked, std::span<const glm::vec3> positions,
                                       std::span<const std::uint32_t> indices, const std::vector<ViewRegion>& regions) {
    std::string note;
    std::error_code ec;
    if (std::filesystem::exists(baked, ec)) {
        try {
            SilhouetteMesh m = readSilhouetteFile(baked);
            const FlatWeld w = weldPositions(positions, indices);
            const auto full = m.indicesOf(m.full);
            if (m.positions == w.positions &&
                std::equal(full.begin(), full.end(), w.indices.begin(), w.indices.end()) &&
                sameRegions(m.regions, regions)) {
                return {std::move(m), true, baked.string() + ": loaded"};
            }
            note = baked.string() + ": made for another mesh or other regions; baked again";
        } catch (const ModelError& e) {
            note = std::string(e.what()) + "; baked again";
        }
    } else {
        note = baked.string() + ": not found; baked";
    }
    SilhouetteMesh m = bakeSilhouetteMesh(positions, indices, regions);
    try {
        writeSilhouetteFile(baked, m);
    } catch (const std::exception& e) {
        note += std::string("; not saved: ") + e.what();
    }
    return {std::move(m), false, std::move(note)};
}

}  // namespace arcomp
