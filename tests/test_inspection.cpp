#include "inspection.h"
#include "mesh_io.h"
#include "metrics.h"
#include "test_support.h"

#include <cmath>
#include <map>

using namespace lloydscope;

namespace {

// A short run on the bundled sphere cap with a uniform density, so that each cell's centroid
// is also its shoelace centroid.
const RemeshResult& uniformRun(RemeshMethod method) {
  static std::map<RemeshMethod, RemeshResult> runs;
  auto found = runs.find(method);
  if (found != runs.end()) return found->second;
  RemeshOptions o = method == RemeshMethod::Relocate ? referencePreset(method) : RemeshOptions{};
  o.density.kind = DensityKind::Uniform;
  o.lloyd.maxIterations = 8;
  o.measureFidelity = false;
  return runs[method] = remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "cap");
}

}  // namespace

TEST(Inspection, CellNumbersMatchTheShoelaceFormulas) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const IterationView& view = replay.view(5);
  double area = 0, surface = 0;
  for (int i = 0; i < static_cast<int>(view.cells.size()); ++i) {
    const CellDetails d = describeCell(r, replay.domain(), view, i);
    ASSERT_EQ(d.index, i);
    EXPECT_NEAR(d.shoelaceArea, d.area, 1e-14);
    if (d.area > 0) {
      const Vec2 unweighted = d.shoelaceSums / (6.0 * d.shoelaceArea);
      EXPECT_NEAR((unweighted - d.centroid).norm(), 0.0, 1e-9) << i;  // rho = 1
    }
    // rho = 1: the mass is the area and the moment the shoelace sums / 6, each computed apart
    EXPECT_NEAR(d.mass, d.area, 1e-14) << i;
    EXPECT_NEAR((d.moment - d.shoelaceSums / 6.0).norm(), 0.0, 1e-14) << i;
    area += d.area;
    surface += d.surfaceArea;
  }
  // The cells tile the domain, so their surface patches tile the input surface.
  double domainArea = 0;
  const Domain& domain = replay.domain();
  for (const Triangle& t : domain.triangles())
    domainArea += triangleArea(domain.uv()[t[0]], domain.uv()[t[1]], domain.uv()[t[2]]);
  EXPECT_NEAR(area, domainArea, 1e-12);
  EXPECT_NEAR(surface, surfaceArea(r.input), 1e-9 * surfaceArea(r.input));
}

TEST(Inspection, CellMovementAndTrajectoryComeFromTheRecording) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const int fixed = static_cast<int>(r.fixedSites.size());
  const int cell = fixed + 17;
  const CellDetails d = describeCell(r, replay.domain(), replay.view(3), cell);
  EXPECT_FALSE(d.fixed);
  EXPECT_EQ(d.site, r.iterations[3].sites[17]);
  EXPECT_DOUBLE_EQ(d.moved, (r.iterations[3].sites[17] - r.iterations[2].sites[17]).norm());
  EXPECT_DOUBLE_EQ(d.toCentroid,
                   (r.cells(replay.domain(), 3, false)[fixed + 17].centroid - d.site).norm());
  EXPECT_EQ(describeCell(r, replay.domain(), replay.view(0), cell).moved, 0.0);
  EXPECT_TRUE(describeCell(r, replay.domain(), replay.view(3), 0).fixed);

  const std::vector<Vec2> path = siteTrajectory(r, cell);
  ASSERT_EQ(path.size(), r.iterations.size());
  for (size_t k = 0; k < path.size(); ++k) EXPECT_EQ(path[k], r.iterations[k].sites[17]);
}

TEST(Inspection, CellValenceIsTheSiteVertexDegreeInTheResult) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const IterationView& view = replay.view(7);
  // Every site is a vertex of the retriangulated result.
  const VertexEdges edges = vertexEdges(view.output);
  int inside = 0;
  for (int v = 0; v < view.output.vertexCount(); ++v) {
    const CellDetails d = describeCell(r, replay.domain(), view, view.outputSite[v]);
    EXPECT_EQ(d.valence, edges.valence[v]);
    // Inside, the result is the Delaunay triangulation of the sites, the dual of their cells:
    // a vertex's valence is its cell's count of neighbours (the Selection panel shows both).
    if (!edges.onBoundary[v]) {
      EXPECT_EQ(d.neighbours, edges.valence[v]) << "site " << view.outputSite[v];
      ++inside;
    }
  }
  EXPECT_GT(inside, view.output.vertexCount() / 2);
}

// The sites' valences make the result's irregularity, relocated as retriangulated: a movable
// site's vertex in a relocated result is the input vertex it started at (the jittered grid's
// vertices are not in the sites' order, border first).
TEST(Inspection, TheSitesValencesAreTheResultsIrregularity) {
  RemeshOptions relocate = referencePreset(RemeshMethod::Relocate);
  relocate.lloyd.maxIterations = 8;
  relocate.measureFidelity = false;
  const RemeshResult relocated = remesh(readMesh(test::assetPath("jittered_grid.off")).mesh, relocate, "grid");
  for (RemeshMethod method : {RemeshMethod::Retriangulate, RemeshMethod::Relocate}) {
    const Recording& r = method == RemeshMethod::Relocate ? relocated.recording : uniformRun(method).recording;
    Replay replay(r);
    const IterationView& view = replay.view(7);
    const std::vector<VertexValence> valences = siteValences(view);
    ASSERT_EQ(valences.size(), view.sites.size());
    int vertices = 0, irregular = 0;
    for (const VertexValence& s : valences) {
      vertices += s.isVertex();
      irregular += s.irregular();
    }
    EXPECT_EQ(vertices, view.output.vertexCount());
    EXPECT_GT(irregular, 0);
    EXPECT_NEAR(100.0 * irregular / vertices, measureQuality(view.output).irregularBoundaryAware, 1e-9);
    if (method != RemeshMethod::Relocate) continue;
    ASSERT_FALSE(r.movableVertex.empty());  // else the replay retriangulates, and nothing below runs
    const VertexEdges input = vertexEdges(r.input);
    for (size_t i = 0; i < r.movableVertex.size(); ++i) {
      const VertexValence& s = valences[r.fixedSites.size() + i];
      EXPECT_EQ(s.valence, input.valence[r.movableVertex[i]]) << "site " << i;
      EXPECT_FALSE(s.onBorder);
      EXPECT_EQ(s.offset(), input.valence[r.movableVertex[i]] - 6);
    }
  }
}

// On a surface cut open (a torus), a seam sample's two sites are one vertex of the stitched
// result: their valence is that vertex's, never a border's (they were counted as border vertices
// of the disk, and the Valence stage's fives and sevens did not add up to its percentage).
TEST(Inspection, ACutSurfacesSitesHaveTheStitchedValences) {
  const RemeshResult r = remesh(test::torus(), test::shortRun(300, 5), "torus");
  ASSERT_GT(r.cut.seamEdges, 0);
  Replay replay(r.recording);
  const IterationView& view = replay.view(4);
  ASSERT_FALSE(view.stitched.triangles.empty());
  int vertices = 0;
  for (const VertexValence& s : siteValences(view)) {
    vertices += s.isVertex();
    EXPECT_FALSE(s.onBorder);
  }
  EXPECT_GT(vertices, view.stitched.vertexCount());  // the seam samples' two copies each
  const IrregularCounts counts = irregularCounts(view.measured());
  EXPECT_GT(counts.fives + counts.sevens, 0);
  EXPECT_NEAR(100.0 * (counts.fives + counts.sevens + counts.others) / view.stitched.vertexCount(),
              measureQuality(view.stitched).irregularBoundaryAware, 1e-9);
}

TEST(Inspection, CellAtIsTheNearestSiteInsideTheDomain) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const IterationView& view = replay.view(2);
  for (int i : {0, 40, 200}) EXPECT_EQ(cellAt(replay.domain(), view, view.sites[i]), i);
  EXPECT_EQ(cellAt(replay.domain(), view, Vec2(-0.5, -0.5)), -1);
}

TEST(Inspection, TriangleNumbers) {
  for (RemeshMethod method : {RemeshMethod::Retriangulate, RemeshMethod::Relocate}) {
    const Recording& r = uniformRun(method).recording;
    Replay replay(r);
    ASSERT_EQ(replay.method(), method);
    const IterationView& view = replay.view(4);
    double total = 0, totalUV = 0, shares = 0;
    for (int f = 0; f < static_cast<int>(view.output.triangles.size()); ++f) {
      const TriangleDetails d = describeTriangle(view, f);
      totalUV += d.areaUV;
      shares += d.areaUV * d.areaDistortion;  // = the UV area share times r: the 3D area share
      EXPECT_NEAR(d.angles3D[0] + d.angles3D[1] + d.angles3D[2], 180.0, 1e-9);
      EXPECT_NEAR(d.anglesUV[0] + d.anglesUV[1] + d.anglesUV[2], 180.0, 1e-9);
      total += d.area3D;
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(d.sites[k], 0);  // relocate: the border vertices are the fixed sites
        if (method == RemeshMethod::Retriangulate) EXPECT_TRUE(d.atSite[k]);
      }
    }
    EXPECT_NEAR(total, surfaceArea(view.output), 1e-12);
    // "area share 3D / UV" r = (3D share) / (UV share): weighted by the UV shares, the 3D
    // shares, which sum to 1.
    EXPECT_NEAR(totalUV, mapArea(view.output, view.outputUV), 1e-12);
    EXPECT_NEAR(shares / totalUV, 1.0, 1e-9);
  }
}

// A triangle pinned in one iteration is found again in another by its corners' sites: the
// triangulation changes, and the triangle's number with it (a pin by number showed another
// triangle at each iteration).
TEST(Inspection, ATriangleIsFoundAgainByItsCornersSites) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const IterationView last = replay.view(7);
  int renumbered = 0, gone = 0;
  for (int f = 0; f < static_cast<int>(last.output.triangles.size()); ++f) {
    const TriangleCorners corners = cornersOf(last, f);
    EXPECT_EQ(triangleWithCorners(last, corners), f);
    const TriangleDetails there = describeTriangle(last, f);
    for (int s : corners) EXPECT_NE(std::find(there.sites.begin(), there.sites.end(), s), there.sites.end());
    const int first = triangleWithCorners(replay.view(0), corners);
    if (first < 0) ++gone;
    else if (first != f) {
      ++renumbered;
      TriangleCorners atFirst = describeTriangle(replay.view(0), first).sites;
      std::sort(atFirst.begin(), atFirst.end());
      EXPECT_EQ(atFirst, corners);
    }
  }
  EXPECT_GT(renumbered, 100);  // the same sites' triangle, under another number
  EXPECT_GT(gone, 0);          // corners that made no triangle at iteration 0
}

// A triangle of a mesh with no map (the final result): its 3D numbers and its corners'
// valences, border ones said as such; nothing of a map or of sites.
TEST(Inspection, AFinalTriangleHasItsValencesAndNoMap) {
  Mesh fan;  // five triangles around vertex 0, a pentagon's corners on the border
  fan.points.push_back(Vec3(0, 0, 0));
  for (int k = 0; k < 5; ++k) fan.points.push_back(Vec3(std::cos(0.4 * M_PI * k), std::sin(0.4 * M_PI * k), 0));
  for (int k = 0; k < 5; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 5});
  const TriangleDetails d = describeTriangle(fan, 2);
  EXPECT_EQ(d.index, 2);
  EXPECT_EQ(d.corners, (Triangle{0, 3, 4}));
  EXPECT_EQ(d.valences, (std::array<int, 3>{5, 3, 3}));
  EXPECT_EQ(d.onBorder, (std::array<bool, 3>{false, true, true}));
  EXPECT_NEAR(d.angles3D[0], 72.0, 1e-9);
  EXPECT_NEAR(d.minAngle, 54.0, 1e-9);
  EXPECT_NEAR(d.area3D, 0.5 * std::sin(0.4 * M_PI), 1e-12);
  EXPECT_EQ(d.areaUV, 0.0);
  for (int s : d.sites) EXPECT_EQ(s, -1);
  EXPECT_EQ(describeTriangle(fan, 5).index, -1);
}

TEST(Inspection, PickingTrianglesInUVAndAlongARay) {
  const Recording& r = uniformRun(RemeshMethod::Retriangulate).recording;
  Replay replay(r);
  const IterationView& view = replay.view(6);
  for (int f : {0, 33, 250}) {
    const Triangle& t = view.output.triangles[f];
    const Vec2 uv = (view.outputUV[t[0]] + view.outputUV[t[1]] + view.outputUV[t[2]]) / 3.0;
    EXPECT_EQ(triangleAtUV(view, uv), f);
    const Vec3 centre =
        (view.output.points[t[0]] + view.output.points[t[1]] + view.output.points[t[2]]) / 3.0;
    const Vec3 normal = (view.output.points[t[1]] - view.output.points[t[0]])
                            .cross(view.output.points[t[2]] - view.output.points[t[0]])
                            .normalized();
    // From just above the triangle, looking down at it: the sphere cap is convex, so nothing
    // else is nearer.
    EXPECT_EQ(triangleOnRay(view.output, centre + 1e-3 * normal, -normal), f);
  }
  EXPECT_EQ(triangleAtUV(view, Vec2(-1, -1)), -1);
  EXPECT_EQ(triangleOnRay(view.output, Vec3(100, 100, 100), Vec3(1, 0, 0)), -1);
}
