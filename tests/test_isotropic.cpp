#include "isotropic.h"
#include "mesh_io.h"
#include "metrics.h"
#include "test_support.h"
#include "topology.h"

using namespace lloydscope;

TEST(Isotropic, MatchesTheVertexCountWithinOnePercent) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  IsotropicOptions o;
  o.vertices = 600;
  const IsotropicResult r = isotropicRemesh(input, o);
  EXPECT_NEAR(r.mesh.vertexCount(), 600, 6);
  EXPECT_GT(r.edgeLength, 0);
  EXPECT_GT(r.milliseconds, 0);
  EXPECT_NO_THROW(validateMesh(r.mesh, "isotropic"));
  EXPECT_TRUE(analyzeTopology(r.mesh).isDisk());
  // It is a good remesher: the badly shaped input gets much better angles.
  EXPECT_GT(measureQuality(r.mesh).avgMinAngle, measureQuality(input).avgMinAngle + 10);
}
