#include "density.h"
#include "parameterization.h"
#include "test_support.h"

#include <Eigen/Dense>

using namespace lloydscope;

namespace {

// Residual of the best similarity (rotation, scale, translation) taking `from` to `to`.
double similarityResidual(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  // Solve [x -y 1 0; y x 0 1] [a b tx ty]^T = to, least squares.
  Eigen::MatrixXd A(2 * from.size(), 4);
  Eigen::VectorXd b(2 * from.size());
  for (size_t i = 0; i < from.size(); ++i) {
    A.row(2 * i) << from[i].x(), -from[i].y(), 1, 0;
    A.row(2 * i + 1) << from[i].y(), from[i].x(), 0, 1;
    b(2 * i) = to[i].x();
    b(2 * i + 1) = to[i].y();
  }
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(b);
  return (A * x - b).cwiseAbs().maxCoeff();
}

std::vector<Vec2> planar(const Mesh& m) {
  std::vector<Vec2> p;
  for (const Vec3& q : m.points) p.emplace_back(q.x(), q.y());
  return p;
}

}  // namespace

class PlanarGrid : public ::testing::TestWithParam<ParamMethod> {};

TEST_P(PlanarGrid, IsReproducedUpToSimilarity) {
  const Mesh mesh = test::grid(8, 3.0);
  const Parameterization p = parameterize(mesh, {GetParam(), Border::Square}, "grid");
  EXPECT_LT(similarityResidual(planar(mesh), p.uv), 1e-9);
  EXPECT_NEAR(p.distortion.minAreaRatio, 1.0, 1e-6);
  EXPECT_NEAR(p.distortion.maxAreaRatio, 1.0, 1e-6);
  EXPECT_EQ(p.boundaryLoop.size(), 32u);
}

INSTANTIATE_TEST_SUITE_P(Methods, PlanarGrid,
                         ::testing::Values(ParamMethod::Authalic, ParamMethod::Conformal,
                                           ParamMethod::MeanValue, ParamMethod::Tutte,
                                           ParamMethod::Lscm));

TEST(Parameterization, CircleBorderPutsTheBorderOnACircle) {
  const Mesh mesh = test::grid(6);
  const Parameterization p = parameterize(mesh, {ParamMethod::Conformal, Border::Circle}, "g");
  for (int v : p.boundaryLoop) EXPECT_NEAR((p.uv[v] - Vec2(0.5, 0.5)).norm(), 0.5, 1e-9);
}

TEST(Parameterization, BoundaryLoopIsCounterClockwiseInUV) {
  const Parameterization p = parameterize(test::grid(5), {}, "g");
  double area = 0;
  for (size_t i = 0; i < p.boundaryLoop.size(); ++i) {
    const Vec2 &a = p.uv[p.boundaryLoop[i]], &b = p.uv[p.boundaryLoop[(i + 1) % p.boundaryLoop.size()]];
    area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_GT(area, 0);
}

TEST(Parameterization, RefusesAClosedSurfaceAndSaysWhatItIs) {
  Mesh tetrahedron;
  tetrahedron.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  try {
    parameterize(tetrahedron, {}, "tet.off");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("tet.off"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("closed"), std::string::npos) << e.what();
  }
}

TEST(Parameterization, OrientationIsPositiveEverywhere) {
  Mesh mesh = test::grid(6);
  for (Vec3& p : mesh.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y()) * 0.3;
  for (ParamMethod m : {ParamMethod::Authalic, ParamMethod::Conformal, ParamMethod::MeanValue,
                        ParamMethod::Tutte, ParamMethod::Lscm}) {
    const Parameterization p = parameterize(mesh, {m, Border::Circle}, "bumpy");
    for (const Triangle& t : mesh.triangles)
      EXPECT_GT(triangleArea(p.uv[t[0]], p.uv[t[1]], p.uv[t[2]]), 0.0) << toString(m);
  }
}

TEST(Density, UniformIsOneAndAreaIsOneForAnIsometricMap) {
  const Mesh mesh = test::grid(6, 2.0);
  const Parameterization p = parameterize(mesh, {ParamMethod::Tutte, Border::Square}, "g");
  for (double d : computeDensity(mesh, p.uv, {DensityKind::Uniform})) EXPECT_EQ(d, 1.0);
  for (double d : computeDensity(mesh, p.uv, {DensityKind::Area})) EXPECT_NEAR(d, 1.0, 1e-9);
}

TEST(Density, AreaDensityIsTheSquaredAreaRatio) {
  // Stretch the grid by 2 in x: the map to UV is then affine with uniform ratio, except that
  // we give the UVs of the unstretched grid, so the 3D/UV ratio is 2 everywhere -> density 1
  // after normalization; doubling only the right half makes that half 4x denser (2^2).
  Mesh mesh = test::grid(4);
  std::vector<Vec2> uv;
  for (const Vec3& p : mesh.points) uv.emplace_back(p.x(), p.y());
  for (Vec3& p : mesh.points)
    if (p.x() > 0.5) p.x() = 0.5 + 2 * (p.x() - 0.5);
  const std::vector<double> d = areaDensity(mesh, uv);
  const int left = 2 * 5 + 1, right = 2 * 5 + 3;  // (0.25, 0.5) and (0.75, 0.5)
  EXPECT_NEAR(d[right] / d[left], 4.0, 1e-9);
}

TEST(Density, CurvatureOfAUnitSphereCap) {
  // Vertices on the unit sphere: K = 1 and H = 1 in the interior.
  Mesh mesh = test::grid(20, 0.6);
  for (Vec3& p : mesh.points) {
    const double x = p.x() - 0.3, y = p.y() - 0.3;
    p = Vec3(x, y, std::sqrt(1 - x * x - y * y));
  }
  const Curvature c = computeCurvature(mesh);
  const int centre = 10 * 21 + 10;
  EXPECT_NEAR(c.gaussian[centre], 1.0, 0.05);
  EXPECT_NEAR(c.mean[centre], 1.0, 0.05);
  const Parameterization p = parameterize(mesh, {}, "cap");
  DensityOptions options{DensityKind::Curvature};
  options.curvatureTimesArea = false;
  for (double d : computeDensity(mesh, p.uv, options)) EXPECT_NEAR(d, 1.0, 0.2);
}
