// The result fitted to the input: its vertices moved along their normals so that the input lies
// on both sides of it (least squares), as a good approximation does, instead of wholly on one
// side of each triangle, as it does with every vertex on the input. Where the input curves, a
// triangle whose corners are on it cuts under it by its sagitta; lifted by part of that, it is
// nearer. On issue 5's bench: Hausdorff distance down by 0-36%, RMS by 12-48%.
#pragma once

#include "mesh.h"
#include "projection.h"

namespace lloydscope {

struct FitOptions {
  // A move that would leave an angle of the vertex's triangles under this many degrees, and
  // under the smallest they had, is halved, quartered or not made: the fit never takes the
  // smallest angle under this or under what it was (larger angles may shrink a little, and
  // the average smallest angle with them: by up to 0.5 deg on issue 5's bench).
  double keepAngle = 40.0;
  // The border's vertices move too, across the border in the plane of their triangles, so that
  // the border's chords cross the input's curved border (least squares again) instead of
  // cutting inside it, or outside where it curves in: there the distance was their sagitta.
  bool border = true;
  int threads = 0;  // for the closest points; 0: all cores
};

struct FitResult {
  int moved = 0;        // vertices moved
  int borderMoved = 0;  // of them, on the border (across it)
  double meanPercent = 0, maxPercent = 0;  // how far they moved, in % of the surface's diagonal

  FitResult& operator+=(const FitResult& o);  // the two parts' vertices together
  // The percentages times `factor`: with a part's diagonal over the whole's, in % of the whole's.
  FitResult scaled(double factor) const;
};

// First the border (FitOptions::border): samples at its vertices and edge midpoints, each
// sample's closest point on the border of `surface`, and the border vertices' moves across the
// border that minimize the samples' weighted squared distances to those points. Then the
// inside: samples at the vertices, edge midpoints and triangle centres, their closest points
// on `surface` (CGAL's AABB tree), and the inside vertices' moves along their normals that
// minimize the distances measured along each sample's normal. Each is one Gauss-Newton step,
// the closest points held: a sparse linear system. A vertex on a vertex of `surface` (a tip
// snapped to, a corner of the border) stays.
FitResult fitToSurface(Mesh& mesh, const SearchableSurface& surface, const FitOptions& options = {});

}  // namespace lloydscope
