#include "cvt_hessian.h"
#include "lloyd.h"
#include "test_support.h"

#include <algorithm>

using namespace lloydscope;

namespace {
Domain unitSquare() {
  return Domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, {});
}

// `count` sites on a spiral from the centre of the unit square outwards.
std::vector<Vec2> spiral(int count) {
  std::vector<Vec2> sites;
  for (int i = 0; i < count; ++i)
    sites.emplace_back(0.5 + 0.45 * std::cos(i * 2.4) * i / count,
                       0.5 + 0.45 * std::sin(i * 2.4) * i / count);
  return sites;
}
}  // namespace

class FourSites : public ::testing::TestWithParam<CvtSolver> {};

TEST_P(FourSites, ConvergeToTheCentresOfThe2x2Grid) {
  const Domain domain = unitSquare();
  LloydOptions options;
  options.solver = GetParam();
  options.percentThreshold = 1e-9;  // every site must be still
  LloydSolver solver(domain, {}, {{0.1, 0.2}, {0.6, 0.1}, {0.3, 0.55}, {0.9, 0.8}}, options);
  solver.run();
  ASSERT_TRUE(solver.converged());
  std::vector<Vec2> sites = solver.movableSites();
  std::sort(sites.begin(), sites.end(), [](const Vec2& a, const Vec2& b) {
    return a.y() < b.y() - 1e-3 || (std::abs(a.y() - b.y()) < 1e-3 && a.x() < b.x());
  });
  const std::vector<Vec2> expected = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
  for (size_t i = 0; i < 4; ++i) EXPECT_NEAR((sites[i] - expected[i]).norm(), 0.0, 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Solvers, FourSites,
                         ::testing::Values(CvtSolver::Lloyd, CvtSolver::Lbfgs,
                                           CvtSolver::Newton));

TEST(Lloyd, EnergyNeverIncreasesAndSitesMoveToCentroids) {
  const Domain domain = unitSquare();
  LloydOptions options;
  options.solver = CvtSolver::Lloyd;
  options.maxIterations = 30;
  std::vector<Vec2> sites;
  for (int i = 0; i < 30; ++i) sites.emplace_back(0.05 + 0.03 * i, 0.5 + 0.4 * std::sin(i));
  LloydSolver solver(domain, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, sites, options);
  solver.run();
  const auto& its = solver.iterations();
  ASSERT_EQ(its.size(), 30u);
  for (size_t k = 1; k < its.size(); ++k) {
    EXPECT_LE(its[k].energy, its[k - 1].energy * (1 + 1e-12));
    // Lloyd: site <- centroid, exactly, on the grid the sites live on.
    const auto before = computeCells(domain, allSites(solver.fixedSites(), its[k - 1].sites), CellDetail::Integrals);
    for (size_t i = 0; i < its[k].sites.size(); ++i)
      EXPECT_EQ(its[k].sites[i], snapToGrid(before[solver.fixedSites().size() + i].centroid));
    EXPECT_EQ(its[k].index, static_cast<int>(k));
  }
  EXPECT_EQ(solver.fixedSites().size(), 4u);
}

TEST(Lloyd, SitesLiveOnAGridThatPacksThemIntoEightBytes) {
  const Vec2 p(0.123456789012345, 0.987654321098765);
  const Vec2 q = snapToGrid(p);
  EXPECT_LE((q - p).cwiseAbs().maxCoeff(), 0.5 / 4294967295.0 + 1e-17);
  EXPECT_EQ(snapToGrid(q), q);  // on the grid already
  EXPECT_EQ(snapToGrid(Vec2(-0.5, 1.5)), Vec2(0, 1));
  const PackedSites packed({q, snapToGrid(Vec2(1, 0)), Vec2(0, 0)});
  ASSERT_EQ(packed.size(), 3u);
  EXPECT_EQ(packed[0], q);  // exactly
  EXPECT_EQ(packed.raw().size() * sizeof(std::uint32_t), 3u * 8);
  EXPECT_EQ(PackedSites::fromRaw(packed.raw()), packed);
  EXPECT_EQ(packed.unpack()[1], Vec2(1, 0));
}

TEST(Lloyd, LbfgsReachesALowerEnergyInFewerIterations) {
  const Domain domain = unitSquare();
  const std::vector<Vec2> sites = spiral(60);
  LloydOptions options;
  options.maxIterations = 40;
  options.solver = CvtSolver::Lloyd;
  LloydSolver lloyd(domain, {}, sites, options);
  lloyd.run();
  options.solver = CvtSolver::Lbfgs;
  LloydSolver lbfgs(domain, {}, sites, options);
  lbfgs.run();
  EXPECT_LT(lbfgs.iterations().back().energy, lloyd.iterations().back().energy);
  // ... and got below Lloyd's 40th energy in fewer than 40 iterations.
  const auto& its = lbfgs.iterations();
  const auto below = std::find_if(its.begin(), its.end(), [&](const IterationRecord& it) {
    return it.energy < lloyd.iterations().back().energy;
  });
  EXPECT_LT(below - its.begin(), 20);  // 13 here
}

// A run stops at its first iteration with fewer than percentThreshold % of the sites farther
// than distanceThreshold from their centroids, and not before: a looser share stops earlier
// with sites still moving, a looser distance stops earlier too.
TEST(Lloyd, ConvergenceUsesBothThresholds) {
  const Domain domain = unitSquare();
  auto run = [&](double distance, double percent) {
    LloydOptions options;
    options.solver = CvtSolver::Lloyd;
    options.maxIterations = 2000;
    options.distanceThreshold = distance;
    options.percentThreshold = percent;
    LloydSolver solver(domain, {}, spiral(40), options);
    solver.run();
    EXPECT_TRUE(solver.converged()) << distance << " " << percent;
    const auto& its = solver.iterations();
    for (size_t k = 0; k + 1 < its.size(); ++k) EXPECT_GE(100 * its[k].fractionMoving, percent) << k;
    EXPECT_LT(100 * its.back().fractionMoving, percent);
    return its;
  };
  const auto strict = run(1e-4, 5), loose = run(1e-4, 50), far = run(1e-3, 5);
  EXPECT_LT(loose.size(), strict.size());
  EXPECT_GT(loose.back().fractionMoving, 0.0);  // the share stopped it, some sites still moving
  EXPECT_LT(far.size(), strict.size());
}

TEST(CvtHessian, IsTheDerivativeOfTheGradient) {
  // Sites over a 6 x 6 grid of triangles with a density that varies linearly in each: the
  // Hessian times a direction must match central differences of the gradient 2 m (z - c).
  const Domain domain =
      test::gridDomain(6, [](const Vec3& p) { return 1.0 + 3.0 * p.x() + 2.0 * p.y() * p.y(); });
  const std::vector<Vec2> fixed = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0}};
  std::vector<Vec2> movable;
  for (int i = 0; i < 40; ++i)
    movable.emplace_back(0.5 + 0.45 * std::sin(1.7 * i), 0.5 + 0.45 * std::cos(2.3 * i + 0.4));
  auto gradient = [&](const std::vector<Vec2>& z, std::vector<std::vector<EdgeMoments>>* edges,
                      std::vector<double>* masses) {
    const auto cells = computeCells(domain, allSites(fixed, z), CellDetail::EdgeMoments);
    Eigen::VectorXd g(2 * z.size());
    for (size_t i = 0; i < z.size(); ++i) {
      const BoundedCell& c = cells[fixed.size() + i];
      g.segment<2>(2 * i) = 2 * c.mass * (z[i] - c.centroid);
      if (edges) edges->push_back(c.edges);
      if (masses) masses->push_back(c.mass);
    }
    return g;
  };
  std::vector<std::vector<EdgeMoments>> edges;
  std::vector<double> masses;
  gradient(movable, &edges, &masses);
  const CvtHessian h(fixed, movable, edges, masses);
  Eigen::VectorXd direction(2 * movable.size());
  for (int k = 0; k < direction.size(); ++k) direction[k] = std::sin(0.9 * k + 0.3);
  const double eps = 1e-6;
  std::vector<Vec2> plus = movable, minus = movable;
  for (size_t i = 0; i < movable.size(); ++i) {
    plus[i] += eps * direction.segment<2>(2 * i);
    minus[i] -= eps * direction.segment<2>(2 * i);
  }
  const Eigen::VectorXd difference =
      (gradient(plus, nullptr, nullptr) - gradient(minus, nullptr, nullptr)) / (2 * eps);
  const Eigen::VectorXd product = h * direction;
  EXPECT_LT((product - difference).norm(), 1e-5 * difference.norm());

  // And it is not the Lloyd part alone: the edges matter.
  EXPECT_GT((h.lloydDiagonal().cwiseProduct(direction) - difference).norm(),
            0.1 * difference.norm());
}

TEST(Lloyd, NewtonConvergesInFewerIterationsThanLbfgs) {
  const Domain domain = unitSquare();
  const std::vector<Vec2> sites = spiral(200);
  LloydOptions options;
  options.solver = CvtSolver::Lbfgs;
  LloydSolver lbfgs(domain, {}, sites, options);
  lbfgs.run();
  options.solver = CvtSolver::Newton;
  LloydSolver newton(domain, {}, sites, options);
  newton.run();
  ASSERT_TRUE(lbfgs.converged());
  ASSERT_TRUE(newton.converged());
  EXPECT_LT(2 * newton.iterations().size(), lbfgs.iterations().size());
  for (size_t k = 1; k < newton.iterations().size(); ++k)  // it descends, as L-BFGS does
    EXPECT_LE(newton.iterations()[k].energy, newton.iterations()[k - 1].energy);
}

TEST(Lloyd, ChangingThreadsMidRunChangesNoBit) {
  // What lets remesh() give a slit disk's two runs a core each once it knows it slits.
  const Domain domain = unitSquare();
  const std::vector<Vec2> sites = spiral(700);
  LloydOptions options;
  options.maxIterations = 6;
  options.threads = 2;
  LloydSolver steady(domain, {}, sites, options), switched(domain, {}, sites, options);
  steady.run();
  for (int k = 0; k < 3; ++k) switched.step();
  switched.setThreads(1);
  switched.run();
  EXPECT_EQ(switched.movableSites(), steady.movableSites());
}

// A site that a quasi-Newton step takes out of the domain, beyond the reach of its Voronoi
// cell, has an empty cell and a zero gradient: it stays there for good, and is not lifted. On
// the cow's map (area ratios up to 2·10⁴ near its border) two sites did so for 200 iterations.
// A density as steep at the border makes the steps overshoot there too (321 empty cells over
// the iterations before).
TEST(Lloyd, NoStepStrandsASiteOutsideTheDomain) {
  const Domain domain = test::gridDomain(40, [](const Vec3& p) {
    const double toBorder = std::min({p.x(), 1 - p.x(), p.y(), 1 - p.y()});
    return 1.0 + 1e6 * std::exp(-toBorder / 0.01);
  });
  LloydOptions options;
  options.solver = CvtSolver::Lbfgs;
  options.maxIterations = 150;
  LloydSolver solver(domain, {}, spiral(400), options);
  solver.run();
  int stranded = 0;
  for (const IterationRecord& it : solver.iterations())
    for (const BoundedCell& cell : computeCells(domain, it.sites.unpack(), CellDetail::Integrals))
      stranded += cell.mass == 0;
  EXPECT_EQ(stranded, 0);
}
