#include "frame_pacing.h"

#include <gtest/gtest.h>

namespace lloydscope {
namespace {

KeyEvent press(int key) { return {key, 0, KeyAction::Press, 0}; }
KeyEvent release(int key) { return {key, 0, KeyAction::Release, 0}; }

std::vector<std::pair<int, KeyAction>> keysOf(const std::vector<KeyEvent>& events) {
  std::vector<std::pair<int, KeyAction>> keys;
  for (const KeyEvent& e : events) keys.emplace_back(e.key, e.action);
  return keys;
}

using Keys = std::vector<std::pair<int, KeyAction>>;

TEST(KeyQueue, ATapBetweenTwoFramesIsSeenPressedThenReleased) {
  KeyQueue queue;
  queue.push(press(262));
  queue.push(release(262));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Press}}));
  EXPECT_FALSE(queue.empty());
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Release}}));
  EXPECT_TRUE(queue.empty());
  EXPECT_TRUE(queue.takeFrame().empty());
}

TEST(KeyQueue, AModifierIsStillHeldWhenTheKeyItChangesIsSeen) {
  // Shift+Right tapped between two frames: the frame that sees Right pressed sees Shift held.
  KeyQueue queue;
  for (const KeyEvent& e : {press(340), press(262), release(262), release(340)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{340, KeyAction::Press}, {262, KeyAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Release}, {340, KeyAction::Release}}));
}

TEST(KeyQueue, TwoTapsOfOneKeyTakeFourFrames) {
  KeyQueue queue;
  for (const KeyEvent& e : {press(32), release(32), press(32), release(32)}) queue.push(e);
  int frames = 0, presses = 0;
  while (!queue.empty()) {
    ++frames;
    for (const KeyEvent& e : queue.takeFrame()) presses += e.action == KeyAction::Press;
  }
  EXPECT_EQ(frames, 4);  // press | release | press | release: each frame sees the key change
  // once, so ImGui sees the second press too
  EXPECT_EQ(presses, 2);
}

TEST(KeyQueue, ATapArrivingWhileTheLastOneIsReleasedWaitsForTheNextFrame) {
  // The first press was seen by an earlier frame; its release and the next press arrive
  // together: one frame sees the key up, the next sees it down again.
  KeyQueue queue;
  queue.push(press(262));
  queue.takeFrame();
  for (const KeyEvent& e : {release(262), press(262), release(262)}) queue.push(e);
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Release}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Press}}));
  EXPECT_EQ(keysOf(queue.takeFrame()), (Keys{{262, KeyAction::Release}}));
}

TEST(KeyQueue, AReleaseOfAKeyPressedEarlierAndRepeatsPassAtOnce) {
  KeyQueue queue;
  queue.push(press(65));
  EXPECT_EQ(queue.takeFrame().size(), 1u);
  queue.push({65, 0, KeyAction::Repeat, 0});
  queue.push({65, 0, KeyAction::Repeat, 0});
  queue.push(release(65));
  EXPECT_EQ(queue.takeFrame().size(), 3u);
  EXPECT_TRUE(queue.empty());
}

TEST(FramePacer, DrawsWhileBusyAndAFewFramesAfterInputThenWaits) {
  FramePacer pacer;
  for (int k = 0; k < FramePacer::kSettleFrames; ++k) EXPECT_EQ(pacer.wait(false), 0);
  EXPECT_EQ(pacer.wait(false), FramePacer::kIdleWaitSeconds);
  EXPECT_EQ(pacer.wait(true), 0);
  EXPECT_EQ(pacer.wait(false), FramePacer::kIdleWaitSeconds);
  pacer.input();
  for (int k = 0; k < FramePacer::kSettleFrames; ++k) EXPECT_EQ(pacer.wait(false), 0);
  EXPECT_GT(pacer.wait(false), 0);
}

}  // namespace
}  // namespace lloydscope
