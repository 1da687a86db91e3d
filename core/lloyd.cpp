#include "lloyd.h"

#include "cvt_hessian.h"
#include "names.h"
#include "stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>

namespace lloydscope {

namespace {
constexpr size_t kMemory = 7;        // L-BFGS pairs kept
constexpr int kMaxHalvings = 8;      // line search tries before falling back to a Lloyd step
constexpr double kArmijo = 1e-4;

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  return std::inner_product(a.begin(), a.end(), b.begin(), 0.0);
}
}  // namespace

namespace {
constexpr double kGrid = 4294967295.0;  // 2^32 - 1 steps over [0, 1]
std::uint32_t gridIndex(double x) {
  return static_cast<std::uint32_t>(std::llround(std::clamp(x, 0.0, 1.0) * kGrid));
}
}  // namespace

Vec2 snapToGrid(const Vec2& p) {
  return Vec2(gridIndex(p.x()) / kGrid, gridIndex(p.y()) / kGrid);
}

PackedSites::PackedSites(const std::vector<Vec2>& sites) {
  coords_.reserve(2 * sites.size());
  for (const Vec2& s : sites) {
    coords_.push_back(gridIndex(s.x()));
    coords_.push_back(gridIndex(s.y()));
  }
}

Vec2 PackedSites::operator[](size_t i) const {
  return Vec2(coords_[2 * i] / kGrid, coords_[2 * i + 1] / kGrid);
}

std::vector<Vec2> PackedSites::unpack() const {
  std::vector<Vec2> sites(size());
  for (size_t i = 0; i < sites.size(); ++i) sites[i] = (*this)[i];
  return sites;
}

PackedSites PackedSites::fromRaw(std::vector<std::uint32_t> coords) {
  PackedSites p;
  p.coords_ = std::move(coords);
  return p;
}

std::vector<Vec2> allSites(const std::vector<Vec2>& fixed, const std::vector<Vec2>& movable) {
  std::vector<Vec2> sites = fixed;
  sites.insert(sites.end(), movable.begin(), movable.end());
  return sites;
}

std::vector<Vec2> allSites(const std::vector<Vec2>& fixed, const PackedSites& movable) {
  std::vector<Vec2> sites = fixed;
  sites.reserve(fixed.size() + movable.size());
  for (size_t i = 0; i < movable.size(); ++i) sites.push_back(movable[i]);
  return sites;
}

LloydSolver::LloydSolver(const Domain& domain, std::vector<Vec2> fixedSites,
                         std::vector<Vec2> movableSites, const LloydOptions& options)
    : domain_(domain), fixed_(std::move(fixedSites)), movable_(std::move(movableSites)),
      options_(options) {
  for (Vec2& s : movable_) s = snapToGrid(s);
}

LloydSolver::Evaluation LloydSolver::evaluate(const std::vector<Vec2>& movable) {
  const bool newton = options_.solver == CvtSolver::Newton;
  std::vector<BoundedCell> cells =
      computeCells(domain_, allSites(fixed_, movable),
                   newton ? CellDetail::EdgeMoments : CellDetail::Integrals, &hints_,
                   options_.threads);
  Evaluation e;
  for (const BoundedCell& cell : cells) e.energy += cell.energy;
  for (size_t i = fixed_.size(); i < cells.size(); ++i) {
    e.centroids.push_back(cells[i].centroid);
    e.masses.push_back(cells[i].mass);
    if (!newton) continue;
    e.areas.push_back(cells[i].area);
    e.edges.push_back(std::move(cells[i].edges));
  }
  return e;
}

// dE/dz_i = 2 m_i (z_i - c_i): the CVT energy's gradient (Du, Faber, Gunzburger).
std::vector<double> LloydSolver::gradient(const std::vector<Vec2>& x, const Evaluation& e) const {
  std::vector<double> g(2 * x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    g[2 * i] = 2 * e.masses[i] * (x[i].x() - e.centroids[i].x());
    g[2 * i + 1] = 2 * e.masses[i] * (x[i].y() - e.centroids[i].y());
  }
  return g;
}

bool LloydSolver::lineSearch(const Evaluation& current, const std::vector<double>& direction,
                             double slope, std::vector<Vec2>& trial, Evaluation& next) {
  const std::vector<Vec2>& x = movable_;
  trial.resize(x.size());
  double step = 1.0;
  for (int tries = 0; tries < kMaxHalvings && slope < 0; ++tries, step *= 0.5) {
    for (size_t i = 0; i < x.size(); ++i)
      trial[i] = snapToGrid(x[i] + step * Vec2(direction[2 * i], direction[2 * i + 1]));
    next = evaluate(trial);
    // A site the step takes out of the domain has an empty cell, a zero gradient and no way
    // back: the cow's L-BFGS run left up to five stranded beyond the border, unlifted. Such a
    // step is shortened as one that does not descend enough.
    if (next.energy <= current.energy + kArmijo * step * slope && next.emptyCells() <= current.emptyCells())
      return true;
  }
  return false;
}

std::vector<Vec2> LloydSolver::lloydStep(const Evaluation& current, Evaluation& next) {
  std::vector<Vec2> trial = current.centroids;
  for (Vec2& s : trial) s = snapToGrid(s);
  next = evaluate(trial);
  return trial;
}

std::vector<Vec2> LloydSolver::lbfgsStep(const Evaluation& current, Evaluation& next) {
  const std::vector<Vec2>& x = movable_;
  const std::vector<double> g = gradient(x, current);
  // Two-loop recursion; the initial inverse Hessian diag(1 / 2m) makes the first step Lloyd's.
  std::vector<double> h0(g.size());
  for (size_t i = 0; i < x.size(); ++i)
    h0[2 * i] = h0[2 * i + 1] = 1.0 / (2.0 * std::max(current.masses[i], 1e-300));
  std::vector<double> q = g, alpha(historyS_.size());
  for (size_t k = historyS_.size(); k-- > 0;) {
    alpha[k] = dot(historyS_[k], q) / dot(historyY_[k], historyS_[k]);
    for (size_t j = 0; j < q.size(); ++j) q[j] -= alpha[k] * historyY_[k][j];
  }
  double gamma = 1.0;
  if (!historyS_.empty()) {
    const auto& s = historyS_.back();
    const auto& y = historyY_.back();
    double yHy = 0;
    for (size_t j = 0; j < y.size(); ++j) yHy += y[j] * h0[j] * y[j];
    gamma = dot(s, y) / yHy;
  }
  for (size_t j = 0; j < q.size(); ++j) q[j] *= gamma * h0[j];
  for (size_t k = 0; k < historyS_.size(); ++k) {
    const double beta = dot(historyY_[k], q) / dot(historyY_[k], historyS_[k]);
    for (size_t j = 0; j < q.size(); ++j) q[j] += historyS_[k][j] * (alpha[k] - beta);
  }
  const double slope = -dot(g, q);  // directional derivative along -q

  std::vector<double> descent(q.size());
  for (size_t j = 0; j < q.size(); ++j) descent[j] = -q[j];
  std::vector<Vec2> trial;
  if (!lineSearch(current, descent, slope, trial, next)) {
    // Not a descent direction: forget the history, take a Lloyd step.
    historyS_.clear();
    historyY_.clear();
    trial = lloydStep(current, next);
  }
  const std::vector<double> gNext = gradient(trial, next);
  std::vector<double> s(g.size()), y(g.size());
  for (size_t i = 0; i < x.size(); ++i) {
    s[2 * i] = trial[i].x() - x[i].x();
    s[2 * i + 1] = trial[i].y() - x[i].y();
  }
  for (size_t j = 0; j < g.size(); ++j) y[j] = gNext[j] - g[j];
  if (dot(s, y) > 1e-12 * std::sqrt(dot(s, s) * dot(y, y))) {  // keep H positive definite
    historyS_.push_back(std::move(s));
    historyY_.push_back(std::move(y));
    if (historyS_.size() > kMemory) {
      historyS_.erase(historyS_.begin());
      historyY_.erase(historyY_.begin());
    }
  }
  return trial;
}

std::vector<Vec2> LloydSolver::newtonStep(const Evaluation& current, Evaluation& next) {
  const std::vector<Vec2>& x = movable_;
  const std::vector<double> g = gradient(x, current);
  const Eigen::Map<const Eigen::VectorXd> gradientVector(g.data(), g.size());
  const CvtHessian hessian(fixed_, x, current.edges, current.masses);
  Eigen::VectorXd direction = newtonDirection(hessian, gradientVector);
  // The Hessian holds while the cells keep their neighbours: no site goes farther than half
  // its cell's size in one step.
  for (size_t i = 0; i < x.size(); ++i) {
    const double reach = 0.5 * std::sqrt(current.areas[i]);
    const double length = direction.segment<2>(2 * i).norm();
    if (length > reach) direction.segment<2>(2 * i) *= reach / length;
  }
  const double slope = gradientVector.dot(direction);
  std::vector<Vec2> trial;
  if (lineSearch(current, std::vector<double>(direction.data(), direction.data() + direction.size()),
                 slope, trial, next))
    return trial;
  return lloydStep(current, next);  // no descent found: Lloyd's step always descends
}

const IterationRecord& LloydSolver::step() {
  Stopwatch stopwatch;
  if (current_.empty()) current_.push_back(evaluate(movable_));
  const Evaluation& e = current_.front();

  IterationRecord record;
  record.index = static_cast<int>(iterations_.size());
  record.sites = PackedSites(movable_);
  record.energy = e.energy;
  int moving = 0;
  for (size_t i = 0; i < movable_.size(); ++i) {
    const double d = (e.centroids[i] - movable_[i]).norm();
    record.maxDisplacement = std::max(record.maxDisplacement, d);
    record.meanDisplacement += d;
    if (d > options_.distanceThreshold) ++moving;
  }
  if (!movable_.empty()) {
    record.meanDisplacement /= movable_.size();
    record.fractionMoving = static_cast<double>(moving) / movable_.size();
  }

  if (options_.solver == CvtSolver::Lloyd) {
    movable_ = e.centroids;
    for (Vec2& s : movable_) s = snapToGrid(s);
    current_.clear();
  } else {
    Evaluation next;
    movable_ = options_.solver == CvtSolver::Newton ? newtonStep(e, next) : lbfgsStep(e, next);
    current_.front() = std::move(next);
  }
  record.milliseconds = stopwatch.lap();
  iterations_.push_back(std::move(record));
  return iterations_.back();
}

bool convergedAt(const std::vector<IterationRecord>& iterations, double percentThreshold) {
  return !iterations.empty() && 100.0 * iterations.back().fractionMoving < percentThreshold;
}

bool LloydSolver::converged() const { return convergedAt(iterations_, options_.percentThreshold); }

void LloydSolver::run(const std::atomic<bool>* stop) {
  while (!converged() && static_cast<int>(iterations_.size()) < options_.maxIterations &&
         !(stop && *stop))
    step();
}

constexpr NamedValue<CvtSolver> kSolverNames[] = {
    {CvtSolver::Lloyd, "lloyd"}, {CvtSolver::Lbfgs, "lbfgs"}, {CvtSolver::Newton, "newton"}};

const char* toString(CvtSolver solver) { return nameOf(kSolverNames, solver); }

CvtSolver parseCvtSolver(const std::string& text) { return parseName(kSolverNames, text, "solver"); }

}  // namespace lloydscope
