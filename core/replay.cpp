#include "replay.h"

#include <algorithm>

namespace lloydscope {

Replay::Replay(Recording recording)
    : recording_(std::move(recording)), domain_(recording_.domain()), method_(recording_.method) {
  setMethod(method_);
}

void Replay::setMethod(RemeshMethod method) {
  // relocate needs one site per inside vertex; a recording made otherwise can only retriangulate
  const bool everySiteHasAVertex =
      !recording_.movableVertex.empty() &&
      std::none_of(recording_.movableVertex.begin(), recording_.movableVertex.end(),
                   [](int v) { return v < 0; });
  if (!everySiteHasAVertex) method = RemeshMethod::Retriangulate;
  if (method != method_) view_.index = -1;  // the output mesh must be rebuilt
  method_ = method;
}

const IterationView& Replay::view(int k) {
  k = std::clamp(k, 0, std::max(0, iterationCount() - 1));
  if (view_.index == k || recording_.iterations.empty()) return view_;
  const IterationRecord& it = recording_.iterations[k];
  view_.index = k;
  view_.sites = allSites(recording_.fixedSites, it.sites);
  view_.cells = recording_.cells(domain_, k, /*keepGeometry=*/true);
  view_.liftedSites.clear();
  for (const Vec2& s : view_.sites) view_.liftedSites.push_back(lift(recording_.input, domain_, s));
  // Retriangulating needs exactly these lifted points: no second lift.
  view_.output = method_ == RemeshMethod::Retriangulate
                     ? assemble(triangulateSites(recording_.fixedSites, it.sites), view_.liftedSites)
                     : relocate(recording_.input, domain_, recording_.movableVertex, it.sites);
  return view_;
}

}  // namespace lloydscope
