// The CVT energy's Hessian, and the truncated Newton step built on it. With exact second
// derivatives the last iterations converge quadratically, where Lloyd's converge linearly.
#pragma once

#include "voronoi.h"

#include <utility>
#include <vector>

namespace lloydscope {

// Second derivatives of E = sum_i ∫_Vi rho |x - z_i|^2 with respect to the movable sites
// (rows 2i, 2i+1: site i's u and v), from their cells' masses and edges (BoundedCell::edges,
// cells in the order fixed sites, then movable ones):
//   d2E/dz_i2     = 2 m_i I - sum_j (2 / |z_i - z_j|) ∫_eij rho (x - z_i)(x - z_i)ᵀ ds,
//   d2E/dz_i dz_j = (2 / |z_i - z_j|) ∫_eij rho (x - z_i)(x - z_j)ᵀ ds
// over the edge e_ij between the two cells (Iri, Murota and Ohya 1984; Liu et al. 2009); the
// domain's own border does not move. Kept as 2x2 blocks, applied without assembling a matrix.
class CvtHessian {
 public:
  CvtHessian(const std::vector<Vec2>& fixed, const std::vector<Vec2>& movable,
             const std::vector<std::vector<EdgeMoments>>& edges, const std::vector<double>& masses);

  Eigen::VectorXd operator*(const Eigen::VectorXd& v) const;
  // 2 m_i, twice per site: the diagonal whose inverse is Lloyd's step.
  const Eigen::VectorXd& lloydDiagonal() const { return lloyd_; }

 private:
  std::vector<Eigen::Matrix2d> diagonal_;
  // Each cell's own side of each edge to a movable site; the product uses the average of the
  // two sides, so the operator is exactly symmetric.
  std::vector<std::pair<int, int>> pairs_;
  std::vector<Eigen::Matrix2d> across_;
  Eigen::VectorXd lloyd_;
};

// An approximate solution of H p = -g by conjugate gradients preconditioned by Lloyd's
// diagonal (Steihaug's truncated Newton): the first iterate is Lloyd's direction, and the
// iteration stops where H shows negative curvature (the energy is not convex everywhere) or
// once the residual is small enough for Newton's fast convergence. Every iterate descends.
Eigen::VectorXd newtonDirection(const CvtHessian& hessian, const Eigen::VectorXd& gradient);

}  // namespace lloydscope
