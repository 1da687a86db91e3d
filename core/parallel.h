// Work split over threads, for the loops whose items are independent.
#pragma once

#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace lloydscope {

// The arena of `threads` worker threads, made once (thread-safe; arenas are shared).
tbb::task_arena& taskArena(int threads);

// fn(begin, end) over [0, count) split into parts of at most ceil(count / threads) items, run
// on TBB's worker threads, which live as long as the program: starting threads for each call
// cost as much as the work itself on a thousand Voronoi cells.
template <class Fn>
void parallelFor(size_t count, size_t threads, const Fn& fn) {
  if (threads <= 1 || count <= 1) {
    fn(0, count);
    return;
  }
  auto parts = [&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, (count + threads - 1) / threads),
                      [&](const tbb::blocked_range<size_t>& r) { fn(r.begin(), r.end()); },
                      tbb::simple_partitioner());
  };
  if (static_cast<int>(threads) == tbb::this_task_arena::max_concurrency()) return parts();
  taskArena(static_cast<int>(threads)).execute(parts);
}

}  // namespace lloydscope
