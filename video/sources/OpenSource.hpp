#pragma once
// Builds the FrameSource a SourceSpec describes and opens it: a capture
// thread over the right grabber, wrapped in a FallbackSource when the spec
// names a fallback.
//
//   std::unique_ptr<FrameSource> src = openSource({.kind = SourceKind::File, .path = "a.avi"});
//
// A missing camera or file does not throw: the source reports it in
// state(). A bad spec (a fallback image that cannot be read, a size of 0)
// throws VideoError.

#include "video/sources/FrameSource.hpp"
#include "video/sources/SourceSpec.hpp"

#include <memory>

namespace arcomp {

std::unique_ptr<FrameSource> openSource(const SourceSpec& spec);

}  // namespace arcomp
