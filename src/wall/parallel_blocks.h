// Independent blocks of work on a few threads, as every grid of the wall is sampled: each thread gets
// a worker of its own (its scratch space, its evaluator), blocks are handed out in order, progress is
// reported from the calling thread (which returns as soon as the last block is done, not at its next
// report: a slicer calls this for every layer), and the first exception (out of memory) stops every thread and is
// rethrown to the caller: an exception escaping a std::thread would abort the process. The results go
// wherever `work` puts them by index, so they do not depend on the threads' schedule.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
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
  std::mutex lock;  // guards failure and finished
  std::condition_variable all_finished;
  int finished = 0;
  auto run = [&] {
    try {
      auto worker = make_worker();
      for (size_t i = next++; i < count && !failed; i = next++) {
        work(worker, i);
        ++done;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> guard(lock);
      if (!failure) failure = std::current_exception();
      failed = true;
    }
    {
      const std::lock_guard<std::mutex> guard(lock);
      ++finished;
    }
    all_finished.notify_all();
  };
  const int workers = std::max(threads, 1);
  if (workers == 1 && !progress) {
    run();  // one thread and nothing to report: no thread to start, nothing to wait for
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < workers; ++t) pool.emplace_back(run);
    // Progress every 20 ms, and back as soon as the last worker finishes (a layer takes milliseconds).
    std::unique_lock<std::mutex> guard(lock);
    while (finished < workers) {
      guard.unlock();
      if (progress) progress(static_cast<double>(done.load()) / static_cast<double>(count));
      guard.lock();
      all_finished.wait_for(guard, std::chrono::milliseconds(20), [&] { return finished == workers; });
    }
    guard.unlock();
    for (auto& t : pool) t.join();
  }
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(1.0);
}

}  // namespace offsetgen::wall
