// Image snapshots of the whole inspector, rendered headless by the lloydscope binary, compared
// with committed PNGs under a per-pixel tolerance. After an intended change of the pictures:
//   LLOYDSCOPE_UPDATE_SNAPSHOTS=1 build/tests/lloydscope_tests --gtest_filter='Inspector*'
#include "gpu.h"
#include "mesh_io.h"
#include "recording.h"
#include "test_support.h"

#include <stb_image.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <sys/wait.h>
#include <unistd.h>

using namespace lloydscope;

namespace {

struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;
  const unsigned char* at(int x, int y) const { return &rgba[4 * (static_cast<size_t>(y) * width + x)]; }
};

Picture readPng(const std::string& path) {
  Picture p;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &p.width, &p.height, &channels, 4);
  if (data) {
    p.rgba.assign(data, data + static_cast<size_t>(p.width) * p.height * 4);
    stbi_image_free(data);
  }
  return p;
}

// The pixels whose colour `is` takes (a pointer to its red, green and blue).
template <class ColourTest>
int pixelsWhere(const Picture& picture, ColourTest is) {
  int count = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) count += is(picture.at(x, y));
  return count;
}

// Pixels of a pinned triangle's teal (Selection::triangleColor: 0, 140, 115).
int tealPixels(const Picture& picture) {
  return pixelsWhere(picture, [](const unsigned char* c) {
    return c[0] < 40 && c[1] > 110 && c[1] < 170 && c[2] > 85 && c[2] < 145;
  });
}

// A seam's purple (kSeamColor in app/inspector.cpp: 150, 40, 190), give or take.
bool isSeamPurple(const unsigned char* c) {
  return std::abs(c[0] - 150) < 30 && std::abs(c[1] - 40) < 30 && std::abs(c[2] - 190) < 30;
}

// Pixels of a pinned cell's magenta (Selection::cellColor: 217, 13, 179).
int magentaPixels(const Picture& picture) {
  return pixelsWhere(picture, [](const unsigned char* c) { return c[0] > 170 && c[1] < 60 && c[2] > 130; });
}

// Pixels of the valence fill's 7 (red, 245 115 89) and 5 (blue, 102 158 242), give or take.
int valencePixels(const Picture& picture) {
  auto near = [](const unsigned char* c, int r, int g, int b) {
    return std::abs(c[0] - r) < 25 && std::abs(c[1] - g) < 25 && std::abs(c[2] - b) < 25;
  };
  return pixelsWhere(picture, [&](const unsigned char* c) { return near(c, 245, 115, 89) || near(c, 102, 158, 242); });
}

// Pixels of rows [firstRow, endRow) that differ between two pictures of one size: a channel
// off by more than `tolerance` (antialiasing stays under 24).
size_t differingPixels(const Picture& a, const Picture& b, int firstRow, int endRow, int tolerance = 24) {
  size_t differing = 0;
  for (int y = firstRow; y < endRow; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(a.at(x, y)[c] - b.at(x, y)[c]) > tolerance) {
          ++differing;
          break;
        }
  return differing;
}

int run(const std::string& args) {
  const int status = std::system((std::string(LLOYDSCOPE_CLI) + " " + args).c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// `inspect ARGS` rendered headless at 960x600 without timings to `png`: the exit code.
int renderScene(const std::string& args, const std::string& png) {
  return run("inspect " + args + " --screenshot " + png + " --size 960x600 --no-timings");
}

// `input`: a mesh or a recording, by default the sphere cap. `exactRows`: the picture's top
// rows (a lesson's caption) must match with no pixel off: its numbers are a few hundred
// pixels, under the whole picture's allowance.
void checkScene(const std::string& name, const std::string& args, std::string input = "", int exactRows = 0) {
  if (input.empty()) input = test::assetPath("sphere_cap.off");
  const std::string actualPath = test::tempPath(name);
  ASSERT_EQ(renderScene(input + " " + args, actualPath), 0);
  const std::string expectedPath = std::string(LLOYDSCOPE_SOURCE_DIR) + "/tests/snapshots/" + name;
  if (std::getenv("LLOYDSCOPE_UPDATE_SNAPSHOTS")) {
    std::rename(actualPath.c_str(), expectedPath.c_str());
    GTEST_SKIP() << "snapshot written: " << expectedPath;
  }
  const Picture expected = readPng(expectedPath), actual = readPng(actualPath);
  ASSERT_FALSE(expected.rgba.empty()) << "missing snapshot " << expectedPath;
  ASSERT_EQ(actual.width, expected.width);
  ASSERT_EQ(actual.height, expected.height);
  // Allow 0.5% of the pixels to differ (antialiasing), none in the exact rows.
  const size_t differing = differingPixels(actual, expected, 0, actual.height),
               inExactRows = differingPixels(actual, expected, 0, exactRows);
  EXPECT_LE(differing, actual.rgba.size() / 4 / 200) << name << ": " << differing << " pixels differ from the snapshot; this run's picture: " << actualPath;
  EXPECT_EQ(inExactRows, 0u) << name << ": the top " << exactRows << " rows differ; this run's picture: " << actualPath;
}

// The 2D domain's border, a colour bar's outline, the legend's text: not the cells' lines.
bool isDark(const unsigned char* c) { return std::max({c[0], c[1], c[2]}) < 70; }

// The longest run of dark pixels down column x.
int longestDarkRun(const Picture& picture, int x) {
  int run = 0, longest = 0;
  for (int y = 0; y < picture.height; ++y) {
    run = isDark(picture.at(x, y)) ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return longest;
}

// The columns of the 2D pane's picture crossed by a dark line of 100 pixels or more (the
// domain's border): the first and the last.
std::pair<int, int> longDarkColumns(const Picture& picture) {
  int first = -1, last = -1;
  for (int x = 0; x < picture.width; ++x)
    if (longestDarkRun(picture, x) >= 100) {
      if (first < 0) first = x;
      last = x;
    }
  return {first, last};
}

// A flat 4:1 strip of 451 vertices, written once: its file.
std::string flatStripFile() {
  const std::string strip = test::tempPath("flat_strip.off");
  if (!std::filesystem::exists(strip))
    writeMesh(test::wrappedGrid(40, 10, false, false, [](double u, double v) { return Vec3(4 * u, v, 0); }), strip);
  return strip;
}

}  // namespace

TEST(Inspector, FirstIteration) { checkScene("inspector_iteration0.png", "--iteration 0"); }
TEST(Inspector, SecondIteration) { checkScene("inspector_iteration1.png", "--iteration 1"); }
TEST(Inspector, LastIteration) { checkScene("inspector_last.png", ""); }
// The worst triangle of a result is a sliver a few pixels across: pinned, it was filled and
// outlined in teal, and a lecturer could not find it (85 and 69 teal pixels in the 2D and 3D
// panes of the cap). A ring around it makes it a mark of its own.
TEST(Inspector, APinnedTriangleIsRingedInBothViews) {
  for (const char* pane : {"2d", "3d"}) {
    const std::string png = test::tempPath(std::string("worst_") + pane + ".png");
    ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --select-worst --pane " + pane, png), 0);
    EXPECT_GE(tealPixels(readPng(png)), 180) << pane;
  }
}

// Triangles a few pixels across were all wire: a dense input (the 25,905-vertex face) was a
// black silhouette with no quality colours. Seen from far, the cap's input keeps its colours
// (dark pixels 1168 and coloured 306 before; 390 and 607 now).
TEST(Inspector, TheWireframeFadesOnTinyTriangles) {
  const std::string png = test::tempPath("far.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --pane 3d --stage load --camera '0.6 0.7 14 0 0 0.75'", png),
            0);
  const Picture picture = readPng(png);
  int dark = 0, green = 0;
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const unsigned char* c = picture.at(x, y);
      if (c[0] < 50 && c[1] < 50 && c[2] < 60) ++dark;
      else if (c[1] > c[0] + 15 && c[1] > c[2] + 15) ++green;
    }
  EXPECT_GT(green, dark);
}

// The 3D view is centred under its label: at 960x600 the final result's label, on two lines,
// covered the top of the lion's head. Seen from above, the cap is a disc as far below the
// label's box as above the pane's foot (before: 90 px below the box, 120 above the foot).
TEST(Inspector, The3DViewIsCentredUnderItsLabel) {
  const std::string png = test::tempPath("under_label.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --final --pane 3d --camera '0 1.5 8 0 0 0.75'", png), 0);
  const Picture picture = readPng(png);
  int labelBottom = -1, discTop = picture.height, discBottom = -1;
  for (int y = 0; y < picture.height; ++y) {
    const unsigned char* box = picture.at(16, y);  // the label's light box, left of its text
    if (box[0] > 245 && box[1] > 245 && box[2] > 245) labelBottom = y;
    for (int x = 45; x < picture.width; ++x) {  // right of the colour bar
      const unsigned char* c = picture.at(x, y);
      if (c[1] > c[0] + 15 && c[1] > c[2] + 15) {  // the cap's green
        discTop = std::min(discTop, y);
        discBottom = y;
      }
    }
  }
  ASSERT_GT(labelBottom, 0);
  ASSERT_GT(discBottom, discTop);
  EXPECT_NEAR(discTop - labelBottom, picture.height - 1 - discBottom, 10)
      << "label's box ends at " << labelBottom << ", the disc spans " << discTop << "-" << discBottom;
}

// On a screen twice as dense (--ui-scale 2, as a window takes it from the screen's Xft.dpi),
// the inspector is the same picture drawn with twice the pixels: panes, type, dots and rings.
// Halved, it differs from the 960x600 one on 2.9% of the pixels (the type's antialiasing).
// Before, a 1920x1200 picture laid out 1920x1200 of 13-pixel type: 25.8%; with the 3D and 2D
// panes' viewports left unscaled, 8.4%; with the dots and rings left their size in pixels, the
// centroids' orange rings had 0.28 of their pixels.
TEST(Inspector, ADenserScreenDrawsTheSamePictureWithTwiceThePixels) {
  const std::string small = test::tempPath("scale1.png"), large = test::tempPath("scale2.png");
  const std::string cap = test::assetPath("sphere_cap.off") + " --final --no-timings --screenshot ";
  ASSERT_EQ(run("inspect " + cap + small + " --size 960x600"), 0);
  ASSERT_EQ(run("inspect " + cap + large + " --size 1920x1200 --ui-scale 2"), 0);
  const Picture a = readPng(small), b = readPng(large);
  ASSERT_EQ(b.width, 2 * a.width);
  ASSERT_EQ(b.height, 2 * a.height);
  Picture halved = a;  // b, each 2x2 block of pixels averaged
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        halved.rgba[4 * (static_cast<size_t>(y) * a.width + x) + c] = static_cast<unsigned char>(
            (b.at(2 * x, 2 * y)[c] + b.at(2 * x + 1, 2 * y)[c] + b.at(2 * x, 2 * y + 1)[c] + b.at(2 * x + 1, 2 * y + 1)[c] + 2) / 4);
  // A channel off by more than 48: type drawn at twice the size and halved is blurred more.
  const size_t differing = differingPixels(halved, a, 0, a.height, 48);
  EXPECT_LT(differing, a.rgba.size() / 4 * 5 / 100) << differing << " pixels differ";
  const auto orange = [](const Picture& p) {
    return pixelsWhere(p, [](const unsigned char* c) { return c[0] > 170 && c[1] > 40 && c[1] < 120 && c[2] < 80; });
  };
  ASSERT_GT(orange(a), 100);
  EXPECT_NEAR(static_cast<double>(orange(halved)) / orange(a), 1.0, 0.4) << orange(a) << " and " << orange(halved);
}

// At --ui-scale 1.5 the left pane is too narrow for "Result: relocate retriangulate" and "2D
// click pins a cell triangle" on one line: the last button goes on the next, where it ran under
// the scroll bar, its label cut ("retriangulat", "triangl": 34 dark pixels in the 20 columns
// left of the bar).
TEST(Inspector, TheLeftPanesButtonsWrapRatherThanRunUnderItsScrollBar) {
  const std::string png = test::tempPath("ui_scale_15.png");
  ASSERT_EQ(run("inspect " + test::assetPath("bumpy_disk.off") +
                " --stage load --no-timings --size 1440x900 --ui-scale 1.5 --screenshot " + png),
            0);
  const Picture picture = readPng(png);
  int bar = -1;  // the scroll bar's left edge: a grey column down most of the left pane
  for (int x = 200; x < picture.width / 2 && bar < 0; ++x) {
    int grey = 0;
    for (int y = 0; y < picture.height; ++y) {
      const unsigned char* c = picture.at(x, y);
      grey += c[0] > 150 && c[0] < 215 && std::abs(c[0] - c[2]) < 10;
    }
    if (grey >= 400) bar = x;
  }
  ASSERT_GT(bar, 0);
  int cut = 0;  // the type's dark pixels
  for (int x = bar - 20; x < bar; ++x)
    for (int y = 0; y < picture.height; ++y) {
      const unsigned char* c = picture.at(x, y);
      cut += std::max({c[0], c[1], c[2]}) < 90;
    }
  EXPECT_EQ(cut, 0) << "text runs under the scroll bar at x = " << bar << ": " << png;
}

// With the final result shown, the worst triangle pinned is the final result's, ringed over it:
// it was the iteration's, which the final result hides (0 teal pixels).
TEST(Inspector, TheWorstTriangleOfTheFinalResultIsPinnedOverIt) {
  const std::string png = test::tempPath("final_worst.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --final --select-worst --pane 3d", png), 0);
  EXPECT_GE(tealPixels(readPng(png)), 180);
}

// The lesson's Voronoi to Lift stages show the input in 3D, with the sites lifted onto it: a
// pinned triangle, filled and ringed in 2D, is drawn there between its lifted corners too (it
// was in 2D alone: no teal in the 3D pane).
TEST(Inspector, TheVoronoiStageDrawsAPinnedTriangleIn3DToo) {
  const std::string png = test::tempPath("voronoi_pin.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --stage voronoi --select-triangle 400 --pane 3d", png), 0);
  EXPECT_GE(tealPixels(readPng(png)), 60);
}

// A fill's colour bar and its labels stand beside the domain: over it they hid a square
// domain's corner cells (its left edge was 27 pixels right of the bar, under the labels).
TEST(Inspector, TheFillsLegendLeavesTheDomainUncovered) {
  const std::string png = test::tempPath("fill_legend.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") +
                            " --param authalic --border square --fill area --pane 2d",
                        png),
            0);
  const Picture picture = readPng(png);
  ASSERT_GT(picture.width, 0);
  int bar = -1, domain = -1;  // their left edges: the bar is 90 pixels tall, the domain more
  for (int x = 0; x < picture.width && domain < 0; ++x) {
    const int run = longestDarkRun(picture, x);
    if (bar < 0 && run >= 80 && run <= 100) bar = x;
    if (run >= 110) domain = x;
  }
  ASSERT_GE(bar, 0);
  ASSERT_GE(domain, 0);
  EXPECT_GE(domain - bar, 70);  // the bar, 12 pixels, and a label "9.68e-03" beside it
}

// A map is scaled to the unit square, which a strip's fills along its length only: the pane
// frames the map's own box, centred where the unit square's middle is and as tall. A flat 4:1
// strip's map on a rectangle (0.25 by 1) lay against the square's right side, 0.375 of its side
// (about 130 pixels here) right of the middle.
TEST(Inspector, ANarrowDomainIsDrawnInThePanesMiddle) {
  const std::string strip = flatStripFile();
  const std::string stripPng = test::tempPath("strip_2d.png"), squarePng = test::tempPath("square_2d.png");
  ASSERT_EQ(renderScene(strip + " --param mean-value --border rectangle --pane 2d", stripPng), 0);
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --param authalic --border square --pane 2d", squarePng), 0);
  const auto [stripLeft, stripRight] = longDarkColumns(readPng(stripPng));
  const auto [squareLeft, squareRight] = longDarkColumns(readPng(squarePng));
  ASSERT_GE(stripLeft, 0);
  ASSERT_GE(squareLeft, 0);
  EXPECT_NEAR(stripRight - stripLeft, (squareRight - squareLeft) / 4, 4);
  EXPECT_NEAR(stripLeft + stripRight, squareLeft + squareRight, 6)
      << "the strip spans columns " << stripLeft << "-" << stripRight << ", the square " << squareLeft << "-" << squareRight;
}

// The marks are sized by the room around each site (its cell's area), not by the unit square
// shared among the sites: on a strip's map a quarter as wide, sites and rings sized for the
// square covered its cells, and the fill's colour showed on 12% of the strip (35% now). Most
// cells have the largest area there: the bar's yellow.
TEST(Inspector, ANarrowDomainsCellsShowTheirFill) {
  const std::string png = test::tempPath("strip_fill.png");
  ASSERT_EQ(renderScene(flatStripFile() + " --param mean-value --border rectangle --fill area --pane 2d", png), 0);
  const Picture picture = readPng(png);
  const auto [left, right] = longDarkColumns(picture);
  ASSERT_GE(left, 0);
  int top = -1, bottom = -1;  // the strip's border, down its middle column
  for (int y = 0; y < picture.height; ++y)
    if (isDark(picture.at((left + right) / 2, y))) {
      if (top < 0) top = y;
      bottom = y;
    }
  ASSERT_GT(bottom - top, 100);
  int inside = 0, yellow = 0;  // inside the border's lines and squares
  for (int y = top + 4; y < bottom - 3; ++y)
    for (int x = left + 4; x < right - 3; ++x) {
      const unsigned char* c = picture.at(x, y);
      ++inside;
      yellow += c[0] > 180 && c[1] > 160 && c[2] < 140;
    }
  EXPECT_GE(yellow, inside / 4) << yellow << " of " << inside << " pixels show the fill; the picture: " << png;
}

// The lesson's Result stage shows the final result: its worst triangle is the one pinned, and
// ringed in 3D (it pinned the iteration's, drawn in 2D only: no teal in the 3D pane).
TEST(Inspector, TheResultStagePinsTheFinalResultsWorstTriangle) {
  const std::string png = test::tempPath("stage_worst.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --stage result --select-worst --pane 3d", png), 0);
  EXPECT_GE(tealPixels(readPng(png)), 100);
}

// A pinned triangle behind the surface is a dashed ring where it is, not filled and ringed as
// if on top (the mushroom's worst, under its cap, looked as if it were on the cap). The cap's
// worst triangle from two sides: in front, then behind.
TEST(Inspector, APinnedTriangleBehindTheSurfaceIsADashedRing) {
  auto tealSeenFrom = [](const std::string& yaw) {
    const std::string png = test::tempPath("behind_" + yaw + ".png");
    EXPECT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --final --select-worst --pane 3d --camera '" + yaw +
                              " 0.5 2.5 0 0 0.6'",
                          png),
              0);
    return tealPixels(readPng(png));
  };
  const int inFront = tealSeenFrom("3.74"), behind = tealSeenFrom("0.6");
  EXPECT_GE(inFront, 300);
  EXPECT_GE(behind, 30);  // the dashes
  EXPECT_LT(behind, inFront / 2);
}

// A pinned cell lies on the input surface: it is drawn over the final result too (it was not).
TEST(Inspector, APinnedCellShowsOverTheFinalResult) {
  const std::string png = test::tempPath("final_pin.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --final --select-cell 200 --pane 3d", png), 0);
  EXPECT_GE(magentaPixels(readPng(png)), 20);
}

// The cap from low at its side: the sites on its far half are behind the near half and must
// not show through it (rows of dots across the dome; a ring across the mushroom's cap).
TEST(Inspector, SitesBehindTheSurfaceAreHidden) {
  checkScene("inspector_hidden_sites.png", "--pane 3d --camera '0.6 0.12 2.2 0 0 0.75'");
}
// The run's L-BFGS curves (blue), plain Lloyd's (grey) and Newton's (purple) from the same start.
TEST(Inspector, ComparesTheSolversCurves) {
  checkScene("inspector_compared.png", "--compare-solvers --pane plots");
}
// A Newton run: each solver keeps its colour (Newton purple, L-BFGS blue, Lloyd grey).
TEST(Inspector, ColoursEachSolverTheSameWhicheverRuns) {
  checkScene("inspector_compared_newton.png", "--solver newton --compare-solvers --pane plots");
  // The legend's first words are the run's, in its solver's colour (solverColour: L-BFGS 38,
  // 77, 178; Newton 158, 77, 184): a solver recoloured is a few hundred pixels of the plots,
  // under the snapshot's allowance.
  auto firstColumnOf = [](const Picture& p, int r, int g, int b) {
    for (int x = 0; x < p.width; ++x)
      for (int y = 0; y < 42; ++y) {
        const unsigned char* c = p.at(x, y);
        if (std::abs(c[0] - r) < 30 && std::abs(c[1] - g) < 30 && std::abs(c[2] - b) < 30) return x;
      }
    return p.width;
  };
  for (const std::string solver : {"lbfgs", "newton"}) {
    const std::string png = test::tempPath("legend_" + solver + ".png");
    ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --solver " + solver + " --compare-solvers --pane plots", png),
              0);
    const Picture picture = readPng(png);
    const int blue = firstColumnOf(picture, 38, 77, 178), purple = firstColumnOf(picture, 158, 77, 184);
    ASSERT_LT(std::max(blue, purple), picture.width) << solver;  // both in the legend
    if (solver == "lbfgs") EXPECT_LT(blue, purple);
    else EXPECT_LT(purple, blue);
  }
}

// A run stopped short: every legend says "not converged", which is longer than the pane is
// wide at 960; the legend that does not fit goes on the next line (Newton's was cut to
// "newton:", and with the plots against time it was not there at all).
TEST(Inspector, ALegendThatDoesNotFitGoesOnTheNextLine) {
  const std::string png = test::tempPath("legend_wrapped.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --max-iterations 40 --compare-solvers --pane plots", png), 0);
  const Picture picture = readPng(png);
  auto topRowOf = [&](int r, int g, int b) {
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < picture.width; ++x) {
        const unsigned char* c = picture.at(x, y);
        if (std::abs(c[0] - r) < 30 && std::abs(c[1] - g) < 30 && std::abs(c[2] - b) < 30) return y;
      }
    return picture.height;
  };
  const int blue = topRowOf(38, 77, 178), purple = topRowOf(158, 77, 184);  // solverColour
  ASSERT_LT(purple, picture.height);
  EXPECT_GE(purple, blue + 10) << "Newton's legend on the run's line";
}

// The same Newton run, recorded and replayed: the same picture. A recording was shown with the
// command line's defaults ("lbfgs, this run", in L-BFGS's blue, and Newton run again beside it).
TEST(Inspector, ReplaysARecordingWithTheSettingsItWasMadeWith) {
  const std::string rec = test::tempPath("newton.lsrec");
  ASSERT_EQ(run("remesh " + test::assetPath("sphere_cap.off") + " --solver newton --no-fidelity --record " + rec +
                " > /dev/null"),
            0);
  checkScene("inspector_compared_newton.png", "--compare-solvers --pane plots", rec);
}

// Each pane shows the iteration asked: iterations 0 and 1, a step apart, differ in each. (The
// snapshots of the whole window at 0 and 1 differ by 3,866 pixels, the 3D pane's share 511,
// under one snapshot's allowance of 2,880: a pane left at one iteration would pass them.)
TEST(Inspector, EveryPaneShowsTheIterationAsked) {
  const std::string rec = test::tempPath("panes.lsrec");
  ASSERT_EQ(run("remesh " + test::assetPath("sphere_cap.off") + " --max-iterations 3 --no-fidelity --record " + rec +
                " > /dev/null"),
            0);
  for (const std::string pane : {"3d", "2d", "plots"}) {
    const std::string first = test::tempPath("pane0_" + pane + ".png"), second = test::tempPath("pane1_" + pane + ".png");
    ASSERT_EQ(renderScene(rec + " --iteration 0 --pane " + pane, first), 0);
    ASSERT_EQ(renderScene(rec + " --iteration 1 --pane " + pane, second), 0);
    const Picture a = readPng(first), b = readPng(second);
    ASSERT_EQ(a.height, b.height);
    EXPECT_GT(differingPixels(a, b, 0, a.height), 100u) << pane;
  }
}

// Against time, each iteration is where its run had got to by then: in a run whose first ten
// steps took 1 ms each and the next ten 9 ms, iteration 10 is an eighth of the way along (10 of
// 91 ms), not half of it. The red line of the iteration shown says where.
TEST(Inspector, ThePlotsAgainstTimePutEachIterationWhereItsRunWas) {
  const std::string made = test::tempPath("timed_made.lsrec"), rec = test::tempPath("timed.lsrec");
  ASSERT_EQ(run("remesh " + test::assetPath("sphere_cap.off") + " --max-iterations 20 --no-fidelity --record " + made +
                " > /dev/null"),
            0);
  Recording recording = loadRecording(made);
  ASSERT_EQ(recording.iterations.size(), 20u);
  for (size_t k = 0; k < 20; ++k) recording.iterations[k].milliseconds = k < 10 ? 1 : 9;
  saveRecording(recording, rec);
  // The column of the red line (217, 77, 26) in the first plot, as a fraction of the plots'
  // picture's width: the one with most red pixels in the left third.
  const auto redLine = [](const std::string& png) {
    const Picture p = readPng(png);
    int best = -1, most = 0;
    for (int x = 0; x < p.width / 3; ++x) {
      int red = 0;
      for (int y = 0; y < p.height; ++y) {
        const unsigned char* c = p.at(x, y);
        red += std::abs(c[0] - 217) < 30 && std::abs(c[1] - 77) < 30 && std::abs(c[2] - 26) < 30;
      }
      if (red > most) most = red, best = x;
    }
    return static_cast<double>(best) / p.width * 3;  // 0..1 across the first plot
  };
  const std::string time = test::tempPath("timed_time.png"), steps = test::tempPath("timed_steps.png"),
                    start = test::tempPath("timed_start.png");
  const std::string args = "inspect " + rec + " --pane plots --size 960x600 --iteration ";
  ASSERT_EQ(run(args + "10 --plot-time --screenshot " + time), 0);
  ASSERT_EQ(run(args + "10 --screenshot " + steps), 0);
  ASSERT_EQ(run(args + "0 --plot-time --screenshot " + start), 0);
  const double atStart = redLine(start), byTime = redLine(time), bySteps = redLine(steps);
  // The plot's frame starts about a fifth of the way in (its axis labels): the iteration's
  // share of the plot's width is measured from iteration 0's line.
  EXPECT_NEAR((bySteps - atStart) / (1 - atStart), 10.0 / 19, 0.12) << atStart << " " << bySteps;
  EXPECT_NEAR((byTime - atStart) / (1 - atStart), 10.0 / 91, 0.06) << atStart << " " << byTime;
  // Timings off: a picture the same on every run has no times to plot.
  EXPECT_EQ(run(args + "10 --plot-time --no-timings --screenshot " + time + " 2> /dev/null"), 1);
}

// The Result stage shows the final result, and frames all of it as --final does: with two
// components it framed the larger one's surface, both off to the right and smaller.
TEST(Inspector, TheResultStageFramesTheWholeResult) {
  Mesh two = test::grid(12);
  append(two, test::moved(test::grid(8), 0.5, Vec3(2, 0, 0)));
  const std::string mesh = test::tempPath("two_grids.off");
  writeMesh(two, mesh);
  // Where the mesh's pixels (greener than blue: the background is grey, the colour bar left out)
  // lie across the pane, on average: 0 its left edge, 1 its right.
  const auto across = [](const Picture& p) {
    double sum = 0;
    int count = 0;
    for (int y = 0; y < p.height; ++y)
      for (int x = 40; x < p.width; ++x)
        if (p.at(x, y)[1] > p.at(x, y)[2] + 40) sum += x, ++count;
    return count > 0 ? sum / count / p.width : -1.0;
  };
  const std::string stage = test::tempPath("two_grids_stage.png"), final = test::tempPath("two_grids_final.png");
  const std::string run = mesh + " --sites 150 --no-fidelity --pane 3d ";
  ASSERT_EQ(renderScene(run + "--stage result", stage), 0);
  ASSERT_EQ(renderScene(run + "--final", final), 0);
  const double framed = across(readPng(final));
  ASSERT_GT(framed, 0.3);
  ASSERT_LT(framed, 0.7);
  // The stage's pane is shorter (its caption), so the mesh a little smaller: 0.45 against 0.42;
  // framing the larger component put it at 0.59.
  EXPECT_NEAR(across(readPng(stage)), framed, 0.06);
}

TEST(Inspector, WithoutADisplayItSaysWhatToDo) {
  const std::string err = test::tempPath("nodisplay.err");
  const int status = std::system(("env -u DISPLAY -u WAYLAND_DISPLAY " + std::string(LLOYDSCOPE_CLI) +
                                  " inspect " + test::assetPath("jittered_grid.off") +
                                  " --max-iterations 2 --no-fidelity 2>" + err).c_str());
  EXPECT_EQ(WEXITSTATUS(status), 1);
  const std::string message = test::readText(err);
  EXPECT_NE(message.find("--screenshot"), std::string::npos) << message;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
}

TEST(Inspector, ValidationLayerReportsNothingHeadless) {
  EXPECT_EQ(run("inspect " + test::assetPath("jittered_grid.off") + " --max-iterations 5 "
                "--no-fidelity --validation --size 960x600 --screenshot " +
                test::tempPath("validated.png")),
            0);
}

// Records a short run to `recording` (a file name in the temporary folder), and opens the
// recording headless with `view` (inspect's options): it must give a picture.
void replayARecording(const std::string& recording, const std::string& view) {
  const std::string rec = test::tempPath(recording);
  ASSERT_EQ(run("remesh " + test::assetPath("jittered_grid.off") +
                " --max-iterations 4 --no-fidelity --record " + rec + " > /dev/null"),
            0);
  const std::string png = test::tempPath(recording + ".png"), last = test::tempPath(recording + "_last.png");
  ASSERT_EQ(run("inspect " + rec + " " + view + " --size 960x600 --screenshot " + png), 0);
  EXPECT_EQ(readPng(png).width, 960);
  if (view.empty()) return;
  // The view asked is shown: not the picture the recording opens on.
  ASSERT_EQ(run("inspect " + rec + " --size 960x600 --screenshot " + last), 0);
  const Picture shown = readPng(png), opened = readPng(last);
  EXPECT_GT(differingPixels(shown, opened, 0, shown.height), 1000u);
}

TEST(Inspector, ReplaysARecording) { replayARecording("inspect.lsrec", "--iteration 2"); }

// Saved under a name of the user's own (it was refused: "unknown extension '.run'").
TEST(Inspector, ReplaysARecordingSavedUnderAnyName) { replayARecording("inspect.run", ""); }

TEST(Inspector, PinnedCellAndTriangle) {
  // Cell 100 and triangle 50 highlighted in both views, their numbers in the details panel.
  checkScene("inspector_selection.png", "--iteration 3 --select-cell 100 --select-triangle 50");
  // The highlights are a few hundred pixels of the window: under the snapshot's 0.5%
  // allowance (2880) all of them could go. Each view is counted on its own.
  for (const char* pane : {"2d", "3d"}) {
    const std::string png = test::tempPath(std::string("pins_") + pane + ".png");
    ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") +
                              " --iteration 3 --select-cell 100 --select-triangle 50 --pane " + pane,
                          png),
              0);
    const Picture picture = readPng(png);
    EXPECT_GE(magentaPixels(picture), 30) << pane;
    EXPECT_GE(tealPixels(picture), 60) << pane;
  }
}

TEST(Inspector, SelectionAndCameraErrorsAreOneLine) {
  const std::string mesh = test::assetPath("sphere_cap.off");
  const std::string out = test::tempPath("never.png"), err = test::tempPath("select.err");
  for (const auto& [args, says] : std::vector<std::pair<std::string, std::string>>{
           {"--select-cell 500", "sphere_cap.off: cell 500 does not exist"},
           {"--select-triangle -1", "--select-triangle: expected a whole number >= 0, not '-1'"},
           {"--iteration 5000", "sphere_cap.off: iteration 5000 does not exist"},  // it showed the last one, as if asked
           {"--select-triangle 5000", "sphere_cap.off: triangle 5000 does not exist"},
           {"--final --select-triangle 5000", "(the final result has 934, numbered from 0)"},
           {"--select-triangle 5000", "(the result at iteration 112 has 934, numbered from 0)"},
           {"--pane x", "unknown pane 'x' (window, 3d, 2d, plots)"},
           {"--fill y", "unknown fill 'y' (none, mass, area, energy, distance, moved, valence)"},
           {"--camera 'one two'", "camera"},
           {"--camera '0 0 -1 0 0 0'", "camera"},
           // read as infinite: it was refused as if not above 0
           {"--camera '0 0 1e308 0 0 0'", "six finite numbers, the angles and the distance in single precision"}}) {
    EXPECT_EQ(run("inspect " + mesh + " --screenshot " + out + " " + args + " 2> " + err), 1) << args;
    const std::string message = test::readText(err);
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
    EXPECT_FALSE(std::ifstream(out).good()) << args;
  }
}

TEST(Inspector, ExportsANumberedSequenceOfOnePane) {
  const std::string base = test::tempPath("sequence.png");
  const std::string stem = base.substr(0, base.size() - 4);
  ASSERT_EQ(run("inspect " + test::assetPath("sphere_cap.off") + " --screenshot " + base +
                " --size 960x600 --no-timings --pane 3d --iterations 2:4"),
            0);
  const Picture first = readPng(stem + "_0002.png"), last = readPng(stem + "_0004.png");
  ASSERT_FALSE(first.rgba.empty());
  ASSERT_FALSE(readPng(stem + "_0003.png").rgba.empty());
  ASSERT_FALSE(last.rgba.empty());
  EXPECT_TRUE(readPng(stem + "_0001.png").rgba.empty());
  EXPECT_TRUE(readPng(stem + "_0005.png").rgba.empty());
  EXPECT_TRUE(readPng(base).rgba.empty());
  // The 3D pane only: narrower and lower than the window, the same size in every picture.
  EXPECT_LT(first.width, 960 / 2);
  EXPECT_GT(first.width, 200);
  EXPECT_LT(first.height, 600);
  EXPECT_EQ(first.width, last.width);
  EXPECT_EQ(first.height, last.height);
  EXPECT_NE(first.rgba, last.rgba);  // the result changed between iterations 2 and 4
}

// A sequence one of whose names cannot be written (a folder of that name) is refused before its
// first picture: it stopped at that one, the pictures before it saved.
TEST(Inspector, ASequenceOneOfWhoseNamesCannotBeWrittenSavesNone) {
  const std::string here = test::emptyFolder("sequence_blocked"), base = here + "/x.png";
  std::filesystem::create_directory(here + "/x_0002.png");
  const std::string err = here + "/err.txt";
  EXPECT_EQ(run("inspect " + test::assetPath("sphere_cap.off") + " --screenshot " + base +
                " --size 960x600 --no-timings --pane 3d --iterations 0:3 2> " + err),
            1);
  EXPECT_EQ(test::readText(err), "lloydscope: " + here + "/x_0002.png: cannot write: it is a folder\n");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"err.txt", "x_0002.png"}));
}

// A sequence whose third picture cannot be written once made (a full disk; here a link to
// /dev/full, which the checks before the first picture pass) replaces none of its files: the
// first two had been replaced, the rest left old. One that can be written replaces them all.
TEST(Inspector, ASequenceThatFailsOnTheWayReplacesNone) {
  const std::string here = test::emptyFolder("sequence_full"), base = here + "/x.png";
  for (const char* name : {"/x_0000.png", "/x_0001.png", "/x_0003.png"}) test::writeText(here + name, "old");
  std::filesystem::create_symlink("/dev/full", here + "/x_0002.png");
  const std::string err = here + "/err.txt", shot = "inspect " + test::assetPath("sphere_cap.off") +
                                                      " --screenshot " + base + " --size 960x600 --no-timings --pane 3d";
  EXPECT_EQ(run(shot + " --iterations 0:3 2> " + err), 1);
  EXPECT_EQ(test::readText(err), "lloydscope: " + here + "/x_0002.png: cannot write (No space left on device)\n");
  for (const char* name : {"/x_0000.png", "/x_0001.png", "/x_0003.png"}) EXPECT_TRUE(test::readText(here + name) == "old") << name << " was replaced";
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"err.txt", "x_0000.png", "x_0001.png", "x_0002.png", "x_0003.png"}));
  ASSERT_EQ(run(shot + " --iterations 0:1"), 0);
  EXPECT_FALSE(readPng(here + "/x_0000.png").rgba.empty());
  EXPECT_FALSE(readPng(here + "/x_0001.png").rgba.empty());
}

// Each picture of a sequence of the Move stage quotes its own arrows' magnification: the
// caption took it from the 2D pane's last drawing, the picture before's.
TEST(Inspector, EachPictureOfASequenceHasItsOwnCaption) {
  const std::string base = test::tempPath("moves.png"), mesh = test::assetPath("sphere_cap.off");
  const std::string stem = base.substr(0, base.size() - 4);
  ASSERT_EQ(run("inspect " + mesh + " --screenshot " + base + " --size 960x600 --no-timings --stage move --iterations 0:3"), 0);
  for (int k : {1, 3}) {
    const std::string alone = test::tempPath("move_" + std::to_string(k) + ".png");
    ASSERT_EQ(renderScene(mesh + " --stage move --iteration " + std::to_string(k), alone), 0);
    const Picture a = readPng(alone), b = readPng(stem + "_000" + std::to_string(k) + ".png");
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_EQ(differingPixels(a, b, 0, 60), 0u) << "iteration " << k;
  }
}

// A picture named like the file shown (through a link, or a recording saved as a .png, as
// --record allows) replaced it with a PNG.
TEST(Inspector, AScreenshotNeverReplacesTheFileShown) {
  const std::string mesh = test::tempPath("shown.off"), link = test::tempPath("shown.png"), err = test::tempPath("shown.err");
  test::writeText(mesh, test::readText(test::assetPath("sphere_cap.off")));
  std::remove(link.c_str());
  ASSERT_EQ(symlink(mesh.c_str(), link.c_str()), 0);
  EXPECT_EQ(run("inspect " + mesh + " --screenshot " + link + " 2> " + err), 1);
  EXPECT_NE(test::readText(err).find("shown.png: the picture would replace"), std::string::npos) << test::readText(err);
  EXPECT_EQ(test::readText(mesh), test::readText(test::assetPath("sphere_cap.off")));
  const std::string recording = test::tempPath("run_0001.png"), base = test::tempPath("run.png");
  ASSERT_EQ(run("remesh " + mesh + " --sites 100 --record " + recording + " > /dev/null"), 0);
  const std::string before = test::readText(recording);
  EXPECT_EQ(run("inspect " + recording + " --screenshot " + base + " --iterations 0:2 2> " + err), 1);
  EXPECT_NE(test::readText(err).find("run_0001.png: the picture would replace"), std::string::npos) << test::readText(err);
  EXPECT_EQ(test::readText(recording), before);
  // A range far past the run's is refused for that, not after a check of each name in it (which
  // ran for minutes at 0:2000000000).
  EXPECT_EQ(run("inspect " + recording + " --screenshot " + test::tempPath("far.png") + " --iterations 0:2000000000 2> " + err), 1);
  // It names the file, as an --iteration past the run's does.
  EXPECT_NE(test::readText(err).find("run_0001.png: iterations 0:2000000000 do not exist: expected FIRST:LAST within 0:"),
            std::string::npos)
      << test::readText(err);
}

// The 3D view of a mesh far from the origin, or of a huge one, is the view of the same mesh
// at unit size: in single precision one 1e8 units off the origin was a line of dots, and one of
// size 1e19 was not drawn at all (remesh takes both).
TEST(Inspector, The3DViewDrawsAMeshAtAnySizeAndPlace) {
  const Mesh cap = readMesh(test::assetPath("sphere_cap.off")).mesh;
  auto meshPixels = [&](const std::string& name, double scale, const Vec3& offset) {
    Mesh moved = cap;
    for (Vec3& p : moved.points) p = scale * p + offset;
    const std::string path = test::tempPath(name + ".off"), png = test::tempPath(name + ".png");
    writeMesh(moved, path);
    EXPECT_EQ(renderScene(path + " --sites 100 --pane 3d", png), 0) << name;
    return pixelsWhere(readPng(png), [](const unsigned char* c) { return c[1] > c[0] + 30 && c[1] > c[2] + 30; });  // green
  };
  const int unit = meshPixels("unit", 1, Vec3::Zero());
  EXPECT_GT(unit, 20000);
  EXPECT_NEAR(meshPixels("far", 1, Vec3(1e8, 0, 0)), unit, 0.05 * unit);
  EXPECT_NEAR(meshPixels("huge", 1e19, Vec3::Zero()), unit, 0.05 * unit);
}

TEST(Inspector, ExportErrorsAreOneLine) {
  const std::string mesh = test::assetPath("sphere_cap.off"), err = test::tempPath("export.err");
  for (const std::string& args :
       {"--screenshot " + test::tempPath("x.png") + " --iterations 5:2",
        "--screenshot " + test::tempPath("x.png") + " --iterations 0:100000",
        "--screenshot " + test::tempPath("x.jpg"),
        "--screenshot " + test::tempPath("x.png") + " --pane left",
        "--screenshot " + test::tempPath("x.png") + " --size 640x480",  // too small to read
        "--screenshot " + test::tempPath("x.png") + " --fill colour"}) {
    EXPECT_EQ(run("inspect " + mesh + " " + args + " 2> " + err), 1) << args;
    const std::string message = test::readText(err);
    EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  }
  EXPECT_TRUE(readPng(test::tempPath("x.png")).rgba.empty());
  // A reversed range is told so: it was told the valid range, which 5:2 is within.
  EXPECT_EQ(run("inspect " + mesh + " --screenshot " + test::tempPath("x.png") + " --iterations 5:2 2> " + err), 1);
  EXPECT_NE(test::readText(err).find("FIRST comes after LAST in '5:2'"), std::string::npos) << test::readText(err);
}

TEST(Inspector, PresentationModeShowsTheLessonStage) {
  // Classroom mode at the centroid stage: large fonts, no controls pane, the caption with the
  // pinned cell's numbers, rings but no arrows.
  checkScene("inspector_presentation.png",
             "--iteration 1 --presentation --stage centroids --select-cell 100", "", 90);
}

// The lesson's caption pane is as tall at every stage, so that the panes under it stay put as
// the lesson goes on: at 960x600 a stage of two lines had 70 pixels, one of four 88.
TEST(Inspector, TheCaptionPaneIsAsTallAtEveryStage) {
  const std::string recording = test::tempPath("caption_height.lsrec");
  ASSERT_EQ(run("remesh " + test::assetPath("sphere_cap.off") + " --sites 300 --record " + recording + " > /dev/null"), 0);
  // The rows from the top down to the last of the caption's cream (255, 250, 229) at the right edge.
  const auto captionRows = [](const Picture& p) {
    int rows = 0;
    for (int y = 0; y < p.height; ++y) {
      const unsigned char* c = p.at(p.width - 10, y);
      if (std::abs(c[0] - 255) < 3 && std::abs(c[1] - 250) < 3 && std::abs(c[2] - 229) < 4) rows = y + 1;
    }
    return rows;
  };
  std::vector<int> heights;
  for (const char* stage : {"voronoi", "parameterize", "valence"}) {
    const std::string png = test::tempPath(std::string("caption_height_") + stage + ".png");
    ASSERT_EQ(renderScene(recording + " --stage " + stage, png), 0);
    heights.push_back(captionRows(readPng(png)));
  }
  EXPECT_GT(heights[0], 40);
  EXPECT_EQ(heights[1], heights[0]);
  EXPECT_EQ(heights[2], heights[0]);
}

// The caption quotes the cell pinned last: with 100 pinned after 40 it reads as with 100 alone
// (it quoted cell 40, the first, whatever was pinned after).
TEST(Inspector, TheCaptionQuotesTheCellPinnedLast) {
  const std::string both = test::tempPath("caption_both.png"), alone = test::tempPath("caption_alone.png"),
                    first = test::tempPath("caption_first.png");
  const std::string stage = test::assetPath("sphere_cap.off") + " --iteration 1 --presentation --stage centroids";
  ASSERT_EQ(renderScene(stage + " --select-cell 40 --select-cell 100", both), 0);
  ASSERT_EQ(renderScene(stage + " --select-cell 100", alone), 0);
  ASSERT_EQ(renderScene(stage + " --select-cell 40", first), 0);
  // The caption's rows, above the panes (its numbers' line is the second and third).
  auto captionDiffers = [](const Picture& a, const Picture& b) { return differingPixels(a, b, 30, 85); };
  const Picture withBoth = readPng(both), withLast = readPng(alone), withFirst = readPng(first);
  EXPECT_EQ(captionDiffers(withBoth, withLast), 0u);
  EXPECT_GT(captionDiffers(withBoth, withFirst), 200u);  // the test tells the two cells apart
}

// Two cells pinned: each is labelled with its number beside its site in 2D ("cell 40", "cell
// 100"), as the selection panel and the caption name them; magenta both, they could not be
// told apart. One cell pinned has no label (inspector_selection.png).
TEST(Inspector, TwoPinnedCellsAreLabelledWithTheirNumbers) {
  checkScene("inspector_two_cells.png", "--iteration 3 --select-cell 40 --select-cell 100 --pane 2d");
}

// Four cells side by side at the domain's bottom: their labels stack upward, clear of the
// pane's legend (two of them went under it, their leaders running down into it).
TEST(Inspector, PinnedCellsLabelsKeepOffTheLegend) {
  checkScene("inspector_labels_legend.png",
             "--iteration 3 --select-cell 19 --select-cell 20 --select-cell 21 --select-cell 22 --pane 2d");
}

// The lesson's Result stage shows and quotes the final result, after the clean-up, as the
// controls pane's Final column has it (it showed the last iteration's mesh before it).
TEST(Inspector, TheLessonsResultStageShowsTheFinalResult) {
  checkScene("inspector_result_stage.png", "--presentation --stage result", "", 90);
}

// The lesson's last stage fills the cells by valence (in the window, whatever the fill chosen;
// inspect refuses another --fill with it), marks the irregular sites in 3D, and counts them in
// its caption.
TEST(Inspector, TheLessonsValenceStageShowsTheIrregularVertices) {
  checkScene("inspector_valence_stage.png", "--presentation --stage valence", "", 90);
}

// The cells coloured by their site's distance to its centroid, the fixed border sites grey and
// outside the scale: their distances made it, and every movable cell was one dark colour.
TEST(Inspector, FillsTheCellsByTheirDistanceToTheCentroid) {
  checkScene("inspector_fill_distance.png", "--iteration 60 --fill distance --pane 2d");
}

// The cells coloured by their site's valence in the result: pale where regular, red with too
// many sides (a 7), blue with too few (a 5); the pairs of a 5 and a 7 are Lloyd's dislocations.
TEST(Inspector, FillsTheCellsByTheirValence) {
  checkScene("inspector_fill_valence.png", "--fill valence --pane 2d");
}

// Presentation mode's type grows with the window; its lines and marks grow with it. On a
// 3840x2160 screen the valence dots in 3D stayed 7 px and the plots' lines 1.5 px beside type
// 56 px high. Twice as tall a window: dots of twice the diameter (four times the pixels, with
// the mesh drawn twice as large; the same count without), threshold lines twice as thick.
TEST(Inspector, PresentationMarksGrowWithTheWindow) {
  const auto picture = [](const std::string& pane, const std::string& size) {
    const std::string png = test::tempPath("marks_" + pane + "_" + size + ".png");
    EXPECT_EQ(run("inspect " + test::assetPath("bumpy_disk.off") + " --presentation --stage valence --pane " + pane +
                  " --no-timings --size " + size + " --screenshot " + png),
              0);
    return readPng(png);
  };
  const int dots = valencePixels(picture("3d", "960x800")), largerDots = valencePixels(picture("3d", "960x1600"));
  EXPECT_GT(dots, 500);
  EXPECT_GT(largerDots, 3 * dots) << dots << " " << largerDots;
  // The thresholds' green lines: how thick, on average over the columns they cross (their
  // pixels in all would also count how wide the plots are, which the taller one's labels take).
  const auto thickness = [](const Picture& p) {
    int pixels = 0, columns = 0;
    for (int x = 0; x < p.width; ++x) {
      int here = 0;
      for (int y = 0; y < p.height; ++y) {
        const unsigned char* c = p.at(x, y);
        here += c[1] > 120 && c[0] < 90 && c[2] < 90;
      }
      pixels += here;
      columns += here > 0;
    }
    return columns > 100 ? static_cast<double>(pixels) / columns : 0.0;  // two plots have a threshold
  };
  const double lines = thickness(picture("plots", "960x800")), thicker = thickness(picture("plots", "960x1600"));
  EXPECT_GT(lines, 0);
  EXPECT_GT(thicker, 1.6 * lines) << lines << " " << thicker;
}

// The Lift stage is about the sites on the surface: each is drawn on a white halo there (3 px
// navy squares alone were lost in the input's dark wire on a projector). The Move stage draws
// the same mesh and sites without it.
TEST(Inspector, TheLiftStageShowsItsSitesOnHalos) {
  const auto whitePixels = [](const std::string& stage) {
    const std::string png = test::tempPath("halo_" + stage + ".png");
    EXPECT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --presentation --stage " + stage + " --pane 3d", png), 0);
    return pixelsWhere(readPng(png), [](const unsigned char* c) { return c[0] >= 250 && c[1] >= 250 && c[2] >= 250; });
  };
  const int lift = whitePixels("lift"), move = whitePixels("move");
  EXPECT_GT(lift, move + 2000) << lift << " " << move;  // the labels' boxes are white in both
}

// The valence legend's five swatches all show whole in presentation mode at 960x600, where the
// pane's own legend (two lines) leaves less room than five rows: there it covered the last, "4-".
TEST(Inspector, TheValenceLegendFitsALowPane) {
  const std::string png = test::tempPath("valence_legend.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --presentation --stage move --fill valence --pane 2d", png), 0);
  const Picture picture = readPng(png);
  // The swatches' colours (the cells' too, but the domain lies right of the legend's strip).
  const int swatches[5][3] = {{166, 20, 20}, {245, 115, 89}, {230, 230, 219}, {102, 158, 242}, {20, 56, 166}};
  for (const auto& rgb : swatches) {
    int count = 0;
    for (int y = 0; y < picture.height; ++y)
      for (int x = 0; x < std::min(picture.width, 100); ++x) {
        const unsigned char* c = picture.at(x, y);
        count += std::abs(c[0] - rgb[0]) < 3 && std::abs(c[1] - rgb[1]) < 3 && std::abs(c[2] - rgb[2]) < 3;
      }
    EXPECT_GE(count, 100) << rgb[0] << " " << rgb[1] << " " << rgb[2];  // a swatch: 10 x 15 pixels inside
  }
}

// Where no room is left beside the domain (a stage's caption over a small window), the hint
// that the sites are crowded waits for the mouse over the pane: in a picture it covered the
// disk's top right (421 pixels of its text's colour there, 53 without it).
TEST(Inspector, TheCrowdedSitesHintLeavesTheCellsUncovered) {
  const std::string png = test::tempPath("crowded.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --method relocate --max-iterations 20 --stage valence --pane 2d", png),
            0);
  const Picture picture = readPng(png);
  int text = 0;
  for (int y = picture.height / 8; y < picture.height / 2; ++y)
    for (int x = picture.width * 6 / 10; x < picture.width; ++x) {
      const unsigned char* c = picture.at(x, y);
      text += std::abs(c[0] - 25) <= 10 && std::abs(c[1] - 25) <= 10 && std::abs(c[2] - 25) <= 10;  // boxedText's
    }
  EXPECT_LT(text, 150);
}

// So does a colour bar, shorter: at its full 90 pixels its foot and its lower label went under
// the pane's legend (85 pixels of its outline showed, the label not at all); it ends above it now.
TEST(Inspector, TheColourBarFitsALowPane) {
  const std::string png = test::tempPath("bar_legend.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --presentation --stage move --fill distance --pane 2d", png), 0);
  const Picture picture = readPng(png);
  int longest = 0;  // the bar's outline: the longest dark run down a column left of the domain
  for (int x = 0; x < std::min(picture.width, 40); ++x) longest = std::max(longest, longestDarkRun(picture, x));
  EXPECT_GE(longest, 40);  // two lines of its labels at least
  EXPECT_LE(longest, 80);
}

// Cells a few pixels across show their fill: at 960x600 in presentation mode the Valence
// stage's cells, 4 pixels apart, were all edges and dots, a dark blue disk.
TEST(Inspector, SmallCellsShowTheirFill) {
  const std::string png = test::tempPath("small_cells.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --presentation --stage valence --pane 2d", png), 0);
  const Picture domain = readPng(png);  // right of the legend's strip: the cells only
  int reds = 0, blues = 0;
  for (int y = 0; y < domain.height; ++y)
    for (int x = 120; x < domain.width; ++x) {
      const unsigned char* c = domain.at(x, y);
      reds += c[0] > 150 && c[0] > c[2] + 60;
      blues += c[2] > 150 && c[2] > c[0] + 60;
    }
  EXPECT_GE(reds, 150);
  EXPECT_GE(blues, 150);
}

// With the valence fill the 3D view marks the irregular sites, in the same colours as their
// cells, or the final result's irregular vertices where it is shown; without it, none.
TEST(Inspector, TheValenceFillMarksTheIrregularVerticesIn3D) {
  for (const std::string shown : {"", " --final"}) {
    const std::string with = test::tempPath("valence_3d.png"), without = test::tempPath("plain_3d.png");
    ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + shown + " --fill valence --pane 3d", with), 0);
    ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + shown + " --pane 3d", without), 0);
    EXPECT_GT(valencePixels(readPng(with)), 300) << shown;
    EXPECT_LT(valencePixels(readPng(without)), 20) << shown;
  }
}

// --simplify is taken: the 2D view shows the simplified input's map, not the full one's.
TEST(Inspector, OpensASimplifiedMesh) {
  const std::string simplified = test::tempPath("simplified.png"), full = test::tempPath("full.png");
  const std::string shown = " --sites 400 --max-iterations 5 --no-resample --pane 2d --stage parameterize";
  ASSERT_EQ(renderScene(test::assetPath("bumpy_disk.off") + " --simplify 400" + shown, simplified), 0);
  ASSERT_EQ(renderScene(test::assetPath("bumpy_disk.off") + shown, full), 0);
  const Picture a = readPng(simplified), b = readPng(full);
  ASSERT_EQ(a.height, b.height);
  EXPECT_GT(differingPixels(a, b, 0, a.height), 1000u);
}

// A face turned against its neighbours: refused, opened with --repair.
TEST(Inspector, OpensWithTheRepair) {
  Mesh disk = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  std::swap(disk.triangles[0][0], disk.triangles[0][1]);
  const std::string mesh = test::tempPath("turned_face.off"), png = test::tempPath("turned_face.png");
  writeMesh(disk, mesh);
  const std::string args = "inspect " + mesh + " --sites 200 --max-iterations 5 --size 960x600 --screenshot " + png;
  EXPECT_EQ(run(args), 1);
  ASSERT_EQ(run(args + " --repair"), 0);
  EXPECT_EQ(readPng(png).width, 960);
}

// Issue 6: where a torus was cut open, the seam is drawn in purple in both views.
TEST(Inspector, DrawsTheSeamsOfACutSurface) {
  const std::string mesh = test::tempPath("seam_torus.off"), png = test::tempPath("seam_torus.png");
  writeMesh(test::torus(), mesh);
  ASSERT_EQ(renderScene(mesh, png), 0);
  const Picture p = readPng(png);
  ASSERT_EQ(p.width, 960);
  int purple3D = 0, purple2D = 0;  // the 3D pane is left of x = 620, the 2D pane right of it
  for (int y = 0; y < 370; ++y)
    for (int x = 290; x < p.width; ++x)
      if (isSeamPurple(p.at(x, y))) ++(x < 620 ? purple3D : purple2D);
  EXPECT_GT(purple3D, 100);
  EXPECT_GT(purple2D, 100);
}

// A chart of a closed surface is an open sheet: seen from behind, its seams with the other
// charts are in view all round. Their triangles' facing hid them (CGAL's elephant in charts,
// its largest chart from the first view: two stretches of its outline drawn, 360 pixels).
TEST(Inspector, DrawsAChartsSeamsSeenFromBehind) {
  const std::string mesh = test::cgalSample("elephant.off");
  SKIP_UNLESS_EXTRACTED(mesh);
  const std::string png = test::tempPath("elephant_chart.png");
  ASSERT_EQ(run("inspect " + mesh + " --simplify 1000 --stage parameterize --pane 3d --no-timings --size 960x600 --screenshot " + png), 0);
  const int purple = pixelsWhere(readPng(png), isSeamPurple);
  EXPECT_GT(purple, 1000) << purple;
}

// CGAL's triceratops: every map of its first resampling collapses a horn, so the run is made
// without that pass (remesh() says why, and so does the inspector's left pane) instead of
// the inspector refusing to open it.
TEST(Inspector, OpensAMeshWhoseFirstResamplingFails) {
  const std::string mesh = test::cgalSample("triceratops.off");
  SKIP_UNLESS_EXTRACTED(mesh);
  const std::string png = test::tempPath("triceratops.png");
  ASSERT_EQ(run("inspect " + mesh + " --simplify 2000 --no-timings --size 960x600 --screenshot " + png), 0);
  EXPECT_EQ(readPng(png).width, 960);
}

// The first view fits the whole shape into the 3D pane, whatever its proportions: a strip ten
// times as long as wide, seen across, touches none of the pane's sides (from the bounding box's
// diagonal alone its ends were cut off) and still fills a good part of its width.
TEST(Inspector, TheFirstViewFitsALongShape) {
  Mesh strip = test::grid(20);
  for (Vec3& p : strip.points) p = Vec3(10 * p.x(), p.y(), 0.3 * std::sin(3 * p.x()));
  const std::string mesh = test::tempPath("strip.off"), png = test::tempPath("strip.png");
  writeMesh(strip, mesh);
  ASSERT_EQ(renderScene(mesh + " --max-iterations 3", png), 0);
  const Picture p = readPng(png);
  ASSERT_EQ(p.width, 960);
  auto isMesh = [&](int x, int y) {  // shaded by its angles: green to red, never grey
    const unsigned char* c = p.at(x, y);
    return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}) > 60;
  };
  int left = p.width, right = 0;  // of the mesh in the 3D pane (x 285..620), under its colour bar
  for (int y = 150; y < 360; ++y)
    for (int x = 286; x < 620; ++x)
      if (isMesh(x, y)) left = std::min(left, x), right = std::max(right, x);
  EXPECT_GT(left, 290);
  EXPECT_LT(right, 615);
  EXPECT_GT(right - left, 150);
}

// In a window 960 px wide the timeline's buttons left the iteration slider a stub of about 80
// px; it now has a row of its own, as wide as the pane less the speed slider.
TEST(Inspector, TheIterationSliderKeepsItsRoomInANarrowWindow) {
  const std::string png = test::tempPath("narrow.png");
  ASSERT_EQ(renderScene(test::assetPath("bumpy_disk.off") + " --no-resample", png), 0);
  const Picture p = readPng(png);
  ASSERT_EQ(p.width, 960);
  int widest = 0;  // the longest white run in the timeline, under the plots: the slider's frame
  for (int y = p.height - 100; y < p.height; ++y)
    for (int x = 285, run = 0; x < p.width; ++x) {
      const unsigned char* c = p.at(x, y);
      run = c[0] == 255 && c[1] == 255 && c[2] == 255 ? run + 1 : 0;
      widest = std::max(widest, run);
    }
  EXPECT_GT(widest, 400);
}

// The largest move's plot shows its threshold, the green line, above the plot's bottom edge: at
// 10^-6 the axis ended on it, and the line read as the axis.
TEST(Inspector, TheDistanceThresholdLineIsAboveTheAxis) {
  const std::string png = test::tempPath("threshold.png");
  ASSERT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --pane plots", png), 0);
  const Picture p = readPng(png);
  ASSERT_GT(p.width, 0);
  const int x = p.width / 2;  // the middle plot's middle
  int green = -1, edge = -1;  // the lowest rows of each in that column
  for (int y = 0; y < p.height; ++y) {
    const unsigned char* c = p.at(x, y);
    if (c[1] > 120 && c[0] < 90 && c[2] < 90) green = y;
    if (std::abs(c[0] - 128) < 8 && std::abs(c[1] - 128) < 8 && std::abs(c[2] - 128) < 8) edge = y;
  }
  ASSERT_GE(green, 0);
  ASSERT_GE(edge, 0);
  EXPECT_LT(green, edge - 4);
}

// Two components are remeshed each on its own; the panes follow the larger, and with --final
// the 3D pane shows both: the view fits them all (it fitted the larger only, the other beyond
// the pane's side).
TEST(Inspector, TheFinalResultOfTwoComponentsFitsBoth) {
  Mesh two = test::grid(8);
  append(two, test::moved(test::grid(8, 0.9), 1.0, Vec3(3, 0, 0)));
  for (Vec3& p : two.points) p.z() = 0.1 * std::sin(3 * p.x()) * std::sin(3 * p.y());
  const std::string mesh = test::tempPath("two_grids.off"), png = test::tempPath("two_grids.png");
  writeMesh(two, mesh);
  ASSERT_EQ(renderScene(mesh + " --final", png), 0);
  const Picture p = readPng(png);
  auto isMesh = [&](int x, int y) {  // shaded by its angles: green to red, never grey
    const unsigned char* c = p.at(x, y);
    return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}) > 60;
  };
  int left = p.width, right = 0, columns = 0;  // of the meshes in the 3D pane, under its colour bar
  for (int x = 286; x < 620; ++x) {
    bool any = false;
    for (int y = 150; y < 360; ++y) any = any || isMesh(x, y);
    if (any) left = std::min(left, x), right = std::max(right, x), ++columns;
  }
  EXPECT_GT(left, 290);
  EXPECT_LT(right, 615);
  EXPECT_LT(columns, right - left - 10);  // a gap between the two
}

// With --final the 3D pane shows the final result, and a red ring where it is farthest from
// the input (the Hausdorff distance); an iteration's mesh has no ring.
TEST(Inspector, TheFinalResultShowsWhereItStraysFarthest) {
  const std::string iteration = test::tempPath("iteration.png"), final = test::tempPath("final.png");
  const std::string common = " --no-timings --size 960x600 --screenshot ";
  ASSERT_EQ(run("inspect " + test::assetPath("bumpy_disk.off") + common + iteration), 0);
  ASSERT_EQ(run("inspect " + test::assetPath("bumpy_disk.off") + " --final" + common + final), 0);
  auto redIn3D = [](const Picture& p) {
    int red = 0;  // inside the 3D pane, right of its colour bar (whose 0 degrees is red)
    for (int y = 30; y < 370; ++y)
      for (int x = 330; x < 620; ++x) {
        const unsigned char* c = p.at(x, y);
        red += c[0] > 200 && c[1] < 70 && c[2] < 70;
      }
    return red;
  };
  EXPECT_EQ(redIn3D(readPng(iteration)), 0);
  EXPECT_GT(redIn3D(readPng(final)), 20);
}

// --select-worst (the button "Pin the worst triangle") pins the triangle with the smallest angle
// at the iteration shown: its details, in the pin's teal, fill the selection section.
TEST(Inspector, PinsTheWorstTriangle) {
  const auto teal = [](const std::string& args, const std::string& name) {
    const std::string png = test::tempPath(name);
    EXPECT_EQ(renderScene(test::assetPath("sphere_cap.off") + " --iteration 0 " + args, png), 0);
    const Picture p = readPng(png);
    int count = 0;
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < 270; ++x) {
        const unsigned char* c = p.at(x, y);
        count += c[0] < 40 && std::abs(c[1] - 140) < 30 && std::abs(c[2] - 115) < 30;
      }
    return count;
  };
  EXPECT_EQ(teal("", "no_worst.png"), 0);
  EXPECT_GT(teal("--select-worst", "worst.png"), 20);
}

// The pixels of the notes' text colour, brown, in the left pane above the selection's controls
// of a 960x600 picture of `mesh`.
int brownNotePixels(const std::string& mesh, const std::string& png) {
  EXPECT_EQ(renderScene(mesh, png), 0);
  const Picture p = readPng(png);
  EXPECT_EQ(p.width, 960);
  int brown = 0;
  for (int y = 0; y < 500; ++y)
    for (int x = 0; x < 270; ++x) {
      const unsigned char* c = p.at(x, y);
      brown += std::abs(c[0] - 115) < 30 && std::abs(c[1] - 51) < 30 && c[2] < 30;
    }
  return brown;
}

// How a result was made (here: two components, each remeshed on its own) is said in brown under
// the table it explains, in view; it was the last line of the left pane, under every control
// and out of sight in a window this size.
TEST(Inspector, HowTheResultWasMadeIsSaidUnderTheTable) {
  Mesh two = test::grid(8);
  append(two, test::moved(test::grid(8, 0.9), 1.0, Vec3(3, 0, 0)));
  const std::string mesh = test::tempPath("two_notes.off");
  writeMesh(two, mesh);
  EXPECT_GT(brownNotePixels(mesh, test::tempPath("two_notes.png")), 50);
}

// A surface remeshed chart by chart too and kept as one disk says so, as `remesh` does (CGAL's
// eight: its charts failed): the inspector said nothing of it.
TEST(Inspector, AResultKeptAsOneDiskAfterChartsSaysSo) {
  const std::string eight = test::cgalSample("eight.off");
  SKIP_UNLESS_EXTRACTED(eight);
  EXPECT_GT(brownNotePixels(eight, test::tempPath("eight_notes.png")), 50);
}

// A disk remeshed again with its coarse border's corners kept as samples says so under the
// table, as `remesh` does (a saddle whose rim is a 24-gon, at 400 vertices). The same saddle
// with a rim of 96 sides, finer than the result's border, is not remeshed again, and nothing is
// said.
TEST(Inspector, AResultKeptWithItsBordersCornersSaysSo) {
  const auto saddle = [](int sides) {
    const std::string path = test::tempPath("saddle" + std::to_string(sides) + ".off");
    writeMesh(test::polarDisk(sides, 12, 0, [](double r, double a) { return 0.5 * r * r * std::cos(2 * a); }), path);
    return path + " --sites 400";
  };
  EXPECT_EQ(brownNotePixels(saddle(96), test::tempPath("saddle96_400.png")), 0);
  EXPECT_GT(brownNotePixels(saddle(24), test::tempPath("saddle24_400.png")), 50);
}

// A pane's scissor and clear stay in the framebuffer: shrunk to 200x150 during a lesson, the
// window laid its panes out below its foot, they were cleared there, and lavapipe crashed
// ("corrupted size vs. prev_size"; reproduced under Xvfb twice, and not since).
TEST(Inspector, APaneIsClearedOnlyWithinTheFramebuffer) {
  const VkExtent2D window{200, 150};
  const float inside[4] = {10, 20, 50, 60}, below[4] = {0, 180, 200, 40}, across[4] = {-30, 140, 100, 30};
  const VkRect2D a = gpu::clipped(inside, window), b = gpu::clipped(below, window), c = gpu::clipped(across, window);
  EXPECT_EQ(a.offset.x, 10);
  EXPECT_EQ(a.offset.y, 20);
  EXPECT_EQ(a.extent.width, 50u);
  EXPECT_EQ(a.extent.height, 60u);
  EXPECT_EQ(b.extent.width * b.extent.height, 0u);  // nothing to clear
  EXPECT_LE(b.offset.y, 150);
  EXPECT_EQ(c.offset.x, 0);  // no negative offset (Vulkan refuses one for a scissor)
  EXPECT_EQ(c.offset.y, 140);
  EXPECT_EQ(c.extent.width, 70u);
  EXPECT_EQ(c.extent.height, 10u);
}

// The window's acquire and present results: a swapchain out of date or suboptimal is made
// again, and any other failure says what failed (both results were ignored: a lost surface
// left the next frame waiting on a semaphore nothing would signal).
TEST(Inspector, TheWindowRemakesAnOutdatedSwapchainAndReportsOtherFailures) {
  EXPECT_FALSE(gpu::swapchainOutOfDate(VK_SUCCESS, "presenting a frame"));
  EXPECT_TRUE(gpu::swapchainOutOfDate(VK_ERROR_OUT_OF_DATE_KHR, "presenting a frame"));
  EXPECT_TRUE(gpu::swapchainOutOfDate(VK_SUBOPTIMAL_KHR, "acquiring a swapchain image"));
  for (VkResult failure : {VK_ERROR_SURFACE_LOST_KHR, VK_ERROR_DEVICE_LOST, VK_TIMEOUT, VK_NOT_READY}) {
    try {
      gpu::swapchainOutOfDate(failure, "presenting a frame");
      ADD_FAILURE() << "no error for VkResult " << failure;
    } catch (const gpu::GpuError& e) {
      EXPECT_NE(std::string(e.what()).find("presenting a frame failed (VkResult " + std::to_string(failure)),
                std::string::npos) << e.what();
    }
  }
}
