#include "density.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lloydscope {

namespace {

void scaleToMeanOne(std::vector<double>& values) {
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / values.size();
  for (double& v : values) v /= mean;
}

double cotangent(const Vec3& a, const Vec3& b, const Vec3& c) {  // of the angle at a
  const Vec3 u = b - a, v = c - a;
  return u.dot(v) / std::max(u.cross(v).norm(), 1e-300);
}

}  // namespace

std::vector<double> areaDensity(const Mesh& mesh, const std::vector<Vec2>& uv) {
  std::vector<double> area3(mesh.points.size(), 0.0), area2(mesh.points.size(), 0.0);
  double total3 = 0, total2 = 0;
  for (const Triangle& t : mesh.triangles) {
    const double a3 = triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double a2 = std::abs(triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]));
    for (int i : t) {
      area3[i] += a3;
      area2[i] += a2;
    }
    total3 += a3;
    total2 += a2;
  }
  std::vector<double> density(mesh.points.size());
  for (size_t v = 0; v < density.size(); ++v) {
    const double ratio = (area3[v] / total3) / std::max(area2[v] / total2, 1e-300);
    density[v] = ratio * ratio;
  }
  scaleToMeanOne(density);
  return density;
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
      angleSum[i] += std::atan2((pj - pi).cross(pl - pi).norm(), (pj - pi).dot(pl - pi));
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

std::vector<double> computeDensity(const Mesh& mesh, const std::vector<Vec2>& uv,
                                   const DensityOptions& options) {
  switch (options.kind) {
    case DensityKind::Uniform:
      return std::vector<double>(mesh.points.size(), 1.0);
    case DensityKind::Area:
      return areaDensity(mesh, uv);
    case DensityKind::Curvature: {
      const Curvature c = computeCurvature(mesh);
      std::vector<double> density(mesh.points.size());
      for (size_t v = 0; v < density.size(); ++v)
        density[v] = options.alpha * std::abs(c.gaussian[v]) +
                     options.beta * c.mean[v] * c.mean[v];  // 1 / psi(v)
      const double mean = std::accumulate(density.begin(), density.end(), 0.0) / density.size();
      for (double& d : density) d += options.floor * mean + 1e-300;
      if (options.curvatureTimesArea) {
        const std::vector<double> area = areaDensity(mesh, uv);
        for (size_t v = 0; v < density.size(); ++v) density[v] *= area[v];
      }
      scaleToMeanOne(density);
      return density;
    }
  }
  return {};
}

const char* toString(DensityKind kind) {
  switch (kind) {
    case DensityKind::Uniform: return "uniform";
    case DensityKind::Area: return "area";
    case DensityKind::Curvature: return "curvature";
  }
  return "?";
}

DensityKind parseDensityKind(const std::string& text) {
  for (DensityKind k : {DensityKind::Uniform, DensityKind::Area, DensityKind::Curvature})
    if (text == toString(k)) return k;
  throw Error("unknown density '" + text + "' (uniform, area, curvature)");
}

}  // namespace lloydscope
