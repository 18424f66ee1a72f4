#pragma once
// What the process holds, for the checks that a station stays flat all day
// (bench soak, tests/runtime/SoakGuard_test.cpp):
// - resident: the pages the kernel counts for it (RSS);
// - heapInUse: what the program holds from malloc, in every arena (glibc's
//   mallinfo2, or AddressSanitizer's own count in a sanitized build). A
//   leak grows both; the allocator settling on its pages grows RSS alone,
//   in steps, and stops;
// - fileDescriptors: the descriptors open.
//
//   const ProcessMemory before = ProcessMemory::now();
//   runFrames(1000);
//   const double bytesPerFrame = double(ProcessMemory::now().heapInUse - before.heapInUse) / 1000;

#include <cstddef>

namespace arcomp {

struct ProcessMemory {
    std::size_t resident = 0;   // bytes
    std::size_t heapInUse = 0;  // bytes; 0 where neither glibc nor AddressSanitizer tells
    int fileDescriptors = 0;

    static ProcessMemory now();
};

}  // namespace arcomp
