#include "background_task.h"

#include <exception>
#include <utility>

namespace lloydscope {

void BackgroundTask::start(Work work, std::function<void()> whenDone) {
  join();
  stopRequested_ = false;
  finished_ = false;
  thread_ = std::thread([this, work = std::move(work), whenDone = std::move(whenDone)] {
    try {
      work(stopRequested_);
    } catch (const std::exception& e) {
      error_ = e.what();
    } catch (...) {
      error_ = "unknown error";
    }
    finished_ = true;
    if (whenDone) whenDone();
  });
}

std::string BackgroundTask::join() {
  if (thread_.joinable()) thread_.join();
  return std::exchange(error_, std::string());
}

}  // namespace lloydscope
