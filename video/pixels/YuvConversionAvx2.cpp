// The YUV row kernel built for AVX2, twice the vector width of the library's
// SSE2 baseline; video/pixels/YuvConversion.cpp calls it only on CPUs that have
// AVX2. Built with -mavx2 (video/CMakeLists.txt) on x86-64 and empty
// elsewhere.
//
// Everything compiled here may carry AVX2 instructions, so no function it
// emits may share a name with one the rest of the program uses: the linker
// keeps one copy of an inline function, and were it this file's, a CPU
// without AVX2 would fault in it. So the kernel goes in its own namespace
// and, as in OpenCV's own dispatched code, so do OpenCV's intrinsics
// (cv::hal_AVX2 rather than cv::hal_baseline); the file includes nothing
// else and skips the target's precompiled headers.
#if defined(__x86_64__)

#ifndef __AVX2__
#error "video/pixels/YuvConversionAvx2.cpp needs -mavx2"
#endif

// OpenCV's headers turn on their AVX2 intrinsics only inside OpenCV's own build.
#include <immintrin.h>
#define CV_AVX2 1
#define CV_CPU_DISPATCH_MODE AVX2

#define ARCOMP_YUV_KERNEL_NAMESPACE avx2
#include "video/pixels/YuvRowKernel.hpp"

static_assert(CV_SIMD256, "the AVX2 build of the YUV kernel has 256-bit vectors");

namespace arcomp::yuv {

RowKernels avx2RowKernels() { return avx2::rowKernels(); }

}  // namespace arcomp::yuv

#endif
