#include "runtime/station/BakeCache.hpp"

#include <cctype>
#include <cstdlib>

namespace arcomp {

namespace {

std::filesystem::path chosenFolder(const CompositorConfig& c) {
    if (c.bakeCache == "none") return {};
    if (!c.bakeCache.empty()) return c.bakeCache;
    if (const char* d = std::getenv("CACHE_DIRECTORY"); d && *d)
        return std::string(d).substr(0, std::string(d).find(':'));
    if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "arcomp";
    if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "arcomp";
    return {};
}

}  // namespace

std::filesystem::path bakeCacheFolder(const CompositorConfig& config) {
    std::filesystem::path folder = chosenFolder(config);
    if (!folder.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(folder, ec);  // a folder that cannot be made: every write says so
    }
    return folder;
}

std::string bakeCacheFileName(const std::filesystem::path& config, const std::string& node, std::uint32_t id,
                              const char* extension) {
    std::string name = config.stem().string() + "-" + node;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
    return name + "-" + std::to_string(id) + extension;
}

}  // namespace arcomp
