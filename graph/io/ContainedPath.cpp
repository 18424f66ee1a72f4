#include "graph/io/ContainedPath.hpp"

#include <algorithm>

namespace arcomp {

namespace fs = std::filesystem;

std::optional<fs::path> containedPath(const fs::path& folder, const std::string& uri, std::string& reason) {
    const auto colon = uri.find(':');
    const auto slash = uri.find('/');
    if (uri.starts_with("data:")) {
        // tinygltf reads a data URI itself when it knows its media type;
        // what reaches here is another type, or not base64.
        const std::size_t base64 = uri.find(";base64,");
        const std::string type = uri.substr(5, std::min(uri.find_first_of(";,"), std::size_t{45}) - 5);
        if (base64 == std::string::npos)
            reason = "data URI '" + uri.substr(0, 40) + "' is not base64-encoded; only base64 data URIs are supported";
        else if (type == "image/webp")
            reason = "data URI '" + uri.substr(0, 40) +
                     "' holds a WebP image (EXT_texture_webp), which arcomp cannot decode; re-export with PNG or JPEG "
                     "textures";
        else
            reason = "data URI '" + uri.substr(0, 40) + "' has media type '" + type +
                     "', which the glTF reader does not take; expected application/octet-stream, "
                     "application/gltf-buffer, image/png or image/jpeg";
        return std::nullopt;
    }
    if (colon != std::string::npos && (slash == std::string::npos || colon < slash)) {
        reason = "URI '" + uri + "' has a scheme; only relative paths inside the model's folder are allowed";
        return std::nullopt;
    }
    const fs::path relative(uri);
    if (relative.is_absolute() || uri.starts_with('\\')) {
        reason = "URI '" + uri + "' is an absolute path; only relative paths inside the model's folder are allowed";
        return std::nullopt;
    }
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(folder, ec);
    const fs::path target = fs::weakly_canonical(folder / relative, ec);
    if (ec) {
        reason = "URI '" + uri + "' cannot be resolved: " + ec.message();
        return std::nullopt;
    }
    // Symbolic links are followed by weakly_canonical, so a link that points
    // out of the folder is refused as well.
    const auto [baseEnd, targetIt] = std::mismatch(base.begin(), base.end(), target.begin(), target.end());
    if (baseEnd != base.end()) {
        reason = "URI '" + uri + "' leads outside the model's folder " + base.string();
        return std::nullopt;
    }
    return target;
}

}  // namespace arcomp
