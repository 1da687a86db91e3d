// Work on a thread of its own, while the window goes on drawing: the inspector's run and its
// comparison of solvers. The work may be asked to stop; what it throws (out of memory, say) is
// kept for the window to say, where on a thread of its own it would end the program.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <thread>

namespace lloydscope {

class BackgroundTask {
 public:
  // The work polls `stopRequested` and returns soon after it turns true.
  using Work = std::function<void(const std::atomic<bool>& stopRequested)>;

  BackgroundTask() = default;
  ~BackgroundTask() { stop(); }
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;

  // Starts `work` on a new thread, once the work before has ended (it is joined first, and what
  // it threw forgotten). `whenDone` runs on that thread after the work, once finished() holds.
  void start(Work work, std::function<void()> whenDone = {});
  // Started and not joined yet: the work may go on, or be done and wait for join().
  bool started() const { return thread_.joinable(); }
  // The work has ended (or none was started): join() does not wait.
  bool finished() const { return finished_; }
  void requestStop() { stopRequested_ = true; }
  // Waits for the work to end, then returns what it threw, or "" (also where none was started).
  std::string join();
  // requestStop(), then join().
  std::string stop() {
    requestStop();
    return join();
  }

 private:
  std::thread thread_;
  std::atomic<bool> stopRequested_{false}, finished_{true};
  std::string error_;  // written by the work's thread before finished_, read after the join
};

}  // namespace lloydscope
