#include "runtime/operator/ProcessMemory.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#if defined(__SANITIZE_ADDRESS__)
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
#include <malloc.h>
#endif

namespace arcomp {

namespace {

std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    statm >> pages >> resident;
    return resident * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

std::size_t heapBytesInUse() {
#if defined(__SANITIZE_ADDRESS__)
    return __sanitizer_get_current_allocated_bytes();
#elif defined(__GLIBC__)
    const struct mallinfo2 m = mallinfo2();  // every arena: small blocks in use plus mmapped ones
    return m.uordblks + m.hblkhd;
#else
    return 0;
#endif
}

int openFileDescriptors() {
    int n = 0;
    std::error_code ec;
    for (std::filesystem::directory_iterator it("/proc/self/fd", ec), end; !ec && it != end; it.increment(ec)) ++n;
    return n - 1;  // the iterator's own descriptor
}

}  // namespace

ProcessMemory ProcessMemory::now() { return {residentBytes(), heapBytesInUse(), openFileDescriptors()}; }

}  // namespace arcomp
