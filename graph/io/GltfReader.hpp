#pragma once
// The checked view of a tinygltf model that the glTF parser's parts share
// (GltfParser.cpp for meshes and nodes, GltfMaterial.cpp, GltfAnimation.cpp):
// accessors read within their buffers and with the types the use allows,
// and every failure a ModelError naming the file and a JSON pointer.
// Internal to graph/io: it sees tinygltf.

#include "graph/io/ModelError.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace arcomp::gltf {

namespace fs = std::filesystem;

// The most components (64 MiB as floats) we accept for an accessor without
// a buffer view (all zeros, possibly sparse): real data is bounded by its
// buffer's size, these only by their count. Counted in components, not
// elements: 2^26 VEC3 elements let a 485-byte file allocate 1.3 GB (fuzz).
constexpr std::size_t kMaxZeroFilledComponents = std::size_t{1} << 24;

inline std::string ptr(const char* array, std::size_t index, const char* field = nullptr) {
    std::string p = std::string("/") + array + "/" + std::to_string(index);
    if (field) p += std::string("/") + field;
    return p;
}

inline int componentCount(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    case TINYGLTF_TYPE_MAT2: return 4;
    case TINYGLTF_TYPE_MAT3: return 9;
    case TINYGLTF_TYPE_MAT4: return 16;
    default: return 0;
    }
}

inline int componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

inline const char* typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    default: return "a matrix type";
    }
}

class GltfReader {
public:
    // `absentBuffers`: per buffer, why the file gives it no bytes (empty
    // when it does); a view into such a buffer fails only when it is read.
    GltfReader(const fs::path& file, tinygltf::Model& model, std::vector<std::string> absentBuffers = {})
        : file_(file.string()), model_(model), absent_(std::move(absentBuffers)) {}

    [[noreturn]] void fail(const std::string& where, const std::string& reason) const {
        throw ModelError(file_, where, reason);
    }

    // Reads `count` elements of `accessor` as floats, each `components` wide,
    // checking every byte it touches. Integer components are converted as
    // the spec says: normalized ones to [0,1] or [-1,1], others as values.
    std::vector<float> readFloats(std::size_t index, const std::string& usePointer, int wantType,
                                  const std::vector<int>& allowedComponents) const {
        const tinygltf::Accessor& a = accessor(index, usePointer);
        const std::string where = ptr("accessors", index);
        if (a.type != wantType)
            fail(where + "/type", std::string("is ") + typeName(a.type) + ", expected " + typeName(wantType) +
                                      " (used by " + usePointer + ")");
        if (std::find(allowedComponents.begin(), allowedComponents.end(), a.componentType) == allowedComponents.end())
            fail(where + "/componentType",
                 "component type " + std::to_string(a.componentType) + " is not allowed for " + usePointer);
        const int n = componentCount(a.type);
        std::vector<float> out(a.count * static_cast<std::size_t>(n), 0.0f);
        if (a.bufferView >= 0) {
            const auto [data, stride] = elements(a, index);
            const int size = componentSize(a.componentType);
            for (std::size_t e = 0; e < a.count; ++e)
                for (int c = 0; c < n; ++c)
                    out[e * n + c] = convert(data + e * stride + static_cast<std::size_t>(c * size), a);
        }
        if (a.sparse.isSparse) applySparse(a, index, out, n);
        for (std::size_t i = 0; i < out.size(); ++i)
            if (!std::isfinite(out[i])) fail(where, "element " + std::to_string(i / n) + " is not a finite number");
        return out;
    }

    std::vector<std::uint32_t> readIndices(std::size_t index, const std::string& usePointer,
                                           std::size_t vertexCount) const {
        const tinygltf::Accessor& a = accessor(index, usePointer);
        const std::string where = ptr("accessors", index);
        if (a.type != TINYGLTF_TYPE_SCALAR) fail(where + "/type", "indices must be SCALAR");
        if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(where + "/componentType",
                 "indices must be unsigned byte, short or int, not " + std::to_string(a.componentType));
        if (a.sparse.isSparse) fail(where + "/sparse", "sparse index accessors are not supported");
        std::vector<std::uint32_t> out(a.count, 0);
        if (a.bufferView < 0) return out;  // all zeros, as the spec says
        const auto [data, stride] = elements(a, index);
        for (std::size_t e = 0; e < a.count; ++e) {
            out[e] = readUnsigned(data + e * stride, a.componentType);
            if (out[e] >= vertexCount)
                fail(where, "index " + std::to_string(out[e]) + " at element " + std::to_string(e) +
                                " is out of range for " + std::to_string(vertexCount) + " vertices");
        }
        return out;
    }

    // Every buffer view must lie inside its buffer, used or not; one into a
    // buffer without bytes is checked when it is read.
    void checkView(std::size_t index) const {
        if (model_.bufferViews[index].byteLength == 0)
            fail(ptr("bufferViews", index, "byteLength"), "is 0; a buffer view holds at least 1 byte");
        const int buffer = model_.bufferViews[index].buffer;
        if (buffer >= 0 && static_cast<std::size_t>(buffer) < absent_.size() &&
            !absent_[static_cast<std::size_t>(buffer)].empty())
            return;
        std::size_t stride = 0;
        view(static_cast<int>(index), ptr("bufferViews", index), stride);
    }

    // Every accessor with a buffer view must fit in it, at an offset aligned
    // to its component size, used or not: checked against the view's length,
    // so that it holds for a buffer without bytes too. Matrix columns start
    // 4-byte aligned (glTF 2.0, 3.6.2.4), so a MAT2 of bytes takes 8.
    void checkAccessorLayout(std::size_t index) const {
        const tinygltf::Accessor& a = model_.accessors[index];
        if (a.sparse.isSparse) {
            const std::string where = ptr("accessors", index) + "/sparse";
            if (a.sparse.count < 1 || static_cast<std::size_t>(a.sparse.count) > a.count)
                fail(where + "/count", "is " + std::to_string(a.sparse.count) + "; it must be 1 to the accessor's " +
                                           std::to_string(a.count));
            for (const auto& [view, part] : {std::pair{a.sparse.indices.bufferView, "/indices/bufferView"},
                                             std::pair{a.sparse.values.bufferView, "/values/bufferView"}})
                if (view >= 0 && static_cast<std::size_t>(view) < model_.bufferViews.size() &&
                    model_.bufferViews[static_cast<std::size_t>(view)].byteStride != 0)
                    fail(where + part,
                         "buffer view " + std::to_string(view) + " has a byteStride; sparse data has none");
        }
        if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model_.bufferViews.size()) return;
        const int size = componentSize(a.componentType), n = componentCount(a.type);
        if (size == 0 || n == 0 || a.count == 0) return;  // refused with its reason where it is used
        const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::size_t rows = a.type == TINYGLTF_TYPE_MAT2   ? 2
                                 : a.type == TINYGLTF_TYPE_MAT3 ? 3
                                 : a.type == TINYGLTF_TYPE_MAT4 ? 4
                                                                : 1;
        const std::size_t column = static_cast<std::size_t>(n) / rows * static_cast<std::size_t>(size);
        const std::size_t element = rows > 1 ? rows * ((column + 3) / 4 * 4) : column;
        // The last column's padding may be cut at the view's end.
        const std::size_t last = rows > 1 ? element - ((column + 3) / 4 * 4 - column) : element;
        const std::size_t stride = v.byteStride ? v.byteStride : element;
        const std::string where = ptr("accessors", index);
        if ((v.byteOffset + a.byteOffset) % static_cast<std::size_t>(size) != 0)
            fail(where + "/byteOffset", "the accessor starts at byte " + std::to_string(v.byteOffset + a.byteOffset) +
                                            " of its buffer, not a multiple of its component size " +
                                            std::to_string(size));
        if (stride < element || a.byteOffset > v.byteLength || (a.count - 1) > (v.byteLength - a.byteOffset) / stride ||
            (a.count - 1) * stride + last > v.byteLength - a.byteOffset)
            fail(where, std::to_string(a.count) + " elements of " + std::to_string(element) + " bytes from byte " +
                            std::to_string(a.byteOffset) + " do not fit in buffer view " +
                            std::to_string(a.bufferView) + " of " + std::to_string(v.byteLength) + " bytes");
    }

    std::size_t count(std::size_t index, const std::string& usePointer) const {
        return accessor(index, usePointer).count;
    }

    // The accessor, checked as readFloats checks it, for attributes that come
    // in more than one shape (COLOR_0: VEC3 or VEC4, normalized integers).
    const tinygltf::Accessor& describe(std::size_t index, const std::string& usePointer) const {
        return accessor(index, usePointer);
    }

private:
    const tinygltf::Accessor& accessor(std::size_t index, const std::string& usePointer) const {
        if (index >= model_.accessors.size())
            fail(usePointer, "accessor " + std::to_string(index) + " does not exist (" +
                                 std::to_string(model_.accessors.size()) + " accessors)");
        const tinygltf::Accessor& a = model_.accessors[index];
        if (componentCount(a.type) == 0) fail(ptr("accessors", index, "type"), "unknown accessor type");
        if (componentSize(a.componentType) == 0)
            fail(ptr("accessors", index, "componentType"), "unknown component type " + std::to_string(a.componentType));
        // The schema's minimum: an empty accessor would also hand null data on.
        if (a.count == 0) fail(ptr("accessors", index, "count"), "count is 0; an accessor holds at least 1 element");
        const std::size_t mostZeroFilled = kMaxZeroFilledComponents / componentCount(a.type);
        if (a.bufferView < 0 && a.count > mostZeroFilled)
            fail(ptr("accessors", index, "count"),
                 "count " + std::to_string(a.count) + " is larger than supported without a buffer view (at most " +
                     std::to_string(mostZeroFilled) + " " + typeName(a.type) + " elements)");
        return a;
    }

    // The bytes of a buffer view, after checking it lies inside its buffer.
    std::pair<const unsigned char*, std::size_t> view(int viewIndex, const std::string& usePointer,
                                                      std::size_t& byteStride) const {
        if (viewIndex < 0 || static_cast<std::size_t>(viewIndex) >= model_.bufferViews.size())
            fail(usePointer, "buffer view " + std::to_string(viewIndex) + " does not exist (" +
                                 std::to_string(model_.bufferViews.size()) + " buffer views)");
        const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(viewIndex)];
        const std::string where = ptr("bufferViews", static_cast<std::size_t>(viewIndex));
        if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model_.buffers.size())
            fail(where + "/buffer", "buffer " + std::to_string(v.buffer) + " does not exist");
        if (static_cast<std::size_t>(v.buffer) < absent_.size() && !absent_[static_cast<std::size_t>(v.buffer)].empty())
            fail(where + "/buffer", "buffer " + std::to_string(v.buffer) +
                                        " has no bytes: " + absent_[static_cast<std::size_t>(v.buffer)]);
        const auto& data = model_.buffers[static_cast<std::size_t>(v.buffer)].data;
        if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
            fail(where, "bytes " + std::to_string(v.byteOffset) + "+" + std::to_string(v.byteLength) +
                            " lie outside buffer " + std::to_string(v.buffer) + " of " + std::to_string(data.size()) +
                            " bytes");
        byteStride = v.byteStride;
        return {data.data() + v.byteOffset, v.byteLength};
    }

    std::pair<const unsigned char*, std::size_t> elements(const tinygltf::Accessor& a, std::size_t index) const {
        const std::string where = ptr("accessors", index);
        std::size_t stride = 0;
        const auto [bytes, length] = view(a.bufferView, where + "/bufferView", stride);
        const std::size_t elementSize =
            static_cast<std::size_t>(componentCount(a.type)) * static_cast<std::size_t>(componentSize(a.componentType));
        if (stride == 0) stride = elementSize;
        if (stride < elementSize)
            fail(ptr("bufferViews", static_cast<std::size_t>(a.bufferView), "byteStride"),
                 "stride " + std::to_string(stride) + " is smaller than an element (" + std::to_string(elementSize) +
                     " bytes)");
        if (a.count == 0) return {bytes, stride};
        // count - 1 strides plus one element must fit, without overflow.
        if (a.byteOffset > length || (a.count - 1) > (length - a.byteOffset) / stride ||
            (a.count - 1) * stride + elementSize > length - a.byteOffset)
            fail(where, std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                            " do not fit in buffer view " + std::to_string(a.bufferView) + " of " +
                            std::to_string(length) + " bytes");
        if (a.byteOffset % static_cast<std::size_t>(componentSize(a.componentType)) != 0)
            fail(where + "/byteOffset", "is not a multiple of the component size");
        return {bytes + a.byteOffset, stride};
    }

    static std::uint32_t readUnsigned(const unsigned char* p, int componentType) {
        switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return *p;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return v;
        }
        default: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        }
    }

    static float convert(const unsigned char* p, const tinygltf::Accessor& a) {
        switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<std::int8_t>(*p);
            return a.normalized ? std::max(static_cast<float>(v) / 127.0f, -1.0f) : static_cast<float>(v);
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return a.normalized ? std::max(static_cast<float>(v) / 32767.0f, -1.0f) : static_cast<float>(v);
        }
        default: {
            const std::uint32_t v = readUnsigned(p, a.componentType);
            if (!a.normalized) return static_cast<float>(v);
            const float max = a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 255.0f
                              : a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 65535.0f
                                                                                          : 4294967295.0f;
            return static_cast<float>(v) / max;
        }
        }
    }

    void applySparse(const tinygltf::Accessor& a, std::size_t index, std::vector<float>& out, int n) const {
        const std::string where = ptr("accessors", index) + "/sparse";
        if (a.sparse.count < 0 || static_cast<std::size_t>(a.sparse.count) > a.count)
            fail(where + "/count", "sparse count " + std::to_string(a.sparse.count) + " exceeds the accessor's " +
                                       std::to_string(a.count));
        const auto count = static_cast<std::size_t>(a.sparse.count);
        const int indexType = a.sparse.indices.componentType;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(where + "/indices/componentType", "must be unsigned byte, short or int");
        auto region = [&](int viewIndex, int byteOffset, std::size_t elementSize, const std::string& p) {
            std::size_t stride = 0;
            const auto [bytes, length] = view(viewIndex, p + "/bufferView", stride);
            if (byteOffset < 0 || static_cast<std::size_t>(byteOffset) > length ||
                count * elementSize > length - static_cast<std::size_t>(byteOffset))
                fail(p,
                     std::to_string(count) + " sparse elements do not fit in buffer view " + std::to_string(viewIndex));
            return bytes + byteOffset;
        };
        const unsigned char* indices = region(a.sparse.indices.bufferView, a.sparse.indices.byteOffset,
                                              static_cast<std::size_t>(componentSize(indexType)), where + "/indices");
        const std::size_t valueSize = static_cast<std::size_t>(n * componentSize(a.componentType));
        const unsigned char* values =
            region(a.sparse.values.bufferView, a.sparse.values.byteOffset, valueSize, where + "/values");
        for (std::size_t s = 0; s < count; ++s) {
            const std::uint32_t target =
                readUnsigned(indices + s * static_cast<std::size_t>(componentSize(indexType)), indexType);
            if (target >= a.count)
                fail(where + "/indices", "index " + std::to_string(target) + " is out of range for " +
                                             std::to_string(a.count) + " elements");
            for (int c = 0; c < n; ++c)
                out[target * static_cast<std::size_t>(n) + static_cast<std::size_t>(c)] =
                    convert(values + s * valueSize + static_cast<std::size_t>(c * componentSize(a.componentType)), a);
        }
    }

    std::string file_;
    const tinygltf::Model& model_;
    std::vector<std::string> absent_;
};

}  // namespace arcomp::gltf
