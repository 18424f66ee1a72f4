#include "runtime/app/ResidentHeap.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace arcomp {
namespace {

#if defined(__GLIBC__)
// A frame-sized block, freed, is still the process's memory afterwards:
// it came from the heap rather than its own mapping, and freeing it did not
// hand the heap's top back. With glibc's defaults a block this large is
// mapped on its own and unmapped when freed.
TEST(ResidentHeap, AFreedFrameBufferStaysInTheProcess) {
    if (!keepFreedMemoryResident()) GTEST_SKIP() << "malloc is not glibc's here (a sanitizer replaces it)";
    constexpr std::size_t kBlock = 24u << 20;  // over what any earlier free may have raised glibc's threshold to
    const struct mallinfo2 before = mallinfo2();
    {
        auto block = std::make_unique<unsigned char[]>(kBlock);
        std::memset(block.get(), 1, kBlock);
        const struct mallinfo2 during = mallinfo2();
        EXPECT_EQ(during.hblkhd, before.hblkhd) << "the block was mapped on its own";
    }
    const struct mallinfo2 after = mallinfo2();
    EXPECT_GE(after.fordblks, kBlock) << "the heap gave the freed block back to the kernel";
}
#endif

}  // namespace
}  // namespace arcomp
