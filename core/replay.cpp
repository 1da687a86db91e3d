#include "replay.h"

#include <algorithm>
#include <map>

namespace lloydscope {

Replay::Replay(Recording recording)
    : recording_(std::move(recording)), domain_(recording_.domain()), method_(recording_.method),
      seams_(seamEdges(recording_.input, kSeamTolerance * boundingBoxDiagonal(recording_.input))) {
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
  return !recording_.movableVertex.empty() &&
         std::none_of(recording_.movableVertex.begin(), recording_.movableVertex.end(), [](int v) { return v < 0; });
}

void Replay::setMethod(RemeshMethod method) {
  if (!canRelocate()) method = RemeshMethod::Retriangulate;
  if (method != method_) view_.index = -1;  // the output mesh must be rebuilt
  method_ = method;
}

const IterationView& Replay::view(int k) {
  k = std::clamp(k, 0, std::max(0, iterationCount() - 1));
  if (view_.index == k || recording_.iterations.empty()) return view_;
  const IterationRecord& it = recording_.iterations[k];
  view_.index = k;
  view_.sites = allSites(recording_.fixedSites, it.sites);
  view_.cells = recording_.cells(domain_, k, /*keepGeometry=*/true, &hints_);
  view_.liftedSites.clear();
  for (size_t i = 0; i < view_.sites.size(); ++i)
    view_.liftedSites.push_back(lift(recording_.input, domain_, view_.sites[i], hints_.triangle[i]));
  // The retriangulated output is made of exactly these lifted points: no second lift
  // (relocate lifts its vertices where they end, short of a site where it would fold).
  const size_t fixedCount = recording_.fixedSites.size();
  view_.outputUV.clear();
  view_.outputSite.clear();
  if (method_ == RemeshMethod::Retriangulate) {
    view_.output = assemble(triangulateSites(recording_.fixedSites, it.sites.unpack()), view_.liftedSites,
                            &view_.outputSite);
    for (int s : view_.outputSite) view_.outputUV.push_back(view_.sites[s]);
  } else {
    Relocation relocated = relocate(recording_.input, domain_, recording_.movableVertex, it.sites.unpack());
    view_.output = std::move(relocated.mesh);
    view_.outputUV = std::move(relocated.uv);  // short of the sites where they would fold
    view_.outputSite = borderSite_;  // relocate leaves the border vertices on their fixed sites
    for (size_t i = 0; i < it.sites.size(); ++i)
      view_.outputSite[recording_.movableVertex[i]] = static_cast<int>(fixedCount + i);
  }
  view_.stitched = !seams_.empty() ? stitchSeams(view_.output, kSeamTolerance * boundingBoxDiagonal(view_.output)) : Mesh{};
  return view_;
}

}  // namespace lloydscope
