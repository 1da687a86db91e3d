#include "density.h"

#include "names.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lloydscope {

namespace {

// Divides by the mean over the parameter domain, each triangle weighted by its UV area.
void scaleToMeanOne(const Mesh& mesh, const std::vector<Vec2>& uv, Density& density) {
  double mass = 0, area = 0;
  for (size_t t = 0; t < density.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    const double a = std::abs(triangleArea(uv[tri[0]], uv[tri[1]], uv[tri[2]]));
    mass += a * (density[t][0] + density[t][1] + density[t][2]) / 3.0;
    area += a;
  }
  const double mean = mass > 0 ? mass / area : 1.0;
  for (auto& corners : density)
    for (double& d : corners) d /= mean;
}

double cotangent(const Vec3& a, const Vec3& b, const Vec3& c) {  // of the angle at a
  const Vec3 u = b - a, v = c - a;
  return u.dot(v) / std::max(u.cross(v).norm(), 1e-300);
}

}  // namespace

Density areaDensity(const Mesh& mesh, const std::vector<Vec2>& uv) {
  double total3 = 0, total2 = 0;
  std::vector<double> area3, area2;
  for (const Triangle& t : mesh.triangles) {
    area3.push_back(triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]));
    area2.push_back(std::abs(triangleArea(uv[t[0]], uv[t[1]], uv[t[2]])));
    total3 += area3.back();
    total2 += area2.back();
  }
  // Each vertex takes the mean of its triangles' ratios weighted by their 3D area. (Their
  // ratio of sums, sum A3 / sum A2, would favour the triangles the map shrank least, and
  // starve the shrunken parts of sites.)
  std::vector<double> weighted(mesh.points.size(), 0.0), weight(mesh.points.size(), 0.0);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    // A flat UV triangle (an ear of a straight border) covers none of the domain, and its
    // ratio, huge where rounding left it a sliver of area, would swamp its corners' (the
    // first pass of ../shared's camel head at --simplify 1000 had one, 10^15 times its share:
    // Lloyd's iterations ran to their limit there).
    if (!(area2[t] > kFlatAreaShare * total2)) continue;
    const double ratio = (area3[t] / total3) / (area2[t] / total2);
    for (int v : mesh.triangles[t]) {
      weighted[v] += area3[t] * ratio;
      weight[v] += area3[t];
    }
  }
  std::vector<double> squared(mesh.points.size(), 1.0);
  for (size_t v = 0; v < squared.size(); ++v)
    if (weight[v] > 0) squared[v] = std::pow(weighted[v] / weight[v], 2);
  Density density = vertexDensity(mesh.triangles, squared);
  scaleToMeanOne(mesh, uv, density);
  return density;
}

Density surfaceDensity(const Mesh& mesh, const std::vector<Vec2>& uv, const Density& density) {
  Density result = areaDensity(mesh, uv);
  for (size_t t = 0; t < result.size(); ++t)
    for (int k = 0; k < 3; ++k)
      result[t][k] = result[t][k] > 0 ? density[t][k] / result[t][k] : 1.0;
  return result;
}

Density vertexDensity(const std::vector<Triangle>& triangles, const std::vector<double>& values) {
  Density density;
  density.reserve(triangles.size());
  for (const Triangle& t : triangles) density.push_back({values[t[0]], values[t[1]], values[t[2]]});
  return density;
}

double densityAt(const Density& density, int t, const Eigen::Vector3d& weights) {
  return weights[0] * density[t][0] + weights[1] * density[t][1] + weights[2] * density[t][2];
}

Curvature computeCurvature(const Mesh& mesh) {
  const size_t n = mesh.points.size();
  std::vector<double> angleSum(n, 0.0), area(n, 0.0);
  std::vector<Vec3> laplacian(n, Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const double a = triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
      const Vec3 &pi = mesh.points[i], &pj = mesh.points[j], &pl = mesh.points[l];
      angleSum[i] += cornerAngle(pi, pj, pl);
      area[i] += a / 3.0;
      // The corner at i weighs the opposite edge (j, l).
      const double w = 0.5 * cotangent(pi, pj, pl);
      laplacian[j] += w * (pl - pj);
      laplacian[l] += w * (pj - pl);
    }
  }
  const std::vector<bool> boundary = vertexEdges(mesh).onBoundary;
  Curvature c;
  c.gaussian.assign(n, 0.0);
  c.mean.assign(n, 0.0);
  for (size_t v = 0; v < n; ++v) {
    if (boundary[v] || area[v] <= 0) continue;
    c.gaussian[v] = (2.0 * M_PI - angleSum[v]) / area[v];
    c.mean[v] = 0.5 * laplacian[v].norm() / area[v];
  }
  // Boundary vertices: the mean of their interior neighbours, or, for a border vertex with
  // none (a corner ear), of neighbours that got a value in an earlier pass.
  std::vector<bool> known(n);
  for (size_t v = 0; v < n; ++v) known[v] = !boundary[v];
  for (int pass = 0; pass < 3; ++pass) {
    std::vector<double> sumK(n, 0.0), sumH(n, 0.0);
    std::vector<int> count(n, 0);
    for (const Triangle& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const int i = t[k], j = t[(k + 1) % 3];
        for (auto [to, from] : {std::pair{i, j}, std::pair{j, i}})
          if (!known[to] && known[from]) {
            sumK[to] += c.gaussian[from];
            sumH[to] += c.mean[from];
            ++count[to];
          }
      }
    for (size_t v = 0; v < n; ++v)
      if (!known[v] && count[v] > 0) {
        c.gaussian[v] = sumK[v] / count[v];
        c.mean[v] = sumH[v] / count[v];
        known[v] = true;
      }
  }
  return c;
}

Density computeDensity(const Mesh& mesh, const std::vector<Vec2>& uv,
                       const DensityOptions& options) {
  switch (options.kind) {
    case DensityKind::Uniform:
      return Density(mesh.triangles.size(), {1.0, 1.0, 1.0});
    case DensityKind::Area:
      return areaDensity(mesh, uv);
    case DensityKind::Curvature: {
      // The density is scaled to a mean of 1 in the end, so only alpha : beta and the floor
      // matter: alpha and beta are taken as weights of at most 1, and 1 / psi relative to its
      // mean, so that large ones (1e200) overflow nothing (they made every density NaN).
      const Curvature c = computeCurvature(mesh);
      const double largest = std::max(options.alpha, options.beta);
      const double alpha = largest > 0 ? options.alpha / largest : 0, beta = largest > 0 ? options.beta / largest : 0;
      std::vector<double> inverseSize(mesh.points.size());  // 1 / psi(v)
      for (size_t v = 0; v < inverseSize.size(); ++v)
        inverseSize[v] = alpha * std::abs(c.gaussian[v]) + beta * c.mean[v] * c.mean[v];
      const double mean =
          std::accumulate(inverseSize.begin(), inverseSize.end(), 0.0) / inverseSize.size();
      // (x + floor) / (1 + floor), x of mean 1: 1 / psi plus the floor times its mean, scaled.
      for (double& d : inverseSize) d = ((mean > 0 ? d / mean : 1.0) + options.floor) / (1 + options.floor);
      Density density =
          options.curvatureTimesArea ? areaDensity(mesh, uv) : Density(mesh.triangles.size(), {1.0, 1.0, 1.0});
      for (size_t t = 0; t < density.size(); ++t)
        for (int k = 0; k < 3; ++k) density[t][k] *= inverseSize[mesh.triangles[t][k]];
      scaleToMeanOne(mesh, uv, density);
      return density;
    }
  }
  return {};
}

constexpr NamedValue<DensityKind> kDensityNames[] = {
    {DensityKind::Uniform, "uniform"}, {DensityKind::Area, "area"}, {DensityKind::Curvature, "curvature"}};

const char* toString(DensityKind kind) { return nameOf(kDensityNames, kind); }

DensityKind parseDensityKind(const std::string& text) { return parseName(kDensityNames, text, "density"); }

}  // namespace lloydscope
