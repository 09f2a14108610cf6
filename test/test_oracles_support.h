// Shared by the test_oracles sources: the meshes as FaceGraphs, the outcome of a solve in soup terms and
// the checks shared by every solve. See test_oracles.cpp for the conventions.
#ifndef SWN_TEST_ORACLES_SUPPORT_H
#define SWN_TEST_ORACLES_SUPPORT_H

#include <CGAL/surface_winding_numbers.h>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/property_map/property_map.hpp>

#include <gtest/gtest.h>
#include <gtest/gtest-spi.h>

#include "mesh_generators.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cstdlib>
#include <iostream>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace SWN = CGAL::Surface_winding_numbers;
using namespace swn_test;

using SM = CGAL::Surface_mesh<Point_3>;
using PH = CGAL::Polyhedron_3<Kernel>;

namespace {

// Seeds of the random meshes. SWN_ORACLE_SEED_OFFSET=k (environment) shifts all of them, to run
// the whole suite on other random meshes; SWN_ORACLE_DIAG=1 prints per-solve diagnostics.
unsigned seed(unsigned s)
{
  static const unsigned offset = [] {
    const char* e = std::getenv("SWN_ORACLE_SEED_OFFSET");
    return e ? unsigned(std::strtoul(e, nullptr, 10)) : 0u;
  }();
  return s + offset;
}

bool diagnostics()
{
  static const bool on = std::getenv("SWN_ORACLE_DIAG") != nullptr;
  return on;
}

constexpr int kIntSentinel = -987654;
constexpr double kRealSentinel = -9.87654e300;

// Mesh sizes (notes 10.1): disk 20x20 (800 faces), torus 24x12 (576), annulus 8x48 (768),
// UV sphere 12 bands x 24 (528).
constexpr int kDiskN = 20;
constexpr int kNu = 24, kNv = 12;
constexpr int kNr = 8, kNt = 48;
constexpr int kLat = 12, kLon = 24;

// Tolerances: w two-valued / constant for one-solve surfaces (disk, sphere) and, loosely, on
// the LP path (notes 10.4).
constexpr double kTolW = 1e-6;
constexpr double kTolWLP = 1e-4;
constexpr double kTolG = 1e-3;

// ------------------------------------------------------------------------------------------
// Raw maps over std::unordered_map, usable with any FaceListGraph
// ------------------------------------------------------------------------------------------

template <class TM>
struct Raw_maps
{
  std::unordered_map<typename Built_mesh<TM>::edge_descriptor, int> chain, G, B;
  std::unordered_map<typename Built_mesh<TM>::edge_descriptor, double> g;
  std::unordered_map<typename Built_mesh<TM>::face_descriptor, int> W;
  std::unordered_map<typename Built_mesh<TM>::halfedge_descriptor, double> w;
  SWN::Solve_report rep;

  explicit Raw_maps(const TM& tm)
  {
    for(auto e : edges(tm)) { chain[e] = 0; G[e] = kIntSentinel; B[e] = kIntSentinel; g[e] = kRealSentinel; }
    for(auto f : faces(tm)) W[f] = kIntSentinel;
    for(auto h : halfedges(tm)) w[h] = kRealSentinel;
    rep.error = "<report not written>";
  }

  auto np(double eps)
  {
    return SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G),
           SWN::parameters::nonbounding_chain_real_map(boost::make_assoc_property_map(g),
           SWN::parameters::bounding_chain_map(boost::make_assoc_property_map(B),
           SWN::parameters::winding_number_map(boost::make_assoc_property_map(w),
           SWN::parameters::epsilon(eps,
           SWN::parameters::report(std::ref(rep)))))));
  }

  bool call(const TM& tm, double eps = 0.01)
  {
    return CGAL::surface_winding_numbers(tm, boost::make_assoc_property_map(chain), boost::make_assoc_property_map(W),
                                         np(eps));
  }

  template <class Solver>
  bool call_solver(Solver& solver, double eps = 0.01)
  {
    const bool ok = solver.solve(boost::make_assoc_property_map(chain), boost::make_assoc_property_map(W), np(eps));
    rep = solver.report();
    return ok;
  }

  bool outputs_untouched() const
  {
    for(const auto& kv : W) if(kv.second != kIntSentinel) return false;
    for(const auto& kv : G) if(kv.second != kIntSentinel) return false;
    for(const auto& kv : B) if(kv.second != kIntSentinel) return false;
    for(const auto& kv : g) if(kv.second != kRealSentinel) return false;
    for(const auto& kv : w) if(!(kv.second == kRealSentinel)) return false;
    return true;
  }
};

// Writes a soup-level chain into a per-edge map of `m` (value along halfedge(e)).
template <class TM, class Map>
void set_chain(const Built_mesh<TM>& m, const Soup_chain& c, Map& chain)
{
  for(const auto& kv : c)
  {
    auto h = m.halfedge_of(kv.first.first, kv.first.second);   // along key.first -> key.second
    chain[edge(h, m.tm)] += m.sign(h) * kv.second;
  }
}

// ------------------------------------------------------------------------------------------
// Outcome of one solve, in soup terms
// ------------------------------------------------------------------------------------------

struct Outcome
{
  bool ok = false;
  SWN::Solve_report rep;
  const Soup* soup = nullptr;
  Soup_chain input;

  std::vector<int> W;                          // per soup triangle
  Soup_chain G, B;                             // along key.first -> key.second
  std::map<Edge_key, double> g;                // along key.first -> key.second (all edges)
  std::vector<std::array<double, 3>> w;        // per soup triangle, per triangle corner

  std::set<Edge_key> all_edges, border_edges;
  std::set<Index> border_vertices;
  std::map<Edge_key, std::pair<Index, Index>> sides;   // interior edges: (left, right) face of key.first -> key.second

  std::size_t unwritten_W = 0, unwritten_G = 0, unwritten_B = 0, unwritten_g = 0, unwritten_w = 0;
};

template <class TM, class Solver = void>
Outcome run_impl(const Built_mesh<TM>& m, const Soup_chain& c, double eps, Solver* solver)
{
  Raw_maps<TM> r(m.tm);
  set_chain(m, c, r.chain);
  Outcome o;
  o.soup = &m.soup;
  o.input = c;
  if constexpr(std::is_void<Solver>::value) o.ok = r.call(m.tm, eps);
  else o.ok = r.call_solver(*solver, eps);
  o.rep = r.rep;

  const TM& tm = m.tm;
  o.W.assign(m.soup.num_faces(), kIntSentinel);
  for(Index f = 0; f < m.soup.num_faces(); ++f)
  {
    o.W[f] = r.W.at(m.face[f]);
    if(o.W[f] == kIntSentinel) ++o.unwritten_W;
  }
  for(auto e : edges(tm))
  {
    const auto ks = m.key(e);
    o.all_edges.insert(ks.first);
    const int Gv = r.G.at(e), Bv = r.B.at(e);
    const double gv = r.g.at(e);
    if(Gv == kIntSentinel) ++o.unwritten_G; else if(Gv != 0) o.G[ks.first] = Gv * ks.second;
    if(Bv == kIntSentinel) ++o.unwritten_B; else if(Bv != 0) o.B[ks.first] = Bv * ks.second;
    if(gv == kRealSentinel) ++o.unwritten_g;
    o.g[ks.first] = gv * ks.second;
    if(CGAL::is_border(e, tm))
    {
      o.border_edges.insert(ks.first);
      o.border_vertices.insert(ks.first.first);
      o.border_vertices.insert(ks.first.second);
    }
    else
    {
      auto h = m.halfedge_of(ks.first.first, ks.first.second);
      o.sides[ks.first] = {m.findex.at(face(h, tm)), m.findex.at(face(opposite(h, tm), tm))};
    }
  }
  o.w.assign(m.soup.num_faces(), {0, 0, 0});
  for(Index f = 0; f < m.soup.num_faces(); ++f)
  {
    const Triangle& t = m.soup.triangles[f];
    for(auto h : CGAL::halfedges_around_face(halfedge(m.face[f], tm), tm))
    {
      const Index v = m.vindex.at(target(h, tm));
      const int k = int(std::find(t.begin(), t.end(), v) - t.begin());
      const double val = r.w.at(h);
      if(val == kRealSentinel) ++o.unwritten_w;
      o.w[f][k] = val;
    }
  }
  return o;
}

template <class TM>
Outcome run(const Built_mesh<TM>& m, const Soup_chain& c, double eps = 0.01)
{
  return run_impl<TM, void>(m, c, eps, nullptr);
}

template <class TM, class Solver>
Outcome run_with_solver(const Built_mesh<TM>& m, Solver& solver, const Soup_chain& c, double eps = 0.01)
{
  return run_impl<TM, Solver>(m, c, eps, &solver);
}

template <class TM>
std::unique_ptr<Built_mesh<TM>> make_mesh(const Soup& s)
{
  auto m = std::make_unique<Built_mesh<TM>>();
  build(s, *m);
  return m;
}

// ------------------------------------------------------------------------------------------
// Checks shared by every successful solve
// ------------------------------------------------------------------------------------------

inline int R(double x) { return int(std::round(x)); }   // half away from zero, as the notes' R

std::string histogram(const std::vector<int>& W, const std::vector<Index>& faces)
{
  std::map<int, std::size_t> h;
  for(Index f : faces) ++h[W[f]];
  std::ostringstream os;
  for(const auto& kv : h) os << " [" << kv.first << "]x" << kv.second;
  return os.str();
}

std::vector<Index> all_faces(const Soup& s)
{
  std::vector<Index> f(s.num_faces());
  for(Index i = 0; i < f.size(); ++i) f[i] = i;
  return f;
}

// Interior endpoints of the input: vertices off the border where the boundary 0-chain is nonzero.
std::set<Index> interior_endpoints(const Outcome& o)
{
  std::set<Index> e;
  for(const auto& kv : boundary(o.input))
    if(!o.border_vertices.count(kv.first)) e.insert(kv.first);
  return e;
}

void print_diagnostics(const Outcome& o)
{
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::ostringstream os;
  os << "[diag] " << (info ? std::string(info->test_suite_name()) + "." + info->name() : std::string("?"))
     << " ok=" << o.ok << " lp_ran=" << o.rep.lp_ran << " lp_obj=" << o.rep.lp_objective
     << " ends=" << o.rep.interior_endpoints << " labels:" << histogram(o.W, all_faces(*o.soup))
     << " |G|=" << o.G.size() << " |B|=" << o.B.size();
  double gmin = 1e300, gmax = 0, wlo = 1e300, whi = -1e300;
  for(const auto& kv : o.g)
    if(std::abs(kv.second) > 1e-9) { gmin = std::min(gmin, std::abs(kv.second)); gmax = std::max(gmax, std::abs(kv.second)); }
  for(const auto& c : o.w) for(double v : c) if(std::isfinite(v)) { wlo = std::min(wlo, v); whi = std::max(whi, v); }
  os << " |g| in [" << (gmax > 0 ? gmin : 0.) << ", " << gmax << "] w in [" << wlo << ", " << whi << "]";
  std::cout << os.str() << std::endl;
}

void check_common(const Outcome& o)
{
  if(diagnostics()) print_diagnostics(o);
  ASSERT_TRUE(o.ok) << "surface_winding_numbers returned false: " << o.rep.error;
  EXPECT_TRUE(o.rep.success);
  EXPECT_TRUE(o.rep.error.empty()) << o.rep.error;
  EXPECT_EQ(o.unwritten_W, 0u) << "faces without label";
  EXPECT_EQ(o.unwritten_G, 0u) << "edges without G";
  EXPECT_EQ(o.unwritten_B, 0u) << "edges without B";
  EXPECT_EQ(o.unwritten_g, 0u) << "edges without g";
  EXPECT_EQ(o.unwritten_w, 0u) << "corners without w";
  const Soup& s = *o.soup;

  // G is the rounding of g, g is finite, and neither lives on border edges.
  std::size_t bad_round = 0, nonfinite = 0;
  std::string first_bad;
  for(const auto& kv : o.g)
  {
    if(!std::isfinite(kv.second)) { ++nonfinite; continue; }
    auto it = o.G.find(kv.first);
    const int Gv = it == o.G.end() ? 0 : it->second;
    if(Gv != R(kv.second))
    {
      if(bad_round++ == 0)
        first_bad = "edge (" + std::to_string(kv.first.first) + "," + std::to_string(kv.first.second) + ") G=" +
                    std::to_string(Gv) + " g=" + std::to_string(kv.second);
    }
  }
  EXPECT_EQ(nonfinite, 0u) << "non-finite g";
  if(o.rep.nonbounding_closing_units == 0)
    EXPECT_EQ(bad_round, 0u) << "G != R(g) on " << bad_round << " edges, first: " << first_bad;
  else   // R(g) was open and G is its closing (test_core: NonboundingChain)
    EXPECT_GT(bad_round, 0u) << "G closed by " << o.rep.nonbounding_closing_units << " units, yet G == R(g)";

  // G is closed: zero boundary at every interior vertex.
  for(const auto& kv : boundary(o.G))
    EXPECT_TRUE(o.border_vertices.count(kv.first)) << "G has boundary " << kv.second << " at interior vertex " << kv.first;
  for(const Edge_key& k : o.border_edges)
    EXPECT_EQ(o.G.count(k), 0u) << "G on border edge (" << k.first << "," << k.second << ")";

  // B is the jump of W (left minus right), zero on border edges.
  std::size_t bad_B = 0;
  std::string first_B;
  for(const auto& kv : o.sides)
  {
    const int jump = o.W[kv.second.first] - o.W[kv.second.second];
    auto it = o.B.find(kv.first);
    const int Bv = it == o.B.end() ? 0 : it->second;
    if(Bv != jump && bad_B++ == 0)
      first_B = "edge (" + std::to_string(kv.first.first) + "," + std::to_string(kv.first.second) + ") B=" +
                std::to_string(Bv) + " JW=" + std::to_string(jump);
  }
  EXPECT_EQ(bad_B, 0u) << "B != JW on " << bad_B << " edges, first: " << first_B;
  for(const Edge_key& k : o.border_edges)
    EXPECT_EQ(o.B.count(k), 0u) << "B on border edge (" << k.first << "," << k.second << ")";

  // B is closed: zero boundary at every interior vertex.
  for(const auto& kv : boundary(o.B))
    EXPECT_TRUE(o.border_vertices.count(kv.first)) << "B has boundary " << kv.second << " at interior vertex " << kv.first;

  // w: NaN exactly at the corners of interior endpoints, finite elsewhere.
  const std::set<Index> ends = interior_endpoints(o);
  std::size_t bad_nan = 0;
  for(Index f = 0; f < s.num_faces(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const bool is_end = ends.count(s.triangles[f][k]) > 0;
      const double val = o.w[f][k];
      if(is_end != std::isnan(val) || (!is_end && !std::isfinite(val))) ++bad_nan;
    }
  EXPECT_EQ(bad_nan, 0u) << "corners where (w is NaN) != (vertex is an interior endpoint); endpoints: " << ends.size();
  EXPECT_EQ(o.rep.interior_endpoints, ends.size());

  // Normalization: per connected component, the label covering the largest area is 0 (checked
  // only when that label's area beats the runner-up by 2%).
  std::map<int, std::map<int, double>> area;   // component -> label -> area
  for(Index f = 0; f < s.num_faces(); ++f) area[s.fcomponent[f]][o.W[f]] += triangle_area(s, f);
  for(const auto& ca : area)
  {
    std::vector<std::pair<double, int>> v;
    for(const auto& la : ca.second) v.push_back({la.second, la.first});
    std::sort(v.rbegin(), v.rend());
    if(v.size() == 1 || v[0].first > 1.02 * v[1].first)
    {
      EXPECT_EQ(v[0].second, 0) << "component " << ca.first << ": largest-area label is " << v[0].second;
    }
  }
}

// For closed curves (no interior endpoints): B = chain - G on curve edges and 0 elsewhere, and G
// lives on curve edges only.
void check_closed_decomposition(const Outcome& o)
{
  ASSERT_TRUE(interior_endpoints(o).empty()) << "test bug: curve is not closed";
  for(const auto& kv : o.G)
    EXPECT_TRUE(o.input.count(kv.first)) << "G off the curve at (" << kv.first.first << "," << kv.first.second << ")";
  const Soup_chain expected_B = difference(o.input, o.G);
  Soup_chain B_on_curve, B_off_curve;
  for(const auto& kv : o.B) (o.input.count(kv.first) ? B_on_curve : B_off_curve)[kv.first] = kv.second;
  EXPECT_TRUE(B_off_curve.empty()) << "B off the curve: " << to_string(B_off_curve);
  EXPECT_TRUE(B_on_curve == expected_B) << "B on curve: " << to_string(B_on_curve) << "\nchain - G: " << to_string(expected_B);
}

// The single label of a region of faces.
::testing::AssertionResult region_label(const Outcome& o, const std::vector<Index>& faces, int& label)
{
  if(faces.empty()) return ::testing::AssertionFailure() << "empty region (test bug)";
  std::set<int> l;
  for(Index f : faces) l.insert(o.W[f]);
  if(l.size() != 1) return ::testing::AssertionFailure() << "region of " << faces.size() << " faces has several labels:" << histogram(o.W, faces);
  label = *l.begin();
  return ::testing::AssertionSuccess();
}

// W(A) - W(B) == diff, each region single-labelled; optionally absolute labels.
void expect_regions(const Outcome& o, const std::vector<Index>& A, const std::vector<Index>& B, int diff,
                    std::optional<int> abs_A = std::nullopt, std::optional<int> abs_B = std::nullopt)
{
  int a = 0, b = 0;
  ASSERT_TRUE(region_label(o, A, a)) << "(region A)";
  ASSERT_TRUE(region_label(o, B, b)) << "(region B)";
  EXPECT_EQ(a - b, diff) << "W(A)=" << a << " W(B)=" << b;
  if(abs_A) { EXPECT_EQ(a, *abs_A) << "absolute label of region A"; }
  if(abs_B) { EXPECT_EQ(b, *abs_B) << "absolute label of region B"; }
}

void expect_constant_W(const Outcome& o)
{
  int l = 0;
  EXPECT_TRUE(region_label(o, all_faces(*o.soup), l));
  EXPECT_EQ(l, 0) << "constant W must be 0 after normalization";
}

std::size_t count_labels(const Outcome& o)
{
  return std::set<int>(o.W.begin(), o.W.end()).size();
}

// w is constant on the corners of A, constant on the corners of B, and w(A) - w(B) = diff.
void expect_w_two_valued(const Outcome& o, const std::vector<Index>& A, const std::vector<Index>& B, double diff,
                         double tol)
{
  auto range = [&](const std::vector<Index>& F, double& lo, double& hi) {
    lo = std::numeric_limits<double>::infinity(); hi = -lo;
    for(Index f : F) for(double v : o.w[f]) if(!std::isnan(v)) { lo = std::min(lo, v); hi = std::max(hi, v); }
  };
  double la, ha, lb, hb;
  range(A, la, ha);
  range(B, lb, hb);
  EXPECT_LT(ha - la, tol) << "w not constant on region A: [" << la << ", " << ha << "]";
  EXPECT_LT(hb - lb, tol) << "w not constant on region B: [" << lb << ", " << hb << "]";
  EXPECT_NEAR(0.5 * (la + ha) - 0.5 * (lb + hb), diff, tol) << "w(A) - w(B)";
}

void expect_w_constant(const Outcome& o, double tol)
{
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for(const auto& c : o.w) for(double v : c) if(!std::isnan(v)) { lo = std::min(lo, v); hi = std::max(hi, v); }
  EXPECT_LT(hi - lo, tol) << "w not constant: [" << lo << ", " << hi << "]";
}

void expect_G(const Outcome& o, const Soup_chain& expected)
{
  EXPECT_TRUE(o.G == expected) << "G        = " << to_string(o.G) << "\nexpected = " << to_string(expected);
}

// g on the support of `loop` lies in [lo, hi] (relative to the loop's orientation and multiplicity).
void expect_g_on(const Outcome& o, const Soup_chain& loop, double lo, double hi)
{
  for(const auto& kv : loop)
  {
    const double ratio = o.g.at(kv.first) / kv.second;
    EXPECT_GE(ratio, lo) << "g/chain on (" << kv.first.first << "," << kv.first.second << ")";
    EXPECT_LE(ratio, hi) << "g/chain on (" << kv.first.first << "," << kv.first.second << ")";
  }
}

double max_abs_g(const Outcome& o)
{
  double m = 0;
  for(const auto& kv : o.g) m = std::max(m, std::abs(kv.second));
  return m;
}

} // namespace

#endif // SWN_TEST_ORACLES_SUPPORT_H
