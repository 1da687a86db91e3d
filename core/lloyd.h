// Weighted Lloyd relaxation in the parameter domain, and its quasi-Newton acceleration
// (L-BFGS on the CVT energy, Liu et al. 2009), recording every iteration.
#pragma once

#include "voronoi.h"

#include <string>
#include <cstdint>
#include <algorithm>
#include <atomic>
#include <vector>

namespace lloydscope {

enum class CvtSolver {
  Lloyd,  // move every site to its centroid
  Lbfgs,  // L-BFGS steps on the CVT energy, preconditioned so its first step is Lloyd's
  Newton, // truncated Newton steps on the CVT energy with its exact Hessian
};

constexpr CvtSolver kCvtSolvers[] = {CvtSolver::Lloyd, CvtSolver::Lbfgs, CvtSolver::Newton};

struct LloydOptions {
  CvtSolver solver = CvtSolver::Lbfgs;
  // Converged when fewer than percentThreshold % of the movable sites are farther than
  // distanceThreshold (a fraction of the domain size, which is 1) from their cells' centroids:
  // the move Lloyd's step would make (the report's test), whatever step the solver takes.
  double distanceThreshold = 1e-6;
  double percentThreshold = 5.0;
  int maxIterations = 1000;
  int threads = 0;  // for the cells; 0: every core, or one under 500 sites (results do not depend on it)
};
// The most iterations a run may be asked for (the command line and the inspector's Settings):
// every iteration is recorded, and a run that never converges (a distance threshold of 1e-300)
// grew by 30 MB a second up to the limit it was given (2147483647 was taken).
constexpr int kMostIterations = 100000;

// One iteration as it happened: the sites it started from and the centroids of their cells.
// Displacements are site-to-centroid distances: the move Lloyd makes (the L-BFGS step differs,
// and the next iteration's sites show where it went). Fixed sites are the same in every
// iteration and are kept once, in the Recording.
// The movable sites live on a grid of step 1/(2^32 - 1) over the unit domain: the solver
// snaps every position it tries, so a recording keeps each site exactly in two 32-bit
// integers (8 bytes, where two doubles took 16). The grid is 1e4 times finer than the
// default distance threshold.
Vec2 snapToGrid(const Vec2& p);

// Sites on that grid, packed.
class PackedSites {
 public:
  PackedSites() = default;
  explicit PackedSites(const std::vector<Vec2>& sites);  // each already snapToGrid()ed
  size_t size() const { return coords_.size() / 2; }
  bool empty() const { return coords_.empty(); }
  Vec2 operator[](size_t i) const;
  std::vector<Vec2> unpack() const;
  bool operator==(const PackedSites& o) const { return coords_ == o.coords_; }
  // u0 v0 u1 v1 ... as grid indices, for files.
  const std::vector<std::uint32_t>& raw() const { return coords_; }
  static PackedSites fromRaw(std::vector<std::uint32_t> coords);

 private:
  std::vector<std::uint32_t> coords_;
};

struct IterationRecord {
  int index = 0;
  PackedSites sites;  // movable sites at the start of the iteration (their cells, hence their
                      // centroids, are recomputed exactly from them: Recording::cells)
  double energy = 0;            // CVT energy Σ ∫ rho |x - site|^2 of all cells, fixed ones too
  double maxDisplacement = 0, meanDisplacement = 0;
  double fractionMoving = 0;    // of movable sites farther than the distance threshold
  double milliseconds = 0;      // time of the step
};

// The convergence test on a run's last iteration: fewer than `percentThreshold` % of the
// movable sites still moving (false before the first).
bool convergedAt(const std::vector<IterationRecord>& iterations, double percentThreshold);

// Fixed sites (the border samples) first, then movable ones: the order of every site list.
std::vector<Vec2> allSites(const std::vector<Vec2>& fixed, const std::vector<Vec2>& movable);
std::vector<Vec2> allSites(const std::vector<Vec2>& fixed, const PackedSites& movable);

class LloydSolver {
 public:
  LloydSolver(const Domain& domain, std::vector<Vec2> fixedSites, std::vector<Vec2> movableSites,
              const LloydOptions& options);

  // Computes the cells of the current sites, records the iteration, then moves the movable
  // sites: to their centroids (Lloyd) or by one L-BFGS step with a backtracking line search.
  const IterationRecord& step();
  bool converged() const;
  // Steps until converged() or options.maxIterations iterations were recorded, or `stop` is
  // set (from another thread).
  void run(const std::atomic<bool>* stop = nullptr);

  void setThreads(int threads) { options_.threads = threads; }  // LloydOptions::threads
  const std::vector<Vec2>& fixedSites() const { return fixed_; }
  const std::vector<Vec2>& movableSites() const { return movable_; }
  const std::vector<IterationRecord>& iterations() const { return iterations_; }
  std::vector<IterationRecord> takeIterations() { return std::move(iterations_); }

 private:
  struct Evaluation {  // the cells of one configuration, as the solvers need them
    double energy = 0;
    std::vector<Vec2> centroids;
    std::vector<double> masses;
    std::vector<double> areas;                    // Newton's only
    std::vector<std::vector<EdgeMoments>> edges;  // Newton's only
    // Sites whose cell is empty: out of the domain (or on another site).
    size_t emptyCells() const { return static_cast<size_t>(std::count(masses.begin(), masses.end(), 0.0)); }
  };
  Evaluation evaluate(const std::vector<Vec2>& movable);
  // Armijo backtracking from the movable sites along `direction` (u, v per site), whose
  // directional derivative is `slope`: whether a step lowered the energy enough (`trial` and
  // `next` then hold it).
  bool lineSearch(const Evaluation& current, const std::vector<double>& direction, double slope,
                  std::vector<Vec2>& trial, Evaluation& next);
  std::vector<Vec2> lloydStep(const Evaluation& current, Evaluation& next);  // to the centroids
  std::vector<Vec2> lbfgsStep(const Evaluation& current, Evaluation& next);
  std::vector<Vec2> newtonStep(const Evaluation& current, Evaluation& next);
  std::vector<double> gradient(const std::vector<Vec2>& x, const Evaluation& e) const;

  const Domain& domain_;
  std::vector<Vec2> fixed_, movable_;
  LloydOptions options_;
  std::vector<IterationRecord> iterations_;
  CellHints hints_;                   // from the last cells, to start the next ones from
  std::vector<Evaluation> current_;   // 0 or 1 element: the evaluation of movable_, if known
  std::vector<std::vector<double>> historyS_, historyY_;  // L-BFGS memory
};

const char* toString(CvtSolver solver);
CvtSolver parseCvtSolver(const std::string& text);  // throws Error on unknown names

}  // namespace lloydscope
