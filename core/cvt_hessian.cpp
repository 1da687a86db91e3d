#include "cvt_hessian.h"

#include <algorithm>
#include <cmath>

namespace lloydscope {

CvtHessian::CvtHessian(const std::vector<Vec2>& fixed, const std::vector<Vec2>& movable,
                       const std::vector<std::vector<EdgeMoments>>& edges,
                       const std::vector<double>& masses)
    : diagonal_(movable.size()), lloyd_(2 * movable.size()) {
  const size_t nf = fixed.size();
  for (size_t i = 0; i < movable.size(); ++i) {
    const Vec2& zi = movable[i];
    lloyd_[2 * i] = lloyd_[2 * i + 1] = 2 * masses[i];
    Eigen::Matrix2d own = 2 * masses[i] * Eigen::Matrix2d::Identity();
    for (const EdgeMoments& e : edges[i]) {
      const size_t j = static_cast<size_t>(e.neighbour);
      const Vec2 zj = j < nf ? fixed[j] : movable[j - nf];
      const double d = (zi - zj).norm();
      if (d == 0) continue;  // (two sites on one point share one cell: no edge between them)
      own -= (2 / d) * e.second;
      if (j < nf) continue;  // a fixed site is not a variable
      pairs_.emplace_back(static_cast<int>(i), static_cast<int>(j - nf));
      across_.push_back((2 / d) * (e.second + e.first * (zi - zj).transpose()));
    }
    diagonal_[i] = own;
  }
}

Eigen::VectorXd CvtHessian::operator*(const Eigen::VectorXd& v) const {
  Eigen::VectorXd y(v.size());
  for (size_t i = 0; i < diagonal_.size(); ++i)
    y.segment<2>(2 * i) = diagonal_[i] * v.segment<2>(2 * i);
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const auto [i, j] = pairs_[k];
    y.segment<2>(2 * i) += 0.5 * (across_[k] * v.segment<2>(2 * j));
    y.segment<2>(2 * j) += 0.5 * (across_[k].transpose() * v.segment<2>(2 * i));
  }
  return y;
}

Eigen::VectorXd newtonDirection(const CvtHessian& hessian, const Eigen::VectorXd& g) {
  // A site with no mass (outside the domain, or on another) does not move in this step.
  const Eigen::VectorXd inverseDiagonal = hessian.lloydDiagonal().unaryExpr(
      [](double m) { return m > 0 ? 1.0 / m : 0.0; });
  // The forcing term of Nocedal and Wright's line-search Newton-CG (their algorithm 7.1): the
  // residual shrinks with the gradient, so the steps become Newton's as the sites settle.
  const double tolerance = std::min(0.5, std::sqrt(g.norm())) * g.norm();
  Eigen::VectorXd p = Eigen::VectorXd::Zero(g.size()), r = -g;
  Eigen::VectorXd z = inverseDiagonal.cwiseProduct(r), d = z;
  double rz = r.dot(z);
  // At most kMaxIterations: near the minimum, where the residual must fall furthest, a few
  // dozen suffice, and a step that asks for more is no better for it.
  constexpr Eigen::Index kMaxIterations = 200;
  for (Eigen::Index k = 0; k < std::min<Eigen::Index>(2 * g.size(), kMaxIterations); ++k) {
    const Eigen::VectorXd hd = hessian * d;
    const double curvature = d.dot(hd);
    if (curvature <= 0) {
      if (k == 0) p = z;  // Lloyd's step itself
      break;
    }
    const double alpha = rz / curvature;
    p += alpha * d;
    r -= alpha * hd;
    if (r.norm() <= tolerance) break;
    z = inverseDiagonal.cwiseProduct(r);
    const double rzNext = r.dot(z);
    d = z + (rzNext / rz) * d;
    rz = rzNext;
  }
  return p;
}

}  // namespace lloydscope
