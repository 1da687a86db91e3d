#include "mesh_io.h"
#include "pipeline.h"
#include "test_support.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace lloydscope;

namespace {

// A short recorded run on the bundled sphere cap.
const RemeshResult& sphereCapRun() {
  static const RemeshResult result = [] {
    RemeshOptions o;
    o.lloyd.maxIterations = 12;
    o.measureFidelity = false;
    return remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "sphere_cap.off");
  }();
  return result;
}

void expectError(const std::string& path, const std::string& words) {
  try {
    loadRecording(path);
    FAIL() << "expected an error for " << path;
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace

TEST(Recording, RoundTripIsExact) {
  const Recording& r = sphereCapRun().recording;
  const std::string path = test::tempPath("roundtrip.lsrec");
  saveRecording(r, path);
  const Recording back = loadRecording(path);
  EXPECT_EQ(back.settings, r.settings);
  EXPECT_EQ(back.input.points, r.input.points);
  EXPECT_EQ(back.input.triangles, r.input.triangles);
  EXPECT_EQ(back.uv, r.uv);
  EXPECT_EQ(back.density, r.density);
  EXPECT_EQ(back.fixedSites, r.fixedSites);
  ASSERT_EQ(back.iterations.size(), r.iterations.size());
  for (size_t k = 0; k < r.iterations.size(); ++k) {
    EXPECT_EQ(back.iterations[k].sites, r.iterations[k].sites);
    EXPECT_EQ(back.iterations[k].maxDisplacement, r.iterations[k].maxDisplacement);
    EXPECT_EQ(back.iterations[k].energy, r.iterations[k].energy);
  }
}

// A chart's seams with the other charts travel with its recording; an index past the mesh is
// refused as damage, not drawn.
TEST(Recording, SharedSeamsRoundTrip) {
  Recording r = sphereCapRun().recording;
  r.sharedSeams = {{0, 1}, {1, 2}};
  const std::string path = test::tempPath("seams.lsrec");
  saveRecording(r, path);
  EXPECT_EQ(loadRecording(path).sharedSeams, r.sharedSeams);
  r.sharedSeams = {{0, r.input.vertexCount()}};
  saveRecordingUnchecked(r, path);
  expectError(path, "seam vertex is out of range");
}

// A border of fewer than 3 sites cannot be triangulated inside (it crashed the replay).
TEST(Recording, ABorderOfFewerThanThreeSitesIsRefused) {
  Recording r = sphereCapRun().recording;
  r.fixedSites.resize(2);
  const std::string path = test::tempPath("two_border_sites.lsrec");
  saveRecordingUnchecked(r, path);
  expectError(path, "fewer than 3 border sites");
}

// A file of the right size and checksum may still hold what no run records (another program
// wrote it, or it was edited): each of these crashed the replay (a segfault, a double free
// in the cells, a floating-point trap in CGAL), or made it hang (border sites 1e300 away),
// and is refused as damage.
TEST(Recording, ContentsNoRunRecordsAreRefused) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string kBadThreshold = "a threshold is not one a run takes (a distance above 0, a percentage from 0 to 100)";
  const std::string kBadDensity = "a density is negative, not a finite number or over 1e100";
  const std::string kBadMeasure = "an iteration's energy, distances, share moving or time is out of range";
  const auto replaced = [](std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from << " not in " << text;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  const std::vector<std::pair<std::function<void(Recording&)>, std::string>> edits = {
      {[](Recording& r) { r.iterations.clear(); }, "no iterations"},
      {[](Recording& r) { r.input.triangles.clear(), r.density.clear(); }, "no triangles"},
      {[&](Recording& r) { r.uv[3].x() = nan; }, "a coordinate is not a finite number"},
      {[&](Recording& r) { r.input.points[0].z() = nan; }, "a coordinate is not a finite number"},
      {[&](Recording& r) { r.fixedSites[1].y() = nan; }, "a coordinate is not a finite number"},
      {[](Recording& r) { std::fill(r.uv.begin(), r.uv.end(), Vec2(0, 0)); }, "its parameter domain has no area"},
      {[&](Recording& r) { r.density[5][1] = nan; }, kBadDensity},
      {[](Recording& r) { r.density[5][1] = -1; }, kBadDensity},
      // a centroid overflowed to NaN, and CGAL's point location stopped the inspector (SIGFPE)
      {[](Recording& r) { for (auto& corners : r.density) corners = {1e308, 1e308, 1e308}; }, kBadDensity},
      // the 3D view was empty, the smallest angle 180 degrees
      {[](Recording& r) { for (Vec3& p : r.input.points) p *= 1e300; },
       "its surface: coordinates as large as 1e+300 are beyond what can be replayed in double precision (up to 1e+30); "
       "scale the mesh down"},
      // a threshold line at 1e308 beside "Thresholds: 1e-06"; the plots' labels over each other
      {[](Recording& r) { r.distanceThreshold = 1e308; }, "its thresholds differ from its settings'"},
      {[](Recording& r) { r.percentThreshold = 50; }, "its thresholds differ from its settings'"},
      {[](Recording& r) { r.method = RemeshMethod::Relocate; }, "its method differs from its settings'"},
      {[](Recording& r) { r.iterations[0].maxDisplacement = 1e308; }, kBadMeasure},
      {[](Recording& r) { r.iterations[1].meanDisplacement = 2; }, kBadMeasure},
      {[](Recording& r) { r.iterations[1].milliseconds = 1e308; }, kBadMeasure},
      {[](Recording& r) { r.iterations[0].fractionMoving = 5e-324; },
       "an iteration's share moving is no whole number of sites"},
      // info listed it so
      {[](Recording& r) { r.iterations.back().index = -2147483647 - 1; }, "an iteration is out of order"},
      {[](Recording& r) { std::swap(r.iterations[0].index, r.iterations[1].index); }, "an iteration is out of order"},
      // Compare, with the threshold below, ran for ever
      {[&](Recording& r) { r.settings = replaced(r.settings, "max-iterations=12", "max-iterations=2147483647"); },
       "setting max-iterations=2147483647 is not an iteration count the command line takes"},
      {[&](Recording& r) { r.settings = replaced(r.settings, "sites=", "sites=-5 was="); },
       "setting sites=-5 is not a count of vertices a run records (1 to 10000000)"},
      {[&](Recording& r) { r.settings = replaced(r.settings, "sites=", "sites=2000000000 was="); },
       "setting sites=2000000000 is not a count of vertices a run records (1 to 10000000)"},
      {[](Recording& r) { r.settings += " alpha=-1"; }, "setting alpha=-1 is not a number >= 0"},
      {[&](Recording& r) { r.settings = replaced(r.settings, "polish=3", "polish=1000000"); }, "setting polish=1000000 is not from -1 to 100"},
      {[&](Recording& r) { r.distanceThreshold = nan; }, kBadThreshold},
      {[](Recording& r) { r.distanceThreshold = 0; }, kBadThreshold},
      {[](Recording& r) { r.percentThreshold = -5; }, kBadThreshold},
      {[](Recording& r) { r.percentThreshold = 200; }, kBadThreshold},
      {[](Recording& r) { r.movableVertex.pop_back(); }, "its sites' vertices are not one per site"},
      {[](Recording& r) { r.movableVertex[0] = r.input.vertexCount(); }, "a site's vertex is out of range"},
      {[](Recording& r) { r.movableVertex[0] = -2; }, "a site's vertex is out of range"},
      {[](Recording& r) { for (Vec2& p : r.uv) p.x() = -p.x(); }, "its parameter domain is not scaled to the unit square"},
      {[](Recording& r) { for (Vec2& p : r.uv) p *= 1e-150; }, "its parameter domain is not scaled to the unit square"},
      {[](Recording& r) { r.fixedSites[0] *= 1e300; }, "a border site lies outside the unit square"},
      // the replay failed on it with an error that named no file
      {[](Recording& r) { std::swap(r.fixedSites[0], r.fixedSites[r.fixedSites.size() / 2]); },
       "the border of the parameter domain crosses itself"},
      // a segfault: the border, all on one line or at one point, was triangulated (found by fuzzing)
      {[](Recording& r) { for (Vec2& p : r.fixedSites) p.y() = 0.5; },
       "the border of the parameter domain encloses no area"},
      {[](Recording& r) { std::fill(r.fixedSites.begin(), r.fixedSites.end(), Vec2(0.5, 0.5)); },
       "the border of the parameter domain encloses no area"},
      // info printed them as "nan", the plots drew what they could
      {[&](Recording& r) { r.iterations.back().energy = nan; }, kBadMeasure},
      {[](Recording& r) { r.iterations.back().fractionMoving = 2; }, kBadMeasure},
      {[](Recording& r) { std::swap(r.input.triangles[10][0], r.input.triangles[10][1]); },
       "a parameter triangle is turned over"},
      // info printed these (inspect refused the first), the escape sequence to the terminal
      {[](Recording& r) { r.settings = "method=bogus " + r.settings; }, "unknown method 'bogus' (relocate, retriangulate)"},
      {[](Recording& r) { r.settings = "param-used=nope " + r.settings; }, "unknown parameterization 'nope' (auto, authalic, conformal, mean-value, tutte, lscm)"},
      {[](Recording& r) { r.settings = "border-used=rectanglX " + r.settings; }, "unknown border 'rectanglX' (square, circle, rectangle)"},
      {[](Recording& r) { r.settings += " solver=\x1b[31mRED"; }, "its settings hold a character no run writes"}};
  const std::string path = test::tempPath("edited.lsrec");
  for (const auto& [edit, why] : edits) {
    Recording r = sphereCapRun().recording;
    edit(r);
    saveRecordingUnchecked(r, path);
    SCOPED_TRACE(why);
    expectError(path, "damaged recording (" + why + ")");
    // remesh --record and the window's Save recording write nothing a replay would refuse.
    const std::string refused = test::tempPath("never_saved.lsrec");
    try {
      saveRecording(r, refused);
      ADD_FAILURE() << "saved";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(refused + ": ", 0), 0u) << message;
      EXPECT_NE(message.find(r.iterations.empty() ? "nothing to record" : "not saved"), std::string::npos) << message;
    }
    EXPECT_FALSE(std::filesystem::exists(refused));
  }
  // Sites without an input vertex (-1) are what a run with a first pass records.
  Recording r = sphereCapRun().recording;
  std::fill(r.movableVertex.begin(), r.movableVertex.end(), -1);
  saveRecording(r, path);
  EXPECT_NO_THROW(loadRecording(path));
}

// The command line takes any distance threshold above 0, but a subnormal one (1e-310) made a
// recording that did not read back: std::stod throws on it ("is not a number").
TEST(Recording, ASubnormalThresholdReadsBack) {
  RemeshOptions o;
  o.lloyd.maxIterations = 3;
  o.lloyd.distanceThreshold = 1e-310;
  o.measureFidelity = false;
  const RemeshResult run = remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "sphere_cap.off");
  const std::string path = test::tempPath("subnormal.lsrec");
  saveRecording(run.recording, path);
  EXPECT_EQ(loadRecording(path).distanceThreshold, 1e-310);
}

// A chart's or a component's run records its own share of the vertices asked (a cube's chart:
// sites=18 of 25): read as the command line's least (20), saving it was refused as damage.
TEST(Recording, APartsShareOfTheVerticesReadsBack) {
  Recording r = sphereCapRun().recording;
  const size_t at = r.settings.find("sites="), end = r.settings.find(' ', at);
  ASSERT_NE(at, std::string::npos);
  r.settings.replace(at, end - at, "sites=18");
  const std::string path = test::tempPath("chart.lsrec");
  saveRecording(r, path);
  EXPECT_NE(loadRecording(path).settings.find("sites=18"), std::string::npos);
}

// As the window's Save recording saves it, given a mesh's name: refused, the mesh kept. So
// through a link named as a recording that leads to a mesh (run.lsrec -> mine.off).
TEST(Recording, IsNotSavedUnderAMeshsExtension) {
  const std::string mine = test::tempPath("mine.off"), link = test::tempPath("run.lsrec");
  std::remove(link.c_str());
  ASSERT_EQ(symlink(mine.c_str(), link.c_str()), 0);
  for (const std::string& path : {test::tempPath("mesh.off"), test::tempPath("mesh.PLY"), test::tempPath("mesh.obj"), link}) {
    const std::string name = path == link ? mine : path;
    test::writeText(name, "OFF\n");
    try {
      saveRecording(sphereCapRun().recording, path);
      ADD_FAILURE() << "saved as " << path;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("a recording is not saved under a mesh's extension"), std::string::npos) << e.what();
    }
    EXPECT_EQ(test::readText(name), "OFF\n");
  }
}

// The method is a byte, 0 relocate or 1 retriangulate: any other (255) read as retriangulate.
// The checksum made again, as another program's file would have it.
TEST(Recording, AMethodByteNoRunWritesIsDamaged) {
  const Recording& r = sphereCapRun().recording;
  const std::string path = test::tempPath("method.lsrec");
  saveRecording(r, path);
  std::string bytes = test::readText(path);
  const size_t header = 20, checksum = 8;  // the magic, version and size; FNV-1a of the payload
  bytes[header + 4 + r.settings.size()] = '\xff';  // after the settings' length and text
  std::uint64_t hash = 1469598103934665603ull;
  for (size_t i = header; i + checksum < bytes.size(); ++i) {
    hash ^= static_cast<unsigned char>(bytes[i]);
    hash *= 1099511628211ull;
  }
  std::memcpy(&bytes[bytes.size() - checksum], &hash, checksum);
  test::writeText(path, bytes);
  expectError(path, "damaged recording (its method is neither relocate nor retriangulate)");
}

TEST(Recording, CellsRecomputedInAnyOrderAreBitIdentical) {
  const Recording& r = sphereCapRun().recording;
  const Domain domain = r.domain();
  for (int k : {7, 0, 11, 3}) {
    const auto cells = r.cells(domain, k, /*keepGeometry=*/true);
    double energy = 0;
    for (const BoundedCell& c : cells) energy += c.energy;
    EXPECT_EQ(energy, r.iterations[k].energy) << "iteration " << k;
    // The solver's own site-to-centroid distances, bit for bit.
    double largest = 0;
    for (size_t i = 0; i < r.iterations[k].sites.size(); ++i)
      largest = std::max(largest, (cells[r.fixedSites.size() + i].centroid - r.iterations[k].sites[i]).norm());
    EXPECT_EQ(largest, r.iterations[k].maxDisplacement) << "iteration " << k;
  }
}

// A recording is told by its first bytes, whatever its name: remesh --record takes any but a
// mesh's, and recordings saved before that under a mesh's name still open.
TEST(Recording, IsToldByItsFirstBytes) {
  const std::string saved = test::tempPath("run.rec"), mesh = test::tempPath("mesh_named.lsrec"),
                    tiny = test::tempPath("tiny.rec");
  saveRecording(sphereCapRun().recording, saved);
  test::writeText(mesh, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  test::writeText(tiny, "LLO");
  EXPECT_TRUE(isRecording(saved));
  EXPECT_FALSE(isRecording(mesh));
  EXPECT_FALSE(isRecording(tiny));
  EXPECT_FALSE(isRecording(test::tempPath("none.rec")));
}

// A pipe is not looked into: its first bytes, read to tell, were gone for the mesh's reader
// (inspect on a pipe said "bad header", or waited for ever for a writer).
TEST(Recording, APipeIsLeftUnreadForItsReader) {
  const std::string saved = test::tempPath("piped.rec"), fifo = test::tempPath("pipe.lsrec");
  saveRecording(sphereCapRun().recording, saved);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0666), 0);
  std::atomic<bool> told{false};
  // Writes a recording's first bytes into the pipe once a reader opens it, until told.
  std::thread writer([&] {
    const std::string start = test::readText(saved).substr(0, 16);
    while (!told) {
      const int fd = open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // fails while no one reads
      if (fd >= 0) {
        (void)!write(fd, start.data(), start.size());
        close(fd);
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  });
  EXPECT_FALSE(isRecording(fifo));
  told = true;
  writer.join();
}

TEST(Recording, MissingFile) { expectError(test::tempPath("nope.lsrec"), "missing"); }

TEST(Recording, NotARecording) {
  const std::string path = test::tempPath("mesh.lsrec");
  test::writeText(path, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  expectError(path, "not a Lloydscope recording");
}

TEST(Recording, Truncated) {
  const std::string path = test::tempPath("cut.lsrec");
  saveRecording(sphereCapRun().recording, path);
  const std::string bytes = test::readText(path);
  for (size_t keep : {size_t(10), bytes.size() / 2, bytes.size() - 1}) {
    test::writeText(path, bytes.substr(0, keep));
    expectError(path, "truncated");
  }
}

// The header's data size set past any recording's: said so, not read as a file cut short with
// a wrapped-round expected size ("expected 19 bytes").
TEST(Recording, AHeaderOverstatingItsSizeIsDamaged) {
  const std::string path = test::tempPath("overstated.lsrec");
  saveRecording(sphereCapRun().recording, path);
  std::string bytes = test::readText(path);
  bytes.replace(12, 8, std::string(8, '\xff'));  // the size follows the magic and the version
  test::writeText(path, bytes);
  expectError(path, "damaged recording (its header gives 18446744073709551615 bytes of data, more than any recording holds)");
}

TEST(Recording, CorruptByte) {
  const std::string path = test::tempPath("corrupt.lsrec");
  saveRecording(sphereCapRun().recording, path);
  std::string bytes = test::readText(path);
  bytes[bytes.size() / 2] ^= 0x40;
  test::writeText(path, bytes);
  expectError(path, "checksum");
}

TEST(Recording, OtherVersion) {
  const std::string path = test::tempPath("v9.lsrec");
  saveRecording(sphereCapRun().recording, path);
  std::string bytes = test::readText(path);
  bytes[8] = 9;  // the version follows the 8-byte magic
  test::writeText(path, bytes);
  expectError(path, "version 9");
}

TEST(Recording, SavingReplacesTheFileWholeAndLeavesNoTemporary) {
  const std::string folder = test::emptyFolder("replace"), path = folder + "/replace.lsrec";
  test::writeText(path, "old contents");
  saveRecording(sphereCapRun().recording, path);
  EXPECT_NO_THROW(loadRecording(path));
  EXPECT_EQ(test::filesIn(folder), std::vector<std::string>{"replace.lsrec"});
}

TEST(Recording, SavingToAnUnwritablePlaceKeepsNothingHalfWritten) {
  const Recording& run = sphereCapRun().recording;
  EXPECT_THROW(saveRecording(run, test::tempPath("no-such-dir/x.lsrec")), Error);
  // A folder where the file would go: refused, nothing left of the recording (no temporary
  // beside it), and the folder stays.
  const std::string folder = test::emptyFolder("unwritable"), path = folder + "/x.lsrec";
  std::filesystem::create_directory(path);
  EXPECT_THROW(saveRecording(run, path), Error);
  EXPECT_EQ(test::filesIn(folder), std::vector<std::string>{"x.lsrec"});
  EXPECT_TRUE(std::filesystem::is_directory(path));
  // A device full at once: an error, not "saved".
  EXPECT_THROW(saveRecording(run, "/dev/full"), Error);
}

TEST(Recording, RelaxAgainWithAnotherSolverStartsWhereTheRunStarted) {
  RemeshOptions o;
  o.measureFidelity = false;
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  const Recording r = remesh(input, o, "cap").recording;
  LloydOptions lloyd;
  lloyd.solver = CvtSolver::Lloyd;
  lloyd.maxIterations = 30;
  const std::vector<IterationRecord> again = relaxAgain(r, lloyd);
  ASSERT_EQ(again.size(), 30u);  // plain Lloyd is far from converged after 30
  EXPECT_EQ(again.front().sites, r.iterations.front().sites);
  EXPECT_DOUBLE_EQ(again.front().energy, r.iterations.front().energy);
  for (size_t k = 1; k < again.size(); ++k) EXPECT_LE(again[k].energy, again[k - 1].energy + 1e-15);
  // The run's own L-BFGS, to convergence, ends lower than 30 iterations of Lloyd's.
  EXPECT_LT(r.iterations.back().energy, again.back().energy);
}

// The inspector's Compare button relaxes on a thread of its own, and stops it when the run on
// show changes.
TEST(Recording, RelaxAgainStopsWhenAskedFromAnotherThread) {
  RemeshOptions o;
  o.measureFidelity = false;
  const Recording r = remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "cap").recording;
  LloydOptions never;  // plain Lloyd to a threshold it never meets
  never.solver = CvtSolver::Lloyd;
  never.distanceThreshold = 1e-300;
  never.maxIterations = 100000;
  std::atomic<bool> stop{true};
  EXPECT_TRUE(relaxAgain(r, never, &stop).empty());
  stop = false;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    stop = true;
  });
  const size_t iterations = relaxAgain(r, never, &stop).size();
  stopper.join();
  EXPECT_GT(iterations, 0u);
  EXPECT_LT(iterations, 100000u);
}
