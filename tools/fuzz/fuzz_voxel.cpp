// libFuzzer target: voxel files through decodeVoxels.
#include "graph/io/VoxelFile.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        arcomp::decodeVoxels(std::span<const std::uint8_t>(data, size), "fuzz.arvox");
    } catch (const arcomp::ModelError&) {}
    return 0;
}
