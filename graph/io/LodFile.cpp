#include "graph/io/LodFile.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace arcomp {

static_assert(std::endian::native == std::endian::little, "the LOD file is written in host order");

namespace {

constexpr char kMagic[8] = {'A', 'R', 'C', 'O', 'M', 'P', 'L', 'D'};
constexpr std::uint32_t kNormals = 1u, kTexcoords = 2u;

struct Reader {
    std::span<const unsigned char> bytes;
    const std::string& name;
    std::size_t at = 0;

    [[noreturn]] void fail(const std::string& reason) const {
        throw ModelError(name, "byte " + std::to_string(at), reason);
    }
    void need(std::size_t n, const char* what) const {
        if (bytes.size() - at < n) fail(std::string("file ends inside ") + what);
    }
    template <class T> T value(const char* what) {
        need(sizeof(T), what);
        T v;
        std::memcpy(&v, bytes.data() + at, sizeof(T));
        at += sizeof(T);
        return v;
    }
    float finite(const char* what) {
        const float v = value<float>(what);
        if (!std::isfinite(v)) { at -= 4; fail(std::string(what) + " is not a finite number"); }
        return v;
    }
    template <class V> void floats(std::vector<V>& out, std::size_t count, const char* what) {
        constexpr std::size_t n = sizeof(V) / sizeof(float);
        need(count * sizeof(V), what);
        out.resize(count);
        for (V& v : out)
            for (std::size_t c = 0; c < n; ++c) v[static_cast<int>(c)] = finite(what);
    }
};

template <class T> void put(std::ofstream& out, const T& v) { out.write(reinterpret_cast<const char*>(&v), sizeof(T)); }
template <class V> void putAll(std::ofstream& out, const std::vector<V>& v) {
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(V)));
}

} // namespace

void writeLodFile(const std::filesystem::path& file, const std::vector<LodLevel>& levels) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(file.string() + ": cannot open for writing");
    out.write(kMagic, sizeof kMagic);
    put(out, kLodFileVersion);
    put(out, static_cast<std::uint32_t>(levels.size()));
    for (const LodLevel& l : levels) {
        const Geometry& g = l.geometry;
        const bool normals = g.normals.size() == g.positions.size() && !g.normals.empty();
        const bool texcoords = g.texcoords.size() == g.positions.size() && !g.texcoords.empty();
        put(out, l.ratio);
        put(out, l.error);
        put(out, static_cast<std::uint32_t>(g.positions.size()));
        put(out, static_cast<std::uint32_t>(g.indices.size()));
        put(out, (normals ? kNormals : 0u) | (texcoords ? kTexcoords : 0u));
        putAll(out, g.positions);
        if (normals) putAll(out, g.normals);
        if (texcoords) putAll(out, g.texcoords);
        putAll(out, g.indices);
    }
    if (!out) throw std::runtime_error(file.string() + ": write failed");
}

std::vector<LodLevel> parseLodFile(std::span<const unsigned char> bytes, const std::string& name) {
    Reader r{bytes, name};
    r.need(sizeof kMagic, "the header");
    if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0) r.fail("not an arcomp LOD file (expected \"ARCOMPLD\")");
    r.at = sizeof kMagic;
    const auto version = r.value<std::uint32_t>("the header");
    if (version != kLodFileVersion)
        r.fail("version " + std::to_string(version) + ", expected " + std::to_string(kLodFileVersion));
    const auto count = r.value<std::uint32_t>("the header");
    if (count < 1 || count > kMaxLodLevels) r.fail("level count " + std::to_string(count) + ", expected 1 to 8");

    std::vector<LodLevel> levels(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        LodLevel& l = levels[i];
        const std::string where = "level " + std::to_string(i);
        l.ratio = r.finite("ratio");
        if (!(l.ratio > 0.0f && l.ratio <= 1.0f)) r.fail(where + ": ratio must be in (0, 1]");
        l.error = r.finite("error");
        if (l.error < 0.0f) r.fail(where + ": negative error");
        const auto vertices = r.value<std::uint32_t>("a level header");
        const auto indices = r.value<std::uint32_t>("a level header");
        const auto flags = r.value<std::uint32_t>("a level header");
        if (flags & ~(kNormals | kTexcoords)) r.fail(where + ": unknown flags " + std::to_string(flags));
        if (indices % 3 != 0) r.fail(where + ": index count " + std::to_string(indices) + " is not a multiple of 3");
        Geometry& g = l.geometry;
        r.floats(g.positions, vertices, "positions");
        if (flags & kNormals) r.floats(g.normals, vertices, "normals");
        if (flags & kTexcoords) r.floats(g.texcoords, vertices, "texcoords");
        r.need(std::size_t{indices} * 4, "indices");
        g.indices.resize(indices);
        for (std::uint32_t& index : g.indices) {
            index = r.value<std::uint32_t>("indices");
            if (index >= vertices) {
                r.at -= 4;
                r.fail(where + ": index " + std::to_string(index) + " not below vertex count " + std::to_string(vertices));
            }
        }
        g.finalize();
    }
    if (r.at != bytes.size()) r.fail(std::to_string(bytes.size() - r.at) + " bytes after the last level");
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
    const Geometry& full = levels[0].geometry;
    return full.positions == mesh.positions && full.indices == mesh.indices;
}

} // namespace

LoadedOrSimplified loadOrSimplifyLevels(const std::filesystem::path& baked, const Geometry& mesh,
                                        std::span<const float> ratios) {
    if (ratios.empty() || ratios[0] != 1.0f) return {simplifyLevels(mesh, ratios), false, "no ratio 1 first: not cached"};
    if (!mesh.colors.empty()) return {simplifyLevels(mesh, ratios), false, "vertex colours, which .lod does not hold: not cached"};
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

} // namespace arcomp
