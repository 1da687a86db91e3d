// `lloydscope bench`: Lloydscope's methods side by side with CGAL's isotropic_remeshing on
// prepared inputs, as markdown and CSV (issue 5's evidence).
#pragma once

#include <string>
#include <vector>

namespace lloydscope {

struct BenchOptions {
  std::vector<std::string> models;  // mesh files; empty: CGAL's disk samples in data/cgal
  std::vector<int> sizes = {500, 1000, 2000};
  std::string csv = "bench.csv";
  std::string saveInputs;  // a folder: write the prepared inputs there, to try other settings on
  bool reference = true;  // also the report's preset (plain Lloyd: slow)
  // The models as they come, not prepared: each remeshed to each size (--sites), with the
  // defaults and --full-input, beside CGAL's remesher on the same model.
  bool asIs = false;
  bool repair = false;    // read the models with the repair (core/repair), each change a note
  int stepSites = 0;      // > 0: time Lloyd iterations at this many sites instead
};

// Prints the tables to stdout and writes the CSV; throws Error on unreadable models.
void runBench(const BenchOptions& options);

// The cost of one Lloyd iteration at options.stepSites sites on the first model (default:
// the bundled bumpy disk), uniform and area density, one core and all: a table of the median
// and the best of iterations 1-10 (iteration 0 has no hints), in ms and in µs per site.
void runStepBench(const BenchOptions& options);

}  // namespace lloydscope
