#include "fit.h"

#include "metrics.h"
#include "polish.h"
#include "projection.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace lloydscope {

namespace {

std::vector<Vec3> vertexNormals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles)
    for (int v : t) normals[v] += faceNormal(mesh, t);
  for (Vec3& n : normals) n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  return normals;
}

// A point where the mesh is sampled: the mean of some of its vertices (one, an edge's two or a
// triangle's three), weighted by the part of the surface it stands for.
struct Sample {
  std::vector<int> corners;
  double weight = 0;
};

// One sample per vertex, edge and triangle, weighted as the rule for triangles that is exact for
// cubics weighs corners, edge midpoints and centres (1/20, 2/15 and 9/20 of the area): the
// distance to a curved surface grows from the corners inwards, and the centre weighs most.
std::vector<Sample> samplesOf(const Mesh& mesh) {
  std::vector<Sample> samples(mesh.points.size());
  for (size_t v = 0; v < samples.size(); ++v) samples[v].corners = {static_cast<int>(v)};
  std::map<std::pair<int, int>, size_t> edgeSample;
  for (const Triangle& t : mesh.triangles) {
    const double area = faceNormal(mesh, t).norm() / 2;
    for (int k = 0; k < 3; ++k) {
      samples[t[k]].weight += area / 20;
      const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [at, added] = edgeSample.emplace(edge, samples.size());
      if (added) samples.push_back({{edge.first, edge.second}, 0});
      samples[at->second].weight += 2 * area / 15;
    }
    samples.push_back({{t[0], t[1], t[2]}, 9 * area / 20});
  }
  return samples;
}

// Each vertex's move along its normal that minimizes the weighted squared distances of the
// samples to their closest points on the input, measured along each sample's normal (the
// closest points kept where they are: one Gauss-Newton step). Fixed vertices do not move.
Eigen::VectorXd normalMoves(const Mesh& mesh, const std::vector<Vec3>& normals, const std::vector<Sample>& samples,
                            const std::vector<bool>& fixed, const SurfaceProjection& projection, int threads) {
  std::vector<Vec3> at(samples.size()), along(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    at[i] = along[i] = Vec3::Zero();
    for (int v : samples[i].corners) {
      at[i] += mesh.points[v] / static_cast<double>(samples[i].corners.size());
      along[i] += normals[v];
    }
    if (along[i].norm() > 0) along[i].normalize();
  }
  const std::vector<Vec3> closest = projection.closestPoints(at, threads);
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(mesh.vertexCount());
  double diagonal = 0;  // the sum of the squared shares: the scale of the system's diagonal
  for (size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    const double d = (closest[i] - at[i]).dot(along[i]);
    // The sample moves by sum over its corners of share * (n_v . n) * t_v along n.
    for (int u : s.corners) {
      const double a = normals[u].dot(along[i]) / s.corners.size();
      diagonal += s.weight * a * a;
      if (fixed[u]) continue;
      rhs[u] += s.weight * a * d;
      for (int v : s.corners)
        if (!fixed[v]) entries.emplace_back(u, v, s.weight * a * normals[v].dot(along[i]) / s.corners.size());
    }
  }
  // Fixed vertices' rows and columns are the identity, their moves zero. A small pull towards
  // no move keeps the system definite where samples say little.
  const double damping = 1e-3 * diagonal / std::max(1, mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) entries.emplace_back(v, v, fixed[v] ? 1.0 : damping);
  Eigen::SparseMatrix<double> system(mesh.vertexCount(), mesh.vertexCount());
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) return Eigen::VectorXd::Zero(mesh.vertexCount());
  Eigen::VectorXd moves = solver.solve(rhs);
  if (!moves.allFinite()) moves.setZero();
  return moves;
}

}  // namespace

FitResult& FitResult::operator+=(const FitResult& o) {
  if (moved + o.moved > 0) meanPercent = (meanPercent * moved + o.meanPercent * o.moved) / (moved + o.moved);
  moved += o.moved;
  maxPercent = std::max(maxPercent, o.maxPercent);
  return *this;
}

FitResult FitResult::scaled(double factor) const {
  FitResult r = *this;
  r.meanPercent *= factor;
  r.maxPercent *= factor;
  return r;
}

FitResult fitToSurface(Mesh& mesh, const SearchableSurface& input, const FitOptions& options) {
  const Mesh& surface = input.mesh;
  const SurfaceProjection& projection = input.projection;
  const std::vector<Sample> samples = samplesOf(mesh);
  // The border stays on the input's border, and a vertex on an input vertex (a tip snapped
  // there, core/polish) stays on it.
  std::vector<bool> fixed = vertexEdges(mesh).onBoundary;
  std::set<std::array<double, 3>> inputVertices;
  for (const Vec3& p : surface.points) inputVertices.insert({p.x(), p.y(), p.z()});
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const Vec3& p = mesh.points[v];
    if (inputVertices.count({p.x(), p.y(), p.z()})) fixed[v] = true;
  }
  const Rings rings(mesh);
  const std::vector<Vec3> start = mesh.points;
  const std::vector<Vec3> normals = vertexNormals(mesh);
  const Eigen::VectorXd moves = normalMoves(mesh, normals, samples, fixed, projection, options.threads);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (moves[v] == 0) continue;
    const double before = smallestAngleOfRing(mesh, rings, v, mesh.points[v]);
    // The whole move, else half of it, else a quarter, else none: the others' moves were solved
    // for with this one whole, so a part of it is a compromise, still closer than none.
    for (double part = 1; part > 0.2; part /= 2) {
      const Vec3 to = mesh.points[v] + part * moves[v] * normals[v];
      if (turnsOver(mesh, rings, v, to)) continue;
      const double after = smallestAngleOfRing(mesh, rings, v, to);
      if (after >= options.keepAngle || after >= before) {
        mesh.points[v] = to;
        break;
      }
    }
  }

  FitResult r;
  const double diagonal = boundingBoxDiagonal(surface);
  double sum = 0;
  for (size_t v = 0; v < mesh.points.size(); ++v) {
    const double d = (mesh.points[v] - start[v]).norm();
    if (d == 0) continue;
    ++r.moved;
    sum += d;
    r.maxPercent = std::max(r.maxPercent, 100.0 * d / diagonal);
  }
  if (r.moved > 0) r.meanPercent = 100.0 * sum / r.moved / diagonal;
  return r;
}

}  // namespace lloydscope
