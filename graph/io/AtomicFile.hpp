#pragma once
// Replacing a file in one step: the bytes go to a temporary beside it
// ("<file>.tmp-<pid>-<n>"), are flushed to disk, and the temporary is
// renamed over `file`. A crash, a full disk or a failed write leaves either
// the old file or the new one under that name, never a half-written one.
//
//   BinaryWriter out;
//   ...
//   writeFileAtomically("bunny.lod", out.bytes());   // throws std::runtime_error
//
// Errors name `file` and the step that failed; the temporary is removed.
// The folder must exist. A symlink at `file` is replaced, not followed.

#include <cstddef>
#include <filesystem>
#include <span>

namespace arcomp {

void writeFileAtomically(const std::filesystem::path& file, std::span<const std::byte> bytes);

}  // namespace arcomp
