// The peer Lloydscope is measured against: CGAL's isotropic_remeshing (Botsch-Kobbelt split,
// collapse, flip and tangential smoothing), run on the same input at the same vertex count.
#pragma once

#include "mesh.h"

namespace lloydscope {

struct IsotropicOptions {
  int vertices = 1000;       // the count to match
  double tolerance = 0.01;   // within 1% of it
  int iterations = 10;       // CGAL's remeshing iterations per run
  int maxSearch = 16;        // runs to find the edge length
};

struct IsotropicResult {
  Mesh mesh;
  double edgeLength = 0;     // the target edge length that matched
  double milliseconds = 0;   // of the final run alone: the search is not the method's cost
};

// Searches the target edge length (vertex count goes as 1/length^2) until the output has
// `vertices` within the tolerance, or the closest after maxSearch runs. Free boundary: the
// border is remeshed too.
IsotropicResult isotropicRemesh(const Mesh& input, const IsotropicOptions& options);

}  // namespace lloydscope
