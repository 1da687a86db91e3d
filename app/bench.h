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
  bool reference = true;  // also the report's preset (plain Lloyd: slow)
};

// Prints the tables to stdout and writes the CSV; throws Error on unreadable models.
void runBench(const BenchOptions& options);

}  // namespace lloydscope
