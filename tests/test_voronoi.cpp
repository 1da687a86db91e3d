#include "test_support.h"
#include "voronoi.h"

#include <numeric>
#include <random>

using namespace lloydscope;

namespace {

// The unit square as a parameter domain of two triangles, with a density given per corner.
Domain unitSquare(std::vector<double> density = {1, 1, 1, 1}) {
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}};
  return Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, triangles, vertexDensity(triangles, density));
}

// Formulas (2)-(4) of the reference, written out independently of the code under test.
void shoelace(const std::vector<Vec2>& p, double& area, Vec2& centroid) {
  area = 0;
  centroid = Vec2::Zero();
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2 &a = p[i], &b = p[(i + 1) % p.size()];
    const double c = a.x() * b.y() - b.x() * a.y();
    area += c / 2;
    centroid += (a + b) * c;
  }
  centroid /= 6 * area;
}

}  // namespace

TEST(Integrals, UniformDensityIsTheShoelaceFormula) {
  const std::vector<Vec2> pentagon = {{0, 0}, {4, 0}, {5, 2}, {2, 4}, {-1, 2}};
  double area;
  Vec2 centroid;
  shoelace(pentagon, area, centroid);
  const PolygonIntegrals i = integratePolygon(pentagon, std::vector<double>(5, 1.0), {0, 0});
  EXPECT_NEAR(i.area, area, 1e-12);
  EXPECT_NEAR(i.mass, area, 1e-12);
  EXPECT_NEAR((i.moment / i.mass - centroid).norm(), 0.0, 1e-12);
}

TEST(Integrals, KnownPolygonCentroid) {
  // Trapezoid (0,0) (4,0) (3,2) (1,2): area 6, centroid (2, 8/9).
  const PolygonIntegrals i =
      integratePolygon({{0, 0}, {4, 0}, {3, 2}, {1, 2}}, std::vector<double>(4, 1.0), {0, 0});
  EXPECT_DOUBLE_EQ(i.area, 6.0);
  EXPECT_NEAR(i.moment.x() / i.mass, 2.0, 1e-12);
  EXPECT_NEAR(i.moment.y() / i.mass, 8.0 / 9.0, 1e-12);
}

TEST(Integrals, LinearDensityOnTheUnitSquare) {
  // rho = x: mass 1/2, ∫ x rho = 1/3, ∫ y rho = 1/4, so the centroid is (2/3, 1/2).
  // Energy about (0,0): ∫ x (x^2 + y^2) = 1/4 + 1/6.
  const PolygonIntegrals i =
      integratePolygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {0, 1, 1, 0}, {0, 0});
  EXPECT_NEAR(i.mass, 0.5, 1e-14);
  EXPECT_NEAR(i.moment.x(), 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(i.moment.y(), 0.25, 1e-14);
  EXPECT_NEAR(i.energy, 0.25 + 1.0 / 6.0, 1e-14);
}

TEST(Integrals, UniformEnergyOfASquareAboutItsCentre) {
  const PolygonIntegrals i =
      integratePolygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, std::vector<double>(4, 1.0), {0.5, 0.5});
  EXPECT_NEAR(i.energy, 1.0 / 6.0, 1e-14);
}

TEST(BoundedCells, FourSitesAtTheCentresOfA2x2GridAreCentroidal) {
  const Domain domain = unitSquare();
  const std::vector<Vec2> sites = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
  const auto cells = computeCells(domain, sites, CellDetail::Geometry);
  for (size_t i = 0; i < sites.size(); ++i) {
    EXPECT_NEAR(cells[i].area, 0.25, 1e-12);
    EXPECT_NEAR((cells[i].centroid - sites[i]).norm(), 0.0, 1e-12);
    // Two edge neighbours, and the diagonal one if the (cocircular) Delaunay picked that diagonal.
    EXPECT_GE(cells[i].neighbours.size(), 2u);
  }
}

TEST(BoundedCells, CellsTileTheDomainAndMassesAddUp) {
  const Domain domain = unitSquare({1, 2, 3, 4});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> sites;
  for (int i = 0; i < 200; ++i) sites.emplace_back(u(rng), u(rng));
  double area = 0, mass = 0;
  for (const BoundedCell& c : computeCells(domain, sites, CellDetail::Integrals)) {
    area += c.area;
    mass += c.mass;
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_NEAR(mass, 0.5 * 2.0 + 0.5 * 8.0 / 3.0, 1e-12);  // ∫ rho over each triangle
}

TEST(BoundedCells, NonConvexDomainIsClippedToItsTriangles) {
  // An L-shaped domain: the unit square minus its top-right quarter, area 3/4.
  const Domain domain({{0, 0}, {0.5, 0}, {1, 0}, {0, 0.5}, {0.5, 0.5}, {1, 0.5}, {0, 1}, {0.5, 1}},
                      {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}}, {});
  const std::vector<Vec2> sites = {{0.2, 0.2}, {0.8, 0.2}, {0.2, 0.8}, {0.6, 0.6}};
  double area = 0;
  for (const BoundedCell& c : computeCells(domain, sites, CellDetail::Geometry)) area += c.area;
  EXPECT_NEAR(area, 0.75, 1e-12);
}

TEST(BoundedCells, HintsDoNotChangeABit) {
  const Domain domain = unitSquare({1, 2, 3, 4});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec2> sites;
  for (int i = 0; i < 600; ++i) sites.emplace_back(u(rng), u(rng));
  CellHints hints;
  hints.triangle.assign(sites.size(), 1);
  hints.order.resize(sites.size());  // the reverse order: a bad one, and not CGAL's
  std::iota(hints.order.rbegin(), hints.order.rend(), 0);
  const auto a = computeCells(domain, sites, CellDetail::Integrals);
  const auto b = computeCells(domain, sites, CellDetail::Integrals, &hints);
  // Nor does the number of threads the cells are split over.
  const auto c = computeCells(domain, sites, CellDetail::Integrals, nullptr, 1);
  const auto d = computeCells(domain, sites, CellDetail::Integrals, nullptr, 3);
  for (size_t i = 0; i < sites.size(); ++i)
    for (const auto* other : {&b, &c, &d}) {
      EXPECT_EQ(a[i].mass, (*other)[i].mass);
      EXPECT_EQ(a[i].energy, (*other)[i].energy);
      EXPECT_EQ(a[i].centroid, (*other)[i].centroid);
    }
}

// The cells and their Delaunay neighbours, bit for bit.
void expectSameCells(const std::vector<BoundedCell>& a, const std::vector<BoundedCell>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].mass, b[i].mass) << "cell " << i;
    EXPECT_EQ(a[i].energy, b[i].energy) << "cell " << i;
    EXPECT_EQ(a[i].centroid, b[i].centroid) << "cell " << i;
    EXPECT_EQ(a[i].voronoi, b[i].voronoi) << "cell " << i;
    EXPECT_EQ(a[i].neighbours, b[i].neighbours) << "cell " << i;
  }
}

TEST(BoundedCells, TheLastTriangulationMovedWithTheSitesGivesTheCellsOfANewOne) {
  const Domain domain = unitSquare({1, 2, 3, 4});
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> shake(-0.01, 0.01), nudge(-1e-3, 1e-3), jump(-0.2, 0.2);
  std::vector<Vec2> sites;  // a shaken 20 x 20 grid: spread out, as Lloyd's sites are
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) sites.emplace_back((i + 0.5) / 20 + shake(rng), (j + 0.5) / 20 + shake(rng));
  CellHints hints;
  computeCells(domain, sites, CellDetail::Geometry, &hints);
  ASSERT_EQ(hints.triangulation.builds, 1);
  // Small moves, as Lloyd's iterations make: some edges flip, no triangle turns over.
  for (int step = 0; step < 3; ++step) {
    for (Vec2& s : sites) s += Vec2(nudge(rng), nudge(rng));
    expectSameCells(computeCells(domain, sites, CellDetail::Geometry, &hints),
                    computeCells(domain, sites, CellDetail::Geometry));
  }
  EXPECT_EQ(hints.triangulation.builds, 1);
  // Sites that jump past each other turn triangles over: it is built again.
  for (Vec2& s : sites) s = (s + Vec2(jump(rng), jump(rng))).cwiseMax(0.0).cwiseMin(1.0);
  expectSameCells(computeCells(domain, sites, CellDetail::Geometry, &hints),
                  computeCells(domain, sites, CellDetail::Geometry));
  EXPECT_EQ(hints.triangulation.builds, 2);
}

TEST(BoundedCells, SitesMovedOntoACocircularGridGetTheCellsOfANewTriangulation) {
  // A square grid: every four sites of a square are cocircular, and which diagonal each square
  // gets is CGAL's symbolic perturbation's choice. Shaken, each square's diagonal is the
  // shaking's; moved onto the grid, the flips must make the perturbation's choice. (The outer
  // rows stay shaken: three sites of a straight outer row would make a flat triangle, and a
  // new triangulation.)
  const Domain domain = unitSquare({1, 3, 2, 5});
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shake(-1e-3, 1e-3);
  std::vector<Vec2> grid, shaken;
  for (int i = 0; i < 12; ++i)
    for (int j = 0; j < 12; ++j) {
      shaken.push_back(Vec2((i + 1) / 16.0, (j + 1) / 16.0) + Vec2(shake(rng), shake(rng)));
      const bool outer = i == 0 || j == 0 || i == 11 || j == 11;
      grid.push_back(outer ? shaken.back() : Vec2((i + 1) / 16.0, (j + 1) / 16.0));
    }
  CellHints hints;
  computeCells(domain, shaken, CellDetail::Geometry, &hints);
  expectSameCells(computeCells(domain, grid, CellDetail::Geometry, &hints),
                  computeCells(domain, grid, CellDetail::Geometry));
  EXPECT_EQ(hints.triangulation.builds, 1);
}

// Sites outside the unit square put the dummy sites elsewhere: the triangulation is built anew,
// and the cells are still those of a new one.
TEST(BoundedCells, SitesLeavingTheUnitSquareGetANewTriangulation) {
  const Domain domain = unitSquare();
  std::vector<Vec2> sites = {{0.2, 0.2}, {0.8, 0.3}, {0.4, 0.7}, {0.7, 0.8}};
  CellHints hints;
  computeCells(domain, sites, CellDetail::Geometry, &hints);
  sites[1] = {1.4, 0.3};
  expectSameCells(computeCells(domain, sites, CellDetail::Geometry, &hints),
                  computeCells(domain, sites, CellDetail::Geometry));
  EXPECT_EQ(hints.triangulation.builds, 2);
}

TEST(BoundedCells, CellsTileAFineDomainExactly) {
  // Cells much larger and much smaller than the parameter triangles, over a 12 x 12 grid.
  const Domain domain = test::gridDomain(12, [](const Vec3& p) { return 1.0 + 3.0 * p.x() * p.y(); });
  double domainMass = 0;
  for (size_t t = 0; t < domain.triangles().size(); ++t) {
    const Triangle& c = domain.triangles()[t];
    const std::array<double, 3>& rho = domain.density()[t];
    domainMass += triangleArea(domain.uv()[c[0]], domain.uv()[c[1]], domain.uv()[c[2]]) *
                  (rho[0] + rho[1] + rho[2]) / 3.0;
  }
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int count : {7, 60, 900}) {
    std::vector<Vec2> sites;
    for (int i = 0; i < count; ++i) sites.emplace_back(u(rng), u(rng));
    double area = 0, mass = 0;
    for (const BoundedCell& c : computeCells(domain, sites, CellDetail::Integrals)) {
      area += c.area;
      mass += c.mass;
    }
    EXPECT_NEAR(area, 1.0, 1e-12) << count;
    EXPECT_NEAR(mass, domainMass, 1e-12) << count;
  }
}

TEST(BoundedCells, VoronoiEdgesAreJoinedAcrossParameterTriangles) {
  // Four sites in general position over the unit square cut into 8x8x2 triangles: five
  // Voronoi edges, each one segment however many parameter triangles it crosses, and the
  // same diagram as over the square made of two triangles.
  const Mesh grid = test::grid(8);
  std::vector<Vec2> uv;
  for (const Vec3& p : grid.points) uv.emplace_back(p.x(), p.y());
  const std::vector<Vec2> sites = {{0.2, 0.3}, {0.7, 0.2}, {0.3, 0.8}, {0.75, 0.7}};
  auto totalLength = [](const std::vector<std::pair<Vec2, Vec2>>& edges) {
    double length = 0;
    for (const auto& [p, q] : edges) length += (q - p).norm();
    return length;
  };
  const Domain fine(uv, grid.triangles, {});
  const auto edges = voronoiEdges(fine, computeCells(fine, sites, CellDetail::Geometry));
  EXPECT_EQ(edges.size(), 5u);
  // Each edge bounds two cells: the outlines hold every edge twice.
  const auto cells = computeCells(fine, sites, CellDetail::Geometry);
  double outlines = 0;
  for (const BoundedCell& cell : cells) outlines += totalLength(cellOutline(fine, cell));
  EXPECT_NEAR(outlines, 2 * totalLength(edges), 1e-12);
  const Domain coarse({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, {});
  const auto reference = voronoiEdges(coarse, computeCells(coarse, sites, CellDetail::Geometry));
  EXPECT_EQ(reference.size(), 5u);
  EXPECT_NEAR(totalLength(edges), totalLength(reference), 1e-12);
}

TEST(BoundedCells, VoronoiEdgesAreTheLinesBetweenCellsEachOnce) {
  // Four sites in the 2x2 grid of the unit square: the diagram is the lines x = 1/2 and
  // y = 1/2, total length 2, split where they cross the domain's diagonal and each other.
  const Domain domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, {});
  const auto cells =
      computeCells(domain, {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}}, CellDetail::Geometry);
  double length = 0;
  for (const auto& [p, q] : voronoiEdges(domain, cells)) {
    length += (q - p).norm();
    const bool vertical = std::abs(p.x() - 0.5) < 1e-12 && std::abs(q.x() - 0.5) < 1e-12;
    const bool horizontal = std::abs(p.y() - 0.5) < 1e-12 && std::abs(q.y() - 0.5) < 1e-12;
    EXPECT_TRUE(vertical || horizontal) << p.transpose() << " - " << q.transpose();
  }
  EXPECT_NEAR(length, 2.0, 1e-12);
}

// A vertex whose only triangle is flat in the map (an ear of a straight border, here the
// middle of the bottom side) is not in the domain's index; located, it is at its own corner of
// that ear, not on the edge of the triangle beside it (lifted there, it would land between that
// edge's ends: a seam copy at a slit's tip lifted off its seam, which then did not stitch).
TEST(Domain, AVertexWhoseOnlyTriangleIsFlatIsLocatedAtItsOwnCorner) {
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}};
  const Domain domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}}, triangles, {});
  for (const Location& l : {domain.locate(Vec2(0.5, 0)), domain.locate(Vec2(0.5, 0), 0)}) {
    ASSERT_EQ(l.triangle, 2);
    EXPECT_EQ(l.weights, Eigen::Vector3d(0, 1, 0));  // all on vertex 4
  }
  const Location beside = domain.locate(Vec2(0.5, 1e-9));  // any other point: as before
  EXPECT_EQ(beside.triangle, 0);
}

// A site on such a vertex (a fixed border site of a square map, the reference's) has its cell:
// its walk started in the flat ear, which has no neighbours, and the cell came out empty, a
// hole of 1.3% of the domain in a 6x6 grid with an ear (found by a review of core/).
TEST(BoundedCells, ASiteOnAVertexOfFlatTrianglesOnlyHasItsCell) {
  const std::vector<Triangle> triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}};
  const Domain domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}}, triangles, {});
  ASSERT_EQ(domain.locateInArea(Vec2(0.5, 0)).triangle, 0);
  const std::vector<Vec2> sites = {{0.5, 0}, {0.5, 0.6}, {0.2, 0.8}};
  CellHints hints;
  for (int pass = 0; pass < 2; ++pass) {  // without hints, then from the first pass's
    const std::vector<BoundedCell> cells = computeCells(domain, sites, CellDetail::Integrals, &hints);
    double area = 0;
    for (const BoundedCell& c : cells) area += c.area;
    EXPECT_NEAR(area, 1.0, 1e-12) << pass;
    EXPECT_GT(cells[0].area, 0.2) << pass;
  }
}
