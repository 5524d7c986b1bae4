#pragma once
// The queue between a real-time stage and the next (STYLE.md habit 5): bounded, with an
// end-of-stream marker, and one of two policies when it is full —
//   kDropOldest: push never waits; the oldest waiting item is dropped and counted, so the
//                newest frame is never blocked (a camera does not wait for us);
//   kBlock:      push waits for room (back-pressure; nothing dropped: --unpaced throughput).
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <optional>

namespace dynanav {

enum class QueueFullPolicy { kDropOldest, kBlock };

template <class T>
class FrameQueue {
 public:
  FrameQueue(size_t capacity, QueueFullPolicy policy)
      : capacity_(capacity < 1 ? 1 : capacity), policy_(policy) {}

  /// Adds an item (ignored after close()). Returns the number of items dropped to make room.
  size_t push(T item) {
    std::unique_lock lock(mutex_);
    if (policy_ == QueueFullPolicy::kBlock)
      changed_.wait(lock, [this] { return items_.size() < capacity_ || closed_; });
    if (closed_) return 0;
    size_t dropped = 0;
    while (items_.size() >= capacity_) {
      items_.pop_front();
      ++dropped;
    }
    dropped_ += dropped;
    items_.push_back(std::move(item));
    changed_.notify_all();
    return dropped;
  }

  /// The oldest item, waiting while the queue is empty; nullopt once closed and drained.
  std::optional<T> pop() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [this] { return !items_.empty() || closed_; });
    if (items_.empty()) return std::nullopt;
    T item = std::move(items_.front());
    items_.pop_front();
    changed_.notify_all();
    return item;
  }

  /// End of stream: pop() returns what is left, then nullopt; blocked pushes return.
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    changed_.notify_all();
  }

  [[nodiscard]] bool closed() const {
    std::lock_guard lock(mutex_);
    return closed_;
  }

  [[nodiscard]] size_t dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
  }

 private:
  const size_t capacity_;
  const QueueFullPolicy policy_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<T> items_;
  size_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace dynanav
