// repairMesh(): each defect it is for, repaired into a mesh validateMesh() accepts; and what it
// leaves alone.

#include "mesh_io.h"
#include "repair.h"

#include <gtest/gtest.h>

namespace lloydscope {
namespace {

Mesh meshOf(std::vector<Vec3> points, std::vector<Triangle> triangles) {
  Mesh m;
  m.points = std::move(points);
  m.triangles = std::move(triangles);
  return m;
}

// The unit square as two triangles, each with its own copy of the diagonal's ends: a seam left
// unwelded.
TEST(Repair, WeldsAnUnweldedSeam) {
  const Mesh seam = meshOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                           {{0, 1, 2}, {3, 4, 5}});
  EXPECT_THROW(validateMesh(seam, "seam"), Error);
  const RepairResult r = repairMesh(seam);
  EXPECT_EQ(r.weldedVertices, 2);
  EXPECT_EQ(r.mesh.vertexCount(), 4);
  EXPECT_EQ(r.mesh.faceCount(), 2);
  EXPECT_NO_THROW(validateMesh(r.mesh, "welded"));
}

// Face 1 has two corners at one position (a needle): welded, it repeats a corner and goes.
TEST(Repair, DropsAFaceOnTwoVerticesAtOnePosition) {
  const Mesh needle = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {{0, 1, 2}, {1, 3, 2}});
  const RepairResult r = repairMesh(needle);
  EXPECT_EQ(r.weldedVertices, 1);
  EXPECT_EQ(r.droppedFaces, 1);
  EXPECT_EQ(r.mesh.faceCount(), 1);
  EXPECT_NO_THROW(validateMesh(r.mesh, "needle"));
}

// Four faces, face 1 a cap whose corner `third` (vertex 3) is on the segment 1-2, from (1, 0, 0)
// to (0, 1, 0).
Mesh capWithCornerAt(const Vec3& third) {
  return meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, third, {1, 1, 0.5}}, {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {1, 4, 2}});
}

// Face 1 is a cap: its three corners are distinct but on a line (vertex 3 on the segment 1-2).
// Its long edge is flipped away or the face collapsed.
TEST(Repair, RemovesAFaceWithThreeCornersOnALine) {
  const Mesh cap = capWithCornerAt({0.25, 0.75, 0});
  EXPECT_THROW(validateMesh(cap, "cap"), Error);
  const RepairResult r = repairMesh(cap);
  EXPECT_EQ(r.degenerateFaces, 1);
  EXPECT_NO_THROW(validateMesh(r.mesh, "cap"));
}

// The same cap with vertex 3 on the line up to rounding only (0.9 and 0.1 are not exact in
// binary): readMesh() calls it zero area, CGAL's exact test a triangle, and the repair left it
// ("face 10 has zero area (left after the repair)").
TEST(Repair, RemovesAFaceFlatUpToRounding) {
  const Mesh cap = capWithCornerAt({0.9, 0.1, 0});
  EXPECT_THROW(validateMesh(cap, "cap"), Error);
  const RepairResult r = repairMesh(cap);
  EXPECT_EQ(r.degenerateFaces, 1);
  EXPECT_NO_THROW(validateMesh(r.mesh, "cap"));
}

TEST(Repair, TurnsAFaceAgainstItsNeighbour) {
  const Mesh flipped = meshOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 3, 2}});
  EXPECT_THROW(validateMesh(flipped, "flipped"), Error);
  const RepairResult r = repairMesh(flipped);
  EXPECT_EQ(r.turnedFaces, 1);
  EXPECT_NO_THROW(validateMesh(r.mesh, "flipped"));
}

// The first face of a fan is the odd one out: it turns, not the three others (CGAL's
// orient_polygon_soup alone keeps the first face and turns the rest).
TEST(Repair, TurnsTheFewerFaces) {
  const Mesh fan = meshOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.1}},
                          {{1, 0, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  const RepairResult r = repairMesh(fan);
  EXPECT_EQ(r.turnedFaces, 1);
  ASSERT_EQ(r.mesh.faceCount(), 4);
  for (const Triangle& t : r.mesh.triangles) EXPECT_GT(faceNormal(r.mesh, t).z(), 0);
}

// A sound mesh, and a closed one touching itself at a point (two tetrahedra sharing a corner's
// position, each with its own copy): nothing to do, the very same mesh back.
TEST(Repair, LeavesASoundMeshAsItIs) {
  const Mesh square = meshOf({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  const Mesh touching = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                               {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6}});
  for (const Mesh& m : {square, touching}) {
    const RepairResult r = repairMesh(m);
    EXPECT_FALSE(r.changed());
    EXPECT_EQ(r.mesh.points, m.points);
    EXPECT_EQ(r.mesh.triangles, m.triangles);
  }
}

}  // namespace
}  // namespace lloydscope
