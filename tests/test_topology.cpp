// Components, boundary loops, Euler characteristic and genus of small hand-built meshes.

#include "mesh_io.h"
#include "test_support.h"
#include "topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace lloydscope {
namespace {

// (n+1) x (n+1) vertices in the plane, two counter-clockwise triangles per cell; cells for which
// keep(i, j) is false are left out.
template <class Keep>
Mesh grid(int n, Keep keep) {
  Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.points.emplace_back(i, j, 0);
  }
  const auto v = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      if (!keep(i, j)) continue;
      mesh.triangles.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1)});
      mesh.triangles.push_back({v(i, j), v(i + 1, j + 1), v(i, j + 1)});
    }
  }
  return mesh;
}

Mesh grid(int n) {
  return grid(n, [](int, int) { return true; });
}

Mesh singleTriangle() { return Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}}; }

Mesh tetrahedron() {
  return Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}};
}

// A 4 x 4 grid whose opposite sides are glued, placed on a torus in space.
Mesh torus() {
  const int n = 4;
  const double pi = std::acos(-1.0);
  Mesh mesh;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / n;
      mesh.points.emplace_back((2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v));
    }
  }
  const auto at = [n](int i, int j) { return (j % n) * n + (i % n); };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

std::string requireDiskError(const Mesh& mesh, const std::string& name) {
  try {
    requireDisk(mesh, name);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Topology, SingleTriangleIsADisk) {
  const Mesh mesh = singleTriangle();
  validateMesh(mesh, "triangle");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 1);
  EXPECT_EQ(t.genus, 0);
  ASSERT_EQ(t.boundaryLoops.size(), 1u);
  EXPECT_EQ(t.boundaryLoops[0], (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(t.isDisk());
  EXPECT_EQ(t.describe(), "a topological disk");
  EXPECT_NO_THROW(requireDisk(mesh, "triangle"));
}

TEST(Topology, GridIsADiskWithItsBoundaryInFaceOrder) {
  const Mesh mesh = grid(2);
  validateMesh(mesh, "grid");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 9 - 16 + 8);
  EXPECT_EQ(t.genus, 0);
  ASSERT_EQ(t.boundaryLoops.size(), 1u);
  // Counter-clockwise faces give a counter-clockwise outer boundary.
  EXPECT_EQ(t.boundaryLoops[0], (std::vector<int>{0, 1, 2, 5, 8, 7, 6, 3}));
  EXPECT_TRUE(t.isDisk());
  EXPECT_EQ(requireDiskError(mesh, "grid"), "");
}

TEST(Topology, TetrahedronIsClosedGenusZero) {
  const Mesh mesh = tetrahedron();
  validateMesh(mesh, "tetrahedron");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_EQ(t.genus, 0);
  EXPECT_TRUE(t.boundaryLoops.empty());
  EXPECT_FALSE(t.isDisk());
  EXPECT_EQ(t.describe(), "a closed surface of genus 0");
  EXPECT_EQ(requireDiskError(mesh, "tet.off"), "tet.off: not a topological disk: it is a closed surface of genus 0");
}

TEST(Topology, SquareAnnulusHasTwoBoundaryLoops) {
  const Mesh mesh = grid(3, [](int i, int j) { return !(i == 1 && j == 1); });
  validateMesh(mesh, "annulus");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 0);
  EXPECT_EQ(t.genus, 0);
  ASSERT_EQ(t.boundaryLoops.size(), 2u);
  std::vector<size_t> sizes = {t.boundaryLoops[0].size(), t.boundaryLoops[1].size()};
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes, (std::vector<size_t>{4, 12}));
  EXPECT_FALSE(t.isDisk());
  EXPECT_EQ(t.describe(), "a genus 0 surface with 2 boundary loops");
  EXPECT_EQ(requireDiskError(mesh, "annulus.obj"),
            "annulus.obj: not a topological disk: it is a genus 0 surface with 2 boundary loops");
}

TEST(Topology, TwoSeparateTrianglesAreTwoComponents) {
  const Mesh mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}}, {{0, 1, 2}, {3, 4, 5}}};
  validateMesh(mesh, "two");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 2);
  EXPECT_EQ(t.boundaryLoops.size(), 2u);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_FALSE(t.isDisk());
  EXPECT_EQ(t.describe(), "2 connected components");
  EXPECT_EQ(requireDiskError(mesh, "two.ply"), "two.ply: not a topological disk: it has 2 connected components");
}

// An unused vertex between them is left out; each part keeps its vertices' order.
TEST(Topology, ComponentsSplitIntoMeshesOfTheirOwn) {
  const Mesh mesh{{{0, 0, 0}, {1, 0, 0}, {9, 9, 9}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}},
                  {{4, 5, 6}, {0, 1, 3}}};
  const std::vector<Mesh> parts = splitComponents(mesh);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].points, (std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_EQ(parts[0].triangles, (std::vector<Triangle>{{0, 1, 2}}));
  EXPECT_EQ(parts[1].points, (std::vector<Vec3>{{5, 0, 0}, {6, 0, 0}, {5, 1, 0}}));
  EXPECT_EQ(parts[1].triangles, (std::vector<Triangle>{{0, 1, 2}}));
  for (const Mesh& part : parts) EXPECT_TRUE(analyzeTopology(part).isDisk());
}

// Valences and border flags: a 2 x 2 grid split along its diagonals (the centre joined to all
// eight others but two corners), a tetrahedron, an unused vertex, and an edge of three faces,
// which is not a border edge.
TEST(Topology, VertexEdgesCountNeighboursAndBorders) {
  const Mesh grid = test::grid(2);  // vertex j * 3 + i at (i, j)
  const VertexEdges g = vertexEdges(grid);
  EXPECT_EQ(g.valence, (std::vector<int>{3, 4, 2, 4, 6, 4, 2, 4, 3}));
  for (int v = 0; v < 9; ++v) EXPECT_EQ(g.onBoundary[v], v != 4) << v;

  const Mesh tetrahedron{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {5, 5, 5}},
                         {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
  const VertexEdges t = vertexEdges(tetrahedron);
  EXPECT_EQ(t.valence, (std::vector<int>{3, 3, 3, 3, 0}));
  EXPECT_EQ(t.onBoundary, (std::vector<bool>(5, false)));

  const Mesh fin{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}};
  const VertexEdges f = vertexEdges(fin);  // edge 0-1 has three faces
  EXPECT_EQ(f.valence, (std::vector<int>{4, 4, 2, 2, 2}));
  EXPECT_EQ(f.onBoundary, (std::vector<bool>(5, true)));  // each also has an edge of one face
}

TEST(Topology, TorusIsClosedGenusOne) {
  const Mesh mesh = torus();
  validateMesh(mesh, "torus");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.eulerCharacteristic, 16 - 48 + 32);
  EXPECT_EQ(t.genus, 1);
  EXPECT_TRUE(t.boundaryLoops.empty());
  EXPECT_EQ(t.describe(), "a closed surface of genus 1");
  EXPECT_EQ(requireDiskError(mesh, "torus.off"), "torus.off: not a topological disk: it is a closed surface of genus 1");
}

TEST(Topology, TorusWithAHoleKeepsItsGenus) {
  Mesh mesh = torus();
  mesh.triangles.resize(mesh.triangles.size() - 2);  // open one cell
  validateMesh(mesh, "holed torus");
  const Topology t = analyzeTopology(mesh);
  EXPECT_EQ(t.genus, 1);
  ASSERT_EQ(t.boundaryLoops.size(), 1u);
  EXPECT_EQ(t.boundaryLoops[0].size(), 4u);
  EXPECT_EQ(t.describe(), "a genus 1 surface with 1 boundary loop");
}

TEST(Topology, EmptyMesh) {
  const Topology t = analyzeTopology(Mesh{});
  EXPECT_EQ(t.components, 0);
  EXPECT_EQ(t.describe(), "an empty mesh");
  EXPECT_EQ(requireDiskError(Mesh{}, "nothing.off"), "nothing.off: not a topological disk: it is an empty mesh");
}

}  // namespace
}  // namespace lloydscope
