#include "fit.h"
#include "metrics.h"
#include "mesh_io.h"
#include "pipeline.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>

using namespace lloydscope;

namespace {
double smallestAngle(const Mesh& mesh) { return measureQuality(mesh).minAngle; }
}  // namespace

// Two polyhedra with their vertices on the unit sphere, a coarse and a fine one: each coarse
// triangle cuts under the fine surface by about its sagitta. Fitted, the coarse one lies on
// both sides of the fine one, nearer at its farthest and far nearer on average.
TEST(Fit, ACoarseSphereComesNearerToAFineOne) {
  const Mesh fine = test::cube(24, true);
  Mesh coarse = test::cube(5, true);  // only its 8 corners are vertices of the fine one
  const Fidelity before = measureFidelity(coarse, fine);
  const double anglesBefore = smallestAngle(coarse);
  const FitResult r = fitToSurface(coarse, fine);
  const Fidelity after = measureFidelity(coarse, fine);
  // Closed: no border. Of the rest, a move that would sharpen a triangle already under the
  // guard's angle (near the cube's corners) is not made.
  EXPECT_GT(r.moved, coarse.vertexCount() / 2);
  EXPECT_GT(r.meanPercent, 0);
  EXPECT_LT(after.hausdorffPercent, 0.7 * before.hausdorffPercent);
  EXPECT_LT(after.rmsPercent, 0.6 * before.rmsPercent);
  EXPECT_GE(smallestAngle(coarse), std::min(anglesBefore, FitOptions{}.keepAngle) - 1e-9);
  int out = 0;
  for (const Vec3& p : coarse.points) out += p.norm() > 1.0 + 1e-12;
  EXPECT_EQ(out, r.moved);  // every move is out of the sphere
}

// A grid lifted off a plane is put back on it (the moves' signs and sizes), its border and the
// plane's own points staying.
TEST(Fit, AGridAboveAPlaneComesBackOntoIt) {
  const Mesh input = test::grid(12);
  Mesh result = test::grid(5);  // the same unit square, coarser
  const std::vector<bool> border = vertexEdges(result).onBoundary;
  for (int v = 0; v < result.vertexCount(); ++v)
    if (!border[v]) result.points[v].z() = 0.02;
  const FitResult r = fitToSurface(result, input);
  int inside = 0;
  for (int v = 0; v < result.vertexCount(); ++v) {
    EXPECT_NEAR(result.points[v].z(), 0.0, 0.004) << v;  // most of the way
    inside += !border[v];
  }
  EXPECT_EQ(r.moved, inside);
  const Mesh flat = test::grid(5);
  Mesh unmoved = flat;
  EXPECT_EQ(fitToSurface(unmoved, input).moved, 0);  // already on it: nothing to gain
  EXPECT_EQ(unmoved.points, flat.points);
}

// On a long flat strip the border's moves were rounding, 1.4e-15 of a diagonal of 20, and the
// report said 149 border vertices were moved: a move under a billionth of the diagonal is none.
TEST(Fit, RoundingIsNoMove) {
  Mesh input = test::grid(12), result = test::grid(5);
  for (Mesh* m : {&input, &result})
    for (Vec3& p : m->points) p = Vec3(20 * p.x() + 0.1, 0.6 * p.y() - 0.3, 0.8 * p.y() + 0.7);  // tilted
  const Mesh before = result;
  const FitResult r = fitToSurface(result, input);
  double farthest = 0;
  for (int v = 0; v < result.vertexCount(); ++v) farthest = std::max(farthest, (result.points[v] - before.points[v]).norm());
  EXPECT_LT(farthest, 1e-12);
  EXPECT_EQ(r.moved, 0) << farthest;
  EXPECT_EQ(r.borderMoved, 0);
}

// A vertex on an input vertex (a snapped tip) stays on it, no move leaves a smaller angle than
// the guard's, and the border's vertices move only across the border, by little.
TEST(Fit, KeepsSnappedVerticesAndAnglesAndMovesTheBorderOnlyAcrossIt) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  RemeshOptions o;
  o.sites.count = 300;
  o.fit = false;
  Mesh result = remesh(input, o, "bumpy_disk.off").output;
  const double anglesBefore = smallestAngle(result);
  const std::vector<bool> border = vertexEdges(result).onBoundary;
  const int tip = static_cast<int>(std::find(border.begin(), border.end(), false) - border.begin());
  // As snapToTips leaves a vertex: on the input vertex nearest to it.
  const Vec3 at = result.points[tip];
  result.points[tip] = *std::min_element(input.points.begin(), input.points.end(), [&](const Vec3& a, const Vec3& b) {
    return (a - at).squaredNorm() < (b - at).squaredNorm();
  });
  const std::vector<Vec3> before = result.points;
  const FitResult r = fitToSurface(result, input);
  EXPECT_GT(r.moved, result.vertexCount() / 2);
  EXPECT_GT(r.borderMoved, 0);
  EXPECT_EQ(result.points[tip], before[tip]);
  // The bumpy disk's border is a circle in the plane z = 0 around the z axis: its vertices
  // move along their radius (across the border), by a small part of an edge.
  for (int v = 0; v < result.vertexCount(); ++v) {
    if (!border[v]) continue;
    const Vec3 move = result.points[v] - before[v], radial = Vec3(before[v].x(), before[v].y(), 0).normalized();
    EXPECT_LT((move - move.dot(radial) * radial).norm(), 1e-3 * before[v].norm()) << v;
    EXPECT_LT(move.norm(), 0.01 * before[v].norm()) << v;
  }
  // The snap may have sharpened a triangle: the guard holds against the smaller of the two.
  EXPECT_GE(smallestAngle(result), std::min({anglesBefore, smallestAngle(Mesh{before, result.triangles}),
                                             FitOptions{}.keepAngle}) - 1e-9);
}

// A hexagon of six equilateral triangles whose corners are on a fine disk's circle (not on its
// vertices, which would hold them): each border edge cuts
// inside the circle by its sagitta, the Hausdorff distance. Fitted, the border moves out
// across itself, its chords crossing the circle, and the distance falls by a third; without
// FitOptions::border it stays where it was.
TEST(Fit, TheBorderComesNearerToACurvedInputBorder) {
  const Mesh fine = test::polarDisk(240, 20);
  const Mesh coarse = test::polarDisk(6, 1, M_PI / 240);  // between the fine one's vertices
  const double before = measureFidelity(coarse, fine).hausdorffPercent;
  Mesh fitted = coarse;
  const FitResult r = fitToSurface(fitted, fine);
  EXPECT_EQ(r.borderMoved, 6);
  for (int v = 1; v <= 6; ++v) EXPECT_GT(fitted.points[v].norm(), 1.0) << v;
  EXPECT_LT(measureFidelity(fitted, fine).hausdorffPercent, 0.75 * before);
  Mesh unfitted = coarse;
  FitOptions noBorder;
  noBorder.border = false;
  EXPECT_EQ(fitToSurface(unfitted, fine, noBorder).borderMoved, 0);
  EXPECT_EQ(unfitted.points, coarse.points);
}

// The hexagon again, and a speck of the input just inside one of its chords (another part of
// the input's border, nearer than the circle): each border vertex still moves out towards its
// own arc of the circle, as far as the others.
TEST(Fit, TheBorderFollowsItsOwnArcOfTheInputsBorder) {
  Mesh fine = test::polarDisk(240, 20);
  const Vec3 speck(0.88, 0.011, 0);
  append(fine, Mesh{{speck, speck + Vec3(0.01, 0, 0), speck + Vec3(0, 0.01, 0)}, {{0, 1, 2}}});
  Mesh hexagon = test::polarDisk(6, 1, M_PI / 6 + M_PI / 240);  // vertices 6 and 1 span the speck
  fitToSurface(hexagon, fine);
  for (int v : {1, 6}) EXPECT_NEAR(hexagon.points[v].norm(), hexagon.points[3].norm(), 0.005) << v;
  EXPECT_GT(hexagon.points[3].norm(), 1.05);
}

// remesh() fits by default: the same triangles, closer to the input, no rounder or less round
// by more than a tenth of a degree on average.
TEST(Fit, RemeshFitsTheResultByDefault) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  RemeshOptions o;
  o.sites.count = 400;
  const RemeshResult fitted = remesh(input, o, "bumpy_disk.off");
  o.fit = false;
  const RemeshResult unfitted = remesh(input, o, "bumpy_disk.off");
  EXPECT_EQ(fitted.output.triangles, unfitted.output.triangles);
  EXPECT_GT(fitted.fit.moved, 0);
  EXPECT_EQ(unfitted.fit.moved, 0);
  EXPECT_LT(fitted.fidelity.rmsPercent, 0.9 * unfitted.fidelity.rmsPercent);
  EXPECT_LE(fitted.fidelity.hausdorffPercent, unfitted.fidelity.hausdorffPercent);
  EXPECT_NEAR(fitted.after.avgMinAngle, unfitted.after.avgMinAngle, 0.1);
  EXPECT_FALSE(referencePreset(RemeshMethod::Retriangulate).fit);
}
