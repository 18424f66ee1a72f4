#pragma once
// A data URI (RFC 2397) as glTF buffers and images use them: base64 or
// percent-encoded, with the media type it names.
//
//   DataUri d = decodeDataUri("data:application/gltf-buffer,0");
//   // d.mediaType == "application/gltf-buffer", d.bytes == {'0'}, d.error empty

#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

struct DataUri {
    std::string mediaType;  // as written; "text/plain" when the URI names none, as RFC 2397 says
    std::vector<std::uint8_t> bytes;
    std::string error;  // why the URI could not be read; empty when it was
};

bool isDataUri(const std::string& uri);
DataUri decodeDataUri(const std::string& uri);

}  // namespace arcomp
