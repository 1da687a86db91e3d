// A first, rough pass of the remeshing pipeline whose result becomes the surface that is
// parameterized. Why: a conformal map (LSCM) of a quadric-simplified input folds on its
// slivers, and the one-to-one maps (mean value, Tutte) stretch the cells; the resampled mesh
// has no slivers, so its conformal map holds, and cells that are round in the plane are round
// on the surface. Every vertex of the resampled mesh lies on the input surface at a known point
// of the input's own (one-to-one) parameterization, so points of the resampled mesh map back
// onto the input surface exactly, not onto its chords.
#pragma once

#include "density.h"
#include "parameterization.h"
#include "remesh.h"
#include "sites.h"

#include <optional>
#include <string>

namespace lloydscope {

struct ResampleOptions {
  int iterations = 20;  // L-BFGS iterations of the rough pass (it need not converge)
  int polish = 3;       // relaxation passes on the surface after it
  std::vector<Vec2> fallback;  // a map of the input to try where LSCM folds (ParamOptions::fallback)
};

struct Resampling {
  Parameterization param;  // of the input (auto: LSCM, or a one-to-one fallback)
  Domain domain;           // the input's parameter domain
  LiftedMesh mesh;         // the resampled surface; mesh.uv in the input's parameter domain

  // Per vertex of `mesh` on its border, where it is along the input's border: the 3D arc
  // length from the first vertex of param.boundaryLoop (NaN elsewhere); and that loop's
  // arc length at each of its vertices, then its whole length.
  std::vector<double> borderPosition, inputBorderLength;

  // The point of the input surface under the point of resampled triangle `triangle` with
  // barycentric `weights` (`input`: the mesh given to resample()).
  Vec3 toInput(const Mesh& input, int triangle, const Eigen::Vector3d& weights) const;
  // The same for a point on a border edge of the resampled surface, onto the input's own border
  // (toInput() would put it on the chord between its two ends' points: inside the input's
  // corners, where the input's border is as coarse as the resampled one); the input border's
  // stretch between the edge's two ends, at the same fraction of its arc length. Empty where the
  // point is on no border edge.
  std::optional<Vec3> borderToInput(const Mesh& input, int triangle, const Eigen::Vector3d& weights) const;
};

// The rough pass's sites as `sites` asks (their count, the seams of a cut surface), placed by
// `density`.
Resampling resample(const Mesh& input, const SiteOptions& sites, const DensityOptions& density,
                    const ResampleOptions& options, const std::string& name);

}  // namespace lloydscope
