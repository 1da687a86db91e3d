// The parameter domain: the mesh's triangles laid out in UV, carrying a density that is linear
// inside each triangle (one value per vertex). Lloyd relaxation, the Voronoi cells and the
// lifting back to 3D all work on it.
#pragma once

#include "density.h"

#include <memory>
#include <vector>

namespace lloydscope {

struct Location {
  int triangle = -1;       // -1: the domain is empty
  Eigen::Vector3d weights;  // barycentric coordinates in that triangle
  bool inside = false;     // false: the point was outside, this is the closest point's location
};

// The corner of a location's triangle whose weight is least: the point lies nearest the edge
// opposite it.
int farthestCorner(const Eigen::Vector3d& weights);

class Domain {
 public:
  // An empty density is uniform.
  Domain(std::vector<Vec2> uv, std::vector<Triangle> triangles, Density density);
  ~Domain();
  Domain(Domain&&) noexcept;
  Domain& operator=(Domain&&) noexcept;

  const std::vector<Vec2>& uv() const { return uv_; }
  const std::vector<Triangle>& triangles() const { return triangles_; }
  const Density& density() const { return density_; }
  // neighbours()[t][k]: the triangle across the edge opposite corner k of t, or -1 on the border.
  const std::vector<std::array<int, 3>>& neighbours() const { return neighbours_; }

  // The triangle that contains p (spatial index, never a scan over all triangles); for a point
  // outside the domain, the location of the closest point of the domain.
  Location locate(const Vec2& p) const;
  // The same, walking from triangle `hint` across shared edges first (cheap when p is near the
  // hint, as a site is to where it was in the previous iteration).
  Location locate(const Vec2& p, int hint) const;
  // As locate(), always in a triangle with an area and its neighbours (hint: one such, or -1):
  // where a walk across the domain starts. locate() puts a vertex whose triangles are all flat
  // (an ear on a square border's side) in one of those, at its own corner, for its lift.
  Location locateInArea(const Vec2& p, int hint = -1) const;
  Vec2 pointAt(const Location& l) const;
  // Whether a location lies on an edge of the domain's border (its weight off that edge at
  // most kOnBorderEdge).
  static constexpr double kOnBorderEdge = 1e-9;
  bool onBorder(const Location& l) const;
  Eigen::Vector3d barycentric(int triangle, const Vec2& p) const;
  // The density at p, linear inside `triangle` (p may be outside it: the plane is extended).
  double densityAt(int triangle, const Vec2& p) const {
    const Eigen::Vector3d& plane = densityPlanes_[triangle];
    return plane[0] + plane[1] * p.x() + plane[2] * p.y();
  }

 private:
  struct Index;
  // The location of a vertex at `p` whose triangles are all flat, at its own corner; else null.
  const Location* stranded(const Vec2& p) const;
  std::vector<Vec2> uv_;
  std::vector<Triangle> triangles_;
  Density density_;
  std::vector<std::array<int, 3>> neighbours_;
  std::vector<Eigen::Vector3d> densityPlanes_;  // rho = a + b u + c v, per triangle
  std::unique_ptr<Index> index_;
};

}  // namespace lloydscope
