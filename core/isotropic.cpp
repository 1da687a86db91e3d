#include "isotropic.h"

#include "cgal_types.h"
#include "stopwatch.h"

#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <cmath>

namespace lloydscope {

namespace {

struct Run {
  Mesh mesh;
  double milliseconds;
};

Run remeshAt(const Mesh& input, double edgeLength, int iterations) {
  SurfaceMesh sm = toSurfaceMesh(input);
  Stopwatch stopwatch;
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
      faces(sm), edgeLength, sm, CGAL::parameters::number_of_iterations(iterations));
  const double ms = stopwatch.lap();
  sm.collect_garbage();
  return {fromSurfaceMesh(sm), ms};
}

}  // namespace

IsotropicResult isotropicRemesh(const Mesh& input, const IsotropicOptions& options) {
  double length = equilateralEdgeLength(surfaceArea(input), options.vertices);
  IsotropicResult best;
  double bestError = INFINITY;
  for (int run = 0; run < options.maxSearch; ++run) {
    Run r = remeshAt(input, length, options.iterations);
    const int count = r.mesh.vertexCount();
    const double error = std::abs(count - options.vertices) / double(options.vertices);
    if (error < bestError) {
      bestError = error;
      best.mesh = std::move(r.mesh);
      best.edgeLength = length;
      best.milliseconds = r.milliseconds;
    }
    if (error <= options.tolerance || count == 0) break;
    // V ~ 1/L^2; damped, since the border and the features do not scale exactly.
    length *= std::pow(double(count) / options.vertices, 0.5 * 0.9);
  }
  return best;
}

}  // namespace lloydscope
