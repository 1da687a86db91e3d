// How much memory operations take beyond what they are given: operator new is replaced here
// (this executable alone, lloydscope_memory_tests) by one that counts the bytes it holds while
// counting is on, and the most it held.
#include "mesh_io.h"
#include "pipeline.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstdio>
#include <new>

namespace {

std::atomic<bool> counting{false};
std::atomic<long long> held{0}, most{0};

// Each block starts with its size and whether it was counted: a block made before counting
// began and freed during it is not taken off.
constexpr std::size_t kHeader = 16;
struct BlockHeader {
  std::size_t size;
  bool counted;
};

void* allocate(std::size_t n) {
  void* block = std::malloc(n + kHeader);
  if (!block) throw std::bad_alloc();
  auto* header = static_cast<BlockHeader*>(block);
  header->size = n;
  header->counted = counting;
  if (header->counted) {
    const long long now = held += static_cast<long long>(n);
    long long seen = most;
    while (now > seen && !most.compare_exchange_weak(seen, now)) {
    }
  }
  return static_cast<char*>(block) + kHeader;
}

void release(void* p) noexcept {
  if (!p) return;
  auto* header = reinterpret_cast<BlockHeader*>(static_cast<char*>(p) - kHeader);
  if (header->counted) held -= static_cast<long long>(header->size);
  std::free(header);
}

// The most bytes `work` held at once beyond what was held before it.
template <class Work>
long long peakBytesOf(Work work) {
  held = 0;
  most = 0;
  counting = true;
  work();
  counting = false;
  return most;
}

}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  try {
    return allocate(n);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t n, const std::nothrow_t& t) noexcept { return operator new(n, t); }
void operator delete(void* p) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }

using namespace lloydscope;

// Saving a recording takes one copy of the file's bytes, and no more: it took 4.9 times them
// (the bytes grown by doubling, copied again behind the header, and the recording read back
// from them whole to check it).
TEST(Memory, SavingARecordingHoldsOneCopyOfItsBytesAtMost) {
  RemeshOptions o;
  o.lloyd.maxIterations = 4;
  o.measureFidelity = false;
  Recording recording =
      remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "sphere_cap.off").recording;
  // Iterations enough for their sites to be nearly all of it (about 8 MB).
  const std::vector<IterationRecord> run = recording.iterations;
  while (recording.iterations.size() * run.front().sites.size() < 1000000)
    recording.iterations.insert(recording.iterations.end(), run.begin(), run.end());
  for (size_t k = 0; k < recording.iterations.size(); ++k) recording.iterations[k].index = static_cast<int>(k);  // as a run numbers them
  const std::string path = test::tempPath("memory.lsrec");
  const long long peak = peakBytesOf([&] { saveRecording(recording, path); });
  const long long fileBytes = static_cast<long long>(test::readText(path).size());
  EXPECT_GT(fileBytes, 8000000);
  EXPECT_LT(peak, 1.25 * fileBytes) << "peak " << peak << " bytes for a file of " << fileBytes;
  EXPECT_EQ(loadRecording(path).iterations.size(), recording.iterations.size());
  std::remove(path.c_str());
}
