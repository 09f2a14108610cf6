// Nonmanifold and nonorientable surfaces (issue 32, parts 2 and 3; paper Sec. 2.2, 3.4, 3.7, Fig. 9):
// polygon soups with three flaps on a spine, two closed cones touching at their tips, a torus with a
// fin glued along some of its edges, and a Moebius strip with curves given as dual chains. Every
// answer is exact: which faces are one label higher than which, and the nonbounding loops G.
#include <CGAL/surface_winding_numbers.h>

#include <gtest/gtest.h>

#include "mesh_generators.h"
#include "test_oracles_soup.h"

#include <cmath>
#include <algorithm>
#include <functional>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace {

// A soup under construction: polygons and one tag per polygon (which part of the surface it is in).
struct Tagged_soup
{
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<std::array<int, 3>> tag;   // (part, i, j) of each polygon

  std::size_t point(double x, double y, double z)
  {
    points.emplace_back(x, y, z);
    return points.size() - 1;
  }
  // the quad a b c d as two triangles, reversed if `flip`
  void quad(std::size_t a, std::size_t b, std::size_t c, std::size_t d, bool flip, std::array<int, 3> t)
  {
    for(std::vector<std::size_t> tri : {std::vector<std::size_t>{a, b, c}, std::vector<std::size_t>{a, c, d}})
    {
      if(flip) std::reverse(tri.begin(), tri.end());
      polygons.push_back(tri);
      tag.push_back(t);
    }
  }
};

// The dual chain of the boundary of a set of polygons: for every edge shared by exactly two polygons
// of which one is inside, the pair (outside, inside): a jump of +1 into the set.
std::vector<Pair> dual_boundary(const Polygons& polygons, const std::function<bool(std::size_t)>& inside)
{
  std::map<Pair, std::vector<std::size_t>> faces_of;
  for(std::size_t p = 0; p < polygons.size(); ++p)
    for(std::size_t k = 0; k < polygons[p].size(); ++k)
    {
      const std::size_t a = polygons[p][k], b = polygons[p][(k + 1) % polygons[p].size()];
      faces_of[Pair((std::min)(a, b), (std::max)(a, b))].push_back(p);
    }
  std::vector<Pair> pairs;
  for(const auto& kv : faces_of)
    if(kv.second.size() == 2 && inside(kv.second[0]) != inside(kv.second[1]))
      pairs.push_back(inside(kv.second[0]) ? Pair(kv.second[1], kv.second[0]) : Pair(kv.second[0], kv.second[1]));
  return pairs;
}

// the labels of the polygons selected by `which`, as a set
std::set<int> labels_of(const Soup_answer& a, const std::function<bool(std::size_t)>& which)
{
  std::set<int> s;
  for(std::size_t p = 0; p < a.W.size(); ++p)
    if(which(p)) s.insert(a.W[p]);
  return s;
}

// Three flaps of M x N cells on the spine x = y = 0, 0 <= z <= N, at 120 degrees. Flaps 0 and 1 are
// oriented as one sheet across the spine (flap 1 reversed), flap 2 like flap 0. vid(f, i, k): i = 0
// is the spine.
struct Three_flaps : Tagged_soup
{
  int M, N;
  std::vector<std::size_t> spine;
  std::vector<std::vector<std::size_t>> flap;   // [f][(i - 1) * (N + 1) + k]
  Three_flaps(int M_, int N_) : M(M_), N(N_), flap(3)
  {
    for(int k = 0; k <= N; ++k) spine.push_back(point(0, 0, k));
    for(int f = 0; f < 3; ++f)
    {
      const double a = 2 * kPi * f / 3;
      for(int i = 1; i <= M; ++i)
        for(int k = 0; k <= N; ++k) flap[f].push_back(point(i * std::cos(a), i * std::sin(a), k + 0.1 * std::sin(i + 2. * k)));
      for(int i = 0; i < M; ++i)
        for(int k = 0; k < N; ++k)
          quad(vid(f, i, k), vid(f, i + 1, k), vid(f, i + 1, k + 1), vid(f, i, k + 1), f == 1, {f, i, k});
    }
  }
  std::size_t vid(int f, int i, int k) const { return i == 0 ? spine[k] : flap[f][(i - 1) * (N + 1) + k]; }
  // the rectangle -5 <= x <= 5, 2 <= k <= 7, counter-clockwise in the plane (x, k) of the sheet made of
  // flaps f (x = i) and g (x = -i), as (flap, i, k) triples
  std::vector<std::array<int, 3>> rectangle_across_the_spine(int f, int g) const
  {
    auto at = [&](int x, int k) { return std::array<int, 3>{x >= 0 ? f : g, std::abs(x), k}; };
    std::vector<std::array<int, 3>> loop;
    for(int x = -5; x < 5; ++x) loop.push_back(at(x, 2));
    for(int k = 2; k < 7; ++k) loop.push_back(at(5, k));
    for(int x = 5; x > -5; --x) loop.push_back(at(x, 7));
    for(int k = 7; k >= 2; --k) loop.push_back(at(-5, k));
    return loop;
  }
  // the directed edges of a path through (f, i, k) triples
  std::vector<Pair> path(const std::vector<std::array<int, 3>>& at) const
  {
    std::vector<Pair> c;
    for(std::size_t n = 0; n + 1 < at.size(); ++n)
      c.emplace_back(vid(at[n][0], at[n][1], at[n][2]), vid(at[n + 1][0], at[n + 1][1], at[n + 1][2]));
    return c;
  }
};

} // namespace

TEST(Nonmanifold, LoopInsideOneOfThreeFlapsOnASpine)
{
  Three_flaps s(8, 8);
  // rectangle 2 <= i < 5, 2 <= k < 6 of flap 0, counter-clockwise in its orientation: inside is +1
  std::vector<std::array<int, 3>> at;
  for(int i = 2; i < 5; ++i) at.push_back({0, i, 2});
  for(int k = 2; k < 6; ++k) at.push_back({0, 5, k});
  for(int i = 5; i > 2; --i) at.push_back({0, i, 6});
  for(int k = 6; k >= 2; --k) at.push_back({0, 2, k});
  const Soup_answer a = solve_soup(s.points, s.polygons, s.path(at));
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.nonmanifold_edges, 8u);     // the spine
  EXPECT_EQ(a.report.nonmanifold_vertices, 9u);
  EXPECT_EQ(a.report.dropped_curve_edges, 0u);
  // three disks glued along a segment: chi = 3 - 2 = 1; every flap can be oriented, the genus is not
  // defined (nonmanifold)
  EXPECT_EQ(a.report.euler_characteristic, 1);
  EXPECT_TRUE(a.report.orientable);
  EXPECT_EQ(a.report.genus, -1);
  auto inside = [&](std::size_t p) {
    const auto& t = s.tag[p];
    return t[0] == 0 && t[1] >= 2 && t[1] < 5 && t[2] >= 2 && t[2] < 6;
  };
  EXPECT_EQ(labels_of(a, inside), std::set<int>{1});
  EXPECT_EQ(labels_of(a, [&](std::size_t p) { return !inside(p); }), std::set<int>{0});
  for(const auto& kv : a.G) EXPECT_EQ(kv.second, 0);
}

TEST(Nonmanifold, LoopAcrossTheSpineLabelsBothFlapsItEncloses)
{
  // In the sheet made of flaps 0 (x = i) and 1 (x = -i), the rectangle -5 <= x <= 5, 2 <= k <= 7,
  // counter-clockwise: it crosses the spine at k = 2 and k = 7, where its edges touch nonmanifold
  // vertices and are dropped (4 edges); the gaps are closed and both halves of the inside are +1
  // (not +1 on one flap and -1 on the other, as after orienting the soup first).
  Three_flaps s(9, 9);
  const Soup_answer a = solve_soup(s.points, s.polygons, s.path(s.rectangle_across_the_spine(0, 1)));
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.dropped_curve_edges, 4u);
  auto inside = [&](std::size_t p) {
    const auto& t = s.tag[p];
    return t[0] < 2 && t[1] < 5 && t[2] >= 2 && t[2] < 7;
  };
  const std::set<int> in = labels_of(a, inside);
  const std::set<int> out = labels_of(a, [&](std::size_t p) { return s.tag[p][0] < 2 && !inside(p); });
  ASSERT_EQ(in.size(), 1u);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(*in.begin() - *out.begin(), 1);
}

TEST(Nonmanifold, LoopAcrossTheSpineBetweenFlapsOrientedAlikeNeedsADualChain)
{
  // The same rectangle in the sheet of flaps 0 (x = i) and 2 (x = -i), whose polygons are oriented
  // alike, i.e. traverse the spine the same way. As directed edges, the higher side of the loop is taken
  // from each polygon's orientation: the inside on flap 0, the outside on flap 2. The labels then jump
  // across the spine, where nothing may jump, and the report counts the spine edges where they do. As a
  // dual chain (jumps into the rectangle on both flaps) the inside is one label higher on both flaps.
  Three_flaps s(9, 9);
  auto inside = [&](std::size_t p) {
    const auto& t = s.tag[p];
    return t[0] != 1 && t[1] < 5 && t[2] >= 2 && t[2] < 7;
  };
  // the label most polygons of one side of one flap carry (near the spine the completion decides)
  auto label = [&](const Soup_answer& a, int flap, bool in) {
    std::map<int, int> count;
    for(std::size_t p = 0; p < s.polygons.size(); ++p)
      if(s.tag[p][0] == flap && inside(p) == in) ++count[a.W[p]];
    return std::max_element(count.begin(), count.end(), [](const auto& x, const auto& y) { return x.second < y.second; })->first;
  };
  const Soup_answer e = solve_soup(s.points, s.polygons, s.path(s.rectangle_across_the_spine(0, 2)));
  ASSERT_TRUE(e.ok) << e.report.error;
  EXPECT_EQ(label(e, 0, true) - label(e, 0, false), 1);
  EXPECT_EQ(label(e, 2, true) - label(e, 2, false), -1);
  // at least the spine edges of the rectangle's inside (5) or of its outside (4): one of the two pairs
  // of sides of the spine differs
  EXPECT_GE(e.report.nonmanifold_label_jumps, 4u);

  const Soup_answer d = solve_soup(s.points, s.polygons, {}, dual_boundary(s.polygons, inside));
  ASSERT_TRUE(d.ok) << d.report.error;
  const std::set<int> in = labels_of(d, inside);
  const std::set<int> out = labels_of(d, [&](std::size_t p) { return s.tag[p][0] != 1 && !inside(p); });
  ASSERT_EQ(in.size(), 1u);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(*in.begin() - *out.begin(), 1);
}

TEST(Nonmanifold, TwoClosedConesTouchingAtTheirTips)
{
  // Two closed cones (lateral surface of `rings` rings of n cells, and a base fan) sharing the tip
  // vertex, outward oriented; a loop around cone 0 at ring `cut`. The tip side of cone 0 and all of
  // cone 1 are one region (no jump at the tip), the base side of cone 0 the other.
  const int n = 12, rings = 8, cut = 4;
  Tagged_soup s;
  const std::size_t tip = s.point(0, 0, 0);
  std::vector<std::vector<std::size_t>> ring_of(2);
  for(int c = 0; c < 2; ++c)
  {
    const double up = c == 0 ? 1 : -1;
    auto vid = [&](int r, int t) { return r == 0 ? tip : ring_of[c][(r - 1) * n + (t % n)]; };
    for(int r = 1; r <= rings; ++r)
      for(int t = 0; t < n; ++t)
      {
        const double a = 2 * kPi * (t + 0.3 * (r % 2)) / n;
        ring_of[c].push_back(s.point(0.5 * r * std::cos(a), 0.5 * r * std::sin(a) * up, up * r));
      }
    for(int r = 0; r < rings; ++r)
      for(int t = 0; t < n; ++t)
        if(r == 0)
        {
          s.polygons.push_back({tip, vid(1, t), vid(1, t + 1)});
          s.tag.push_back({c, 0, t});
        }
        else
          s.quad(vid(r, t), vid(r + 1, t), vid(r + 1, t + 1), vid(r, t + 1), false, {c, r, t});
    const std::size_t centre = s.point(0, 0, up * rings);
    for(int t = 0; t < n; ++t)
    {
      s.polygons.push_back({centre, vid(rings, t + 1), vid(rings, t)});
      s.tag.push_back({c, rings, t});
    }
  }
  std::vector<Pair> loop;
  for(int t = 0; t < n; ++t) loop.emplace_back(ring_of[0][(cut - 1) * n + t], ring_of[0][(cut - 1) * n + (t + 1) % n]);
  const Soup_answer a = solve_soup(s.points, s.polygons, loop);
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.nonmanifold_vertices, 1u);   // the tip
  EXPECT_EQ(a.report.nonmanifold_edges, 0u);
  EXPECT_EQ(a.report.euler_characteristic, 3);   // two spheres sharing a vertex
  EXPECT_TRUE(a.report.orientable);
  EXPECT_EQ(a.report.genus, -1);
  const std::set<int> tip_side = labels_of(a, [&](std::size_t p) { return s.tag[p][0] == 1 || s.tag[p][1] < cut; });
  const std::set<int> base_side = labels_of(a, [&](std::size_t p) { return s.tag[p][0] == 0 && s.tag[p][1] >= cut; });
  ASSERT_EQ(tip_side.size(), 1u);
  ASSERT_EQ(base_side.size(), 1u);
  EXPECT_EQ(std::abs(*tip_side.begin() - *base_side.begin()), 1);
  for(const auto& kv : a.G) EXPECT_EQ(kv.second, 0);
}

TEST(Nonmanifold, TorusWithAFinKeepsItsMeridianAndItsRegion)
{
  // A torus with a fin (3 x 4 quads) glued along 4 edges of a longitude: nonmanifold edges, and the
  // handle makes the residual problem run. A broken meridian away from the fin bounds nothing (G is
  // exactly the meridian) and a rectangle loop bounds its cells.
  const int nu = 18, nv = 10;
  const Polygon_torus t(nu, nv, [](int, int) { return true; });
  std::vector<Point_3> points = t.points;
  Polygons polygons = t.polygons;
  auto fin = [&](int i, int r) -> std::size_t {
    const std::size_t on = torus_vid(nu, nv, i, 0);
    if(r == 0) return on;
    return t.points.size() + std::size_t(r - 1) * 5 + std::size_t(i);
  };
  for(int r = 1; r <= 3; ++r)
    for(int i = 0; i <= 4; ++i)
    {
      const Point_3& p = t.points[torus_vid(nu, nv, i, 0)];
      points.emplace_back(p.x() * (1 + 0.15 * r), p.y() * (1 + 0.15 * r), 0.1 * r);
    }
  for(int r = 0; r < 3; ++r)
    for(int i = 0; i < 4; ++i) polygons.push_back({fin(i, r), fin(i + 1, r), fin(i + 1, r + 1), fin(i, r + 1)});
  std::vector<Index> meridian = torus_meridian(nu, nv, 12);
  const std::vector<Pair> broken = loop_edges(meridian, 4, 2);
  std::vector<Pair> curve = broken;
  for(const Pair& e : loop_edges(torus_rect_loop(nu, nv, 5, 3, 9, 7))) curve.push_back(e);
  const Soup_answer a = solve_soup(points, polygons, curve);
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.nonmanifold_edges, 4u);
  EXPECT_TRUE(a.report.lp_ran);
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    const bool in = p < t.polygons.size() && t.cell[p].first >= 5 && t.cell[p].first < 9 && t.cell[p].second >= 3 &&
                    t.cell[p].second < 7;
    EXPECT_EQ(a.W[p], in ? 1 : 0) << "polygon " << p;
  }
  int on = 0, total = 0;
  for(const auto& kv : a.G) total += std::abs(kv.second);
  for(const Pair& e : loop_edges(meridian)) on += along(a.G, e.first, e.second);
  EXPECT_EQ(on, nv);
  EXPECT_EQ(total, nv);
}

namespace {

// A Moebius strip of n x m cells: chart vertex (i, j), 0 <= i < n, 0 <= j <= m; (n, j) is (0, m - j).
struct Moebius : Tagged_soup
{
  int n, m;
  Moebius(int n_, int m_) : n(n_), m(m_)
  {
    for(int i = 0; i < n; ++i)
      for(int j = 0; j <= m; ++j)
      {
        const double phi = 2 * kPi * i / n, s = (double(j) / m - 0.5) * 0.8;
        point((2 + s * std::cos(phi / 2)) * std::cos(phi), (2 + s * std::cos(phi / 2)) * std::sin(phi), s * std::sin(phi / 2));
      }
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < m; ++j) quad(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1), false, {0, i, j});
  }
  std::size_t vid(int i, int j) const
  {
    return i < n ? std::size_t(i * (m + 1) + j) : std::size_t(m - j);
  }
};

} // namespace

TEST(Nonorientable, SmallLoopOnAMoebiusStripAsADualChainAndAsEdges)
{
  const Moebius s(24, 6);
  auto inside = [&](std::size_t p) { return s.tag[p][1] >= 5 && s.tag[p][1] < 10 && s.tag[p][2] >= 2 && s.tag[p][2] < 5; };
  const Soup_answer a = solve_soup(s.points, s.polygons, {}, dual_boundary(s.polygons, inside));
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.nonorientable_edges, 6u);   // the seam
  EXPECT_EQ(a.report.euler_characteristic, 0);
  EXPECT_FALSE(a.report.orientable);
  EXPECT_EQ(a.report.genus, -1);                  // not defined (the nonorientable genus would be 1)
  EXPECT_EQ(a.report.border_loops, 1u);
  EXPECT_EQ(a.report.inconsistent_curve_vertices, 0u);
  EXPECT_EQ(labels_of(a, inside), std::set<int>{1});
  EXPECT_EQ(labels_of(a, [&](std::size_t p) { return !inside(p); }), std::set<int>{0});
  // the same loop as directed edges, counter-clockwise in the chart (away from the seam the faces are
  // oriented as the chart): the same labels
  std::vector<Pair> loop;
  for(int i = 5; i < 10; ++i) loop.emplace_back(s.vid(i, 2), s.vid(i + 1, 2));
  for(int j = 2; j < 5; ++j) loop.emplace_back(s.vid(10, j), s.vid(10, j + 1));
  for(int i = 10; i > 5; --i) loop.emplace_back(s.vid(i, 5), s.vid(i - 1, 5));
  for(int j = 5; j > 2; --j) loop.emplace_back(s.vid(5, j), s.vid(5, j - 1));
  const Soup_answer e = solve_soup(s.points, s.polygons, loop);
  ASSERT_TRUE(e.ok) << e.report.error;
  EXPECT_EQ(e.W, a.W);
}

TEST(Nonorientable, LoopAlongTheBorderOfAMoebiusStripCutsOffACollar)
{
  // The curve parallel to the border, two cells in, goes around twice; with its normal pointing away
  // from the border all along (an orientable curve) it splits the strip into a collar along the border
  // and a narrower Moebius strip, one higher. A broken version (two separate pairs left out, one where the strip is glued) gives the same.
  const Moebius s(30, 6);
  auto inner = [&](std::size_t p) { return s.tag[p][2] >= 2 && s.tag[p][2] < 4; };
  std::vector<Pair> dual = dual_boundary(s.polygons, inner);
  ASSERT_EQ(dual.size(), 2u * 30u);   // one edge per cell on either side of the inner strip
  // broken: one pair left out where the strip is glued, one elsewhere
  std::vector<Pair> broken = dual;
  broken.erase(broken.begin() + 20);
  broken.erase(broken.begin());
  for(const std::vector<Pair>& curve : {dual, broken})
  {
    const Soup_answer a = solve_soup(s.points, s.polygons, {}, curve);
    ASSERT_TRUE(a.ok) << a.report.error;
    EXPECT_EQ(a.report.inconsistent_curve_vertices, 0u);
    const std::set<int> in = labels_of(a, inner), out = labels_of(a, [&](std::size_t p) { return !inner(p); });
    ASSERT_EQ(in.size(), 1u);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(*in.begin() - *out.begin(), 1);
  }
}

TEST(Nonorientable, CenterlineOfAMoebiusStripIsReportedAsInconsistent)
{
  // The centerline has no consistent normal (paper Fig. 9): given with its jumps into the chart's
  // upper side, the normal flips where the chart is glued; the report says where.
  const Moebius s(24, 6);
  std::vector<Pair> dual;
  auto cell_triangle = [&](int i, int j, int which) { return std::size_t(2 * (i * 6 + j) + which); };
  for(int i = 0; i < 24; ++i) dual.emplace_back(cell_triangle(i, 2, 1), cell_triangle(i, 3, 0));
  const Soup_answer a = solve_soup(s.points, s.polygons, {}, dual);
  ASSERT_TRUE(a.ok) << a.report.error;
  EXPECT_EQ(a.report.inconsistent_curve_vertices, 1u);
  EXPECT_EQ(a.report.interior_endpoints, 1u);
}

TEST(Nonorientable, ReversingSomePolygonsOfAnOrientableSoupChangesNoLabel)
{
  // An annulus of 30 x 6 cells whose middle band (two cells wide) is bounded by two circles given as a
  // dual chain with gaps: reversing the polygons of half the rows makes the soup inconsistently
  // oriented (12 edges traversed twice the same way) but describes the same surface and curve, so
  // every label must stay as it is (even the few triangles the completion of the gaps gets wrong).
  const int n = 30, m = 6;
  auto annulus = [&](int flip_from) {
    Tagged_soup s;
    for(int i = 0; i < n; ++i)
      for(int j = 0; j <= m; ++j)
      {
        const double phi = 2 * kPi * i / n, r = 2 + (double(j) / m - 0.5) * 0.8;
        s.point(r * std::cos(phi), r * std::sin(phi), 0.1 * std::sin(3 * phi));
      }
    auto vid = [&](int i, int j) { return std::size_t((i % n) * (m + 1) + j); };
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < m; ++j) s.quad(vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1), i >= flip_from, {0, i, j});
    return s;
  };
  const Tagged_soup plain = annulus(n), flipped = annulus(n / 2);
  auto inner = [&](std::size_t p) { return plain.tag[p][2] >= 2 && plain.tag[p][2] < 4; };
  std::vector<Pair> dual = dual_boundary(plain.polygons, inner);
  ASSERT_EQ(dual, dual_boundary(flipped.polygons, inner));
  for(std::size_t gap : {std::size_t(0), std::size_t(2), std::size_t(4), std::size_t(40)})
  {
    std::vector<Pair> broken = dual;
    broken.erase(broken.begin() + gap, broken.begin() + gap + 2);
    const Soup_answer a = solve_soup(plain.points, plain.polygons, {}, broken);
    const Soup_answer b = solve_soup(flipped.points, flipped.polygons, {}, broken);
    ASSERT_TRUE(a.ok && b.ok) << a.report.error << b.report.error;
    EXPECT_EQ(a.report.nonorientable_edges, 0u);
    EXPECT_EQ(b.report.nonorientable_edges, 12u);
    // the same surface: an orientable annulus of genus 0 with two border loops either way
    for(const Soup_answer* x : {&a, &b})
    {
      EXPECT_TRUE(x->report.orientable);
      EXPECT_EQ(x->report.euler_characteristic, 0);
      EXPECT_EQ(x->report.genus, 0);
      EXPECT_EQ(x->report.border_loops, 2u);
    }
    EXPECT_EQ(a.W, b.W) << "gap at " << gap;
    EXPECT_EQ(a.report.interior_endpoints, b.report.interior_endpoints);
  }
}
