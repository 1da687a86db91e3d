// The texts the command line and the inspector show (app/report.h).
#include "pipeline.h"
#include "report.h"
#include "test_support.h"

using namespace lloydscope;

// A run without the measurement (--no-fidelity) says so, rather than "Hausdorff 0.000%": the
// inspector's picture of ./build.sh run (made with --no-fidelity) claimed a perfect fit.
TEST(Report, TheDistanceToTheInputIsShownOnlyWhereMeasured) {
  RemeshOptions options;
  options.sites.count = 60;
  options.measureFidelity = false;
  const Mesh grid = test::grid(8);
  EXPECT_EQ(distanceText(remesh(grid, options, "grid").fidelity),
            "Distance to the input not measured (--no-fidelity)");
  options.measureFidelity = true;
  const std::string measured = distanceText(remesh(grid, options, "grid").fidelity);
  EXPECT_EQ(measured.rfind("Hausdorff ", 0), 0u) << measured;
  EXPECT_NE(measured.find("%, RMS "), std::string::npos) << measured;
  EXPECT_NE(measured.find("% of diagonal"), std::string::npos) << measured;
}
