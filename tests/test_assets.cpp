#include "test_support.h"

#include <cstdlib>

using namespace lloydscope;

// The committed meshes are exactly what the committed generator makes.
TEST(Assets, GeneratorReproducesTheCommittedMeshes) {
  const std::string folder = test::tempPath("assets");
  ASSERT_EQ(std::system(("mkdir -p " + folder + " && " + LLOYDSCOPE_MAKE_ASSETS + " " + folder).c_str()), 0);
  for (const char* name : {"bumpy_disk.off", "sphere_cap.off", "jittered_grid.off"}) {
    const std::string committed = test::readText(test::assetPath(name));
    ASSERT_FALSE(committed.empty()) << name;
    EXPECT_TRUE(committed == test::readText(folder + "/" + name)) << name << " differs";
  }
}
