#pragma once
// A parallel loop over chunks of items on a few std::threads (the caller one of them), for
// geometry that writes each item's results into its own place in preallocated arrays: the
// output is then the same whichever thread ran which chunk, and whatever the thread count.
#include <cstddef>
#include <functional>
#include <vector>

namespace sweep {

/// The most threads a parallel loop may use.
inline constexpr int kMaxWorkers = 256;

/// The threads a parallel loop uses: the last set_worker_count, else SWEEP_THREADS when it is
/// set to a number from 1 to kMaxWorkers, else the hardware's threads (at least 1; read once).
int worker_count();

/// The count without set_worker_count: SWEEP_THREADS or the hardware's threads.
int default_worker_count();

/// Sets what worker_count returns from now on (`--threads N`, the viewer's Display panel); loops
/// already running keep theirs. Precondition: 1 <= threads <= kMaxWorkers.
void set_worker_count(int threads);

/// Calls body(begin, end, worker) for consecutive chunks [begin, end) of [0, count), each of at
/// most `chunk` items, on `threads` threads (fewer when there are fewer chunks; the calling
/// thread is worker 0, the others are started for the call and joined before it returns), and
/// returns once every chunk is done. `worker` is in [0, threads): per-thread scratch. Chunks are
/// handed out in order as threads come free, so which worker runs which chunk varies from run
/// to run. The first exception a body throws is rethrown here, after the other threads stop
/// taking chunks.
void parallel_chunks(std::size_t count, std::size_t chunk, int threads,
                     const std::function<void(std::size_t begin, std::size_t end, int worker)>& body);

/// Runs each task once, on up to `threads` threads (in the order given as threads come free), and
/// returns when all are done: independent work side by side, e.g. sizing fresh arrays.
void run_side_by_side(const std::vector<std::function<void()>>& tasks, int threads);

}  // namespace sweep
