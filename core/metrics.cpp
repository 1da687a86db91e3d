#include "metrics.h"

#include "parallel.h"
#include "projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <thread>

namespace lloydscope {

namespace {
double angleDeg(const Vec3& at, const Vec3& p, const Vec3& q) { return cornerAngle(at, p, q) * 180.0 / M_PI; }
}  // namespace

std::array<double, 3> cornerAnglesDeg(const Vec3& a, const Vec3& b, const Vec3& c) {
  return {angleDeg(a, b, c), angleDeg(b, c, a), angleDeg(c, a, b)};
}

double smallestAngleDeg(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Opposite the shortest edge.
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc <= ab && bc <= ca) return angleDeg(a, b, c);
  if (ca <= ab) return angleDeg(b, c, a);
  return angleDeg(c, a, b);
}

int worstTriangle(const Mesh& mesh) {
  int worst = -1;
  double smallest = std::numeric_limits<double>::infinity();
  for (int t = 0; t < mesh.faceCount(); ++t) {
    const Triangle& f = mesh.triangles[t];
    const double angle = smallestAngleDeg(mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]]);
    if (angle < smallest) smallest = angle, worst = t;
  }
  return worst;
}

int barsMet(const QualityMetrics& q) {
  return (q.irregularBoundaryAware <= kMostIrregularPercent) + (q.minAngle >= kLeastMinAngle) +
         (q.avgMinAngle >= kLeastAvgMinAngle);
}

QualityMetrics measureQuality(const Mesh& mesh) {
  QualityMetrics m;
  m.vertices = mesh.vertexCount();
  m.faces = mesh.faceCount();
  if (mesh.triangles.empty()) return m;

  const VertexEdges edges = vertexEdges(mesh);
  const std::vector<int>& valence = edges.valence;
  const std::vector<bool>& boundary = edges.onBoundary;
  int irregular = 0, irregularAware = 0, used = 0;
  for (size_t v = 0; v < valence.size(); ++v) {
    if (valence[v] == 0) continue;
    ++used;
    if (boundary[v]) ++m.boundaryVertices;
    if (valence[v] != 6) ++irregular;
    if (valence[v] != (boundary[v] ? 4 : 6)) ++irregularAware;
  }
  m.irregularPercent = 100.0 * irregular / used;
  m.irregularBoundaryAware = 100.0 * irregularAware / used;

  m.minAngle = 180;
  double sumMin = 0;
  int under30 = 0;
  for (const Triangle& t : mesh.triangles) {
    const auto angles = cornerAnglesDeg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double lo = *std::min_element(angles.begin(), angles.end());
    m.minAngle = std::min(m.minAngle, lo);
    m.maxAngle = std::max(m.maxAngle, *std::max_element(angles.begin(), angles.end()));
    sumMin += lo;
    if (lo < 30.0) ++under30;
    for (double a : angles) ++m.angleHistogram[std::clamp(static_cast<int>(a / 10.0), 0, 17)];
  }
  m.avgMinAngle = sumMin / mesh.faceCount();
  m.percentUnder30 = 100.0 * under30 / mesh.faceCount();
  return m;
}

namespace {

// Metro's sampling: every vertex, every edge midpoint, and area-weighted random points. The
// random numbers are drawn in order, and the triangle each point falls in is found in parallel
// (a binary search per point: most of the sampling's time on a large input).
std::vector<Vec3> samplePoints(const Mesh& mesh, int randomCount) {
  std::vector<Vec3> samples = mesh.points;
  samples.reserve(mesh.points.size() + 2 * mesh.triangles.size() + randomCount);
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0;
  for (const Triangle& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k)
      if (t[k] < t[(k + 1) % 3])  // each interior edge once (boundary edges may appear once more)
        samples.push_back(0.5 * (mesh.points[t[k]] + mesh.points[t[(k + 1) % 3]]));
    total += triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    cumulative.push_back(total);
  }
  std::mt19937_64 rng(12345);
  auto uniform01 = [&] { return (rng() >> 11) * 0x1.0p-53; };
  std::vector<std::array<double, 3>> draws(randomCount);  // where in the area, then where in the triangle
  for (auto& draw : draws) draw = {uniform01() * total, uniform01(), uniform01()};
  const size_t first = samples.size();
  samples.resize(first + draws.size());
  parallelFor(draws.size(), std::max(1u, std::thread::hardware_concurrency()), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      auto [at, a, b] = draws[i];
      const size_t f = std::min<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin(),
                                        cumulative.size() - 1);
      if (a + b > 1) {
        a = 1 - a;
        b = 1 - b;
      }
      const Triangle& t = mesh.triangles[f];
      samples[first + i] = mesh.points[t[0]] + a * (mesh.points[t[1]] - mesh.points[t[0]]) +
                           b * (mesh.points[t[2]] - mesh.points[t[0]]);
    }
  });
  return samples;
}

// The farthest sample of `from` from the surface `to`, and the summed squared distances. The
// queries are independent: they are split over the cores.
struct OneSided {
  double maxSquared = 0, sumSquared = 0;
  Vec3 farthest = Vec3::Zero();
  int count = 0;
};

OneSided oneSided(const Mesh& from, const SurfaceProjection& to) {
  const std::vector<Vec3> samples = samplePoints(from, 10000 + 10 * from.faceCount());
  const std::vector<double> squared = to.squaredDistances(samples);
  // Summed in parts, as when each thread summed its own: the figures stay as they were.
  const size_t threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<OneSided> part(threads);
  for (size_t t = 0; t < threads; ++t) {
    for (size_t i = samples.size() * t / threads; i < samples.size() * (t + 1) / threads; ++i) {
      if (squared[i] > part[t].maxSquared) {
        part[t].maxSquared = squared[i];
        part[t].farthest = samples[i];
      }
      part[t].sumSquared += squared[i];
    }
  }
  OneSided all;
  for (const OneSided& p : part) {  // in a fixed order: the sum does not depend on timing
    if (p.maxSquared > all.maxSquared) {
      all.maxSquared = p.maxSquared;
      all.farthest = p.farthest;
    }
    all.sumSquared += p.sumSquared;
  }
  all.count = static_cast<int>(samples.size());
  return all;
}

}  // namespace

Fidelity measureFidelity(const Mesh& mesh, const Mesh& reference) {
  if (mesh.triangles.empty() || reference.triangles.empty()) return Fidelity{};
  return measureFidelity(mesh, SearchableSurface(reference));
}

Fidelity measureFidelity(const Mesh& mesh, const SearchableSurface& reference) {
  Fidelity f;
  if (mesh.triangles.empty() || reference.mesh.triangles.empty()) return f;
  const OneSided fromMesh = oneSided(mesh, reference.projection),
                 fromReference = oneSided(reference.mesh, SurfaceProjection(mesh));
  const double diagonal = boundingBoxDiagonal(reference.mesh);
  f.samples = fromMesh.count + fromReference.count;
  f.farthestOnReference = fromReference.maxSquared > fromMesh.maxSquared;
  const OneSided& worst = f.farthestOnReference ? fromReference : fromMesh;
  f.farthestPoint = worst.farthest;
  f.hausdorffPercent = 100.0 * std::sqrt(worst.maxSquared) / diagonal;
  f.rmsPercent =
      100.0 * std::sqrt((fromMesh.sumSquared + fromReference.sumSquared) / f.samples) / diagonal;
  return f;
}

}  // namespace lloydscope
