#include "resample.h"

#include "lloyd.h"
#include "polish.h"
#include "sites.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lloydscope {

Vec3 Resampling::toInput(const Mesh& input, int triangle, const Eigen::Vector3d& weights) const {
  const Triangle& t = mesh.mesh.triangles[triangle];
  const Vec2 uv = weights[0] * mesh.uv[t[0]] + weights[1] * mesh.uv[t[1]] + weights[2] * mesh.uv[t[2]];
  return lift(input, domain, uv);
}

std::optional<Vec3> Resampling::borderToInput(const Mesh& input, int triangle, const Eigen::Vector3d& weights) const {
  const Triangle& t = mesh.mesh.triangles[triangle];
  const int off = farthestCorner(weights);
  const int a = t[(off + 1) % 3], b = t[(off + 2) % 3];
  const double wa = weights[(off + 1) % 3], wb = weights[(off + 2) % 3];
  if (weights[off] > Domain::kOnBorderEdge || std::isnan(borderPosition[a]) || std::isnan(borderPosition[b])) return std::nullopt;
  const double whole = inputBorderLength.back();
  double along = borderPosition[b] - borderPosition[a];  // the short way round
  if (along > 0.5 * whole) along -= whole;
  if (along < -0.5 * whole) along += whole;
  double at = borderPosition[a] + along * wb / (wa + wb);
  at -= whole * std::floor(at / whole);
  const std::vector<int>& loop = param.boundaryLoop;
  const int n = static_cast<int>(loop.size());
  const int i = std::clamp(static_cast<int>(std::upper_bound(inputBorderLength.begin(), inputBorderLength.end(), at) -
                                            inputBorderLength.begin()) - 1, 0, n - 1);
  const double span = inputBorderLength[i + 1] - inputBorderLength[i];
  const double f = span > 0 ? std::clamp((at - inputBorderLength[i]) / span, 0.0, 1.0) : 0.0;
  return (1 - f) * input.points[loop[i]] + f * input.points[loop[(i + 1) % n]];
}

namespace {

// Where each border vertex of `resampled` is along the input's border (Resampling::borderPosition):
// its parameter point lies on an edge of the input's border in the plane (the polish leaves the
// border where the samples put it).
void locateOnInputBorder(const Mesh& input, Resampling& r) {
  const std::vector<int>& loop = r.param.boundaryLoop;
  const int n = static_cast<int>(loop.size());
  r.inputBorderLength.assign(1, 0.0);
  for (int i = 0; i < n; ++i)
    r.inputBorderLength.push_back(r.inputBorderLength.back() +
                                  (input.points[loop[(i + 1) % n]] - input.points[loop[i]]).norm());
  const std::vector<bool> onBorder = vertexEdges(r.mesh.mesh).onBoundary;
  r.borderPosition.assign(r.mesh.mesh.vertexCount(), std::numeric_limits<double>::quiet_NaN());
  for (int v = 0; v < r.mesh.mesh.vertexCount(); ++v) {
    if (!onBorder[v]) continue;
    const Vec2& p = r.mesh.uv[v];
    double nearest = INFINITY;
    for (int i = 0; i < n; ++i) {
      const Vec2 &from = r.param.uv[loop[i]], &to = r.param.uv[loop[(i + 1) % n]];
      const Vec2 edge = to - from;
      const double f = edge.squaredNorm() > 0 ? std::clamp((p - from).dot(edge) / edge.squaredNorm(), 0.0, 1.0) : 0.0;
      const double distance = (from + f * edge - p).squaredNorm();
      if (distance < nearest) {
        nearest = distance;
        r.borderPosition[v] = r.inputBorderLength[i] + f * (r.inputBorderLength[i + 1] - r.inputBorderLength[i]);
      }
    }
  }
}

}  // namespace

Resampling resample(const Mesh& input, const SiteOptions& siteOptions,
                    const DensityOptions& density, const ResampleOptions& options,
                    const std::string& name) {
  ParamOptions map;
  map.fallback = options.fallback;
  Parameterization param = parameterize(input, map, name);
  Density rho = computeDensity(input, param.uv, density);
  Domain domain(param.uv, input.triangles, rho);
  const InitialSites sites = initialSites(input, param, domain, siteOptions, name);
  LloydOptions lloyd;
  lloyd.maxIterations = options.iterations;
  LloydSolver solver(domain, sites.fixed, sites.movable, lloyd);
  solver.run();
  LiftedMesh mesh = retriangulate(input, domain, solver.fixedSites(), solver.movableSites(), name,
                                  siteOptions.sharesSeams() ? sites.fixedPoints : std::vector<Vec3>{});
  PolishOptions polishOptions;
  polishOptions.iterations = options.polish;
  polishOptions.target = PolishTarget::Centroid;
  polishOptions.seams = !siteOptions.onSeam.empty();
  polishOptions.slideBorder = false;  // its angles are not the result's: its border stays sampled evenly
  polish(mesh, {input, domain}, surfaceDensity(input, param.uv, rho), polishOptions);
  Resampling r{std::move(param), std::move(domain), std::move(mesh), {}, {}};
  locateOnInputBorder(input, r);
  return r;
}

}  // namespace lloydscope
