// The swn tool's label options: --anchor-face, --labels-per-input-face (after a cut that splits faces).
#include "test_tool_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace {

typedef std::array<double, 2> P2;

// a planar n x n grid on [0,1]^2 (OFF, z = 0), cell (i, j) the faces 2 (j n + i) (below its diagonal from
// (i, j) to (i + 1, j + 1)) and 2 (j n + i) + 1; and an OBJ polyline file with the rectangle
// [x0, x1] x [y0, y1], counter-clockwise seen from +z
void write_grid_and_rectangle(const fs::path& dir, int n, double x0, double x1, double y0, double y1)
{
  fs::create_directories(dir);
  std::ofstream off(dir / "grid.off");
  off << "OFF\n" << (n + 1) * (n + 1) << " " << 2 * n * n << " 0\n";
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) off << double(i) / n << " " << double(j) / n << " 0\n";
  auto V = [&](int i, int j) { return j * (n + 1) + i; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      off << "3 " << V(i, j) << " " << V(i + 1, j) << " " << V(i + 1, j + 1) << "\n3 " << V(i, j) << " "
          << V(i + 1, j + 1) << " " << V(i, j + 1) << "\n";
  std::ofstream obj(dir / "rectangle.obj");
  obj << "v " << x0 << " " << y0 << " 0\nv " << x1 << " " << y0 << " 0\nv " << x1 << " " << y1 << " 0\nv " << x0 << " "
      << y1 << " 0\nl 1 2 3 4 1\n";
}

double polygon_area(const std::vector<P2>& p)
{
  double a = 0;
  for(std::size_t k = 0; k < p.size(); ++k)
    a += p[k][0] * p[(k + 1) % p.size()][1] - p[(k + 1) % p.size()][0] * p[k][1];
  return 0.5 * std::abs(a);
}

// the part of `poly` where coordinate `axis` is >= v (above) or <= v (!above): Sutherland-Hodgman
std::vector<P2> clip(const std::vector<P2>& poly, int axis, double v, bool above)
{
  std::vector<P2> out;
  auto in = [&](const P2& p) { return above ? p[axis] >= v : p[axis] <= v; };
  for(std::size_t k = 0; k < poly.size(); ++k)
  {
    const P2 &p = poly[k], &q = poly[(k + 1) % poly.size()];
    if(in(p)) out.push_back(p);
    if(in(p) != in(q))
    {
      const double t = (v - p[axis]) / (q[axis] - p[axis]);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
    }
  }
  return out;
}

// the analytic label of every input face of the grid: 1 where most of its area is inside the rectangle;
// `fraction` gets the inside fraction
std::vector<int> majority_labels(int n, double x0, double x1, double y0, double y1, std::vector<double>& fraction)
{
  std::vector<int> labels;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const P2 a = {double(i) / n, double(j) / n}, b = {double(i + 1) / n, double(j) / n},
               c = {double(i + 1) / n, double(j + 1) / n}, d = {double(i) / n, double(j + 1) / n};
      for(const std::vector<P2>& t : {std::vector<P2>{a, b, c}, std::vector<P2>{a, c, d}})
      {
        const std::vector<P2> inside = clip(clip(clip(clip(t, 0, x0, true), 0, x1, false), 1, y0, true), 1, y1, false);
        fraction.push_back(inside.size() > 2 ? polygon_area(inside) / polygon_area(t) : 0.);
        labels.push_back(fraction.back() > 0.5 ? 1 : 0);
      }
    }
  return labels;
}

} // namespace

TEST(ToolLabels, PerInputFaceLabelsAfterACutAreTheAnalyticOnesAndTheAnchorFaceIsZero)
{
  // a 5 x 5 grid (lines at multiples of 0.2) and the rectangle [0.32, 0.71] x [0.26, 0.73], which cuts
  // faces (none of its corners on an edge): the label of every input face is 1 where most of its area is
  // inside (fractions from 0.002 to 0.91, one of 0.49 and one of 0.517), 0 elsewhere (the outside is larger)
  const int n = 5;
  const double x0 = 0.32, x1 = 0.71, y0 = 0.26, y1 = 0.73;
  const fs::path dir = fresh_dir("labels_in");
  write_grid_and_rectangle(dir, n, x0, x1, y0, y1);
  std::vector<double> fraction;
  const std::vector<int> expected = majority_labels(n, x0, x1, y0, y1, fraction);
  for(double f : fraction) ASSERT_GT(std::abs(f - 0.5), 0.005);   // no near-tie
  const std::string base = "'" + (dir / "grid.off").string() + "' --polylines '" + (dir / "rectangle.obj").string() + "'";
  const fs::path out = fresh_dir("labels_out");
  Tool_run r = run(base + " --labels-per-input-face --output-dir '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("50 input faces"), std::string::npos) << r.out;   // the tool says the faces changed
  const std::string summary = slurp((out / "summary.json").string());
  EXPECT_NE(summary.find("\"faces_changed\": true"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"labels_txt\": \"per input face\""), std::string::npos) << summary;
  const std::vector<int> per_input = read_labels(out / "labels.txt");
  ASSERT_EQ(per_input.size(), std::size_t(2 * n * n));
  EXPECT_EQ(per_input, expected);
  // the anchor: an input face inside and not cut (after a cut, the largest piece of the face gets 0)
  const std::size_t inside_face = std::size_t(std::find(fraction.begin(), fraction.end(), 1.) - fraction.begin());
  ASSERT_LT(inside_face, expected.size());
  // two regions (inside, outside): the inside one makes the second-best labeling; no per-region list and
  // no confidence in mesh.ply unless asked
  EXPECT_NE(summary.find("\"regions\": 2"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"second_best_region\": "), std::string::npos) << summary;
  EXPECT_EQ(summary.find("\"per_region\""), std::string::npos) << summary;
  EXPECT_EQ(slurp((out / "mesh.ply").string()).find("property float confidence"), std::string::npos);
  fs::remove_all(out);

  // without the option: one line per solved face, more than the input's; with --confidence, the regions
  r = run(base + " --quiet --confidence --output-dir '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(read_labels(out / "labels.txt").size(), std::size_t(2 * n * n));
  const std::string with_confidence = slurp((out / "summary.json").string());
  EXPECT_NE(with_confidence.find("\"labels_txt\": \"per solved face\""), std::string::npos);
  EXPECT_NE(with_confidence.find("\"per_region\": ["), std::string::npos) << with_confidence;
  EXPECT_NE(with_confidence.find("\"largest_in_component\": true"), std::string::npos) << with_confidence;
  const std::string ply = slurp((out / "mesh.ply").string());
  EXPECT_NE(ply.find("property float confidence"), std::string::npos);
  EXPECT_NE(ply.find("property int region"), std::string::npos);
  fs::remove_all(out);

  // anchored at an inside face (1-based): inside 0, outside -1, the differences unchanged
  r = run(base + " --quiet --labels-per-input-face --anchor-face " + std::to_string(inside_face + 1) + " --output-dir '" +
          out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<int> anchored = read_labels(out / "labels.txt");
  ASSERT_EQ(anchored.size(), per_input.size());
  EXPECT_EQ(anchored[inside_face], 0);
  for(std::size_t f = 0; f < anchored.size(); ++f) EXPECT_EQ(anchored[f], per_input[f] - 1) << "face " << f;
  fs::remove_all(out);

  // out of range, or not a number: exit 2, no output
  r = run(base + " --quiet --anchor-face 51 --output-dir '" + out.string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--anchor-face 51 is out of range (the mesh has 50 faces"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = run(base + " --anchor-face 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--anchor-face needs a face number"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(ToolLabels, AnchorFaceAndConfidenceOnTheSoupRoute)
{
  // the same grid with its two triangles per cell merged into quads: solved as a polygon soup, no cut;
  // the square along grid lines [0.2, 0.8]^2 given as a vertex polyline
  const int n = 5;
  const fs::path dir = fresh_dir("labels_soup");
  fs::create_directories(dir);
  {
    std::ofstream obj(dir / "quads.obj");
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i) obj << "v " << double(i) / n << " " << double(j) / n << " 0\n";
    auto V = [&](int i, int j) { return j * (n + 1) + i + 1; };
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i) obj << "f " << V(i, j) << " " << V(i + 1, j) << " " << V(i + 1, j + 1) << " " << V(i, j + 1) << "\n";
    obj << "l";   // counter-clockwise along the grid lines
    for(int i = 1; i < 4; ++i) obj << " " << V(i, 1);
    for(int j = 1; j < 4; ++j) obj << " " << V(4, j);
    for(int i = 4; i > 1; --i) obj << " " << V(i, 4);
    for(int j = 4; j >= 1; --j) obj << " " << V(1, j);
    obj << "\n";
  }
  const fs::path out = fresh_dir("labels_soup_out");
  // the inner cell (2, 2) is quad 13 (1-based)
  const Tool_run r = run("'" + (dir / "quads.obj").string() + "' --quiet --anchor-face 13 --output-dir '" + out.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<int> labels = read_labels(out / "labels.txt");
  ASSERT_EQ(labels.size(), std::size_t(n * n));
  for(std::size_t q = 0; q < labels.size(); ++q)
  {
    const int i = int(q) % n, j = int(q) / n;
    EXPECT_EQ(labels[q], i >= 1 && i <= 3 && j >= 1 && j <= 3 ? 0 : -1) << "quad " << q;
  }
  fs::remove_all(out);

  // confidence: two regions; the inside one (9 quads, 18 triangles of the internal triangulation) flips
  // at epsilon times the square's length (12 edges of 1/5), in mean interior edge lengths (the 40 interior
  // grid edges of 1/5 and the 25 diagonals of sqrt(2)/5); mesh.ply gets confidence and region per quad
  const Tool_run c = run("'" + (dir / "quads.obj").string() + "' --quiet --confidence --output-dir '" + out.string() + "'");
  ASSERT_EQ(c.status, 0) << c.err;
  const std::string summary = slurp((out / "summary.json").string());
  const double mean = (40 * 0.2 + 25 * 0.2 * std::sqrt(2.)) / 65;
  EXPECT_EQ(json_number(summary, "regions"), 2.) << summary;
  EXPECT_NEAR(json_number(summary, "second_best_cost"), 0.01 * 12 * 0.2 / mean, 1e-9) << summary;
  EXPECT_NEAR(json_number(summary, "second_best_area"), 0.36, 1e-12) << summary;
  EXPECT_NE(summary.find("\"faces\": 18,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"per_region\": ["), std::string::npos) << summary;
  const std::string ply = slurp((out / "mesh.ply").string());
  EXPECT_NE(ply.find("element face 25\n"), std::string::npos);
  EXPECT_NE(ply.find("property float winding_number\nproperty float confidence\nproperty int region\n"), std::string::npos);
  fs::remove_all(out);
  fs::remove_all(dir);
}
