#include "graph/io/GltfDocument.hpp"

#include "graph/io/ContainedPath.hpp"
#include "graph/io/DataUri.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

namespace arcomp::gltf {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A meshopt fallback buffer has no bytes in the file; it is made to hold
// the decoded views. Its byteLength is the file's claim, so it is bounded
// (a fuzzed file must not allocate gigabytes).
constexpr std::size_t kMaxFallbackBytes = std::size_t{256} << 20;

std::uint32_t le32(const std::uint8_t* p) { return p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t(p[3]) << 24; }

struct Container {
    std::string jsonText;
    std::vector<std::uint8_t> bin;
    bool binary = false;
    bool hasBin = false;
};

// GLB 2.0: a 12-byte header, a JSON chunk, at most one BIN chunk; other
// chunk types are skipped, as the spec asks.
Container splitGlb(const std::vector<std::uint8_t>& bytes, const std::string& file) {
    Container c;
    c.binary = true;
    if (bytes.size() < 20)
        throw ModelError(file, "", "GLB file of " + std::to_string(bytes.size()) + " bytes is shorter than its header");
    if (le32(&bytes[4]) != 2)
        throw ModelError(file, "", "GLB version " + std::to_string(le32(&bytes[4])) + ", expected 2");
    const std::size_t total = le32(&bytes[8]);
    if (total > bytes.size())
        throw ModelError(file, "",
                         "GLB header says " + std::to_string(total) + " bytes, the file has " +
                             std::to_string(bytes.size()));
    std::size_t at = 12;
    bool first = true;
    while (at + 8 <= total) {
        const std::size_t length = le32(&bytes[at]);
        const std::uint32_t type = le32(&bytes[at + 4]);
        at += 8;
        if (length > total - at)
            throw ModelError(file, "",
                             "GLB chunk at byte " + std::to_string(at - 8) + " of " + std::to_string(length) +
                                 " bytes runs past the file's end");
        if (first && type != 0x4E4F534A) throw ModelError(file, "", "GLB's first chunk is not JSON");
        if (!first && type == 0x4E4F534A) throw ModelError(file, "", "GLB has a second JSON chunk");
        if (type == 0x004E4942 && (c.hasBin || at != 12 + 8 + c.jsonText.size() + 8))
            throw ModelError(file, "", "GLB's BIN chunk must be the one chunk right after the JSON chunk");
        if (first)
            c.jsonText.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                              bytes.begin() + static_cast<std::ptrdiff_t>(at + length));
        else if (type == 0x004E4942 && !c.hasBin) {
            c.bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                         bytes.begin() + static_cast<std::ptrdiff_t>(at + length));
            c.hasBin = true;
        }
        first = false;
        at += length;
    }
    if (first) throw ModelError(file, "", "GLB file has no JSON chunk");
    return c;
}

std::vector<std::uint8_t> readFile(const fs::path& path, const std::string& file, const std::string& where) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ModelError(file, where, "cannot read " + path.string());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

bool isMeshoptFallback(const json& buffer) {
    const json* ext = member(buffer, "extensions");
    const json* meshopt = ext ? member(*ext, "EXT_meshopt_compression") : nullptr;
    const json* fallback = meshopt ? member(*meshopt, "fallback") : nullptr;
    return fallback && fallback->is_boolean() && fallback->get<bool>();
}

GltfBuffer readBuffer(const GltfDocument& doc, const json& buffer, std::size_t index, Container& container) {
    const std::string where = "/buffers/" + std::to_string(index);
    if (!buffer.is_object()) doc.fail(where, "is not an object");
    const std::size_t length = requiredUnsigned(doc, buffer, "byteLength", where);
    if (length == 0) doc.fail(where + "/byteLength", "is 0; a buffer holds at least 1 byte");
    GltfBuffer out;
    const json* uri = member(buffer, "uri");
    if (uri && !uri->is_string()) doc.fail(where + "/uri", "is not a string");
    if (!uri) {
        if (isMeshoptFallback(buffer)) {
            if (length > kMaxFallbackBytes)
                doc.fail(where + "/byteLength", "EXT_meshopt_compression fallback buffer of " + std::to_string(length) +
                                                    " bytes is larger than supported (" +
                                                    std::to_string(kMaxFallbackBytes) + ")");
            out.bytes.assign(length, 0);
        } else if (index == 0 && container.binary) {
            if (!container.hasBin) doc.fail(where, "has no uri, and the GLB file has no BIN chunk to hold it");
            // The BIN chunk is padded to 4 bytes, so it may be up to 3 longer.
            if (container.bin.size() < length)
                doc.fail(where + "/byteLength", std::to_string(length) + " bytes, but the GLB's BIN chunk has " +
                                                    std::to_string(container.bin.size()));
            container.bin.resize(length);
            out.bytes = std::move(container.bin);
        } else {
            out.absent = container.binary ? "it has no uri, and only buffer 0 lies in a GLB's BIN chunk"
                                          : "it has no uri, and a .gltf file has no binary chunk";
        }
        return out;
    }
    UriBytes read = uriBytes(doc, uri->get<std::string>(), where + "/uri");
    if (!read.readable) doc.fail(where + "/uri", "cannot read " + read.file);
    if (read.file.empty() && read.mediaType != "application/octet-stream" &&
        read.mediaType != "application/gltf-buffer")
        doc.fail(where + "/uri", "data URI has media type '" + read.mediaType +
                                     "'; a buffer's is application/octet-stream or application/gltf-buffer");
    out.bytes = std::move(read.bytes);
    if (out.bytes.size() < length)
        doc.fail(where + "/byteLength",
                 std::to_string(length) + " bytes, but its uri holds " + std::to_string(out.bytes.size()));
    out.bytes.resize(length);
    return out;
}

}  // namespace

UriBytes uriBytes(const GltfDocument& doc, const std::string& uri, const std::string& where) {
    UriBytes out;
    if (isDataUri(uri)) {
        DataUri data = decodeDataUri(uri);
        if (!data.error.empty()) doc.fail(where, data.error);
        out.bytes = std::move(data.bytes);
        out.mediaType = std::move(data.mediaType);
        return out;
    }
    std::string reason;
    const auto path = containedPath(doc.folder, uri, reason);
    if (!path) doc.fail(where, reason);
    out.file = path->string();
    std::ifstream in(*path, std::ios::binary);
    out.readable = static_cast<bool>(in);
    out.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return out;
}

const json* member(const json& object, const char* key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

std::size_t unsignedMember(const GltfDocument& doc, const json& object, const char* key, const std::string& where,
                           std::size_t fallback) {
    const json* value = member(object, key);
    if (!value) return fallback;
    if (value->is_number_unsigned()) return value->get<std::size_t>();
    if (value->is_number_integer() && value->get<std::int64_t>() >= 0) return value->get<std::size_t>();
    // JSON has one number type: 4.0 is the integer 4 (the validator agrees).
    if (value->is_number_float()) {
        const double d = value->get<double>();
        if (d >= 0.0 && d <= 9007199254740992.0 && d == static_cast<double>(static_cast<std::uint64_t>(d)))
            return static_cast<std::size_t>(d);
    }
    doc.fail(where + "/" + key, "must be a non-negative integer");
}

std::size_t requiredUnsigned(const GltfDocument& doc, const json& object, const char* key, const std::string& where) {
    if (!member(object, key)) doc.fail(where, std::string("has no ") + key);
    return unsignedMember(doc, object, key, where, 0);
}

ViewBytes viewBytes(GltfDocument& doc, std::size_t view, const std::string& usePointer) {
    const json* views = member(doc.json, "bufferViews");
    if (!views || !views->is_array() || view >= views->size())
        doc.fail(usePointer, "buffer view " + std::to_string(view) + " does not exist");
    const json& v = (*views)[view];
    const std::string where = "/bufferViews/" + std::to_string(view);
    const std::size_t buffer = requiredUnsigned(doc, v, "buffer", where);
    const std::size_t offset = unsignedMember(doc, v, "byteOffset", where, 0);
    const std::size_t length = requiredUnsigned(doc, v, "byteLength", where);
    if (buffer >= doc.buffers.size())
        doc.fail(where + "/buffer", "buffer " + std::to_string(buffer) + " does not exist");
    GltfBuffer& b = doc.buffers[buffer];
    if (!b.absent.empty())
        doc.fail(where + "/buffer", "buffer " + std::to_string(buffer) + " has no bytes: " + b.absent);
    if (offset > b.bytes.size() || length > b.bytes.size() - offset)
        doc.fail(where, "bytes " + std::to_string(offset) + "+" + std::to_string(length) + " lie outside buffer " +
                            std::to_string(buffer) + " of " + std::to_string(b.bytes.size()) + " bytes");
    return {b.bytes.data() + offset, length};
}

GltfDocument readGltfDocument(const fs::path& path) {
    GltfDocument doc;
    doc.file = path.string();
    doc.folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) doc.fail("", "no such file");
    const std::vector<std::uint8_t> bytes = readFile(path, doc.file, "");
    Container container;
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0)
        container = splitGlb(bytes, doc.file);
    else
        container.jsonText.assign(bytes.begin(), bytes.end());
    try {
        doc.json = json::parse(container.jsonText);
    } catch (const json::exception& e) {
        doc.fail("", std::string("the JSON does not parse: ") + e.what());
    }
    if (!doc.json.is_object()) doc.fail("", "the JSON is not an object");
    if (const json* buffers = member(doc.json, "buffers")) {
        if (!buffers->is_array()) doc.fail("/buffers", "is not an array");
        for (std::size_t i = 0; i < buffers->size(); ++i)
            doc.buffers.push_back(readBuffer(doc, (*buffers)[i], i, container));
    }
    return doc;
}

}  // namespace arcomp::gltf
