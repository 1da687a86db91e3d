// The command line as a user meets it: exit codes, one-line errors, JSON, files left alone.
#include "lloyd.h"
#include "mesh_io.h"
#include "report.h"
#include "ring_moves.h"
#include "topology.h"
#include "test_support.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>
#include <sys/wait.h>
#include <thread>

using namespace lloydscope;

namespace {

struct CliRun {
  int code;
  std::string out, err;
};

CliRun runCli(const std::string& args) {
  const std::string out = test::tempPath("cli.out"), err = test::tempPath("cli.err");
  const int status = std::system((std::string(LLOYDSCOPE_CLI) + " " + args + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::readText(out), test::readText(err)};
}

// Exits with 1 (an Error, not a crash or an internal error) and one line naming the file.
void expectCleanFailure(const std::string& file, const std::string& contents,
                        const std::string& words) {
  const std::string path = test::tempPath(file);
  test::writeText(path, contents);
  const CliRun r = runCli("remesh " + path + " -o " + test::tempPath("never.off"));
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
}

const char* kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";

// A markdown row's cells, trimmed ([0] is before the first |).
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, '|');) {
    const size_t first = cell.find_first_not_of(' ');
    out.push_back(first == std::string::npos ? "" : cell.substr(first, cell.find_last_not_of(' ') - first + 1));
  }
  return out;
}

// The first line of `text` from `from` on that starts with `start` (empty: none).
std::string lineStarting(const std::string& text, const std::string& start, size_t from = 0) {
  const size_t at = text.find(start, from);
  return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
}

}  // namespace

// A mesh the loader reads (coordinates up to 1e150) but double precision cannot measure or
// simplify: refused in one line naming it. Its distance to itself raised a floating-point trap
// in GMP (exit 136); its angles (at 1e78 and up) all read 90 degrees, and simplify collapsed
// nothing and wrote it back as read, both with exit 0.
TEST(Cli, ABeyondDoublePrecisionMeshIsRefused) {
  const std::string path = test::tempPath("huge.off");
  test::writeText(path, "OFF\n4 2 0\n0 0 0\n1e149 0 0\n0 1e149 0\n1e149 1e149 1e148\n3 0 1 2\n3 1 3 2\n");
  for (const std::string& command : {"metrics " + path, "metrics " + path + " --reference " + path,
                                     "simplify " + path + " -o " + test::tempPath("never.off") + " --vertices 3"}) {
    const CliRun r = runCli(command);
    EXPECT_EQ(r.code, 1) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(path + ": coordinates as large as 1e+149 are beyond what can be"), std::string::npos) << r.err;
  }
  // At unit scale the same square's angles are 45 and 90 degrees.
  test::writeText(path, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n");
  const CliRun unit = runCli("metrics " + path + " --json");
  ASSERT_EQ(unit.code, 0) << unit.err;
  EXPECT_NEAR(nlohmann::json::parse(unit.out)["min_angle_deg"].get<double>(), 45.0, 1e-9);
}

// CGAL's mannequin is a nearly closed disk: remeshed both slit open and whole, and the report
// says which it kept; --no-slit keeps it whole without trying, and the settings line says so.
TEST(Cli, NoSlitKeepsANearlyClosedDiskWhole) {
  const std::string path = test::cgalSample("mannequin-devil.off");
  SKIP_UNLESS_EXTRACTED(path);
  const CliRun both = runCli("remesh " + path + " --simplify 300 --no-fidelity");
  ASSERT_EQ(both.code, 0) << both.err;
  EXPECT_NE(both.out.find("(remeshed both slit open and whole: its map to a disk shrinks part of it"), std::string::npos) << both.out;
  EXPECT_EQ(both.out.find("slit-disks"), std::string::npos) << both.out;
  const CliRun whole = runCli("remesh " + path + " --simplify 300 --no-fidelity --no-slit");
  ASSERT_EQ(whole.code, 0) << whole.err;
  EXPECT_NE(whole.out.find(" slit-disks=no"), std::string::npos) << whole.out;
  EXPECT_EQ(whole.out.find("remeshed both"), std::string::npos) << whole.out;
  EXPECT_EQ(whole.out.find("Cut open"), std::string::npos) << whole.out;
}

// What a command prints is its output (metrics, info, --json): where the standard output cannot
// take it (a full disk, a closed stream) that is said, with exit code 1, not 0 with nothing written.
TEST(Cli, AStandardOutputThatCannotBeWrittenIsAnError) {
  for (const std::string redirect : {">/dev/full", ">&-"}) {
    const std::string err = test::tempPath("cli.err");
    const int status = std::system((std::string(LLOYDSCOPE_CLI) + " metrics " + test::assetPath("bumpy_disk.off") +
                                    " " + redirect + " 2>" + err)
                                       .c_str());
    EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1) << redirect;
    EXPECT_EQ(test::readText(err),
              "lloydscope: the standard output could not be written (a full disk, or a closed stream)\n")
        << redirect;
  }
  EXPECT_EQ(runCli("metrics " + test::assetPath("bumpy_disk.off")).code, 0);
}

// A fan of 1200 triangles around one vertex (a CAD disk's hub, or a 1200-gon an OBJ reader fans
// out): simplifying it takes time cubic in that (a hub of 3000: half a minute, printing
// nothing, and it looked hung). simplify and remesh --simplify say so first; a mesh without a
// hub gets no such note.
TEST(Cli, ASimplificationAroundAHubSaysItIsSlow) {
  const Mesh hub = test::polarDisk(1200, 2);
  const std::string in = test::tempPath("hub.off");
  writeMesh(hub, in);
  const std::string note = "note: " + in + ": one vertex has 1200 triangles around it, and simplifying takes time "
                           "cubic in that number (seconds at 1000, half a minute at 3000)\n";
  CliRun r = runCli("simplify " + in + " --ratio 0.999 -o " + test::tempPath("hub_out.off"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, note);
  r = runCli("remesh " + in + " --simplify 2390 --sites 100 --max-iterations 2 --no-fidelity -o " +
             test::tempPath("hub_remeshed.off"));
  EXPECT_EQ(r.err.rfind(note, 0), 0u) << r.err;
  r = runCli("simplify " + in + " --ratio 1 -o " + test::tempPath("hub_same.off"));  // nothing to collapse
  EXPECT_EQ(r.err, "");
  r = runCli("simplify " + test::assetPath("bumpy_disk.off") + " --ratio 0.5 -o " + test::tempPath("bumpy_out.off"));
  EXPECT_EQ(r.err, "");
}

// --no-snap leaves the snaps to tips out: on a spike the result cuts off, the distance stays.
TEST(Cli, NoSnapLeavesTheTipsAlone) {
  Mesh spike = test::grid(40);
  spike.points[20 * 41 + 20].z() = 0.3;
  const std::string in = test::tempPath("spike.off"), out = test::tempPath("spike_out.off");
  writeMesh(spike, in);
  auto run = [&](const std::string& extra) {
    const CliRun r = runCli("remesh " + in + " -o " + out + " --sites 100 --json" + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto snapped = run(""), unsnapped = run(" --no-snap");
  EXPECT_GE(snapped["snapped_tips"].get<int>(), 1);
  EXPECT_EQ(unsnapped["snapped_tips"].get<int>(), 0);
  EXPECT_FALSE(unsnapped["settings"]["snap"].get<bool>());
  EXPECT_LT(snapped["output"]["fidelity"]["hausdorff_percent_diagonal"].get<double>(),
            unsnapped["output"]["fidelity"]["hausdorff_percent_diagonal"].get<double>());
}

TEST(Cli, NoFitLeavesTheVerticesOnTheInput) {
  auto run = [&](const std::string& extra) {
    const CliRun r = runCli("remesh " + test::assetPath("bumpy_disk.off") + " --sites 300 --json" + extra);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out);
  };
  const auto fitted = run(""), unfitted = run(" --no-fit");
  EXPECT_TRUE(fitted["settings"]["fit"].get<bool>());
  EXPECT_FALSE(unfitted["settings"]["fit"].get<bool>());
  EXPECT_GT(fitted["fit"]["vertices_moved"].get<int>(), 100);
  EXPECT_GT(fitted["fit"]["border_vertices_moved"].get<int>(), 10);  // the bumpy disk's circle
  EXPECT_EQ(unfitted["fit"]["vertices_moved"].get<int>(), 0);
  EXPECT_EQ(unfitted["fit"]["border_vertices_moved"].get<int>(), 0);
  const CliRun text = runCli("remesh " + test::assetPath("bumpy_disk.off") + " --sites 300 --no-fidelity");
  const int border = fitted["fit"]["border_vertices_moved"].get<int>();
  EXPECT_NE(text.out.find("Fitted to the input: " + std::to_string(fitted["fit"]["vertices_moved"].get<int>() - border) +
                          " vertices moved along their normals, " + std::to_string(border) + " on the border across it"),
            std::string::npos) << text.out;
  EXPECT_LT(fitted["output"]["fidelity"]["rms_percent_diagonal"].get<double>(),
            unfitted["output"]["fidelity"]["rms_percent_diagonal"].get<double>());
}

// An input with more than 10 vertices per vertex asked is simplified first; --full-input keeps it.
TEST(Cli, FullInputKeepsALargeInputAsItIs) {
  for (const std::string extra : {"", " --full-input"}) {
    const CliRun r = runCli("remesh " + test::assetPath("bumpy_disk.off") + " --sites 60 --no-fidelity --json" + extra);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["coarse_input_vertices"], extra.empty() ? 600 : 0) << extra;
  }
}

// Fewer than 20 vertices asked is a one-line error naming the option (a handful of border
// samples crashed the triangulation, or left an empty result); so are over a million, and over
// 100 polish passes (2,000,000 sites and 1,000,000 passes were taken, to run for hours). --sites
// says so in the help (it said ">= 1").
TEST(Cli, TooFewVerticesAskedIsAnError) {
  const std::string path = test::assetPath("bumpy_disk.off");
  for (const auto& [asked, why] : std::vector<std::pair<std::string, std::string>>{
           {"--sites 2", "--sites: expected a whole number from 20 to 1000000, not '2'"},
           {"--sites 19", "--sites: expected a whole number from 20 to 1000000, not '19'"},
           {"--sites 2000000", "--sites: expected a whole number from 20 to 1000000, not '2000000'"},
           {"--simplify 5", "--simplify: expected a whole number from 20 to 1000000, not '5'"},
           {"--simplify -5", "--simplify: expected a whole number from 20 to 1000000, not '-5'"},
           {"--polish 1000000", "--polish: expected a whole number from -1 to 100, not '1000000'"}}) {
    const CliRun r = runCli("remesh " + path + " " + asked + " -o " + test::tempPath("never.off"));
    EXPECT_EQ(r.code, 1) << asked << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
  }
  EXPECT_NE(runCli("remesh --help").out.find("--sites INT:20..1000000"), std::string::npos);
  EXPECT_EQ(runCli("remesh " + path + " --sites 20 --no-fidelity -o " + test::tempPath("twenty.off")).code, 0);
}

// --no-fit's help said every vertex stays "on the input"; where the input was simplified first
// the vertices the last steps leave alone are on the simplification (the lion simplified to 500
// and remeshed at 1000: up to 0.86% of its diagonal from the input).
TEST(Cli, TheNoFitHelpSaysTheVerticesMayBeOnTheSimplification) {
  const std::string help = runCli("remesh --help").out;
  const size_t at = help.find("--no-fit");
  ASSERT_NE(at, std::string::npos);
  const std::string noFit = help.substr(at, help.find("\n  -", at + 1) - at);
  EXPECT_NE(noFit.find("on that simplification"), std::string::npos) << noFit;
}

// The JSON's settings are the text report's settings line, every key of it: "sites" read 0 for
// "as many as the input" and for relocate's input vertices, and resample, the polish's target
// and the slits were left out. A recording's summary has the same object.
TEST(Cli, TheJsonSettingsAreTheSettingsLine) {
  const std::string grid = test::assetPath("jittered_grid.off"), rec = test::tempPath("settings.lsrec");
  auto settings = [&](const std::string& command) {
    const CliRun r = runCli(command);
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["settings"];
  };
  const auto relocated = settings("remesh " + grid + " --method relocate --no-fidelity --json");
  EXPECT_EQ(relocated["sites"], "input-vertices");
  EXPECT_EQ(relocated["resample"], false);
  EXPECT_FALSE(relocated.contains("fit"));  // relocate has no fit
  const auto retriangulated =
      settings("remesh " + grid + " --no-fidelity --no-slit --max-iterations 3 --record " + rec + " --json");
  EXPECT_EQ(retriangulated["sites"], "as-many-as-input");
  EXPECT_EQ(retriangulated["resample"], true);
  EXPECT_EQ(retriangulated["polish_target"], "centroid");
  EXPECT_EQ(retriangulated["slit_disks"], false);
  EXPECT_EQ(retriangulated["max_iterations"], 3);
  EXPECT_EQ(retriangulated["distance_threshold"], 1e-6);
  EXPECT_EQ(retriangulated["param_used"], "lscm");
  const auto recorded = settings("info " + rec + " --json");
  for (const auto& [key, value] : retriangulated.items()) EXPECT_EQ(recorded[key], value) << key;
}

TEST(Cli, TheCurvatureDensitysFloorIsAnOption) {
  const CliRun r = runCli("remesh " + test::assetPath("jittered_grid.off") +
                          " --density curvature --floor 4 --max-iterations 2 --no-fidelity --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["settings"]["floor"], 4.0);
}

TEST(Cli, RemeshJsonReportsBothTablesAndWritesTheMesh) {
  const std::string out = test::tempPath("grid_out.ply");
  const std::string rec = test::tempPath("grid.lsrec");
  const CliRun r = runCli("remesh " + test::assetPath("jittered_grid.off") + " -o " + out +
                           " --record " + rec + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_EQ(j["input"]["vertices"], 441);
  EXPECT_GT(j["output"]["avg_min_angle_deg"].get<double>(), 50.0);
  const double hausdorff = j["output"]["fidelity"]["hausdorff_percent_diagonal"].get<double>();
  EXPECT_GT(hausdorff, 0.0);  // a remeshed grid of 441 vertices is not its input
  EXPECT_LT(hausdorff, 5.0);
  EXPECT_EQ(j["output"]["fidelity"]["farthest_point"].size(), 3u);
  EXPECT_EQ(j["snapped_tips"].get<int>(), 0);  // a flat grid has no tip to snap to
  EXPECT_TRUE(j["output"]["fidelity"]["farthest_on"] == "input" ||
              j["output"]["fidelity"]["farthest_on"] == "output");
  for (const char* stage : {"parameterize", "density", "lloyd", "remesh", "metrics", "total"})
    EXPECT_TRUE(j["milliseconds"].contains(stage)) << stage;
  // Not measured: null, where it read as a perfect fit (0%, 0 samples).
  const CliRun unmeasured = runCli("remesh " + test::assetPath("jittered_grid.off") + " --no-fidelity --json");
  ASSERT_EQ(unmeasured.code, 0) << unmeasured.err;
  EXPECT_TRUE(nlohmann::json::parse(unmeasured.out)["output"]["fidelity"].is_null()) << unmeasured.out;
  EXPECT_EQ(j["settings"]["param"], "auto");
  EXPECT_EQ(j["settings"]["param_used"], "lscm");

  const CliRun metrics = runCli("metrics " + out + " --reference " +
                                 test::assetPath("jittered_grid.off") + " --json");
  ASSERT_EQ(metrics.code, 0) << metrics.err;
  EXPECT_EQ(nlohmann::json::parse(metrics.out)["faces"], j["output"]["faces"]);

  const CliRun info = runCli("info " + rec + " --json");
  ASSERT_EQ(info.code, 0) << info.err;
  const auto summary = nlohmann::json::parse(info.out);
  EXPECT_EQ(summary["iterations"].size(), j["iterations"].get<size_t>());
  // What each iteration's figures are: a site's distance to its centroid (named a displacement,
  // which for L-BFGS and Newton it is not), of the movable sites only.
  EXPECT_TRUE(summary["iterations"][0].contains("max_site_centroid_distance")) << info.out;
  EXPECT_NE(runCli("info " + rec).out.find(" movable (the distances and % moving below are theirs)"), std::string::npos);
  // The recording holds the mesh the map is of: here the input's rough first remeshing, not
  // the input, which it was called (the bumpy disk's: 1899 faces, the input's 1908).
  EXPECT_TRUE(summary.contains("parameterized_faces"));
  EXPECT_FALSE(summary.contains("input_faces"));
  EXPECT_EQ(runCli("info " + rec).out.find("Input:"), std::string::npos);
}

TEST(Cli, ReferencePresetPrintsTheTable) {
  const CliRun r = runCli("remesh " + test::assetPath("jittered_grid.off") +
                           " --preset reference --max-iterations 5");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("param=authalic border=square density=uniform"), std::string::npos);
  EXPECT_NE(r.out.find("Avg. min angle"), std::string::npos);
  EXPECT_NE(r.out.find("Irregularity"), std::string::npos);
}

TEST(Cli, MissingFile) {
  const CliRun r = runCli("remesh /no/such/mesh.off -o x.off");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("/no/such/mesh.off"), std::string::npos) << r.err;
}

TEST(Cli, Garbage) { expectCleanFailure("garbage.off", "\x01\x02garbage\xff\n", "bad header"); }
TEST(Cli, Empty) { expectCleanFailure("empty.obj", "", "empty"); }
TEST(Cli, Truncated) { expectCleanFailure("cut.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n", "truncated"); }
TEST(Cli, NaN) {
  expectCleanFailure("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "non-finite");
}
TEST(Cli, IndexOutOfRange) {
  expectCleanFailure("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "vertex 7");
}
TEST(Cli, Degenerate) {
  expectCleanFailure("flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n", "zero area");
}
// A gently curved 9 x 9 grid whose right half has its own copies of the middle column: a seam
// left unwelded. Refused, with the way out named; read with --repair, and remeshed.
TEST(Cli, RepairWeldsAnUnweldedSeamAndSaysSo) {
  const int n = 9;
  std::string off = "OFF\n" + std::to_string(n * n + n) + " " + std::to_string(2 * (n - 1) * (n - 1)) + " 0\n";
  const auto point = [&](int i, int j) {
    const double x = i / double(n - 1), y = j / double(n - 1);
    return std::to_string(x) + " " + std::to_string(y) + " " + std::to_string(0.2 * x * y) + "\n";
  };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) off += point(i, j);
  for (int j = 0; j < n; ++j) off += point(n / 2, j);  // the copies, n * n + j
  const auto index = [&](int i, int j, bool right) { return (right && i == n / 2) ? n * n + j : j * n + i; };
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const bool right = i >= n / 2;
      const int a = index(i, j, right), b = index(i + 1, j, right), c = index(i + 1, j + 1, right),
                d = index(i, j + 1, right);
      off += "3 " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\n3 " +
             std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
    }
  const std::string path = test::tempPath("seam.off");
  test::writeText(path, off);
  const CliRun refused = runCli("remesh " + path + " --sites 60 --no-fidelity");
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("on a border (an unwelded seam, a crack, or the border touching itself at a point) (--repair fixes this)"), std::string::npos) << refused.err;
  const CliRun repaired = runCli("remesh " + path + " --sites 60 --no-fidelity --repair");
  ASSERT_EQ(repaired.code, 0) << repaired.err;
  EXPECT_NE(repaired.err.find("note: " + path + ": repaired: 9 vertices welded to another at the same position"),
            std::string::npos) << repaired.err;
  EXPECT_NE(repaired.out.find("|         81 |         60 |"), std::string::npos) << repaired.out;
}

TEST(Cli, DuplicateVertices) {
  expectCleanFailure("dup.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n3 0 1 2\n3 1 3 2\n",
                     "same position");
}
TEST(Cli, NonManifoldEdge) {
  expectCleanFailure("fin.off",
                     "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
                     "shared by 3 faces");
}
// A closed surface is cut open and stitched again (core/cut); four triangles are too few for
// that to hold, and the failure says so instead of writing a broken mesh.
// A tetrahedron cut open along two edges: its few sites left an inside vertex joined to two
// copies of one seam sample, one edge of four triangles once stitched, and it was refused
// ("did not stitch back") until the polish split such edges. Now it comes back closed.
TEST(Cli, ATetrahedronIsCutAndStitchedBackClosed) {
  const std::string path = test::tempPath("tet.off"), out = test::tempPath("tet_out.off");
  test::writeText(path, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  const CliRun r = runCli("remesh " + path + " -o " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const Mesh result = readMesh(out).mesh;
  EXPECT_NO_THROW(validateMesh(result, out));
  const Topology t = analyzeTopology(result);
  EXPECT_EQ(t.genus, 0);
  EXPECT_TRUE(t.boundaryLoops.empty());
}
// Two components are remeshed each on its own, and the report says so (it was refused).
TEST(Cli, TwoComponentsAreRemeshedEachOnItsOwn) {
  const std::string path = test::tempPath("two.off"), out = test::tempPath("two_out.off");
  test::writeText(path, "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n");
  const CliRun r = runCli("remesh " + path + " -o " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Remeshed 2 of 2 connected components, each on its own"), std::string::npos) << r.out;
  EXPECT_EQ(analyzeTopology(readMesh(out).mesh).components, 2);
  const CliRun json = runCli("remesh " + path + " --json");
  ASSERT_EQ(json.code, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["components"], 2);
  // Its recording is of one of them, and says so wherever it is read (info gave its settings
  // as the run's, its iterations as all of them).
  const std::string rec = test::tempPath("two.lsrec");
  ASSERT_EQ(runCli("remesh " + path + " --no-fidelity --record " + rec).code, 0);
  const CliRun info = runCli("info " + rec);
  EXPECT_NE(info.out.find("\nThe iterations are of one part of the run, the largest: component 1 of 2\n"), std::string::npos)
      << info.out;
  EXPECT_EQ(nlohmann::json::parse(runCli("info " + rec + " --json").out)["settings"]["part"], "component-1-of-2");
}

TEST(Cli, TruncatedRecording) {
  const std::string rec = test::tempPath("cli_cut.lsrec");
  ASSERT_EQ(runCli("remesh " + test::assetPath("jittered_grid.off") +
                       " --max-iterations 3 --no-fidelity --record " + rec).code, 0);
  const std::string bytes = test::readText(rec);
  test::writeText(rec, bytes.substr(0, bytes.size() - 100));
  const CliRun r = runCli("info " + rec);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  // Its name told in any case, as a mesh's is: inspect said that a damaged x.LSREC, cut before
  // its first bytes, was "a recording, not a mesh" and to open it with inspect.
  const std::string upper = test::tempPath("cli_cut.LSREC");
  test::writeText(upper, bytes.substr(0, 4));
  const CliRun inspected = runCli("inspect " + upper + " --screenshot " + test::tempPath("never.png"));
  EXPECT_EQ(inspected.code, 1);
  EXPECT_EQ(inspected.err, "lloydscope: " + upper + ": not a Lloydscope recording\n");
  // Under a name of the user's own (--record takes any but a mesh's), cut before its first
  // bytes: it was "unknown extension '.rec' (expected .off, .obj or .ply)".
  const std::string own = test::tempPath("cli_cut.rec");
  test::writeText(own, bytes.substr(0, 4));
  const CliRun ownName = runCli("inspect " + own + " --screenshot " + test::tempPath("never.png"));
  EXPECT_EQ(ownName.code, 1);
  EXPECT_EQ(ownName.err, "lloydscope: " + own +
                             ": neither a mesh (.off, .obj or .ply) nor a Lloydscope recording (its first bytes are "
                             "not a recording's: another file, or a recording cut short or damaged)\n");
}

// A recording replays its own run: an option that would remesh is refused, in one line naming
// it (inspect cap.lsrec --solver newton drew the L-BFGS run in Newton's colour, labelled newton),
// as is --final, which it cannot show (it was ignored, exit 0).
TEST(Cli, ARecordingRefusesRemeshingOptions) {
  const std::string rec = test::tempPath("cli_options.lsrec");
  ASSERT_EQ(runCli("remesh " + test::assetPath("jittered_grid.off") + " --max-iterations 3 --no-fidelity --record " + rec).code, 0);
  for (const std::string option : {"--solver newton", "--density uniform", "--distance-threshold 1e-3", "--polish 0", "--final"}) {
    const CliRun r = runCli("inspect " + rec + " " + option + " --screenshot " + test::tempPath("never.png"));
    EXPECT_EQ(r.code, 1) << option;
    EXPECT_EQ(r.err.rfind("lloydscope: " + rec + ": " + option.substr(0, option.find(' ')) + " applies to a mesh", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // Refused before they are read: the notes of options without effect came first, and an
  // unknown value's error instead.
  for (const std::string options : {"--method relocate --polish 2 --no-fit", "--param bogus", "--density uniform --alpha 2"}) {
    const CliRun r = runCli("inspect " + rec + " " + options + " --screenshot " + test::tempPath("never.png"));
    EXPECT_EQ(r.code, 1) << options;
    EXPECT_NE(r.err.find(" applies to a mesh"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_EQ(runCli("inspect " + rec + " --iteration 1 --screenshot " + test::tempPath("fine.png")).code, 0);
}

// A mesh of parts each too small for its share of the vertices asked is kept as it is, and no
// iteration is run: inspect and bench-frames crashed on it (a segfault), and remesh
// --record saved a recording that info then refused as damaged.
TEST(Cli, ARunWithoutIterationsIsNeitherShownNorRecorded) {
  const std::string mesh = test::tempPath("two_triangles.off"), rec = test::tempPath("none.lsrec"),
                    out = test::tempPath("none_out.off");
  test::writeText(mesh, "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0\n4 0 0\n3 1 0\n3 0 1 2\n3 3 4 5\n");
  for (const std::string command : {"inspect " + mesh + " --sites 20 --screenshot " + test::tempPath("none.png"),
                                    "bench-frames " + mesh + " --sites 20 --frames 2",
                                    "remesh " + mesh + " --sites 20 --record " + rec + " -o " + out}) {
    const CliRun r = runCli(command);
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_NE(r.err.find(": no iteration was run ("), std::string::npos) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(rec));
  EXPECT_FALSE(std::filesystem::exists(out));  // the output and the recording: both or neither
  EXPECT_EQ(runCli("remesh " + mesh + " --sites 20 -o " + out).code, 0);  // without --record, as before
}

// --record onto the input or the output replaced it with a recording (exit 0), as did bench's
// --csv onto an input, and remesh's and simplify's -o onto the input (exit 0); a folder given
// as a recording was an "internal error" (exit 2); a recording that could not be written failed
// the run after the output was replaced.
TEST(Cli, ARecordingNeitherReplacesTheInputNorTheOutputNorReadsAFolder) {
  const std::string mesh = test::tempPath("keep_me.off"), out = test::tempPath("keep_out.off");
  test::writeText(mesh, test::readText(test::assetPath("jittered_grid.off")));
  test::writeText(out, kTriangle);
  CliRun r = runCli("remesh " + mesh + " --max-iterations 2 -o " + mesh);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh + ": --output would replace the input mesh; give it another name\n");
  r = runCli("simplify " + mesh + " --ratio 0.5 -o " + mesh);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh + ": --output would replace the input mesh; give it another name\n");
  r = runCli("remesh " + mesh + " --max-iterations 2 --no-fidelity -o " + out + " --record /dev/full");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("/dev/full: cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(test::readText(out), kTriangle);
  r = runCli("remesh " + mesh + " --max-iterations 2 --record " + mesh);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh + ": --record would replace the input mesh; give it another name\n");
  r = runCli("remesh " + mesh + " --max-iterations 2 -o " + out + " --record " + out);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + out + ": --record and --output name the same file; give them two\n");
  EXPECT_EQ(test::readText(mesh), test::readText(test::assetPath("jittered_grid.off")));
  EXPECT_EQ(test::readText(out), kTriangle);
  // The same new file named two ways, the output written first and then replaced by the
  // recording: a bare name of no file yet was not resolved against the folder it is in. (A
  // recording takes no mesh's name now: here a link to the output, by its full name.)
  const std::string here = test::emptyFolder("two_spellings");
  ASSERT_EQ(symlink("new.off", (here + "/run.lsrec").c_str()), 0);
  const int status = std::system(("cd " + here + " && " + std::string(LLOYDSCOPE_CLI) + " remesh " + mesh +
                                  " --max-iterations 2 --no-fidelity -o new.off --record " + here +
                                  "/run.lsrec >/dev/null 2>err.txt").c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 1);
  EXPECT_EQ(test::readText(here + "/err.txt"),
            "lloydscope: " + here + "/run.lsrec: --record and --output name the same file; give them two\n");
  std::remove((here + "/err.txt").c_str());
  std::remove((here + "/run.lsrec").c_str());
  EXPECT_TRUE(test::filesIn(here).empty());
  // bench's CSV onto one of its inputs replaced the mesh with the table.
  r = runCli("bench " + mesh + " --sizes 100 --no-reference --csv " + mesh);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh + ": --csv would replace the input mesh; give it another name\n");
  EXPECT_EQ(test::readText(mesh), test::readText(test::assetPath("jittered_grid.off")));
  const std::string folder = test::tempPath("folder.lsrec");
  std::filesystem::create_directory(folder);
  r = runCli("info " + folder);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + folder + ": is a folder, not a recording\n");
}

// A result that did not stitch back says what is wrong with the result, not with the input: a
// tetrahedron's was "(tetra.off: the mesh has no faces)", of a file of four faces.
TEST(Cli, AResultThatDidNotStitchBackIsNotTakenForTheInput) {
  const std::string tetra = test::tempPath("tetra.off");
  test::writeText(tetra, "OFF\n4 4 0\n1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
  const CliRun r = runCli("remesh " + tetra + " --no-resample -o " + test::tempPath("tetra_out.off"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("did not stitch back into a closed surface of genus 0 (the stitched result: "), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find(tetra + ": the mesh has no faces"), std::string::npos) << r.err;
}

// A square border on a border of three vertices: "the border is too short" said neither why
// nor what to do.
TEST(Cli, ASquareBorderOnThreeVerticesSaysWhatToTry) {
  const std::string triangle = test::tempPath("one_triangle.off");
  test::writeText(triangle, kTriangle);
  const CliRun r = runCli("remesh " + triangle + " --preset reference -o " + test::tempPath("one_triangle_out.off"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(triangle + ": authalic parameterization failed: the border has too few vertices (a square border "
                                  "needs 4 at least: try --border circle)"),
            std::string::npos)
      << r.err;
}

TEST(Cli, AFailedRunLeavesTheUsersFileAlone) {
  const std::string out = test::tempPath("precious.off");
  test::writeText(out, kTriangle);
  const std::string bad = test::tempPath("bad.off");
  test::writeText(bad, "OFF\n3 1 0\n0 0 0\n");
  EXPECT_EQ(runCli("remesh " + bad + " -o " + out).code, 1);
  EXPECT_EQ(test::readText(out), kTriangle);
}

// A recording under a mesh's name replaced that mesh (the window's Save recording wrote one
// over the input). Refused before the run, the file left as it was, nothing else written.
TEST(Cli, ARecordingIsNotSavedUnderAMeshsExtension) {
  const std::string mesh = test::tempPath("mine.OBJ"), out = test::tempPath("never_written.off");
  test::writeText(mesh, "the user's own mesh");
  std::remove(out.c_str());
  const CliRun r = runCli("remesh " + test::assetPath("sphere_cap.off") + " --record " + mesh + " -o " + out);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh +
                       ": a recording is not saved under a mesh's extension (.obj): it would replace a mesh with what "
                       "no mesh reader reads; name it .lsrec\n");
  EXPECT_EQ(test::readText(mesh), "the user's own mesh");
  EXPECT_FALSE(std::filesystem::exists(out));
  // Said before the pipe is opened to see that it can be written: it waited for a reader.
  const std::string pipe = test::tempPath("waits.off");
  std::remove(pipe.c_str());
  ASSERT_EQ(mkfifo(pipe.c_str(), 0666), 0);
  const CliRun piped = runCli("remesh " + test::assetPath("sphere_cap.off") + " --record " + pipe);
  EXPECT_EQ(piped.code, 1);
  EXPECT_NE(piped.err.find("a recording is not saved under a mesh's extension (.off)"), std::string::npos) << piped.err;
  std::remove(pipe.c_str());
}

// bench's table under a mesh's name replaced that mesh (mine.off began "model,size,method,...").
// Refused before any model is run, the file left as it was.
TEST(Cli, TheBenchsTableIsNotSavedUnderAMeshsExtension) {
  const std::string mesh = test::tempPath("mine_table.off");
  test::writeText(mesh, kTriangle);
  const CliRun r = runCli("bench " + test::assetPath("sphere_cap.off") + " --sizes 100 --no-reference --csv " + mesh);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + mesh +
                       ": the table is not saved under a mesh's extension (.off): it would replace a mesh with what "
                       "no mesh reader reads; name it .csv\n");
  EXPECT_EQ(test::readText(mesh), kTriangle);
}

// The recording and the output are saved both or neither: with the output on a full disk the
// recording of the run before was replaced all the same.
TEST(Cli, AnOutputThatCannotBeWrittenLeavesTheRecordingAlone) {
  const std::string record = test::tempPath("kept.lsrec"), full = test::tempPath("full.off");
  test::writeText(record, "the user's own");
  std::remove(full.c_str());
  ASSERT_EQ(symlink("/dev/full", full.c_str()), 0);
  const CliRun r = runCli("remesh " + test::assetPath("sphere_cap.off") + " --sites 100 -o " + full + " --record " + record);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("full.off: cannot write"), std::string::npos) << r.err;
  EXPECT_EQ(test::readText(record), "the user's own");
}

// An option the run ignores is said: --alpha without the curvature density, or the polish's
// options with relocate, were accepted and changed nothing (the output was byte for byte the same).
TEST(Cli, AnOptionWithNoEffectIsSaid) {
  const std::string mesh = test::assetPath("sphere_cap.off"), out = test::tempPath("ignored.off");
  // `options` remesh the cap, and each of `notes` is said on stderr.
  const auto noted = [&](const std::string& options, const std::vector<std::string>& notes) {
    const CliRun r = runCli("remesh " + mesh + " " + options + " -o " + out);
    EXPECT_EQ(r.code, 0) << options << ": " << r.err;
    for (const std::string& note : notes) EXPECT_NE(r.err.find(note), std::string::npos) << options << ": " << r.err;
    return r;
  };
  EXPECT_EQ(noted("--sites 100", {}).err.find("note:"), std::string::npos);
  noted("--sites 100 --alpha 3", {"note: --alpha has no effect here: it shapes the curvature density"});
  EXPECT_EQ(noted("--sites 100 --density curvature --alpha 3", {}).err.find("note:"), std::string::npos);
  noted("--method relocate --no-fit --polish 5",
        {"note: --no-fit has no effect here", "note: --polish has no effect here"});
  // A disk relocate keeps as it is; a size --simplify sets (their runs were the same with these).
  noted("--method relocate --no-slit", {"note: --no-slit has no effect here"});
  noted("--simplify 100 --sites 200 --full-input", {"note: --full-input has no effect here"});
  EXPECT_EQ(noted("--sites 100 --full-input", {}).err.find("note:"), std::string::npos);
  // A size over the input's where its own vertices are the sites: the cap has 500.
  for (const std::string own : {"--method relocate", "--preset reference"}) {
    const CliRun r = noted(own + " --simplify 1000 --no-fidelity",
                           {"note: --simplify 1000 has no effect here: the input has 500 vertices, and they are the sites"});
    EXPECT_EQ(r.out.find("vertices for the 1000 asked"), std::string::npos) << r.out;  // the clean-up was blamed
  }
}

TEST(Cli, UnknownOptionValues) {
  const CliRun r = runCli("remesh " + test::assetPath("jittered_grid.off") + " --param nope");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown parameterization 'nope'"), std::string::npos) << r.err;
  EXPECT_NE(runCli("remesh " + test::assetPath("jittered_grid.off") +
                       " --method relocate --sites 100").code, 0);
}

// The help lists every value an option with a fixed set of choices takes.
TEST(Cli, RemeshHelpNamesEverySolverAndPolishTarget) {
  const CliRun r = runCli("remesh --help");
  ASSERT_EQ(r.code, 0) << r.err;
  for (CvtSolver s : kCvtSolvers) EXPECT_NE(r.out.find(toString(s)), std::string::npos) << toString(s);
  for (PolishTarget t : kPolishTargets) EXPECT_NE(r.out.find(toString(t)), std::string::npos) << toString(t);
}

// An option's help says its default, as the options hold it (the guide and the help said
// nothing of --max-iterations' 1000, which a comparison's legend shows as "not converged").
TEST(Cli, TheHelpSaysEachTunedOptionsDefault) {
  const std::string help = runCli("remesh --help").out;
  const auto line = [&](const std::string& option) {
    const size_t at = help.find(option);
    const size_t next = help.find("\n  -", at + 1);
    return at == std::string::npos ? std::string() : help.substr(at, next - at);
  };
  EXPECT_NE(line("--max-iterations").find("(default 1000)"), std::string::npos) << line("--max-iterations");
  EXPECT_NE(line("--alpha").find("(default 1)"), std::string::npos) << line("--alpha");
  EXPECT_NE(line("--floor").find("(default 0.1)"), std::string::npos) << line("--floor");
  EXPECT_NE(line("--distance-threshold").find("(default 1e-06)"), std::string::npos);
  EXPECT_NE(line("--sites").find("default: as many as the input has"), std::string::npos) << line("--sites");
  EXPECT_NE(runCli("bench-frames --help").out.find("Frames to time (default 100)"), std::string::npos);
}

TEST(Cli, BenchComparesWithCgalAndWritesCsv) {
  const std::string csv = test::tempPath("bench.csv");
  const CliRun r = runCli("bench " + test::assetPath("sphere_cap.off") + " --sizes 300 --no-reference --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string& table = r.out;
  const std::string rows = test::readText(csv);
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope |"), std::string::npos) << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | cgal isotropic |"), std::string::npos) << table;
  EXPECT_NE(table.find("time ratio"), std::string::npos);
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --polish -1 |"), std::string::npos) << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --no-resample |"), std::string::npos) << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --no-snap |"), std::string::npos) << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --no-fit |"), std::string::npos) << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --solver newton |"), std::string::npos)
      << table;
  EXPECT_NE(table.find("| sphere_cap | 300 | lloydscope --method relocate |"), std::string::npos) << table;
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 9) << rows;  // header and eight rows
  EXPECT_EQ(rows.rfind("model,size,method,vertices", 0), 0u);
}

// A row that failed (a strip 1000 times as long as wide, at 20 vertices) was one cell short in the markdown, and
// all zeros in the CSV, which a spreadsheet averages in as results: its results are empty, its
// input's (before) kept; CGAL's row has no stages, empty too.
TEST(Cli, BenchLeavesAFailedRowsResultsEmpty) {
  std::ostringstream strip;
  strip << "OFF\n400 398 0\n";
  for (int i = 0; i < 200; ++i) strip << i << " 0 0\n" << i << " 0.2 0\n";  // 1000 times as long as wide
  for (int i = 0; i + 1 < 200; ++i)
    strip << "3 " << 2 * i << " " << 2 * i + 2 << " " << 2 * i + 1 << "\n3 " << 2 * i + 1 << " " << 2 * i + 2 << " " << 2 * i + 3 << "\n";
  const std::string mesh = test::tempPath("long_strip.off"), csv = test::tempPath("failed_rows.csv");
  test::writeText(mesh, strip.str());
  const CliRun r = runCli("bench " + mesh + " --sizes 20 --no-reference --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string failed = lineStarting(r.out, "| long_strip | 20 | lloydscope |");
  ASSERT_NE(failed.find("failed: "), std::string::npos) << r.out;
  EXPECT_EQ(cells(failed).size(), cells(lineStarting(r.out, "| model | size | method |")).size()) << failed;
  const auto fields = [&](const std::string& start) {
    const std::string text = test::readText(csv);
    const size_t at = text.find("\n" + start);
    std::vector<std::string> row;
    std::istringstream line(text.substr(at + 1, text.find('\n', at + 1) - at - 1));
    for (std::string field; std::getline(line, field, ',') && row.size() < 28;) row.push_back(field);
    return row;
  };
  const std::vector<std::string> row = fields("long_strip,20,lloydscope,");
  ASSERT_EQ(row.size(), 28u);
  for (int k : {3, 4, 7, 8, 10, 11, 13, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27}) EXPECT_EQ(row[k], "") << "field " << k;
  EXPECT_EQ(row[5], "20");  // vertices_before: the input as given
  const std::vector<std::string> cgal = fields("long_strip,20,cgal isotropic,");
  ASSERT_EQ(cgal.size(), 28u);
  EXPECT_NE(cgal[3], "");
  for (int k = 19; k < 28; ++k) EXPECT_EQ(cgal[k], "") << "stage field " << k;
}

// Issue 5 asks the bench to print the input's size (Table I before) and the time of each stage
// too: a table of the defaults' stages, its total the main table's time, and the same in the CSV.
TEST(Cli, BenchPrintsWhereTheTimeGoes) {
  const std::string csv = test::tempPath("bench_stages.csv");
  const CliRun r = runCli("bench " + test::assetPath("sphere_cap.off") + " --sizes 200 --no-reference --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<std::string> main = cells(lineStarting(r.out, "| sphere_cap | 200 | lloydscope |"));
  const size_t header = r.out.find("| model | size | input vertices | input faces |");
  ASSERT_NE(header, std::string::npos) << r.out;
  const std::vector<std::string> stages = cells(lineStarting(r.out, "| sphere_cap | 200 |", header));
  ASSERT_GE(main.size(), 8u);
  ASSERT_GE(stages.size(), 15u) << r.out;
  EXPECT_EQ(stages[3], "200");  // the prepared input has the size asked
  EXPECT_GT(std::stoi(stages[4]), 300);  // faces: a disk of 200 vertices has nearly twice as many
  EXPECT_GT(std::stod(stages[10]), 0);  // Lloyd's stage took time
  EXPECT_EQ(stages[13], main[7]);  // the total is the main table's time

  const std::string rows = test::readText(csv);
  const std::string head = rows.substr(0, rows.find('\n'));
  for (const char* column : {"vertices_before", "faces_before", "ms_cut", "ms_other_way"})
    EXPECT_NE(head.find(column), std::string::npos) << column;
  const std::string first = rows.substr(head.size() + 1, rows.find('\n', head.size() + 1) - head.size() - 1);
  EXPECT_EQ(first.rfind("sphere_cap,200,lloydscope,", 0), 0u) << first;
  EXPECT_NE(first.find(",200," + stages[4] + ","), std::string::npos) << first;  // before: as printed
}

// The bench sums up each method over all its inputs, so that what each step of the defaults
// buys (the variants each leave one out) reads off one table (docs/bench.md).
TEST(Cli, BenchSumsUpEachMethodOverItsInputs) {
  const CliRun r = runCli("bench " + test::assetPath("sphere_cap.off") + " --sizes 150 200 --no-reference --csv " +
                          test::tempPath("bench_summary.csv"));
  ASSERT_EQ(r.code, 0) << r.err;
  const size_t header = r.out.find("| method | runs | irregular % (b-aware), mean (range) |");
  ASSERT_NE(header, std::string::npos) << r.out;
  for (const char* method : {"lloydscope", "lloydscope --polish -1", "lloydscope --no-snap", "lloydscope --no-fit",
                             "lloydscope --solver newton", "lloydscope --no-resample", "lloydscope --method relocate",
                             "cgal isotropic"})
    EXPECT_EQ(cells(lineStarting(r.out, std::string("| ") + method + " |", header)).at(2), "2") << method << r.out;
  // The defaults' line against their two rows of the CSV.
  std::vector<std::vector<std::string>> defaults;  // CSV fields
  int cgalMet = 0;
  std::istringstream csv(test::readText(test::tempPath("bench_summary.csv")));
  for (std::string line; std::getline(csv, line);) {
    std::vector<std::string> fields;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    if (fields.size() > 15 && fields[2] == "lloydscope") defaults.push_back(fields);
    // CGAL's rows meet the bars by themselves where they meet the three that need no reference
    // (the sphere cap's border has no corner).
    if (fields.size() > 15 && fields[2] == "cgal isotropic")
      cgalMet += std::stod(fields[10]) <= 15 && std::stod(fields[13]) >= 30 && std::stod(fields[15]) >= 53;
  }
  ASSERT_EQ(defaults.size(), 2u);
  EXPECT_EQ(cells(lineStarting(r.out, "| cgal isotropic |", header)).at(9), std::to_string(cgalMet)) << r.out;
  const auto both = [&](int column) { return std::make_pair(std::stod(defaults[0][column]), std::stod(defaults[1][column])); };
  const std::vector<std::string> sum = cells(lineStarting(r.out, "| lloydscope |", header));
  ASSERT_GE(sum.size(), 10u) << r.out;
  const auto [irregular150, irregular200] = both(10);
  EXPECT_EQ(sum[3], format("%.1f (%.1f-%.1f)", (irregular150 + irregular200) / 2, std::min(irregular150, irregular200),
                           std::max(irregular150, irregular200)));
  const auto [smallest150, smallest200] = both(13);
  EXPECT_EQ(sum[4], format("%.1f", std::min(smallest150, smallest200)));  // the smallest angle of all
  const auto [average150, average200] = both(15);
  EXPECT_EQ(sum[5], format("%.2f", (average150 + average200) / 2));
  const auto [iterations150, iterations200] = both(7);
  EXPECT_EQ(sum[7], format("%.0f", (iterations150 + iterations200) / 2));
  // All four bars: as many as the verdicts say.
  int met = 0;
  for (const char* size : {"150", "200"})
    met += cells(lineStarting(r.out, std::string("| sphere_cap | ") + size + " | ", r.out.find("| model | size | time ratio"))).at(4) == "all met";
  EXPECT_EQ(sum[9], std::to_string(met));
}

// --as-is: the model as it comes, remeshed to the size, the defaults and --full-input beside CGAL.
TEST(Cli, BenchAsIsRemeshesTheModelsAsTheyCome) {
  const std::string csv = test::tempPath("bench_as_is.csv");
  // --save-inputs makes its folder (it failed with "cannot write" where the folder was new)
  const std::string inputs = test::tempPath("bench_inputs") + "/as_is";
  const CliRun r = runCli("bench " + test::assetPath("bumpy_disk.off") + " --as-is --sizes 60 --csv " + csv +
                          " --save-inputs " + inputs);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(readMesh(inputs + "/bumpy_disk_60.off").mesh.vertexCount(), readMesh(test::assetPath("bumpy_disk.off")).mesh.vertexCount());
  const std::string& table = r.out;
  const std::string rows = test::readText(csv);
  EXPECT_NE(table.find("| bumpy_disk | 60 | lloydscope | 6"), std::string::npos) << table;  // ~60 vertices
  EXPECT_NE(table.find("| bumpy_disk | 60 | lloydscope --full-input |"), std::string::npos) << table;
  EXPECT_NE(table.find("| bumpy_disk | 60 | cgal isotropic |"), std::string::npos) << table;
  EXPECT_EQ(table.find("--polish -1"), std::string::npos) << table;
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 4) << rows;  // header and three rows
}

TEST(Cli, BenchTimesLloydIterations) {
  const CliRun r = runCli("bench --lloyd-step 1500");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string& table = r.out;
  for (const char* row : {"| 1500 | uniform | 1 |", "| 1500 | uniform | all |", "| 1500 | area | 1 |",
                          "| 1500 | area | all |", "| 11 iterations of 1500 sites | 7."})
    EXPECT_NE(table.find(row), std::string::npos) << table;  // under 8 bytes a site
}

// The recording whose cost the step bench measures is a temporary of its own: it was
// "<csv>.lsrec", replacing and then deleting a user's file of that name. The comparison's own
// options are refused with it: they were accepted and ignored (no CSV, no input saved), and so
// was every model but the first.
TEST(Cli, BenchTimingLloydIterationsTouchesNoFileOfTheUser) {
  const std::string here = test::emptyFolder("step_bench"), csv = here + "/step.csv";
  const std::string mesh = test::assetPath("sphere_cap.off");
  test::writeText(csv + ".lsrec", "precious");
  for (const std::string& option : std::vector<std::string>{"--csv " + csv, "--sizes 500", "--save-inputs " + here + "/in", "--no-reference", "--as-is"}) {
    const CliRun r = runCli("bench --lloyd-step 20 " + mesh + " " + option);
    EXPECT_EQ(r.code, 1) << option;
    EXPECT_EQ(r.err, "lloydscope: " + option.substr(0, option.find(' ')) + " excludes --lloyd-step (--help lists the options)\n");
  }
  const CliRun two = runCli("bench --lloyd-step 20 " + mesh + " " + test::assetPath("bumpy_disk.off"));
  EXPECT_EQ(two.code, 1);
  EXPECT_EQ(two.err, "lloydscope: --lloyd-step times one mesh; 2 were given\n");
  EXPECT_EQ(test::readText(csv + ".lsrec"), "precious");
  EXPECT_EQ(test::filesIn(here), std::vector<std::string>{"step.csv.lsrec"});
}

// A model's file name goes into the markdown and the CSV as it is only where it breaks neither:
// a comma split its CSV row into one column more, a '|' its markdown row, a line break both.
TEST(Cli, BenchTablesHoldAnyModelName) {
  const std::string here = test::emptyFolder("odd_names"), model = here + "/c,o|m\"a.off";
  test::writeText(model, test::readText(test::assetPath("jittered_grid.off")));
  const std::string csv = here + "/b.csv";
  const CliRun r = runCli("bench '" + model + "' --as-is --sizes 100 --no-reference --csv " + csv);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("| c,o\\|m\"a | 100 | lloydscope |"), std::string::npos) << r.out;
  const std::string rows = test::readText(csv);
  EXPECT_NE(rows.find("\n\"c,o|m\"\"a\",100,lloydscope,"), std::string::npos) << rows;
  // --save-inputs onto a model of the run is refused before any work.
  test::writeText(here + "/a.off", test::readText(test::assetPath("jittered_grid.off")));
  test::writeText(here + "/a_100.off", test::readText(test::assetPath("sphere_cap.off")));
  const CliRun saved = runCli("bench " + here + "/a.off " + here + "/a_100.off --sizes 100 --as-is --no-reference "
                              "--save-inputs " + here + " --csv " + csv);
  EXPECT_EQ(saved.code, 1);
  EXPECT_NE(saved.err.find("--save-inputs would replace the input mesh"), std::string::npos) << saved.err;
  EXPECT_EQ(test::readText(here + "/a_100.off"), test::readText(test::assetPath("sphere_cap.off")));
  // So is a CSV onto a prepared input: it replaced the input just saved, exit 0.
  const CliRun onInput = runCli("bench " + here + "/a.off --sizes 100 --as-is --no-reference --save-inputs " + here +
                                " --csv " + here + "/a_100.off");
  EXPECT_EQ(onInput.code, 1);
  EXPECT_EQ(onInput.err, "lloydscope: " + here + "/a_100.off: --csv and --save-inputs name the same file; give them two\n");
  EXPECT_EQ(test::readText(here + "/a_100.off"), test::readText(test::assetPath("sphere_cap.off")));
}

// A file name that is not UTF-8 goes into --json's strings (here the charts' failure) with
// U+FFFD for its bad bytes: dump() threw, an "internal error" (exit 2) after the files were
// written.
TEST(Cli, JsonTakesAFileNameThatIsNotUtf8) {
  const std::string femur = test::cgalSample("femur.off");
  SKIP_UNLESS_EXTRACTED(femur);
  const std::string odd = test::tempPath("fe\xffmur.off");
  test::writeText(odd, test::readText(femur));
  const CliRun r = runCli("remesh '" + odd + "' --sites 500 --no-fidelity --json -o " + test::tempPath("femur_out.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_NE(j.dump().find("fe\xef\xbf\xbdmur"), std::string::npos) << j.dump();  // U+FFFD
}

// A run whose map fell back to the input's own (no method holds a tetrahedron cut open) records
// "param-used=input-map", which inspect refused to read back as an unknown parameterization.
TEST(Cli, ARecordingOfTheInputsOwnMapOpens) {
  const std::string tet = test::tempPath("tet.off"), rec = test::tempPath("tet.lsrec");
  test::writeText(tet, "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_EQ(runCli("remesh " + tet + " --record " + rec + " -o " + test::tempPath("tet_out.off")).code, 0);
  const CliRun r = runCli("inspect " + rec + " --size 960x600 --screenshot " + test::tempPath("tet.PNG"));
  EXPECT_EQ(r.code, 0) << r.err;  // and a .PNG is a PNG, as a mesh's .OFF is an OFF
}

TEST(Cli, BenchNamesAMissingModel) {
  const CliRun r = runCli("bench /nonexistent/model.off --csv " + test::tempPath("never.csv"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("/nonexistent/model.off"), std::string::npos) << r.err;
}

// A bad model after a good one fails before the good one is run (minutes, on real inputs).
TEST(Cli, BenchReadsEveryModelBeforeRunningAny) {
  const std::string bad = test::tempPath("cracked.off");
  test::writeText(bad, "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n1 1 0\n3 0 1 2\n3 3 4 2\n");
  const CliRun r = runCli("bench " + test::assetPath("sphere_cap.off") + " " + bad +
                          " --sizes 300 --no-reference --csv " + test::tempPath("never.csv"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("same position on a border"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("done"), std::string::npos) << r.err;  // no model was run
}

// A file that cannot be saved (a missing folder, an extension no writer knows) is named before
// the run: nothing else is written, and no minutes are spent first.
TEST(Cli, AFileThatCannotBeSavedFailsBeforeTheRun) {
  const std::string out = test::tempPath("before.off");
  const std::string missing = test::tempPath("no_such_folder") + "/run.lsrec";
  CliRun r = runCli("remesh " + test::assetPath("jittered_grid.off") + " -o " + out + " --record " + missing);
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "lloydscope: " + missing + ": cannot write: there is no folder " + test::tempPath("no_such_folder") + "\n");
  EXPECT_FALSE(std::ifstream(out).good()) << "the mesh was written before the recording failed";
  EXPECT_EQ(r.out, "");

  // Checked before the input is even read: a bad input is not what the user hears of first.
  const std::string bad = test::tempPath("unread.off");
  test::writeText(bad, "not a mesh");
  r = runCli("remesh " + bad + " -o " + test::tempPath("out.stl"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("out.stl: cannot write: unknown extension '.stl'"), std::string::npos) << r.err;
  r = runCli("inspect " + bad + " --screenshot " + test::tempPath("shot.jpg"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("shot.jpg: exports are PNG files"), std::string::npos) << r.err;
  r = runCli("inspect " + bad + " --screenshot " + missing + ".png");
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find(missing + ".png: cannot write"), std::string::npos) << r.err;
}

// Numbers are checked as they are read: NaN, infinities and values out of range are refused
// with the option's name (CLI11's own checks let NaN through), before the mesh is read.
// (bench-frames --frames 0 crashed; bench --lloyd-step -3 ran the whole bench instead.)
TEST(Cli, NumbersOutOfRangeOrNotFiniteAreRefused) {
  const std::string mesh = test::assetPath("jittered_grid.off"), out = test::tempPath("never");
  for (const std::string option : {"--distance-threshold nan", "--distance-threshold 0", "--percent-threshold inf",
                                   "--percent-threshold 101", "--alpha -1", "--beta nan", "--floor -0.5",
                                   "--max-iterations 0", "--sites 0"}) {
    const CliRun r = runCli("remesh " + mesh + " " + option);
    EXPECT_EQ(r.code, 1) << option;
    EXPECT_EQ(r.out, "") << option;
    EXPECT_EQ(r.err.rfind("lloydscope: " + option.substr(0, option.find(' ')) + ": ", 0), 0u) << option << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  for (const std::string& command : std::vector<std::string>{
           "bench-frames " + mesh + " --frames 0", "bench --lloyd-step -3", "bench --sizes 0",
        "simplify " + mesh + " -o " + out + ".off --ratio nan",
        "inspect " + mesh + " --screenshot " + out + ".png --iteration -5"}) {
    const CliRun r = runCli(command);
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_EQ(r.out, "") << command;
    const std::string option = command.substr(command.rfind("--"), command.rfind(' ') - command.rfind("--"));
    EXPECT_EQ(r.err.rfind("lloydscope: " + option + ": ", 0), 0u) << command << ": " << r.err;
  }
  // A distance under the smallest normal double is still above 0, as the refusal of 0 says
  // (it was refused as "expected a number > 0").
  const CliRun tiny = runCli("remesh " + mesh + " --distance-threshold 1e-310 --max-iterations 2 --no-fidelity");
  EXPECT_EQ(tiny.code, 0) << tiny.err;
}

// A command-line mistake is one line and exit code 1, as every other error (CLI11's own were two
// lines and exit codes 105-109), and says what was expected; --help still exits 0.
TEST(Cli, CommandLineMistakesAreOneLineErrors) {
  const std::string mesh = test::assetPath("jittered_grid.off");
  const std::vector<std::pair<std::string, std::string>> mistakes = {
      {"remesh " + mesh + " --bogus", "--bogus"},
      {"remesh", "input"},
      {"remesh " + mesh + " --max-iterations abc", "expected a whole number from 1 to 100000, not 'abc'"},
      {"remesh " + mesh + " --sites 1.5", "expected a whole number from 20 to 1000000, not '1.5'"},
      {"remesh " + mesh + " --polish -2", "expected a whole number from -1 to 100, not '-2'"},
      {"remesh " + mesh + " --sites 0x20", "expected a whole number from 20 to 1000000, not '0x20'"},  // was 32
      // Sizes and numbers past what the run takes (bench-frames took any size; the others wrapped
      // round or printed CLI11's own text).
      {"bench-frames " + mesh + " --size 100000x100000", "--size must be between 960x600 and 8192x8192, not '100000x100000'"},
      {"inspect " + mesh + " --size 4294968256x600 --screenshot x.png", "--size must be between 960x600 and 8192x8192"},
      {"inspect " + mesh + " --size 1280x800x --screenshot x.png", "--size must look like 1280x800, not '1280x800x'"},
      {"inspect " + mesh + " --size 1280x800 --ui-scale 2 --screenshot x.png",
       "--size 1280x800 at --ui-scale 2 leaves the inspector less than 960x600 to lay out in"},
      {"inspect " + mesh + " --ui-scale 5 --screenshot x.png", "--ui-scale"},
      {"inspect " + mesh + " --ui-scale nan --screenshot x.png", "expected a number from 0.5 to 4, not 'nan'"},  // was taken
      {"inspect " + mesh + " --iterations 0:4294967296 --screenshot x.png", "--iterations: expected FIRST:LAST, e.g. 0:20, not '0:4294967296'"},
      {"inspect " + mesh + " --iterations 99999999999999999999:1 --screenshot x.png", "expected FIRST:LAST"},
      // Digits alone, as --size takes them (sscanf took a space and a sign).
      {"inspect " + mesh + " --iterations ' 0:5' --screenshot x.png", "--iterations: expected FIRST:LAST, e.g. 0:20, not ' 0:5'"},
      {"inspect " + mesh + " --iterations 0:+5 --screenshot x.png", "--iterations: expected FIRST:LAST, e.g. 0:20, not '0:+5'"},
      // Options a picture would not show, refused (they were left out in silence).
      {"inspect " + mesh + " --stage voronoi --final --screenshot x.png", "--final excludes --stage"},
      {"inspect " + mesh + " --iteration 3 --iterations 0:2 --screenshot x.png", "--iterations excludes --iteration"},
      // It pinned the last iteration's worst triangle in every picture.
      {"inspect " + mesh + " --select-worst --iterations 0:2 --screenshot x.png", "--iterations excludes --select-worst"},
      {"inspect " + mesh + " --stage valence --fill mass --screenshot x.png", "--fill mass: the valence stage fills the cells by valence"},
      {"inspect " + mesh + " --stage parameterize --fill energy --screenshot x.png",
       "--fill energy: the parameterize stage shows no cells to fill"},
      {"inspect " + mesh + " --fill '' --screenshot x.png", "unknown fill ''"},  // was taken for none
      {"inspect " + mesh + " --size ' 960x600' --screenshot x.png", "--size must look like 1280x800, not ' 960x600'"},
      {"inspect " + mesh + " --size 99999999999999999999x600 --screenshot x.png",
       "--size must be between 960x600 and 8192x8192, not '99999999999999999999x600'"},
      {"inspect " + mesh + " --iterations 5:2 --screenshot x.png", "--iterations: FIRST comes after LAST in '5:2'"},
      {"inspect " + mesh + " --screenshot .png", ".png: a picture needs a name before its .png"},  // "end the name with .png"
      // A picture's options without a picture (a window ignored them in silence).
      {"inspect " + mesh + " --pane 2d", "--pane requires --screenshot"},
      {"inspect " + mesh + " --iterations 0:5", "--iterations requires --screenshot"},
      {"inspect " + mesh + " --size 960x600", "--size requires --screenshot"},
      // What the pane pictured does not show (the picture was the same with it as without).
      {"inspect " + mesh + " --pane plots --fill mass --screenshot x.png", "--fill has nothing to show in --pane plots: it is for the 2D view"},
      {"inspect " + mesh + " --pane plots --select-worst --screenshot x.png", "--select-worst has nothing to show in --pane plots"},
      {"inspect " + mesh + " --pane 2d --camera '1 0.5 3 0 0 0' --screenshot x.png", "--camera has nothing to show in --pane 2d: it is for the 3D view"},
      {"inspect " + mesh + " --pane 2d --final --screenshot x.png", "--final has nothing to show in --pane 2d"},
      {"inspect " + mesh + " --pane 3d --fill energy --screenshot x.png", "--fill has nothing to show in --pane 3d"},
      {"inspect " + mesh + " --stage load --select-cell 3 --screenshot x.png",
       "--select-cell has nothing to show at --stage load: it draws no cells and no result"},
      {"inspect " + mesh + " --stage parameterize --select-triangle 3 --screenshot x.png",
       "--select-triangle has nothing to show at --stage parameterize"},
      // No file name (an unset variable): the run went on and wrote nothing.
      {"remesh " + mesh + " -o ''", "--output: expected a file name, not an empty one"},
      {"remesh " + mesh + " --record ''", "--record: expected a file name, not an empty one"},
      {"bench " + mesh + " --csv ''", "--csv: expected a file name, not an empty one"},
      {"inspect " + mesh + " --screenshot ''", "--screenshot: expected a file name, not an empty one"},
      // Nor an empty value (it was taken as none: one picture, the default size or view, no inputs saved).
      {"bench " + mesh + " --save-inputs ''", "--save-inputs: expected a folder, not an empty one"},
      {"inspect " + mesh + " --iterations '' --screenshot x.png", "--iterations: expected FIRST:LAST, not an empty one"},
      {"inspect " + mesh + " --size '' --screenshot x.png", "--size: expected WxH, not an empty one"},
      {"bench-frames " + mesh + " --size ''", "--size: expected WxH, not an empty one"},
      {"inspect " + mesh + " --camera '' --screenshot x.png", "--camera: expected \"yaw pitch distance x y z\", not an empty one"},
      {"remesh " + mesh + " --preset ''", "--preset: expected best or reference, not an empty one"},
      // Every iteration is recorded: a run that never converges grew by 30 MB a second.
      {"remesh " + mesh + " --max-iterations 2000000000", "--max-iterations: expected a whole number from 1 to 100000"},
      // A line break in a file name or a value stays on the error's one line.
      {"metrics 'bad\nname.off'", "bad\\nname.off: no such file"},
      {"metrics 'esc\x1b[2Jname.off'", "esc\\x1b[2Jname.off: no such file"},  // the terminal was cleared
      {"metrics 'page\fname.off'", "page\\x0cname.off: no such file"},
      {"metrics 'csi\xc2\x9b" "2Jname.off'", "csi\\xc2\\x9b2Jname.off: no such file"},  // UTF-8's C1 CSI
      {"metrics 'caf\xc3\xa9.off'", "caf\xc3\xa9.off: no such file"},  // other UTF-8 as it is
      {"remesh " + mesh + " --solver 'x\ny'", "unknown solver 'x\\ny'"},
      {"inspect " + mesh + " --select-cell 99999999999 --screenshot x.png", "--select-cell: expected a whole number from 0 to 2147483647, not '99999999999'"},
      {"inspect " + mesh + " --select-triangle -1 --screenshot x.png", "--select-triangle: expected a whole number >= 0, not '-1'"},
      // bench's sizes as --sites (--lloyd-step 214748365 wrapped round in the border check and
      // was told it was too few; --sizes 50000000 and --frames 2000000000 ran on for hours).
      {"bench --lloyd-step 214748365", "--lloyd-step: expected a whole number from 20 to 1000000, not '214748365'"},
      {"bench " + mesh + " --sizes 500 50000000", "--sizes: expected a whole number from 20 to 1000000, not '50000000'"},
      {"bench " + mesh + " --sizes 1", "--sizes: expected a whole number from 20 to 1000000, not '1'"},
      {"bench-frames " + mesh + " --frames 2000000000", "--frames: expected a whole number from 1 to 100000, not '2000000000'"}};
  for (const auto& [command, says] : mistakes) {
    const CliRun r = runCli(command);
    EXPECT_EQ(r.code, 1) << command;
    EXPECT_EQ(r.err.rfind("lloydscope: ", 0), 0u) << command << ": " << r.err;
    EXPECT_NE(r.err.find(says), std::string::npos) << command << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << command << ": " << r.err;
  }
  const CliRun help = runCli("remesh --help");
  EXPECT_EQ(help.code, 0);
  EXPECT_NE(help.out.find("--max-iterations"), std::string::npos);
  // The picture sizes' help says both limits, as the refusal does.
  for (const char* command : {"inspect --help", "bench-frames --help"})
    EXPECT_NE(runCli(command).out.find("between 960x600 and 8192x8192"), std::string::npos) << command;
  // A number's range is in the help, as a count's is (it said FLOAT:NUMBER).
  EXPECT_NE(runCli("inspect --help").out.find("--ui-scale FLOAT:number from 0.5 to 4"), std::string::npos);
  // inspect's help lists the window's keys (they were in the guide alone), every key of the
  // guide's table (T, Ctrl+S and Ctrl+Q were left out).
  const std::string keys = runCli("inspect --help").out;
  for (const char* key : {"Space play/pause", "P presentation", "T the plots", "L the lesson", "Escape unpin",
                          "F (over", "Ctrl+S save", "Ctrl+Q close"})
    EXPECT_NE(keys.find(key), std::string::npos) << key;
  std::istringstream guide(test::readText(std::string(LLOYDSCOPE_SOURCE_DIR) + "/docs/guide.md"));
  int rows = 0;
  for (std::string line; std::getline(guide, line) && line != "### Keys";) {
  }
  for (std::string line; std::getline(guide, line);) {
    if (line.rfind("| ", 0) != 0) {
      if (rows > 0) break;  // the table's end
      continue;
    }
    const std::string key = cells(line).at(1);
    if (key == "key") continue;  // the header
    ++rows;
    // "Home, End" as Home/End, "← → (Shift: ten)" as <- ->, "F (over the 3D or 2D view)" as F.
    const std::string first = key.substr(0, key.find_first_of(" ,"));
    const std::string inHelp = first == "←" ? "<- ->" : first;
    const bool listed = keys.find(" " + inHelp + " ") != std::string::npos || keys.find(" " + inHelp + "/") != std::string::npos;
    EXPECT_TRUE(listed) << key << " of the guide's table";
  }
  EXPECT_EQ(rows, 10);
}

// A file whose name starts with '-' is taken for an option by the command line; the error says
// how to name it (it said only "mesh is required").
TEST(Cli, AFileNamedLikeAnOptionIsToldHowToNameIt) {
  const std::string folder = test::emptyFolder("dashed");
  std::filesystem::copy_file(test::assetPath("jittered_grid.off"), folder + "/-lead.off");
  const std::string err = folder + "/err";
  const std::string cli = "cd " + folder + " && " + LLOYDSCOPE_CLI;
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " metrics -lead.off 2> err").c_str())), 1);
  const std::string message = test::readText(err);
  EXPECT_NE(message.find("'-lead.off' was read as an option: write ./-lead.off for the file"), std::string::npos)
      << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " metrics ./-lead.off > /dev/null").c_str())), 0);
  // After --, a name is read as one: another mistake is not blamed on it.
  EXPECT_EQ(WEXITSTATUS(std::system((cli + " metrics --bogus -- -lead.off 2> err").c_str())), 1);
  EXPECT_EQ(test::readText(err).find("read as an option"), std::string::npos) << test::readText(err);
}

// A run that needs more memory than the process may have ends with one line saying so, not an
// internal error.
namespace {
// The command line's exit code (-1 if it did not exit) for `args`, its stderr in `err`, with
// `programKiB` of address space for the program, plus what each core's worker thread reserves
// (its stack; one malloc arena for all, where 100 MB a core for the arenas would allow a
// million sites' 1.2 GB on 8 cores or more).
int exitCodeUnderAddressLimit(long programKiB, const std::string& args, const std::string& err) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::string limit = std::to_string(programKiB + 16000L * cores);
  const int status = std::system(("export MALLOC_ARENA_MAX=1; ulimit -v " + limit + "; " + std::string(LLOYDSCOPE_CLI) +
                                  " " + args + " >/dev/null 2>" + err).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
}  // namespace

TEST(Cli, RunningOutOfMemoryIsAOneLineError) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory at start, which no ulimit -v allows";
#endif
  const std::string err = test::tempPath("oom.err");
  // A few seconds' work on the million sites fills the rest (their run takes 1.2 GB).
  EXPECT_EQ(exitCodeUnderAddressLimit(600000,
                                      "remesh " + test::assetPath("jittered_grid.off") + " --sites 1000000 -o " +
                                          test::tempPath("huge.off"),
                                      err),
            1);
  EXPECT_EQ(test::readText(err), "lloydscope: " + test::assetPath("jittered_grid.off") +
                                     ": out of memory: fewer vertices asked, or a smaller input, need less\n");
}

// The largest picture (8192x8192: three buffers of 256 MB) where they do not fit: one line
// naming the picture and what to do (it was "Vulkan: allocating memory failed (VkResult -2)"),
// no picture, and every Vulkan object made before the failure freed (the validation layer
// listed an image or a buffer made without its memory, and the render pass, left behind).
TEST(Cli, APictureTooLargeForTheMemoryIsAOneLineError) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory at start, which no ulimit -v allows";
#endif
  const std::string png = test::tempPath("too_large.png"), err = test::tempPath("too_large.err");
  EXPECT_EQ(exitCodeUnderAddressLimit(900000,
                                      "inspect " + test::assetPath("sphere_cap.off") +
                                          " --size 8192x8192 --validation --screenshot " + png,
                                      err),
            1);
  const std::string text = test::readText(err);
  const std::string expected =
      "lloydscope: " + png + ": not enough memory to render a 8192x8192 picture: a smaller --size needs less\n";
  EXPECT_TRUE(text.size() >= expected.size() && text.compare(text.size() - expected.size(), expected.size(), expected) == 0)
      << text;
  EXPECT_EQ(text.find("not been destroyed"), std::string::npos) << text;
  EXPECT_FALSE(std::filesystem::exists(png));
}
