#pragma once
// Resolving a URI found inside a content file (a glTF buffer or image, an
// OBJ's material library) against the file's folder. Content comes from
// authors, not from the station's owner, so it may only reach files under
// its own folder: "../", absolute paths and URI schemes are refused.

#include <filesystem>
#include <optional>
#include <string>

namespace arcomp {

// The path inside `folder` that `uri` names, or nullopt with `reason` set
// when the URI would leave the folder.
std::optional<std::filesystem::path> containedPath(const std::filesystem::path& folder, const std::string& uri,
                                                   std::string& reason);

}  // namespace arcomp
