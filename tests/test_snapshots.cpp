// Recorded runs on bundled meshes, compared with committed snapshots at iterations 0, 1, 10
// and the last one. After an intended change, regenerate them with
//   LLOYDSCOPE_UPDATE_SNAPSHOTS=1 build/tests/lloydscope_tests --gtest_filter='Snapshot*'
// and explain the difference in the commit.
#include "mesh_io.h"
#include "pipeline.h"
#include "test_support.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>

using namespace lloydscope;

namespace {

constexpr double kTolerance = 1e-7;  // of the unit parameter domain

std::string snapshotText(const RemeshResult& run, const std::string& mesh) {
  const Recording& r = run.recording;
  std::ostringstream out;
  out << std::setprecision(12);
  out << "# " << mesh << ": " << r.settings << "\n";
  out << "iterations " << r.iterations.size() << " fixed " << r.fixedSites.size() << "\n";
  const int last = static_cast<int>(r.iterations.size()) - 1;
  for (int k : {0, 1, 10, last}) {
    if (k > last) continue;
    const IterationRecord& it = r.iterations[k];
    out << "iteration " << k << " energy " << it.energy << " max " << it.maxDisplacement
        << " moving " << it.fractionMoving << " sites " << it.sites.size() << "\n";
    const auto cells = r.cells(r.domain(), k, /*keepGeometry=*/false);
    for (size_t i = 0; i < it.sites.size(); ++i) {
      const Vec2& c = cells[r.fixedSites.size() + i].centroid;
      out << it.sites[i].x() << " " << it.sites[i].y() << " " << c.x() << " " << c.y() << "\n";
    }
  }
  return out.str();
}

// Compares word by word: numbers within kTolerance (relative for the energy), words exactly.
void expectMatches(const std::string& expected, const std::string& actual) {
  std::istringstream e(expected), a(actual);
  std::string we, wa;
  int word = 0;
  while (e >> we) {
    ASSERT_TRUE(a >> wa) << "snapshot has more data than the run, at word " << word;
    char* endE;
    char* endA;
    const double de = std::strtod(we.c_str(), &endE), da = std::strtod(wa.c_str(), &endA);
    if (*endE == '\0' && *endA == '\0' && !we.empty())
      ASSERT_NEAR(da, de, kTolerance * std::max(1.0, std::abs(de))) << "word " << word;
    else
      ASSERT_EQ(wa, we) << "word " << word;
    ++word;
  }
  EXPECT_FALSE(a >> wa) << "the run has more data than the snapshot";
}

void checkSnapshot(const std::string& mesh, const RemeshOptions& options, const std::string& name) {
  const RemeshResult run = remesh(readMesh(test::assetPath(mesh)).mesh, options, mesh);
  const std::string actual = snapshotText(run, mesh);
  const std::string path = std::string(LLOYDSCOPE_SOURCE_DIR) + "/tests/snapshots/" + name;
  if (std::getenv("LLOYDSCOPE_UPDATE_SNAPSHOTS")) {
    std::ofstream(path) << actual;
    GTEST_SKIP() << "snapshot written: " << path;
  }
  const std::string expected = test::readText(path);
  ASSERT_FALSE(expected.empty()) << "missing snapshot " << path;
  expectMatches(expected, actual);
}

}  // namespace

TEST(Snapshot, SphereCapDefaultSettings) {
  RemeshOptions options;
  options.measureFidelity = false;
  checkSnapshot("sphere_cap.off", options, "sphere_cap_default.txt");
}

TEST(Snapshot, SphereCapReferencePreset) {
  RemeshOptions options = referencePreset(RemeshMethod::Retriangulate);
  options.lloyd.maxIterations = 25;
  options.measureFidelity = false;
  checkSnapshot("sphere_cap.off", options, "sphere_cap_reference.txt");
}
