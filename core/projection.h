// The closest point of a triangle mesh's surface to any point in space (CGAL's AABB tree):
// what the Hausdorff distance measures, and where the seam polish puts a vertex it moved.
#pragma once

#include "mesh.h"

#include <memory>

namespace lloydscope {

class SurfaceProjection {
  struct Tree;

 public:
  explicit SurfaceProjection(const Mesh& surface);
  ~SurfaceProjection();
  SurfaceProjection(SurfaceProjection&&) noexcept;

  Vec3 closestPoint(const Vec3& p) const;
  // The same, the search started from `onSurface`, a point this projection gave before near p
  // (a tight first bound prunes most of the tree): several times faster.
  Vec3 closestPoint(const Vec3& p, const Vec3& onSurface) const;
  // The index of the surface's triangle that holds closestPoint(p); with `squaredDistance`, also
  // the squared distance to it.
  int closestTriangle(const Vec3& p, double* squaredDistance = nullptr) const;
  double squaredDistance(const Vec3& p) const;  // thread-safe, as closestPoint
  // The same, the search started from `onSurface` as closestPoint(p, onSurface) does, which
  // then holds the point found: for searches in turn along a path (the climb to the farthest
  // point of a triangle in the Hausdorff distance).
  double squaredDistance(const Vec3& p, Vec3& onSurface) const;

  // Whether the surface crosses the line of sight from `eye` to `point`, a point on it, short of
  // the point by a millionth of the way (its own triangles hold it): what hides it from the eye
  // (the 3D view's seams, drawn over the mesh with no depth test).
  bool hides(const Vec3& eye, const Vec3& point) const;

  // closestPoint, squaredDistance of each, several times faster for many points (inSpatialOrder),
  // split over `threads` threads (0: all cores; one under a thousand points).
  std::vector<Vec3> closestPoints(const std::vector<Vec3>& points, int threads = 0) const;
  std::vector<double> squaredDistances(const std::vector<Vec3>& points) const;
  // closestTriangle of each, the same way (the squared distances in `squared`).
  std::vector<int> closestTriangles(const std::vector<Vec3>& points, std::vector<double>& squared) const;

  // The surface's triangles that meet the cube of half-side `reach` around `centre`, for many
  // searches near it (a vertex's moves in the last steps).
  class Nearby {
   public:
    // closestPoint(p, onSurface) over those triangles alone; over the whole tree where the
    // sphere around p through the point found leaves the cube (a triangle outside it could be
    // closer), which `searchedTree` tells. (The raise of mean angles on nefertiti at 1000
    // vertices, 45,000 points tried: 36-38 ms instead of 49-53.)
    Vec3 closestPoint(const Vec3& p, const Vec3& onSurface, bool* searchedTree = nullptr) const;

   private:
    friend class SurfaceProjection;
    const Tree* tree_ = nullptr;  // the projection's own, which a move of it keeps
    Vec3 low_, high_;             // the cube, as searched
    std::vector<int> triangles_;
    std::vector<Vec3> triangleLow_, triangleHigh_;  // each one's bounding box
  };
  Nearby nearby(const Vec3& centre, double reach) const;

 private:
  // fn(i, closest point to points[i], the index of its triangle) for each, the points taken
  // in a spatial (Morton) order and each search started from the closest point of the one
  // before: a tight first bound prunes most of the tree.
  template <class Fn>
  void inSpatialOrder(const std::vector<Vec3>& points, int threads, const Fn& fn) const;

  std::unique_ptr<Tree> tree_;
};

// A surface and its closest-point search, built once for the steps that each search it (the
// last steps (core/last_steps) and core/fit against the input: on a scan of 52,000 triangles each
// search took 50 ms to build). Any mesh will do where one is asked for, its search built then.
struct SearchableSurface {
  SearchableSurface(const Mesh& surface) : mesh(surface), projection(surface) {}  // NOLINT: implicit
  const Mesh& mesh;
  const SurfaceProjection projection;
};

}  // namespace lloydscope
