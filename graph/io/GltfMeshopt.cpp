#include "graph/io/GltfMeshopt.hpp"

#include <meshoptimizer.h>

#include <vector>

namespace arcomp::gltf {

using nlohmann::json;

void decodeMeshoptViews(GltfDocument& doc) {
    const json* views = member(doc.json, "bufferViews");
    if (!views || !views->is_array()) return;
    for (std::size_t i = 0; i < views->size(); ++i) {
        const json* extensions = member((*views)[i], "extensions");
        const json* ext = extensions ? member(*extensions, "EXT_meshopt_compression") : nullptr;
        if (!ext) continue;
        const std::string where = "/bufferViews/" + std::to_string(i) + "/extensions/EXT_meshopt_compression";
        if (!ext->is_object()) doc.fail(where, "is not an object");
        const std::size_t count = requiredUnsigned(doc, *ext, "count", where);
        const std::size_t stride = requiredUnsigned(doc, *ext, "byteStride", where);
        const json* modeValue = member(*ext, "mode");
        const std::string mode = modeValue && modeValue->is_string() ? modeValue->get<std::string>() : "";
        const json* filterValue = member(*ext, "filter");
        const std::string filter = filterValue && filterValue->is_string() ? filterValue->get<std::string>() : "NONE";

        // The compressed stream, as if it were a view of its own.
        const std::size_t buffer = requiredUnsigned(doc, *ext, "buffer", where);
        const std::size_t offset = unsignedMember(doc, *ext, "byteOffset", where, 0);
        const std::size_t length = requiredUnsigned(doc, *ext, "byteLength", where);
        if (buffer >= doc.buffers.size())
            doc.fail(where + "/buffer", "buffer " + std::to_string(buffer) + " does not exist");
        const GltfBuffer& source = doc.buffers[buffer];
        if (!source.absent.empty())
            doc.fail(where + "/buffer", "buffer " + std::to_string(buffer) + " has no bytes: " + source.absent);
        if (offset > source.bytes.size() || length > source.bytes.size() - offset)
            doc.fail(where, "compressed bytes " + std::to_string(offset) + "+" + std::to_string(length) +
                                " lie outside buffer " + std::to_string(buffer) + " of " +
                                std::to_string(source.bytes.size()) + " bytes");
        // Copied: the fallback buffer may be the same buffer, and decoding
        // must not write over the stream it reads.
        const std::vector<std::uint8_t> stream(source.bytes.begin() + static_cast<std::ptrdiff_t>(offset),
                                               source.bytes.begin() + static_cast<std::ptrdiff_t>(offset + length));

        const ViewBytes target = viewBytes(doc, i, where);
        if (stride == 0 || (count > 0 && stride > target.size / count) || count * stride > target.size)
            doc.fail(where, std::to_string(count) + " elements of " + std::to_string(stride) +
                                " bytes do not fit in the view's " + std::to_string(target.size) + " bytes");
        int status = 0;
        if (mode == "ATTRIBUTES") {
            if (stride % 4 != 0 || stride > 256)
                doc.fail(where + "/byteStride",
                         "is " + std::to_string(stride) + "; ATTRIBUTES take a multiple of 4 up to 256");
            status = meshopt_decodeVertexBuffer(target.data, count, stride, stream.data(), stream.size());
        } else if (mode == "TRIANGLES" || mode == "INDICES") {
            if (stride != 2 && stride != 4)
                doc.fail(where + "/byteStride", "is " + std::to_string(stride) + "; " + mode + " take 2 or 4");
            if (mode == "TRIANGLES" && count % 3 != 0)
                doc.fail(where + "/count", "is " + std::to_string(count) + "; TRIANGLES take a multiple of 3");
            status = mode == "TRIANGLES"
                         ? meshopt_decodeIndexBuffer(target.data, count, stride, stream.data(), stream.size())
                         : meshopt_decodeIndexSequence(target.data, count, stride, stream.data(), stream.size());
        } else {
            doc.fail(where + "/mode", "is '" + mode + "', expected ATTRIBUTES, TRIANGLES or INDICES");
        }
        if (status != 0)
            doc.fail(where, "the " + mode + " stream does not decode (meshoptimizer's decoder gives " +
                                std::to_string(status) + ")");
        if (filter == "NONE") continue;
        if (mode != "ATTRIBUTES") doc.fail(where + "/filter", "is " + filter + "; only ATTRIBUTES take a filter");
        if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
            meshopt_decodeFilterOct(target.data, count, stride);
        else if (filter == "QUATERNION" && stride == 8)
            meshopt_decodeFilterQuat(target.data, count, stride);
        else if (filter == "EXPONENTIAL")
            meshopt_decodeFilterExp(target.data, count, stride);
        else
            doc.fail(where + "/filter", "'" + filter + "' with byteStride " + std::to_string(stride) +
                                            " is not one the extension defines (OCTAHEDRAL 4 or 8, QUATERNION 8, "
                                            "EXPONENTIAL)");
    }
}

}  // namespace arcomp::gltf
