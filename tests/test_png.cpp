#include "mesh.h"
#include "png.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

using namespace lloydscope;

// stb's encoder fails only where its buffers cannot be allocated: that is what the error says,
// naming the file (it said "cannot write ... (disk full?)"), and no file is left. Run in a
// child process whose address space is capped at what it uses plus 100 MB: the 64 MB copy of
// the pixels that encodePng makes fits, the encoder's 64 MB of filtered rows do not.
TEST(Png, RunningOutOfMemoryWhileEncodingIsAOneLineError) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's shadow memory does not fit under a limit on the address space";
#endif
  constexpr int kSide = 4096;
  const std::vector<unsigned char> pixels(static_cast<size_t>(kSide) * kSide * 4, 128);
  const std::string path = test::tempPath("too_large.png");
  const auto encodeUnderALimit = [&] {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = static_cast<rlim_t>(pages) * sysconf(_SC_PAGESIZE) + (rlim_t(100) << 20);
    const rlimit bound{limit, limit};
    if (setrlimit(RLIMIT_AS, &bound) != 0) std::_Exit(4);
    try {
      encodePng(path, pixels.data(), kSide, kSide, false, {0, 0, kSide, kSide});
      std::_Exit(3);  // written: the limit was not reached
    } catch (const Error& e) {
      std::fprintf(stderr, "%s\n", e.what());
      std::_Exit(std::filesystem::exists(path) ? 5 : 0);
    } catch (const std::bad_alloc&) {
      std::_Exit(2);  // the copy did not fit
    }
  };
  EXPECT_EXIT(encodeUnderALimit(), ::testing::ExitedWithCode(0),
              "too_large.png: not enough memory to encode a 4096x4096 picture as PNG");
}
