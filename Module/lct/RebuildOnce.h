/**
 * @file RebuildOnce.h
 * @brief A cache rebuilt by the first reader that finds it stale, once, while other readers may
 *        run concurrently: double-checked with an atomic flag (acquire on the fast path, release
 *        after the rebuild) and a mutex around the rebuild. Writers that mark it stale must not
 *        run concurrently with readers (the interpolators document this).
 */
#ifndef lct_RebuildOnce_h
#define lct_RebuildOnce_h

#include <atomic>
#include <mutex>

namespace lct
{

template <typename Build>
void rebuildOnce(std::atomic<bool>& current, std::mutex& mutex, Build&& build)
{
  if (current.load(std::memory_order_acquire))
  {
    return;
  }
  std::lock_guard<std::mutex> lock(mutex);
  if (current.load(std::memory_order_relaxed))
  {
    return;
  }
  build();
  current.store(true, std::memory_order_release);
}

} // namespace lct

#endif
