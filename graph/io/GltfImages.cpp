#include "graph/io/GltfImages.hpp"

#include <tiny_gltf.h>
#include <webp/decode.h>

#include <cstring>

namespace arcomp::gltf {

using nlohmann::json;

namespace {

// 8192 x 8192: the largest texture a kiosk GPU is expected to take.
constexpr std::size_t kMaxTexels = std::size_t{1} << 26;

bool startsWith(const std::vector<std::uint8_t>& bytes, std::size_t at, const char* magic, std::size_t length) {
    return bytes.size() >= at + length && std::memcmp(bytes.data() + at, magic, length) == 0;
}

Image toRgba8(const tinygltf::Image& src) {
    Image out;
    if (src.width <= 0 || src.height <= 0 || src.component < 1 || src.component > 4) return out;
    const std::size_t pixels = static_cast<std::size_t>(src.width) * static_cast<std::size_t>(src.height);
    const std::size_t bytesPerChannel = src.bits == 16 ? 2 : src.bits == 32 ? 4 : 1;
    if (src.image.size() < pixels * static_cast<std::size_t>(src.component) * bytesPerChannel) return out;
    out.width = src.width;
    out.height = src.height;
    out.rgba.resize(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        auto channel = [&](int c) -> std::uint8_t {
            // The most significant byte of little-endian 16-bit samples.
            const std::size_t at =
                (p * static_cast<std::size_t>(src.component) + static_cast<std::size_t>(c)) * bytesPerChannel;
            return src.image[at + bytesPerChannel - 1];
        };
        const std::uint8_t r = channel(0);
        const std::uint8_t g = src.component >= 3 ? channel(1) : r;
        const std::uint8_t b = src.component >= 3 ? channel(2) : r;
        const std::uint8_t a = src.component == 4 ? channel(3) : src.component == 2 ? channel(1) : 255;
        out.rgba[p * 4 + 0] = r;
        out.rgba[p * 4 + 1] = g;
        out.rgba[p * 4 + 2] = b;
        out.rgba[p * 4 + 3] = a;
    }
    return out;
}

// The image in `bytes`, told by its first bytes rather than by the media
// type the file claims; empty, with `why` set, when it does not decode.
Image decode(const std::vector<std::uint8_t>& bytes, std::size_t index, std::string& why) {
    if (startsWith(bytes, 0, "RIFF", 4) && startsWith(bytes, 8, "WEBP", 4)) {
        int width = 0, height = 0;
        // The header's size is checked before libwebp allocates for it.
        if (!WebPGetInfo(bytes.data(), bytes.size(), &width, &height)) {
            why = "is a WebP image (EXT_texture_webp) whose header libwebp cannot read";
            return {};
        }
        if (std::size_t(width) * std::size_t(height) > kMaxTexels) {
            why = "is a WebP image of " + std::to_string(width) + "x" + std::to_string(height) +
                  ", more texels than arcomp takes (" + std::to_string(kMaxTexels) + ")";
            return {};
        }
        std::uint8_t* pixels = WebPDecodeRGBA(bytes.data(), bytes.size(), &width, &height);
        if (!pixels) {
            why = "is a WebP image (EXT_texture_webp) that libwebp cannot decode";
            return {};
        }
        Image out{width, height, {pixels, pixels + std::size_t(width) * std::size_t(height) * 4}};
        WebPFree(pixels);
        return out;
    }
    if (startsWith(bytes, 0, "\xABKTX 20\xBB", 8)) {
        why = "is a KTX2 image (KHR_texture_basisu), for which Debian 12 has no decoder";
        return {};
    }
    if (bytes.size() > std::size_t(INT32_MAX)) {
        why = "is larger than the decoder takes";
        return {};
    }
    tinygltf::Image image;
    std::string err, warn;
    if (!tinygltf::LoadImageData(&image, static_cast<int>(index), &err, &warn, 0, 0, bytes.data(),
                                 static_cast<int>(bytes.size()), nullptr)) {
        while (!err.empty() && err.back() == '\n') err.pop_back();
        why = "does not decode as PNG, JPEG or WebP: " + err;
        return {};
    }
    return toRgba8(image);
}

}  // namespace

std::vector<Image> readGltfImages(GltfDocument& doc, std::vector<std::string>& warnings) {
    const json* images = member(doc.json, "images");
    if (!images) return {};
    if (!images->is_array()) doc.fail("/images", "is not an array");
    std::vector<Image> out;
    for (std::size_t i = 0; i < images->size(); ++i) {
        const json& image = (*images)[i];
        const std::string where = "/images/" + std::to_string(i);
        const json* uri = member(image, "uri");
        const json* view = member(image, "bufferView");
        if (!image.is_object() || (uri == nullptr) == (view == nullptr))
            doc.fail(where, "must have exactly one of uri and bufferView");
        std::vector<std::uint8_t> bytes;
        std::string why;
        if (uri) {
            if (!uri->is_string()) doc.fail(where + "/uri", "is not a string");
            UriBytes read = uriBytes(doc, uri->get<std::string>(), where + "/uri");
            if (!read.readable) why = "cannot be read from " + read.file;
            bytes = std::move(read.bytes);
        } else {
            const std::size_t index = unsignedMember(doc, image, "bufferView", where, 0);
            if (!member(image, "mimeType")) doc.fail(where, "has a bufferView but no mimeType");
            const ViewBytes v = viewBytes(doc, index, where + "/bufferView");
            if (member(doc.json["bufferViews"][index], "byteStride"))
                doc.fail(where + "/bufferView",
                         "buffer view " + std::to_string(index) + " has a byteStride; an image's view has none");
            bytes.assign(v.data, v.data + v.size);
        }
        Image decoded;
        if (why.empty()) decoded = decode(bytes, i, why);
        if (!why.empty()) warnings.push_back("image " + std::to_string(i) + " " + why + "; drawn without it");
        out.push_back(std::move(decoded));
    }
    return out;
}

}  // namespace arcomp::gltf
