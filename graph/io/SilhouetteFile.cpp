#include "graph/io/SilhouetteFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace arcomp {

namespace {

constexpr char kMagic[8] = {'A', 'R', 'C', 'S', 'I', 'L', '\0', '\0'};

struct Writer {
    std::vector<std::byte> out;
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::byte>((v >> (8 * i)) & 0xff));
    }
    void f32(float f) {
        std::uint32_t v;
        std::memcpy(&v, &f, 4);
        u32(v);
    }
    void vec3(const glm::vec3& p) { f32(p.x); f32(p.y); f32(p.z); }
};

struct Reader {
    std::span<const std::byte> in;
    const std::string& name;
    std::size_t pos = 0;

    [[noreturn]] void fail(const std::string& what) const {
        throw ModelError(name, "byte " + std::to_string(pos), what);
    }
    // Refuses counts the remaining bytes cannot hold, before any allocation.
    void need(std::uint64_t bytes, const char* what) const {
        if (bytes > in.size() - pos)
            fail(std::string("file ends early: ") + what + " needs " + std::to_string(bytes) + " bytes, " +
                 std::to_string(in.size() - pos) + " left");
    }
    std::uint32_t u32(const char* what) {
        need(4, what);
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t(std::to_integer<std::uint8_t>(in[pos + i])) << (8 * i);
        pos += 4;
        return v;
    }
    float f32(const char* what) {
        const std::uint32_t v = u32(what);
        float f;
        std::memcpy(&f, &v, 4);
        if (!std::isfinite(f)) { pos -= 4; fail(std::string(what) + " is not a finite number"); }
        return f;
    }
    glm::vec3 vec3(const char* what) {
        const float x = f32(what), y = f32(what), z = f32(what);
        return {x, y, z};
    }
};

void writeRange(Writer& w, SilhouetteRange r) {
    w.u32(r.firstIndex);
    w.u32(r.indexCount);
}

SilhouetteRange readRange(Reader& r, std::uint32_t indexCount) {
    const std::uint32_t first = r.u32("range start"), count = r.u32("range count");
    if (first % 3 != 0 || count % 3 != 0 || std::uint64_t{first} + count > indexCount)
        r.fail("index range [" + std::to_string(first) + ", +" + std::to_string(count) +
               ") must be whole triangles inside " + std::to_string(indexCount) + " indices");
    return {first, count};
}

} // namespace

std::vector<std::byte> encodeSilhouetteMesh(const SilhouetteMesh& mesh) {
    Writer w;
    for (char c : kMagic) w.out.push_back(static_cast<std::byte>(c));
    w.u32(kSilhouetteFileVersion);
    w.u32(static_cast<std::uint32_t>(mesh.positions.size()));
    w.u32(static_cast<std::uint32_t>(mesh.indices.size()));
    w.u32(static_cast<std::uint32_t>(mesh.regions.size()));
    writeRange(w, mesh.full);
    for (const glm::vec3& p : mesh.positions) w.vec3(p);
    for (std::uint32_t i : mesh.indices) w.u32(i);
    for (std::size_t r = 0; r < mesh.regions.size(); ++r) {
        const auto vertices = mesh.regions[r].vertices();
        w.u32(static_cast<std::uint32_t>(vertices.size()));
        for (const glm::vec3& p : vertices) w.vec3(p);
        writeRange(w, mesh.ranges[r]);
    }
    return w.out;
}

SilhouetteMesh decodeSilhouetteMesh(std::span<const std::byte> bytes, const std::string& name) {
    Reader r{bytes, name};
    r.need(sizeof kMagic, "magic");
    if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) r.fail("not a baked silhouette file (bad magic)");
    r.pos = sizeof kMagic;
    const std::uint32_t version = r.u32("version");
    if (version != kSilhouetteFileVersion)
        r.fail("version " + std::to_string(version) + " not supported (expected " +
               std::to_string(kSilhouetteFileVersion) + ")");
    const std::uint32_t vertexCount = r.u32("vertex count"), indexCount = r.u32("index count"),
                        regionCount = r.u32("region count");
    SilhouetteMesh m;
    m.full = readRange(r, indexCount);
    r.need(std::uint64_t{vertexCount} * 12 + std::uint64_t{indexCount} * 4 + std::uint64_t{regionCount} * 12,
           "vertices, indices and regions");
    m.positions.reserve(vertexCount);
    for (std::uint32_t v = 0; v < vertexCount; ++v) m.positions.push_back(r.vec3("vertex position"));
    m.indices.reserve(indexCount);
    for (std::uint32_t i = 0; i < indexCount; ++i) {
        const std::uint32_t index = r.u32("index");
        if (index >= vertexCount) {
            r.pos -= 4;
            r.fail("index " + std::to_string(index) + " out of range (" + std::to_string(vertexCount) + " vertices)");
        }
        m.indices.push_back(index);
    }
    for (std::uint32_t k = 0; k < regionCount; ++k) {
        const std::uint32_t n = r.u32("region vertex count");
        if (n < 4 || n > kMaxRegionVertices)
            r.fail("region " + std::to_string(k) + " has " + std::to_string(n) + " vertices; expected 4 to " +
                   std::to_string(kMaxRegionVertices));
        std::vector<glm::vec3> vertices;
        for (std::uint32_t v = 0; v < n; ++v) vertices.push_back(r.vec3("region vertex"));
        try {
            m.regions.push_back(ViewRegion::fromVertices(vertices));
        } catch (const std::invalid_argument& e) {
            r.fail("region " + std::to_string(k) + ": " + e.what());
        }
        m.ranges.push_back(readRange(r, indexCount));
    }
    if (r.pos != bytes.size()) r.fail(std::to_string(bytes.size() - r.pos) + " bytes after the last region");
    return m;
}

void writeSilhouetteFile(const std::filesystem::path& file, const SilhouetteMesh& mesh) {
    const std::vector<std::byte> bytes = encodeSilhouetteMesh(mesh);
    // Written beside the target and renamed, so that a crash never leaves a
    // half-written file where a station would load it.
    const std::filesystem::path temp = file.string() + ".partial";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out) throw std::runtime_error(temp.string() + ": cannot be written");
    }
    std::filesystem::rename(temp, file);
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

} // namespace

LoadedOrBaked loadOrBakeSilhouetteMesh(const std::filesystem::path& baked, std::span<const glm::vec3> positions,
                                       std::span<const std::uint32_t> indices, const std::vector<ViewRegion>& regions) {
    std::string note;
    std::error_code ec;
    if (std::filesystem::exists(baked, ec)) {
        try {
            SilhouetteMesh m = readSilhouetteFile(baked);
            const FlatWeld w = weldPositions(positions, indices);
            const auto full = m.indicesOf(m.full);
            if (m.positions == w.positions && std::equal(full.begin(), full.end(), w.indices.begin(), w.indices.end()) &&
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

} // namespace arcomp
