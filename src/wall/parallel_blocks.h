// Independent blocks of work on a few threads, as every grid of the wall is sampled: each thread gets
// a worker of its own (its scratch space, its evaluator), blocks are handed out in order, progress is
// reported from the calling thread, and the first exception (out of memory) stops every thread and is
// rethrown to the caller: an exception escaping a std::thread would abort the process. The results go
// wherever `work` puts them by index, so they do not depend on the threads' schedule.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace offsetgen::wall {

// make_worker() -> W, once per thread; work(W&, i) for every i in [0, count).
template <typename MakeWorker, typename Work>
void for_each_block(size_t count, int threads, const std::function<void(double)>& progress,
                    const MakeWorker& make_worker, const Work& work) {
  std::atomic<size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr failure;
  std::mutex failure_lock;
  auto run = [&] {
    try {
      auto worker = make_worker();
      for (size_t i = next++; i < count && !failed; i = next++) {
        work(worker, i);
        ++done;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> guard(failure_lock);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(threads, 1); ++t) pool.emplace_back(run);
  std::thread main_worker(run);
  while (done.load() < count && !failed) {
    if (progress) progress(static_cast<double>(done.load()) / static_cast<double>(count));
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  main_worker.join();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(1.0);
}

}  // namespace offsetgen::wall
