#pragma once
// The process heap as the allocator sees it (glibc), beside the resident figures of timer.hpp.
// dynanav keeps freed frame-sized buffers in the heap (apps/dynanav/main.cpp raises glibc's
// mmap and trim thresholds: re-faulting fresh pages for every frame's images cost more than the
// work on them), so the heap does not shrink by itself. Over a long run the map's objects,
// allocated and freed as keyframes come and go, scatter through the arenas between the frame
// buffers: in a paced ten-pass run of the Bonn window the arenas' free bytes grew from 30 to
// 58 MiB between two loop closures while the live heap grew by 10 MiB, and the pages of those
// free chunks stayed resident (scratch logging, docs/robustness.md "Session 14").
#include <chrono>

namespace dynanav {

/// Bytes malloc has handed out and not had back (every arena; large mmapped blocks included), in
/// MiB: the live heap. -1 where the allocator does not say (not glibc).
double heapInUseMb();

/// Hands the pages of every free chunk back to the system (every arena, not only the top). They
/// are faulted in again when next used, and the call walks every free list: not for every
/// frame. No-op without glibc.
void releaseFreeHeapPages();

/// releaseFreeHeapPages at most once per period: what jemalloc does by itself (its unused pages
/// decay after 10 s by default) and glibc does not.
class PeriodicHeapRelease {
 public:
  explicit PeriodicHeapRelease(double period_s);
  /// Releases when a period has passed since the last release (or construction); true if so.
  bool operator()();

 private:
  std::chrono::steady_clock::duration period_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace dynanav
