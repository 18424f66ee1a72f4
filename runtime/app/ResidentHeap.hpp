#pragma once
// Freed memory stays in the process, to be reused by the next frame, instead
// of going back to the kernel and coming back as fresh pages.
//
// Why: a frame allocates and frees the same buffers every time. llvmpipe bins
// each draw's work in 64 KiB blocks from malloc and frees them at the end of
// the frame; decoded and converted video frames are megabytes each. glibc
// hands the top of its heap back once more than 128 KiB of it is free, and
// serves blocks over 128 KiB (a threshold it raises by itself, but only up to
// what it has seen freed) with mmap. Either way the next frame takes page
// faults on zeroed pages. On the VMs this project is measured on that was
// most of the frame: `arcomp-bench budget` at 1280x720 drew its unmanaged frames in
// 566 ms (median) with glibc's defaults and in 122 ms with this policy, and
// the process spent 43 s of 120 in the kernel against 1 s of 29.
//
// The price is that memory freed after a peak (a large model loaded, then
// dropped) stays with the process up to kTrimThreshold. A station's working
// set is steady from frame to frame, so its peak is its working set anyway.
//
//   int main() { keepFreedMemoryResident(); ... }
//
// A no-op where the C library is not glibc. Process-wide: it is for the
// station's executable to call, not for a library.

#include <cstddef>

namespace arcomp {

// Free memory kept at the top of the heap before any goes back to the kernel.
inline constexpr std::size_t kTrimThreshold = std::size_t{256} << 20;

// False where the C library refused a setting (or is not glibc).
bool keepFreedMemoryResident();

}  // namespace arcomp
