#include "background_task.h"

#include "mesh.h"  // Error

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <new>
#include <thread>

namespace lloydscope {
namespace {

using namespace std::chrono_literals;

TEST(BackgroundTask, RunsTheWorkOnAThreadOfItsOwn) {
  BackgroundTask task;
  EXPECT_FALSE(task.started());
  EXPECT_TRUE(task.finished());  // nothing to wait for
  std::thread::id ranOn;
  task.start([&](const std::atomic<bool>&) { ranOn = std::this_thread::get_id(); });
  EXPECT_TRUE(task.started());
  EXPECT_EQ(task.join(), "");
  EXPECT_FALSE(task.started());
  EXPECT_TRUE(task.finished());
  EXPECT_NE(ranOn, std::thread::id());
  EXPECT_NE(ranOn, std::this_thread::get_id());
}

TEST(BackgroundTask, IsNotFinishedWhileTheWorkGoesOn) {
  BackgroundTask task;
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  task.start([released](const std::atomic<bool>&) { released.wait(); });
  std::this_thread::sleep_for(20ms);
  EXPECT_TRUE(task.started());
  EXPECT_FALSE(task.finished());
  release.set_value();
  EXPECT_EQ(task.join(), "");
  EXPECT_TRUE(task.finished());
}

TEST(BackgroundTask, StopEndsWorkThatWaitsForIt) {
  BackgroundTask task;
  int rounds = 0;
  task.start([&](const std::atomic<bool>& stop) {
    while (!stop) {
      ++rounds;
      std::this_thread::sleep_for(1ms);
    }
  });
  std::this_thread::sleep_for(10ms);
  EXPECT_EQ(task.stop(), "");
  EXPECT_FALSE(task.started());
  EXPECT_GT(rounds, 0);
}

// What the work threw (out of memory, an Error) is kept for the owner, where on a thread of its
// own it would end the program.
TEST(BackgroundTask, KeepsWhatTheWorkThrew) {
  BackgroundTask task;
  task.start([](const std::atomic<bool>&) { throw Error("m.off: something went wrong"); });
  EXPECT_EQ(task.join(), "m.off: something went wrong");
  EXPECT_EQ(task.join(), "");  // said once
  task.start([](const std::atomic<bool>&) { throw std::bad_alloc(); });
  EXPECT_EQ(task.join(), std::bad_alloc().what());
  task.start([](const std::atomic<bool>&) { throw 42; });
  EXPECT_EQ(task.join(), "unknown error");
}

// The window sleeps until an event: the comparison's end wakes it, and a frame drawn then
// must find the task finished.
TEST(BackgroundTask, WhenDoneRunsAfterTheWorkHasFinished) {
  BackgroundTask task;
  std::promise<bool> finishedWhenDone;
  task.start([](const std::atomic<bool>&) {}, [&] { finishedWhenDone.set_value(task.finished()); });
  EXPECT_TRUE(finishedWhenDone.get_future().get());
  EXPECT_EQ(task.join(), "");
}

// Run pressed again after a run ended but before a frame joined it: a std::thread assigned over
// one not joined ends the program.
TEST(BackgroundTask, StartingAgainJoinsTheWorkBeforeAndForgetsItsError) {
  BackgroundTask task;
  task.start([](const std::atomic<bool>&) { throw Error("first"); });
  task.requestStop();
  int second = 0;
  task.start([&](const std::atomic<bool>& stop) { second = stop ? -1 : 1; });
  EXPECT_EQ(task.join(), "");
  EXPECT_EQ(second, 1);  // a stop asked of the first run is not the second's
}

TEST(BackgroundTask, GoingOutOfScopeStopsTheWork) {
  std::atomic<bool> ended{false};
  {
    BackgroundTask task;
    task.start([&](const std::atomic<bool>& stop) {
      while (!stop) std::this_thread::sleep_for(1ms);
      ended = true;
    });
  }
  EXPECT_TRUE(ended);
}

}  // namespace
}  // namespace lloydscope
