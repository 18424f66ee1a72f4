#include "runtime/app/ResidentHeap.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace arcomp {

bool keepFreedMemoryResident() {
#if defined(__GLIBC__)
    // Blocks up to glibc's largest mmap threshold (32 MiB on 64-bit: four
    // 1080p RGBA frames) come from the heap, where freeing them keeps their
    // pages; setting it also stops glibc from moving it on its own. The top
    // pad makes the heap grow in steps of 16 MiB, not one page run at a time.
    const bool mmap = mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1;
    const bool trim = mallopt(M_TRIM_THRESHOLD, static_cast<int>(kTrimThreshold)) == 1;
    const bool pad = mallopt(M_TOP_PAD, 16 << 20) == 1;
    return mmap && trim && pad;
#else
    return false;
#endif
}

}  // namespace arcomp
