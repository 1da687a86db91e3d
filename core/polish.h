// A last clean-up of a retriangulated surface, in 3D: Delaunay edge flips, then CGAL's angle
// smoothing with the vertices projected back onto the surface, then flips again.
#pragma once

#include "mesh.h"

namespace lloydscope {

struct PolishOptions {
  int smoothingIterations = 3;  // 0: flips only
};

// The border stays as it is (its vertices do not move, its edges do not flip).
Mesh polish(const Mesh& mesh, const PolishOptions& options);

// Flips interior edges whose two opposite angles sum to more than 180 degrees (the 3D
// Delaunay criterion) where the flip neither duplicates an edge nor folds the surface.
// Returns the number of flips.
int flipToDelaunay(Mesh& mesh);

}  // namespace lloydscope
