// Work split over threads, for the loops whose items are independent.
#pragma once

#include <cstddef>
#include <thread>
#include <vector>

namespace lloydscope {

// fn(begin, end) over [0, count) split into `threads` contiguous parts, one per thread (the
// first on the calling thread).
template <class Fn>
void parallelFor(size_t count, size_t threads, const Fn& fn) {
  std::vector<std::thread> pool;
  for (size_t t = 1; t < threads; ++t)
    pool.emplace_back(fn, count * t / threads, count * (t + 1) / threads);
  fn(0, count / threads);
  for (std::thread& thread : pool) thread.join();
}

}  // namespace lloydscope
