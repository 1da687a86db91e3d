#include "charts.h"

#include "cgal_types.h"
#include "cut.h"
#include "topology.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <unordered_map>

namespace lloydscope {

namespace {

// across[f][k]: the face across the edge from corner k to corner k + 1 of face f, or -1.
std::vector<std::array<int, 3>> facesAcross(const Mesh& mesh) {
  std::unordered_map<long long, int> firstSide;  // edge (a < b) -> 3 f + k of its first face
  std::vector<std::array<int, 3>> across(mesh.faceCount(), {-1, -1, -1});
  const long long n = mesh.vertexCount();
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      const long long key = std::min(a, b) * n + std::max(a, b);
      const auto [it, inserted] = firstSide.emplace(key, 3 * f + k);
      if (inserted) continue;
      across[f][k] = it->second / 3;
      across[it->second / 3][it->second % 3] = f;
    }
  return across;
}

Vec3 unitNormal(const Mesh& mesh, const Triangle& t) {
  const Vec3 n = faceNormal(mesh, t);
  const double length = n.norm();
  return length > 0 ? Vec3(n / length) : Vec3::Zero();
}

// A merged chart's faces stay within this angle of its mean normal (cosine).
const double kMergedCos = std::cos(75.0 * M_PI / 180.0);

// Labels the faces chart by chart. Each chart grows from the first face not yet taken, breadth
// first, over faces within the cone around the seed's normal, and stays a disk: a face joins
// across one of its edges only if its third corner is not yet the chart's, or across two
// (filling a notch). A small chart is then merged into a neighbour if the two share one
// stretch of border (the union is a disk again).
class Labelling {
 public:
  Labelling(const Mesh& mesh, const ChartOptions& options, int resultVertices)
      : mesh_(mesh), across_(facesAcross(mesh)), label_(mesh.faceCount(), -1) {
    double total = 0;
    for (const Triangle& t : mesh.triangles) {
      area_.push_back(triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]));
      total += area_.back();
      normal_.push_back(unitNormal(mesh, t));
    }
    smallest_ = total * options.smallestShare / std::max(1, resultVertices);
    grow(std::cos(options.coneDegrees * M_PI / 180.0));
    mergeSmall(true);
    mergeSmall(false);
    smoothBorders();
    compact();
  }
  const std::vector<int>& labels() const { return label_; }
  const std::vector<std::array<int, 3>>& across() const { return across_; }
  int count() const { return count_; }
  Vec3 normal(int chart) const { return meanNormal(chart, chart); }

 private:
  void grow(double cosCone) {
    std::vector<int> cornersIn(mesh_.vertexCount(), 0), stamp(mesh_.vertexCount(), -1);
    for (int seed = 0; seed < mesh_.faceCount(); ++seed) {
      if (label_[seed] >= 0) continue;
      const int chart = count_++;
      auto inChart = [&](int v) { return stamp[v] == chart && cornersIn[v] > 0; };
      auto take = [&](int f) {
        label_[f] = chart;
        for (int v : mesh_.triangles[f]) {
          if (stamp[v] != chart) cornersIn[v] = 0;
          stamp[v] = chart;
          ++cornersIn[v];
        }
      };
      take(seed);
      std::vector<int> queue = {seed};
      for (size_t head = 0; head < queue.size(); ++head)
        for (int g : across_[queue[head]]) {
          if (g < 0 || label_[g] >= 0 || normal_[g].dot(normal_[seed]) < cosCone) continue;
          int shared = 0;
          for (int h : across_[g]) shared += h >= 0 && label_[h] == chart;
          const bool joins =
              shared == 2 || (shared == 1 && !inChart(mesh_.triangles[g][oppositeOfShared(g, chart)]));
          if (!joins) continue;  // a later face of the chart may let it in
          take(g);
          queue.push_back(g);
        }
    }
  }

  // The corner of g opposite its one edge shared with `chart`.
  int oppositeOfShared(int g, int chart) const {
    for (int k = 0; k < 3; ++k) {
      const int h = across_[g][k];
      if (h >= 0 && label_[h] == chart) return (k + 2) % 3;
    }
    return 0;
  }

  std::vector<double> chartAreas() const {
    std::vector<double> area(count_, 0.0);
    for (int f = 0; f < mesh_.faceCount(); ++f) area[label_[f]] += area_[f];
    return area;
  }

  double edgeLength(int f, int k) const {
    const Triangle& t = mesh_.triangles[f];
    return (mesh_.points[t[(k + 1) % 3]] - mesh_.points[t[k]]).norm();
  }

  // Whether charts a and b share exactly one stretch of border: the vertices both have are
  // one more than the edges between them, and those edges connect them all (a path).
  bool shareOneStretch(int a, int b) const {
    std::set<int> inA, shared;
    for (int f = 0; f < mesh_.faceCount(); ++f)
      if (label_[f] == a) inA.insert(mesh_.triangles[f].begin(), mesh_.triangles[f].end());
    for (int f = 0; f < mesh_.faceCount(); ++f)
      if (label_[f] == b)
        for (int v : mesh_.triangles[f])
          if (inA.count(v)) shared.insert(v);
    std::vector<std::pair<int, int>> edges;
    for (int f = 0; f < mesh_.faceCount(); ++f)
      if (label_[f] == a)
        for (int k = 0; k < 3; ++k)
          if (across_[f][k] >= 0 && label_[across_[f][k]] == b)
            edges.emplace_back(mesh_.triangles[f][k], mesh_.triangles[f][(k + 1) % 3]);
    if (edges.empty() || shared.size() != edges.size() + 1) return false;
    std::unordered_map<int, int> parent;
    std::function<int(int)> root = [&](int v) {
      auto it = parent.find(v);
      return it == parent.end() || it->second == v ? v : it->second = root(it->second);
    };
    for (const auto& [u, v] : edges) parent[root(u)] = root(v);
    std::set<int> roots;
    for (int v : shared) roots.insert(root(v));
    return roots.size() == 1;
  }

  // The area-weighted mean normal of the faces of charts a and b (b = a: of a alone).
  Vec3 meanNormal(int a, int b) const {
    Vec3 sum = Vec3::Zero();
    for (int f = 0; f < mesh_.faceCount(); ++f)
      if (label_[f] == a || label_[f] == b) sum += area_[f] * normal_[f];
    return sum.normalized();
  }

  // Whether every face of charts a and b is within kMergedCos of their mean normal.
  bool staysFlat(int a, int b) const {
    const Vec3 mean = meanNormal(a, b);
    for (int f = 0; f < mesh_.faceCount(); ++f)
      if ((label_[f] == a || label_[f] == b) && area_[f] > 0 && normal_[f].dot(mean) < kMergedCos) return false;
    return true;
  }

  // Smallest first, each small chart into the neighbour it shares the longest border with, of
  // those it shares a single stretch with (and, if `flat`, that it stays flat with); one that
  // has none stays as it is.
  void mergeSmall(bool flat) {
    std::set<int> stays;
    for (;;) {
      const std::vector<double> area = chartAreas();
      int small = -1;
      for (int c = 0; c < count_; ++c)
        if (area[c] > 0 && area[c] < smallest_ && !stays.count(c) && (small < 0 || area[c] < area[small])) small = c;
      if (small < 0) return;
      std::unordered_map<int, double> sharedLength;
      for (int f = 0; f < mesh_.faceCount(); ++f)
        if (label_[f] == small)
          for (int k = 0; k < 3; ++k) {
            const int g = across_[f][k];
            if (g >= 0 && label_[g] != small) sharedLength[label_[g]] += edgeLength(f, k);
          }
      std::vector<std::pair<double, int>> neighbours;
      for (const auto& [chart, length] : sharedLength) neighbours.emplace_back(length, chart);
      std::sort(neighbours.rbegin(), neighbours.rend());
      int into = -1;
      for (const auto& [length, chart] : neighbours)
        if (shareOneStretch(small, chart) && (!flat || staysFlat(small, chart))) {
          into = chart;
          break;
        }
      if (into < 0) {
        stays.insert(small);
        continue;
      }
      for (int& l : label_)
        if (l == small) l = into;
    }
  }

  // A face with two neighbours in one other chart and at most one in its own (a tooth of a
  // jagged border) goes to that chart: its own stays a disk (the face was an ear of it) and so
  // does the other (the face fills a notch of it). A jagged border makes thin triangles along
  // the seam and sample chords that cross the border.
  void smoothBorders() {
    for (int pass = 0; pass < 10; ++pass) {
      bool moved = false;
      for (int f = 0; f < mesh_.faceCount(); ++f) {
        int own = 0, other = -1, inOther = 0;
        for (int g : across_[f]) {
          if (g < 0) continue;
          if (label_[g] == label_[f])
            ++own;
          else if (other < 0 || label_[g] == other) {
            other = label_[g];
            ++inOther;
          }
        }
        if (own <= 1 && inOther == 2) {
          label_[f] = other;
          moved = true;
        }
      }
      if (!moved) return;
    }
  }

  // Labels 0 .. count - 1 in the order of each chart's first face.
  void compact() {
    std::unordered_map<int, int> renamed;
    for (int& l : label_) l = renamed.emplace(l, static_cast<int>(renamed.size())).first->second;
    count_ = static_cast<int>(renamed.size());
  }

  const Mesh& mesh_;
  std::vector<std::array<int, 3>> across_;
  std::vector<int> label_;
  std::vector<double> area_;
  std::vector<Vec3> normal_;
  double smallest_ = 0;
  int count_ = 0;
};

}  // namespace

Charts splitIntoCharts(const Mesh& mesh, int resultVertices, const ChartOptions& options) {
  const Labelling labelling(mesh, options, resultVertices);
  const std::vector<int>& label = labelling.labels();
  const auto& across = labelling.across();
  Charts result;
  // Per surface vertex: seam edges at it, the charts around it, on the surface's border.
  std::vector<int> seamEdges(mesh.vertexCount(), 0);
  std::vector<std::set<int>> chartsAt(mesh.vertexCount());
  std::vector<bool> onBorder(mesh.vertexCount(), false);
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3], g = across[f][k];
      chartsAt[a].insert(label[f]);
      if (g < 0) onBorder[a] = onBorder[b] = true;
      if (g < 0 || label[g] == label[f] || g < f) continue;  // each seam edge once
      ++seamEdges[a];
      ++seamEdges[b];
      ++result.seamEdges;
    }
  std::vector<bool> onSeam(mesh.vertexCount()), node(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    onSeam[v] = seamEdges[v] > 0;
    node[v] = onSeam[v] && (chartsAt[v].size() > 2 || onBorder[v] || seamEdges[v] != 2);
  }

  result.charts.resize(labelling.count());
  std::vector<int> local(mesh.vertexCount(), -1);
  for (int c = 0; c < labelling.count(); ++c) {
    Chart& chart = result.charts[c];
    for (int f = 0; f < mesh.faceCount(); ++f)
      if (label[f] == c)
        for (int v : mesh.triangles[f]) chart.original.push_back(v);
    std::sort(chart.original.begin(), chart.original.end());
    chart.original.erase(std::unique(chart.original.begin(), chart.original.end()), chart.original.end());
    for (size_t i = 0; i < chart.original.size(); ++i) {
      local[chart.original[i]] = static_cast<int>(i);
      chart.mesh.points.push_back(mesh.points[chart.original[i]]);
    }
    for (int f = 0; f < mesh.faceCount(); ++f)
      if (label[f] == c) {
        const Triangle& t = mesh.triangles[f];
        chart.mesh.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
      }
    // A border loop that is all seam and meets no node (a chart inside another) gets one: its
    // smallest vertex, the same seen from either side.
    for (const std::vector<int>& loop : analyzeTopology(chart.mesh).boundaryLoops) {
      bool allSeam = true, hasNode = false;
      int smallest = -1;
      for (size_t i = 0; i < loop.size(); ++i) {
        const int s = chart.original[loop[i]], next = chart.original[loop[(i + 1) % loop.size()]];
        allSeam = allSeam && onSeam[s];
        hasNode = hasNode || node[s];
        smallest = smallest < 0 ? s : std::min(smallest, s);
        if (onSeam[s] && onSeam[next]) chart.seamLength += (mesh.points[s] - mesh.points[next]).norm();
      }
      if (allSeam && !hasNode) node[smallest] = true;
    }
  }
  for (int c = 0; c < labelling.count(); ++c) {
    Chart& chart = result.charts[c];
    for (int s : chart.original) {
      chart.onSeam.push_back(onSeam[s]);
      chart.seamNode.push_back(node[s]);
      if (node[s] && chartsAt[s].size() > 2)
        chart.nodeSamples += (chartsAt[s].size() - 2.0) / (2.0 * chartsAt[s].size());
    }
    const Vec3 n = labelling.normal(c);
    const Vec3 e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    for (const Vec3& p : chart.mesh.points) chart.uv.emplace_back(p.dot(e1), p.dot(e2));
  }
  return result;
}

std::vector<std::pair<int, int>> sharedSeamEdges(const Mesh& surface, const Mesh& chart,
                                                 const std::vector<bool>& onSeam) {
  std::vector<Kernel::Segment_3> seams;
  for (const std::vector<int>& loop : analyzeTopology(chart).boundaryLoops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      if (!onSeam[a] || !onSeam[b]) continue;
      const Vec3 &p = chart.points[a], &q = chart.points[b];
      seams.emplace_back(Point3(p.x(), p.y(), p.z()), Point3(q.x(), q.y(), q.z()));
    }
  const double tolerance = seamTolerance(chart);
  auto onASeam = [&](const Vec3& p) {
    const Point3 point(p.x(), p.y(), p.z());
    return std::any_of(seams.begin(), seams.end(), [&](const Kernel::Segment_3& s) {
      return CGAL::squared_distance(point, s) <= tolerance * tolerance;
    });
  };
  std::vector<std::pair<int, int>> edges;
  for (const std::vector<int>& loop : analyzeTopology(surface).boundaryLoops) {
    std::vector<bool> on;
    for (int v : loop) on.push_back(onASeam(surface.points[v]));
    for (size_t i = 0; i < loop.size(); ++i)
      if (on[i] && on[(i + 1) % loop.size()]) edges.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
  }
  return edges;
}

}  // namespace lloydscope
