#pragma once
// A glTF file as arcomp reads it ahead of tinygltf: the JSON, and the bytes
// of every buffer. arcomp reads the buffers itself, so that what tinygltf
// 2.7 refuses while parsing (a buffer without a uri, a data URI without
// base64, accessors without a buffer view as Draco writes them) reaches
// arcomp's own checks, and compressed views are decoded (GltfMeshopt,
// GltfDraco) into plain ones before anything reads them. Internal to
// graph/io.

#include "graph/io/ModelError.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace arcomp::gltf {

struct GltfBuffer {
    std::vector<std::uint8_t> bytes;
    std::string absent;  // why the file gives this buffer no bytes; empty when it does
};

struct GltfDocument {
    std::string file;              // for messages
    std::filesystem::path folder;  // relative URIs resolve here, and nowhere outside it
    nlohmann::json json;
    std::vector<GltfBuffer> buffers;

    [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
        throw ModelError(file, where, reason);
    }
};

// Reads the file once: the GLB container or the JSON text, then each buffer
// from the GLB's BIN chunk, a data URI or a file beside the model. A URI
// that leads outside the model's folder, or a buffer shorter than its
// byteLength, is a ModelError.
GltfDocument readGltfDocument(const std::filesystem::path& file);

// The bytes a buffer's or an image's uri names: a data URI, or a file
// inside the model's folder. A data URI that does not decode, or a path that
// leads outside the folder, is a ModelError at `where`; a file that cannot
// be read leaves `readable` false, for the caller to refuse or draw without.
struct UriBytes {
    std::vector<std::uint8_t> bytes;
    std::string mediaType;  // a data URI's; empty for a file
    bool readable = true;
    std::string file;  // the file read, for messages; empty for a data URI
};
UriBytes uriBytes(const GltfDocument& doc, const std::string& uri, const std::string& where);

// JSON access that names the pointer of what is wrong.
const nlohmann::json* member(const nlohmann::json& object, const char* key);
std::size_t unsignedMember(const GltfDocument& doc, const nlohmann::json& object, const char* key,
                           const std::string& where, std::size_t fallback);
std::size_t requiredUnsigned(const GltfDocument& doc, const nlohmann::json& object, const char* key,
                             const std::string& where);

// The bytes a buffer view covers, checked to lie inside a buffer that has
// bytes. Its pointer names the view.
struct ViewBytes {
    std::uint8_t* data;
    std::size_t size;
};
ViewBytes viewBytes(GltfDocument& doc, std::size_t view, const std::string& usePointer);

}  // namespace arcomp::gltf
