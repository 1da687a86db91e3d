// Voronoi cells of a set of sites, bounded by the parameter domain, with their exact mass,
// centroid and energy under the domain's piecewise-linear density.
#pragma once

#include "domain.h"

#include <memory>
#include <vector>

namespace lloydscope {

struct CellPiece {
  int triangle;                // the parameter triangle this piece lies in
  std::vector<Vec2> polygon;   // Voronoi cell ∩ that triangle, counter-clockwise
};

// The integrals along the edge between a cell and one neighbouring cell, inside the domain,
// about the cell's own site z: the CVT energy's Hessian is made of them (Iri, Murota and
// Ohya 1984; Liu et al. 2009, section 3).
struct EdgeMoments {
  int neighbour = -1;                          // the site across the edge
  double mass = 0;                             // ∫ rho ds
  Vec2 first = Vec2::Zero();                   // ∫ rho (x - z) ds
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();  // ∫ rho (x - z)(x - z)ᵀ ds
};

struct BoundedCell {
  // Filled only when asked for (CellDetail): Lloyd's and L-BFGS need just the integrals.
  std::vector<Vec2> voronoi;        // the whole Voronoi cell, counter-clockwise (not clipped)
  std::vector<CellPiece> pieces;    // its parts inside the domain, one per parameter triangle
  std::vector<int> neighbours;      // sites whose cells share an edge with this one, ascending
  std::vector<EdgeMoments> edges;   // those inside the domain, by neighbour (EdgeMoments asked)

  double area = 0;    // of cell ∩ domain, in the parameter domain
  double mass = 0;    // ∫ rho over cell ∩ domain
  Vec2 centroid = Vec2::Zero();  // ∫ x rho / mass; the site itself when the mass is 0
  double energy = 0;  // ∫ rho |x - site|^2: the cell's share of the CVT energy
};

// Exact integrals of a density that is linear over a convex polygon: the polygon is split into
// a fan of triangles, each integrated in closed form (formula (1) of the reference). With a
// constant density they are the shoelace area and centroid, formulas (2)-(4).
struct PolygonIntegrals {
  double area = 0, mass = 0, energy = 0;
  Vec2 moment = Vec2::Zero();  // ∫ x rho
};
// density(i) is the density at polygon[i]; energy is taken about `site`.
PolygonIntegrals integratePolygon(const std::vector<Vec2>& polygon,
                                  const std::vector<double>& density, const Vec2& site);

// The edges between cells, inside the domain, each once: the sides of the cells' pieces that
// do not lie on their parameter triangle's sides (what a picture of the diagram draws). The
// pieces of one Voronoi edge in consecutive parameter triangles are joined into one segment.
std::vector<std::pair<Vec2, Vec2>> voronoiEdges(const Domain& domain,
                                                const std::vector<BoundedCell>& cells);

// One cell's edges with its neighbours (the same segments as voronoiEdges, both directions).
std::vector<std::pair<Vec2, Vec2>> cellOutline(const Domain& domain, const BoundedCell& cell);

// The Delaunay triangulation of the last call's sites (voronoi.cpp). A copy starts empty:
// each owner of hints keeps its own.
class SiteTriangulation {
 public:
  SiteTriangulation();
  ~SiteTriangulation();
  SiteTriangulation(SiteTriangulation&&) noexcept;
  SiteTriangulation& operator=(SiteTriangulation&&) noexcept;
  SiteTriangulation(const SiteTriangulation&);
  SiteTriangulation& operator=(const SiteTriangulation&);
  struct State;
  std::unique_ptr<State> state;
  int builds = 0;  // how many calls built it anew rather than moving the last one
};

// What one computeCells call leaves for the next one on nearby sites (Lloyd's next
// iteration): where to start searching, in which order to insert them, and their
// triangulation, which the next call moves to the new sites and mends by edge flips where no
// triangle turned over (a few flips where the sites moved little: a rebuild costs half an
// evaluation at a thousand sites).
struct CellHints {
  std::vector<int> triangle;  // per site, the parameter triangle that held it (or -1)
  std::vector<int> order;     // the sites in the spatial (Hilbert) order of the last call
  SiteTriangulation triangulation;
};

// What computeCells fills beyond each cell's area, mass, centroid and energy.
enum class CellDetail {
  Integrals,    // nothing more: what Lloyd's and the L-BFGS steps need
  EdgeMoments,  // BoundedCell::edges too: what Newton's step needs
  Geometry,     // the polygons and neighbours to draw (not the edges: a view needs none)
};

// Cells of all `sites`, in their order. Deterministic: the same sites give bit-identical cells,
// whatever the hints. `hints`, if given, is read and updated: pass it back next iteration to
// skip the spatial search and the spatial sort.
// `threads`: 0 for every core (from 500 sites up), or how many.
std::vector<BoundedCell> computeCells(const Domain& domain, const std::vector<Vec2>& sites,
                                      CellDetail detail, CellHints* hints = nullptr,
                                      int threads = 0);

}  // namespace lloydscope
