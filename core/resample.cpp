#include "resample.h"

#include "lloyd.h"
#include "polish.h"
#include "sites.h"

namespace lloydscope {

Vec3 Resampling::toInput(const Mesh& input, int triangle, const Eigen::Vector3d& weights) const {
  const Triangle& t = mesh.mesh.triangles[triangle];
  const Vec2 uv = weights[0] * mesh.uv[t[0]] + weights[1] * mesh.uv[t[1]] + weights[2] * mesh.uv[t[2]];
  return lift(input, domain, uv);
}

Resampling resample(const Mesh& input, const SiteOptions& siteOptions,
                    const DensityOptions& density, const ResampleOptions& options,
                    const std::string& name) {
  ParamOptions map;
  map.fallback = options.fallback;
  Parameterization param = parameterize(input, map, name);
  Density rho = computeDensity(input, param.uv, density);
  Domain domain(param.uv, input.triangles, rho);
  const InitialSites sites = initialSites(input, param, domain, siteOptions);
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
  polish(mesh, {input, domain}, surfaceDensity(input, param.uv, rho), polishOptions);
  return {std::move(param), std::move(domain), std::move(mesh)};
}

}  // namespace lloydscope
