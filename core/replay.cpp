#include "replay.h"

#include <algorithm>
#include <map>

namespace lloydscope {

Replay::Replay(Recording recording)
    : recording_(std::move(recording)), domain_(recording_.domain()), method_(recording_.method),
      seams_(seamEdges(recording_.input, seamTolerance(recording_.input))) {
  setMethod(method_);
  // The fixed sites are the border vertices' own parameter points.
  std::map<std::pair<double, double>, int> fixedAt;
  for (size_t j = 0; j < recording_.fixedSites.size(); ++j)
    fixedAt[{recording_.fixedSites[j].x(), recording_.fixedSites[j].y()}] = static_cast<int>(j);
  auto fixedSite = [&](int v) {
    const auto it = fixedAt.find({recording_.uv[v].x(), recording_.uv[v].y()});
    return it == fixedAt.end() ? -1 : it->second;
  };
  for (const auto& [a, b] : recording_.sharedSeams)
    if (fixedSite(a) >= 0 && fixedSite(b) >= 0) sharedOnOutput_.emplace_back(fixedSite(a), fixedSite(b));
  for (int v = 0; v < static_cast<int>(recording_.uv.size()); ++v) borderSite_.push_back(fixedSite(v));
}

bool Replay::canRelocate() const {
  // A relocate run of a disk whose every vertex is on the border has no movable site, and no
  // vertex to say so by (the inspector said its run had placed its own sites).
  const bool noneMovable = recording_.iterations.empty() || recording_.iterations.front().sites.size() == 0;
  if (noneMovable) return recording_.method == RemeshMethod::Relocate;
  return !recording_.movableVertex.empty() &&
         std::none_of(recording_.movableVertex.begin(), recording_.movableVertex.end(), [](int v) { return v < 0; });
}

void Replay::setMethod(RemeshMethod method) {
  if (!canRelocate()) method = RemeshMethod::Retriangulate;
  if (method != method_) view_.index = -1;  // the output mesh must be rebuilt
  method_ = method;
}

Topology Replay::surface() const {
  const Mesh& disk = recording_.input;
  return analyzeTopology(seams_.empty() ? disk : stitchSeams(disk, seamTolerance(disk)));
}

const IterationView& Replay::view(int k) {
  k = std::clamp(k, 0, std::max(0, iterationCount() - 1));
  if (view_.index == k || recording_.iterations.empty()) return view_;
  const IterationRecord& it = recording_.iterations[k];
  // Made apart and moved in whole: where it fails (a damaged recording), the view before stays
  // as it was (it was left half made, its new sites over its old mesh).
  IterationView next;
  next.index = k;
  next.sites = allSites(recording_.fixedSites, it.sites);
  next.cells = recording_.cells(domain_, k, /*keepGeometry=*/true, &hints_);
  for (size_t i = 0; i < next.sites.size(); ++i)
    next.liftedSites.push_back(lift(recording_.input, domain_, next.sites[i], hints_.triangle[i]));
  // The retriangulated output is made of exactly these lifted points: no second lift
  // (relocate lifts its vertices where they end, short of a site where it would fold).
  const size_t fixedCount = recording_.fixedSites.size();
  if (method_ == RemeshMethod::Retriangulate) {
    next.output = assemble(triangulateSites(recording_.fixedSites, it.sites.unpack()), next.liftedSites,
                           &next.outputSite);
    for (int s : next.outputSite) next.outputUV.push_back(next.sites[s]);
  } else {
    Relocation relocated = relocate(recording_.input, domain_, recording_.movableVertex, it.sites.unpack());
    next.output = std::move(relocated.mesh);
    next.outputUV = std::move(relocated.uv);  // short of the sites where they would fold
    next.outputSite = borderSite_;  // relocate leaves the border vertices on their fixed sites
    for (size_t i = 0; i < it.sites.size(); ++i)
      next.outputSite[recording_.movableVertex[i]] = static_cast<int>(fixedCount + i);
  }
  if (!seams_.empty())
    next.stitched = stitchSeams(next.output, seamTolerance(next.output), nullptr, &next.stitchedVertex);
  view_ = std::move(next);
  return view_;
}

}  // namespace lloydscope
