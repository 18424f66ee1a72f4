#include "graph/io/DataUri.hpp"

#include "graph/io/Base64.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>

namespace arcomp {

bool isDataUri(const std::string& uri) {
    return uri.size() >= 5 && std::equal(uri.begin(), uri.begin() + 5, "data:", [](char a, char b) {
               return std::tolower(static_cast<unsigned char>(a)) == b;
           });
}

DataUri decodeDataUri(const std::string& uri) {
    DataUri out;
    const std::string shown = uri.substr(0, 40) + (uri.size() > 40 ? "..." : "");
    const auto comma = uri.find(',');
    if (!isDataUri(uri) || comma == std::string::npos) {
        out.error = "'" + shown + "' is not a data URI (data:[<media type>][;base64],<data>)";
        return out;
    }
    std::string header = uri.substr(5, comma - 5);
    const bool isBase64 = header.ends_with(";base64");
    if (isBase64) header.resize(header.size() - 7);
    out.mediaType = header.substr(0, header.find(';'));
    // Each parameter after the media type is attribute=value.
    for (auto at = header.find(';'); at != std::string::npos; at = header.find(';', at + 1)) {
        const std::string parameter = header.substr(at + 1, header.find(';', at + 1) - at - 1);
        if (parameter.find('=') == std::string::npos || parameter.front() == '=') {
            out.error = "data URI '" + shown + "' has a parameter '" + parameter + "' that is not attribute=value";
            return out;
        }
    }
    if (out.mediaType.empty()) out.mediaType = "text/plain";
    const std::string_view data = std::string_view(uri).substr(comma + 1);
    if (isBase64) {
        auto bytes = fromBase64(data);
        if (!bytes) {
            out.error = "data URI '" + shown + "' says base64 but holds characters or a length base64 does not";
            return out;
        }
        out.bytes = std::move(*bytes);
        return out;
    }
    out.bytes.reserve(data.size());
    for (std::size_t i = 0; i < data.size(); ++i) {
        if (data[i] != '%') {
            out.bytes.push_back(static_cast<std::uint8_t>(data[i]));
            continue;
        }
        const auto hex = [](char c) {
            return c >= '0' && c <= '9'   ? c - '0'
                   : c >= 'a' && c <= 'f' ? c - 'a' + 10
                   : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                          : -1;
        };
        if (i + 2 >= data.size() || hex(data[i + 1]) < 0 || hex(data[i + 2]) < 0) {
            out.error = "data URI '" + shown + "' has a '%' at character " + std::to_string(comma + 1 + i) +
                        " that two hexadecimal digits do not follow";
            out.bytes.clear();
            return out;
        }
        out.bytes.push_back(static_cast<std::uint8_t>(hex(data[i + 1]) * 16 + hex(data[i + 2])));
        i += 2;
    }
    return out;
}

}  // namespace arcomp
