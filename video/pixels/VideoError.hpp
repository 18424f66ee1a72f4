#pragma once
// A video input that cannot be used: what() reads
// "<source>: <where>: <reason>", e.g.
// "clips/a.avi: frame 287 of 795: decoder returned no image (truncated or damaged)".
// Bad input like any other (graph/core/BadInput.hpp holds no scene types).

#include "graph/core/BadInput.hpp"

namespace arcomp {

class VideoError : public BadInput {
public:
    using BadInput::BadInput;
};

}  // namespace arcomp
