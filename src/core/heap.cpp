#include "core/heap.hpp"

#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace dynanav {

double heapInUseMb() {
#if defined(__GLIBC__)
  const struct mallinfo2 info = mallinfo2();
  return double(info.uordblks + info.hblkhd) / (1024.0 * 1024.0);
#else
  return -1.0;
#endif
}

void releaseFreeHeapPages() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

PeriodicHeapRelease::PeriodicHeapRelease(double period_s)
    : period_(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
          std::chrono::duration<double>(period_s))),
      last_(std::chrono::steady_clock::now()) {}

bool PeriodicHeapRelease::operator()() {
  const auto now = std::chrono::steady_clock::now();
  if (now - last_ < period_) return false;
  last_ = now;
  releaseFreeHeapPages();
  return true;
}

}  // namespace dynanav
