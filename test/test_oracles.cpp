// End-to-end analytic oracle tests for CGAL::surface_winding_numbers (algorithm notes, section 10).
//
// Every oracle runs on CGAL::Surface_mesh and on CGAL::Polyhedron_3 (typed tests), mostly on
// jittered meshes with random diagonals. Results are converted to "soup terms" (labels per
// soup triangle, chains keyed by soup vertex pairs) so that expectations are written once,
// independently of the data structure and of its edge orientation.
//
// Conventions (section 1 of the notes): a chain value counts traversals along a -> b; W increases
// by chain(e) when crossing e from its right to its left (the inside of a CCW loop is one higher);
// per connected component, the label covering the largest area is 0.
//
// Every successful solve goes through check_common(): all outputs written; G == R(g) on every
// edge unless the report says R(g) had to be closed; G closed at interior vertices; no G or B on
// border edges; B == JW (left minus right label) on interior edges, hence B closed at interior
// vertices; w NaN exactly at the corners of interior endpoints; report.interior_endpoints;
// largest-area label 0 in every component. Closed curves also go through
// check_closed_decomposition(): B = chain - G on curve edges, 0 elsewhere.
//
// Suites (typed on both data structures unless noted): OraclesGenerators, OraclesDisk (D*),
// OraclesTorus (T*), OraclesAnnulus (A*), OraclesSphere, OraclesTwoComponents, OraclesMetamorphic
// (reversal, multiplicity, similarity x1e3 / x1e-3, far loop, renumbering, data structures),
// OraclesApi (solver class, chain helpers), OraclesSurfaceMesh (not typed: native maps, garbage),
// OraclesBadInput, OraclesHarness (not typed: the checks themselves can fail). The checks of each
// kind of curve are written once: expect_closed_bounding(), expect_closed_nonbounding(),
// expect_completed_nonbounding(), expect_open_curve().
//
// Environment: SWN_ORACLE_SEED_OFFSET=k runs everything on other random meshes;
// SWN_ORACLE_DIAG=1 prints one line of diagnostics per solve.

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

// ------------------------------------------------------------------------------------------
// Face selections (parameter space, grid units)
// ------------------------------------------------------------------------------------------

std::vector<Index> select(const Soup& s, const std::function<bool(double, double, int)>& pred)
{
  std::vector<Index> r;
  for(Index f = 0; f < s.num_faces(); ++f)
    if(pred(s.fparam[f][0], s.fparam[f][1], s.fcomponent[f])) r.push_back(f);
  return r;
}

inline double pdist(double a, double b, double period)
{
  double d = std::abs(a - b);
  if(period > 0) d = std::min(d, period - d);
  return d;
}

// A condition on a face's centre (x, y) in grid units and its component k; empty: every face.
using Face_filter = std::function<bool(double, double, int)>;

// Faces whose centre is farther than r (Chebyshev distance, grid units) from every point of `centres`.
Face_filter far_from(std::vector<Param> centres, double r, double px = 0, double py = 0)
{
  return [=](double x, double y, int) {
    for(const Param& c : centres)
      if(pdist(x, c[0], px) <= r && pdist(y, c[1], py) <= r) return false;
    return true;
  };
}

// Faces of component k.
Face_filter component(int k)
{
  return [k](double, double, int c) { return c == k; };
}

// Rectangle [x0,x1] x [y0,y1] in grid units, for cell centres.
inline bool in_rect(double x, double y, double x0, double y0, double x1, double y1)
{
  return x > x0 && x < x1 && y > y0 && y < y1;
}

// The faces (that `keep` accepts) whose centre lies inside, or outside, the rectangle (x0,y0)-(x1,y1).
std::vector<Index> inside_rect(const Soup& s, double x0, double y0, double x1, double y1, const Face_filter& keep = nullptr)
{
  return select(s, [&](double x, double y, int k) { return in_rect(x, y, x0, y0, x1, y1) && (!keep || keep(x, y, k)); });
}
std::vector<Index> outside_rect(const Soup& s, double x0, double y0, double x1, double y1, const Face_filter& keep = nullptr)
{
  return select(s, [&](double x, double y, int k) { return !in_rect(x, y, x0, y0, x1, y1) && (!keep || keep(x, y, k)); });
}

// Both conditions.
Face_filter both(Face_filter a, Face_filter b)
{
  return [=](double x, double y, int k) { return a(x, y, k) && b(x, y, k); };
}

// ------------------------------------------------------------------------------------------
// Solves with the checks of their kind of curve (notes 10.2)
// ------------------------------------------------------------------------------------------

// run() and the checks every successful solve passes.
template <class TM>
Outcome checked_run(const Built_mesh<TM>& m, const Soup_chain& c, double eps = 0.01)
{
  Outcome o = run(m, c, eps);
  check_common(o);
  return o;
}

// A closed curve (no interior endpoint, ends on the border allowed): B = chain - G too.
template <class TM>
Outcome closed_run(const Built_mesh<TM>& m, const Soup_chain& c)
{
  Outcome o = checked_run(m, c);
  check_closed_decomposition(o);
  return o;
}

// A closed curve that bounds: regions A and B single-labelled, W(A) - W(B) = diff (with the absolute
// labels when given), no other label, G = 0, w two-valued with the same step (to kTolWLP on the LP
// path, kTolW otherwise).
template <class TM>
Outcome expect_closed_bounding(const Built_mesh<TM>& m, const Soup_chain& c, const std::vector<Index>& A,
                               const std::vector<Index>& B, int diff, std::optional<int> abs_A = std::nullopt,
                               std::optional<int> abs_B = std::nullopt)
{
  Outcome o = closed_run(m, c);
  expect_regions(o, A, B, diff, abs_A, abs_B);
  EXPECT_EQ(count_labels(o), 2u);
  expect_G(o, {});
  expect_w_two_valued(o, A, B, diff, o.rep.lp_ran ? kTolWLP : kTolW);
  return o;
}

// A closed curve that bounds nothing (T1-T4, T11, A1): W constant, G = the curve, g = the curve (to
// kTolG), w constant (to kTolWLP), through the LP.
template <class TM>
Outcome expect_closed_nonbounding(const Built_mesh<TM>& m, const Soup_chain& c)
{
  Outcome o = closed_run(m, c);
  expect_constant_W(o);
  expect_G(o, c);
  expect_g_on(o, c, 1 - kTolG, 1 + kTolG);
  expect_w_constant(o, kTolWLP);
  EXPECT_TRUE(o.rep.lp_ran);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
  return o;
}

// A curve with gaps that bounds nothing (T8, T10, T13, A4): W constant, G = the completed curve, g
// on it in [g_lo, g_hi], `endpoints` interior endpoints.
template <class TM>
Outcome expect_completed_nonbounding(const Built_mesh<TM>& m, const Soup_chain& c, const Soup_chain& completed,
                                     double g_lo, double g_hi, std::size_t endpoints)
{
  Outcome o = checked_run(m, c);
  expect_constant_W(o);
  expect_G(o, completed);
  expect_g_on(o, completed, g_lo, g_hi);
  EXPECT_EQ(o.rep.interior_endpoints, endpoints);
  return o;
}

// A curve with gaps: regions A and B (kept away from the gaps) single-labelled with W(A) - W(B) =
// diff (and the absolute labels when given), G as expected, `endpoints` interior endpoints.
template <class TM>
Outcome expect_open_curve(const Built_mesh<TM>& m, const Soup_chain& c, const std::vector<Index>& A,
                          const std::vector<Index>& B, int diff, std::optional<int> abs_A, std::optional<int> abs_B,
                          const Soup_chain& G, std::size_t endpoints)
{
  Outcome o = checked_run(m, c);
  expect_regions(o, A, B, diff, abs_A, abs_B);
  expect_G(o, G);
  EXPECT_EQ(o.rep.interior_endpoints, endpoints);
  return o;
}

struct Mesh_names
{
  template <class T>
  static std::string GetName(int)
  {
    if(std::is_same<T, SM>::value) return "Surface_mesh";
    if(std::is_same<T, PH>::value) return "Polyhedron_3";
    return "unknown";
  }
};

} // namespace

// ==========================================================================================
// Typed suites: every oracle on Surface_mesh and on Polyhedron_3
// ==========================================================================================

template <class TM>
class Oracles : public ::testing::Test
{
};
using Mesh_types = ::testing::Types<SM, PH>;

// One suite per surface (and for the metamorphic checks, the API, bad input), all typed on Mesh_types.
template <class TM> using OraclesGenerators = Oracles<TM>;
template <class TM> using OraclesDisk = Oracles<TM>;
template <class TM> using OraclesTorus = Oracles<TM>;
template <class TM> using OraclesAnnulus = Oracles<TM>;
template <class TM> using OraclesSphere = Oracles<TM>;
template <class TM> using OraclesTwoComponents = Oracles<TM>;
template <class TM> using OraclesMetamorphic = Oracles<TM>;
template <class TM> using OraclesApi = Oracles<TM>;
template <class TM> using OraclesBadInput = Oracles<TM>;
TYPED_TEST_SUITE(OraclesGenerators, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesDisk, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesTorus, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesAnnulus, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesSphere, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesTwoComponents, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesMetamorphic, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesApi, Mesh_types, Mesh_names);
TYPED_TEST_SUITE(OraclesBadInput, Mesh_types, Mesh_names);

// ------------------------------------------------------------------------------------------
// Generators sanity (the oracles are only as good as the meshes)
// ------------------------------------------------------------------------------------------

TYPED_TEST(OraclesGenerators, ProduceValidOrientedMeshes)
{
  const Soup disk = make_disk(kDiskN, seed(3)), ann = make_annulus(kNr, kNt, seed(3)), tor = make_torus(kNu, kNv, seed(3)),
             sph = make_uv_sphere(kLat, kLon, seed(3));
  EXPECT_GT(min_signed_xy_area(disk), 0.);
  EXPECT_GT(min_signed_xy_area(ann), 0.);
  EXPECT_GT(min_outward_ratio_sphere(sph), 0.5);
  struct Case { const Soup* s; long chi; bool closed; std::size_t F; };
  for(const Case& c : {Case{&disk, 1, false, 800}, Case{&ann, 0, false, 768}, Case{&tor, 0, true, 576},
                       Case{&sph, 2, true, 528}})
  {
    auto m = make_mesh<TypeParam>(*c.s);
    EXPECT_TRUE(m->vertex_order_preserved);
    EXPECT_TRUE(m->face_order_preserved);
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m->tm));
    EXPECT_TRUE(CGAL::is_triangle_mesh(m->tm));
    EXPECT_EQ(CGAL::is_closed(m->tm), c.closed);
    EXPECT_EQ(num_faces(m->tm), c.F);
    EXPECT_EQ(long(num_vertices(m->tm)) - long(num_edges(m->tm)) + long(num_faces(m->tm)), c.chi);
    for(Index v = 0; v < c.s->num_vertices(); ++v)
      EXPECT_EQ(get(CGAL::vertex_point, m->tm, m->vertex[v]), c.s->points[v]);
  }
}

// ==========================================================================================
// Disk (simply connected: one solve, no LP)
// ==========================================================================================

namespace {
// Loop used by D1, D2, D4, D5: the 10x10-cell square (4,4)-(14,14), 25% of the disk.
std::vector<Index> d_loop() { return disk_rect_loop(kDiskN, 4, 4, 14, 14); }
std::vector<Index> d_inside(const Soup& s, const Face_filter& keep = nullptr) { return inside_rect(s, 4, 4, 14, 14, keep); }
std::vector<Index> d_outside(const Soup& s, const Face_filter& keep = nullptr) { return outside_rect(s, 4, 4, 14, 14, keep); }
Soup_chain loop_chain(const std::vector<Index>& loop, int mult = 1)
{
  Soup_chain c;
  add_loop(c, loop, mult);
  return c;
}
Soup_chain path_chain(const std::vector<Index>& path)
{
  Soup_chain c;
  add_path(c, path);
  return c;
}
// the two pieces of a path with a gap (path_with_gap)
Soup_chain pieces_chain(const std::pair<std::vector<Index>, std::vector<Index>>& pieces)
{
  Soup_chain c;
  add_path(c, pieces.first);
  add_path(c, pieces.second);
  return c;
}
// D1 with a gap of `gap` edges of the bottom side starting at (8,4)
Soup_chain d_loop_with_gap(std::size_t gap) { return path_chain(loop_with_gap(d_loop(), 4, gap)); }
} // namespace

TYPED_TEST(OraclesDisk, D1_ClosedCCWLoop)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(11)));
  const Soup_chain c = loop_chain(d_loop());
  const Outcome o = expect_closed_bounding(*m, c, d_inside(m->soup), d_outside(m->soup), +1, 1, 0);
  EXPECT_TRUE(o.B == c) << to_string(o.B);
  EXPECT_LT(max_abs_g(o), 1e-12);
  EXPECT_FALSE(o.rep.lp_ran);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
}

TYPED_TEST(OraclesDisk, D1_RegularMeshNoJitter)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(11), 0.0, false));
  expect_closed_bounding(*m, loop_chain(d_loop()), d_inside(m->soup), d_outside(m->soup), +1, 1, 0);
}

TYPED_TEST(OraclesDisk, D2_ReversedLoop)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(12)));
  const Outcome o = expect_closed_bounding(*m, loop_chain(reversed(d_loop())), d_inside(m->soup), d_outside(m->soup), -1, -1, 0);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, D3_LoopEnclosingMostOfTheDisk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(13)));
  // 256 of 400 cells; normalization: the inside covers the largest area, so it is 0 and the outside is -1
  const Outcome o = expect_closed_bounding(*m, loop_chain(disk_rect_loop(kDiskN, 2, 2, 18, 18)), inside_rect(m->soup, 2, 2, 18, 18),
                                           outside_rect(m->soup, 2, 2, 18, 18), +1, 0, -1);
  EXPECT_FALSE(o.rep.lp_ran);
}

namespace {
template <class TM>
void disk_gap_case(std::size_t gap, unsigned seed)
{
  auto m = make_mesh<TM>(make_disk(kDiskN, seed));
  const Soup_chain c = d_loop_with_gap(gap);
  ASSERT_EQ(boundary(c).size(), 2u);
  const auto away = far_from({{8 + 0.5 * gap, 4}}, 0.5 * gap + 2.0);   // from the gap's midpoint
  const Outcome o = expect_open_curve(*m, c, d_inside(m->soup, away), d_outside(m->soup, away), +1, 1, 0, {}, 2);
  EXPECT_EQ(count_labels(o), 2u) << histogram(o.W, all_faces(m->soup));
  EXPECT_LT(max_abs_g(o), 1e-12);
  EXPECT_FALSE(o.rep.lp_ran);
}

std::vector<Index> left_of(const Soup& s, double x0, const Face_filter& keep = nullptr)
{
  return select(s, [&](double x, double y, int k) { return x < x0 && (!keep || keep(x, y, k)); });
}
std::vector<Index> right_of(const Soup& s, double x0, const Face_filter& keep = nullptr)
{
  return select(s, [&](double x, double y, int k) { return x > x0 && (!keep || keep(x, y, k)); });
}
} // namespace

TYPED_TEST(OraclesDisk, D4_LoopWithOneEdgeGap) { disk_gap_case<TypeParam>(1, 14); }
TYPED_TEST(OraclesDisk, D5_LoopWithThreeEdgeGap) { disk_gap_case<TypeParam>(3, 15); }

TYPED_TEST(OraclesDisk, D6_ChordBoundaryToBoundary)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(16)));
  const Soup_chain c = path_chain(disk_vertical_path(kDiskN, 10, 0, kDiskN));   // going up at x = 1/2
  // ends on the border: counts as closed
  const Outcome o = expect_closed_bounding(*m, c, left_of(m->soup, 10), right_of(m->soup, 10), +1);
  EXPECT_TRUE(o.B == c) << to_string(o.B);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, D6_ChordDownwardsAndOffCentre)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(17)));
  // going down at x = 0.3: left is x > 0.3, which covers 70% of the area
  expect_closed_bounding(*m, path_chain(disk_vertical_path(kDiskN, 6, kDiskN, 0)), right_of(m->soup, 6), left_of(m->soup, 6), +1, 0, -1);
}

TYPED_TEST(OraclesDisk, D7_ChordWithTwoEdgeGap)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(18)));
  const Soup_chain c = pieces_chain(path_with_gap(disk_vertical_path(kDiskN, 10, 0, kDiskN), 9, 2));   // gap (10,9)-(10,11)
  const auto away = far_from({{10, 10}}, 3.0);
  const Outcome o = expect_open_curve(*m, c, left_of(m->soup, 10, away), right_of(m->soup, 10, away), +1, std::nullopt,
                                      std::nullopt, {}, 2);
  EXPECT_EQ(count_labels(o), 2u);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesDisk, NestedLoops)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(19)));
  const Soup_chain c = sum(loop_chain(disk_rect_loop(kDiskN, 3, 3, 13, 13)), loop_chain(disk_rect_loop(kDiskN, 6, 6, 10, 10)));
  const Outcome o = closed_run(*m, c);
  const auto ring = inside_rect(m->soup, 3, 3, 13, 13, [](double x, double y, int) { return !in_rect(x, y, 6, 6, 10, 10); });
  expect_regions(o, inside_rect(m->soup, 6, 6, 10, 10), ring, +1, 2, 1);
  expect_regions(o, ring, outside_rect(m->soup, 3, 3, 13, 13), +1, 1, 0);
  EXPECT_EQ(count_labels(o), 3u);
  expect_G(o, {});
  EXPECT_TRUE(o.B == c);
}

TYPED_TEST(OraclesDisk, OverlappingOppositeLoopsCrossingAtVertices)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(20)));
  // CCW and CW; they cross at (11,7) and (7,11)
  const Soup_chain c = sum(loop_chain(disk_rect_loop(kDiskN, 3, 3, 11, 11)), loop_chain(reversed(disk_rect_loop(kDiskN, 7, 7, 15, 15))));
  const Outcome o = closed_run(*m, c);
  const Face_filter inA = [](double x, double y, int) { return in_rect(x, y, 3, 3, 11, 11); };
  const Face_filter inB = [](double x, double y, int) { return in_rect(x, y, 7, 7, 15, 15); };
  const auto none = outside_rect(m->soup, 3, 3, 11, 11, [&](double x, double y, int k) { return !inB(x, y, k); });
  expect_regions(o, outside_rect(m->soup, 7, 7, 15, 15, inA), none, +1, 1, 0);   // only in A
  expect_regions(o, outside_rect(m->soup, 3, 3, 11, 11, inB), none, -1, -1, 0);   // only in B
  expect_regions(o, inside_rect(m->soup, 3, 3, 11, 11, inB), none, 0, 0, 0);      // in both
  EXPECT_EQ(count_labels(o), 3u);
  expect_G(o, {});
}

TYPED_TEST(OraclesDisk, LoopTouchingTheBorderAtAVertex)
{
  // diagonals (i,j)-(i+1,j+1) everywhere (jittered positions): the loop dips to the border
  // vertex (9,0) through the edges (9,1)-(9,0) and (9,0)-(10,1).
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(21), 0.2, false));
  std::vector<Index> l;
  for(int i = 6; i < 9; ++i) l.push_back(disk_vid(kDiskN, i, 1));
  l.push_back(disk_vid(kDiskN, 9, 1));
  l.push_back(disk_vid(kDiskN, 9, 0));
  for(int i = 10; i < 12; ++i) l.push_back(disk_vid(kDiskN, i, 1));
  for(int j = 1; j < 6; ++j) l.push_back(disk_vid(kDiskN, 12, j));
  for(int i = 12; i > 6; --i) l.push_back(disk_vid(kDiskN, i, 6));
  for(int j = 6; j > 1; --j) l.push_back(disk_vid(kDiskN, 6, j));
  const Soup_chain c = loop_chain(l);
  ASSERT_TRUE(boundary(c).empty());
  const Face_filter cell90 = [](double x, double y, int) { return x > 9 && x < 10 && y < 1; };
  const Outcome o = expect_closed_bounding(*m, c, inside_rect(m->soup, 6, 1, 12, 6),
                                           outside_rect(m->soup, 6, 1, 12, 6, [&](double x, double y, int k) { return !cell90(x, y, k); }),
                                           +1, 1, 0);
  EXPECT_TRUE(o.B == c);
  EXPECT_EQ(o.rep.interior_endpoints, 0u);
  // the triangle (9,0),(10,1),(9,1) is inside, (9,0),(10,0),(10,1) outside
  for(Index f : select(m->soup, cell90))
  {
    const Triangle& t = m->soup.triangles[f];
    const bool has_91 = std::count(t.begin(), t.end(), disk_vid(kDiskN, 9, 1)) > 0;
    EXPECT_EQ(o.W[f], has_91 ? 1 : 0);
  }
}

// ==========================================================================================
// Torus (genus 1: LP path)
// ==========================================================================================

namespace {
Soup_chain meridian(int i, int mult = 1) { return loop_chain(torus_meridian(kNu, kNv, i), mult); }
Soup_chain meridian_down(int i) { return loop_chain(reversed(torus_meridian(kNu, kNv, i))); }
Soup_chain longitude(int j) { return loop_chain(torus_longitude(kNu, kNv, j)); }
// Meridian at u-index i (upwards, or downwards) with the `gap` edges (i,j)-(i,j+1)-...-(i,j+gap) removed.
Soup_chain broken_meridian(int i, int j, std::size_t gap, bool down = false)
{
  Soup_chain c = down ? meridian_down(i) : meridian(i);
  for(std::size_t k = 0; k < gap; ++k)
    c.erase(edge_key(torus_vid(kNu, kNv, i, j + int(k)), torus_vid(kNu, kNv, i, j + int(k) + 1)));
  return c;
}
// Contractible square on the torus, CCW w.r.t. the outward normal.
Soup_chain torus_square(int i0, int j0, int i1, int j1) { return loop_chain(torus_rect_loop(kNu, kNv, i0, j0, i1, j1)); }
template <class TM>
std::unique_ptr<Built_mesh<TM>> torus(unsigned seed)
{
  return make_mesh<TM>(make_torus(kNu, kNv, seed));
}
// the band between the meridians u = 3 and u = 10 (cells 3..9), and the rest
std::vector<Index> t_band(const Soup& s, const Face_filter& keep = nullptr) { return inside_rect(s, 3, -1, 10, kNv + 1, keep); }
std::vector<Index> t_rest(const Soup& s, const Face_filter& keep = nullptr) { return outside_rect(s, 3, -1, 10, kNv + 1, keep); }
// inside and outside of torus_square(4, 3, 10, 8)
std::vector<Index> t6_inside(const Soup& s, const Face_filter& keep = nullptr) { return inside_rect(s, 4, 3, 10, 8, keep); }
std::vector<Index> t6_outside(const Soup& s, const Face_filter& keep = nullptr) { return outside_rect(s, 4, 3, 10, 8, keep); }
} // namespace

TYPED_TEST(OraclesTorus, T1_Meridian)
{
  auto m = torus<TypeParam>(seed(21));
  expect_closed_nonbounding(*m, meridian(6));
}

TYPED_TEST(OraclesTorus, T1_MeridianRegularMesh)
{
  auto m = make_mesh<TypeParam>(make_torus(kNu, kNv, seed(22), 0.0, false));
  expect_closed_nonbounding(*m, meridian(0));
}

TYPED_TEST(OraclesTorus, T2_MeridianAndLongitudeCrossing)
{
  auto m = torus<TypeParam>(seed(23));
  expect_closed_nonbounding(*m, sum(meridian(6), longitude(3)));   // cross at vertex (6,3)
}

TYPED_TEST(OraclesTorus, T3_TwoParallelMeridiansEqualSpacing)
{
  auto m = torus<TypeParam>(seed(24));
  expect_closed_nonbounding(*m, sum(meridian(0), meridian(12)));   // G: each loop x1, not one loop x2
}

TYPED_TEST(OraclesTorus, T4_TwoParallelMeridiansUnequalSpacing)
{
  auto m = torus<TypeParam>(seed(25));
  expect_closed_nonbounding(*m, sum(meridian(2), meridian(7)));
}

TYPED_TEST(OraclesTorus, T5_TwoOppositeMeridians)
{
  auto m = torus<TypeParam>(seed(26));
  // the band is to the right of both curves
  const Outcome o = expect_closed_bounding(*m, sum(meridian(3), meridian_down(10)), t_band(m->soup), t_rest(m->soup), -1, -1, 0);
  EXPECT_TRUE(o.rep.lp_ran);
}

TYPED_TEST(OraclesTorus, T6_ContractibleLoop)
{
  auto m = torus<TypeParam>(seed(27));
  const Soup_chain c = torus_square(4, 3, 10, 8);
  const Outcome o = expect_closed_bounding(*m, c, t6_inside(m->soup), t6_outside(m->soup), +1, 1, 0);
  EXPECT_TRUE(o.B == c);
  EXPECT_TRUE(o.rep.lp_ran);
  EXPECT_NEAR(o.rep.lp_objective, 0.0, 1e-6);
}

TYPED_TEST(OraclesTorus, T7_ContractibleLoopWithOneEdgeGap)
{
  auto m = torus<TypeParam>(seed(28));
  const Soup_chain c = path_chain(loop_with_gap(torus_rect_loop(kNu, kNv, 4, 3, 10, 8), 2, 1));   // gap (6,3)-(7,3)
  const auto away = far_from({{6.5, 3}}, 2.5, kNu, kNv);
  const Outcome o = expect_open_curve(*m, c, t6_inside(m->soup, away), t6_outside(m->soup, away), +1, 1, 0, {}, 2);
  EXPECT_LT(max_abs_g(o), kTolG) << "the Hodge step should remove everything";
}

TYPED_TEST(OraclesTorus, T8_MeridianWithTwoEdgeGap)
{
  auto m = torus<TypeParam>(seed(29));
  // gap (6,4)-(6,6); G: the completed loop; g ~0.91 in the notes' prototype
  const Outcome o = expect_completed_nonbounding(*m, broken_meridian(6, 4, 2), meridian(6), 0.5, 1 + kTolG, 2);
  EXPECT_TRUE(o.rep.lp_ran);
}

TYPED_TEST(OraclesTorus, T9_TwoOppositeMeridiansWithGaps)
{
  auto m = torus<TypeParam>(seed(30));
  const auto away = far_from({{3, 2.5}, {10, 8.5}}, 2.5, kNu, kNv);
  expect_open_curve(*m, sum(broken_meridian(3, 2, 1), broken_meridian(10, 8, 1, true)), t_band(m->soup, away),
                    t_rest(m->soup, away), -1, -1, 0, {}, 4);
}

TYPED_TEST(OraclesTorus, T10_TwoSameMeridiansWithGaps)
{
  auto m = torus<TypeParam>(seed(31));
  // g 0.87 .. 1 in the notes' prototype
  expect_completed_nonbounding(*m, sum(broken_meridian(0, 3, 1), broken_meridian(12, 8, 1)), sum(meridian(0), meridian(12)),
                               0.8, 1 + kTolG, 4);
}

TYPED_TEST(OraclesTorus, T11_MeridianWithMultiplicityTwo)
{
  auto m = torus<TypeParam>(seed(32));
  expect_closed_nonbounding(*m, meridian(6, 2));
}

namespace {
// T12: broken meridian at u = 0 (2-edge gap at v 4..6) + contractible square (8,3)-(14,8).
Soup_chain t12_chain()
{
  return sum(broken_meridian(0, 4, 2), torus_square(8, 3, 14, 8));
}
// regions kept >= 3 cells away from the broken meridian, in component k
Face_filter t12_away(int k = 0)
{
  return [k](double x, double, int c) { return c == k && x > 3 && x < kNu - 3; };
}
std::vector<Index> t12_inside(const Soup& s, int k = 0) { return inside_rect(s, 8, 3, 14, 8, component(k)); }
std::vector<Index> t12_outside(const Soup& s, int k = 0) { return outside_rect(s, 8, 3, 14, 8, t12_away(k)); }
} // namespace

TYPED_TEST(OraclesTorus, T12_BrokenMeridianPlusContractibleLoop)
{
  auto m = torus<TypeParam>(seed(33));
  const Outcome o = expect_open_curve(*m, t12_chain(), t12_inside(m->soup), t12_outside(m->soup), +1, 1, 0, meridian(0), 2);
  EXPECT_TRUE(o.rep.lp_ran);
}

// T13: a meridian with a 5-edge gap on this mesh leaves g about 1/2 along the whole loop (0.5007 on
// the curve, 0.498 in the gap), so round(g) keeps the curve and drops the gap: an open chain. G is
// its closing (test_core: NonboundingChain): the completed meridian, the closed chain nearest to g
// with the curve's edges weighted twice (dropping the whole curve is the other closing, and the
// nearer one if every edge counted the same).
TYPED_TEST(OraclesTorus, T13_MeridianWhoseRoundingIsOpen)
{
  if(seed(2) != 2) GTEST_SKIP() << "the open rounding is a property of this one mesh";
  auto m = torus<TypeParam>(seed(2));
  const Outcome o = expect_completed_nonbounding(*m, broken_meridian(6, 2, 5), meridian(6), 0.45, 0.55, 2);
  EXPECT_EQ(o.rep.nonbounding_closing_units, 1u);
}

// ==========================================================================================
// Annulus (relative homology: LP path)
// ==========================================================================================

namespace {
Soup_chain radial(int t, int k0 = 0, int k1 = kNr) { return path_chain(annulus_radial_path(kNr, kNt, t, k0, k1)); }
Soup_chain core_circle(int k = kNr / 2, int t0 = 0) { return loop_chain(annulus_circle_loop(kNr, kNt, k, t0)); }
// the radial arc at t = 0 with a gap at k = 3..5
Soup_chain broken_radial() { return pieces_chain(path_with_gap(annulus_radial_path(kNr, kNt, 0, 0, kNr), 3, 2)); }
std::vector<Index> inner_ring(const Soup& s) { return select(s, [](double k, double, int) { return k < kNr / 2; }); }
std::vector<Index> outer_ring(const Soup& s) { return select(s, [](double k, double, int) { return k > kNr / 2; }); }
template <class TM>
std::unique_ptr<Built_mesh<TM>> annulus(unsigned seed)
{
  return make_mesh<TM>(make_annulus(kNr, kNt, seed));
}
} // namespace

TYPED_TEST(OraclesAnnulus, A1_RadialArcInnerToOuter)
{
  auto m = annulus<TypeParam>(seed(41));
  expect_closed_nonbounding(*m, radial(0));
}

TYPED_TEST(OraclesAnnulus, A2_CoreCircle)
{
  auto m = annulus<TypeParam>(seed(42));
  // outer ring is larger (0.4375 pi vs 0.3125 pi)
  expect_closed_bounding(*m, core_circle(), inner_ring(m->soup), outer_ring(m->soup), +1, 1, 0);
}

TYPED_TEST(OraclesAnnulus, A3_ArcCuttingOffACap)
{
  auto m = annulus<TypeParam>(seed(43));
  Soup_chain c;
  add_path(c, annulus_radial_path(kNr, kNt, 10, kNr, 6));       // inwards from the outer border
  add_path(c, annulus_circle_path(kNr, kNt, 6, 10, 16));         // CCW along k = 6
  add_path(c, annulus_radial_path(kNr, kNt, 16, 6, kNr));        // back out
  // the cap is to the right of the curve
  expect_closed_bounding(*m, c, inside_rect(m->soup, 6, 10, kNr, 16), outside_rect(m->soup, 6, 10, kNr, 16), -1, -1, 0);
}

TYPED_TEST(OraclesAnnulus, A4_RadialArcWithTwoEdgeGap)
{
  auto m = annulus<TypeParam>(seed(44));
  expect_completed_nonbounding(*m, broken_radial(), radial(0), 0.5, 1 + kTolG, 2);   // g ~0.80 in the notes' prototype
}

TYPED_TEST(OraclesAnnulus, A5_TwoOppositeRadialArcs)
{
  auto m = annulus<TypeParam>(seed(45));
  // out at t = 0, back in at t = 12
  expect_closed_bounding(*m, sum(radial(0), radial(12, kNr, 0)), select(m->soup, [](double, double t, int) { return t < 12; }),
                         select(m->soup, [](double, double t, int) { return t > 12; }), +1, 1, 0);
}

TYPED_TEST(OraclesAnnulus, A6_RadialArcPlusCoreCircleSharingAVertex)
{
  auto m = annulus<TypeParam>(seed(46));
  const Outcome o = closed_run(*m, sum(radial(0), core_circle(kNr / 2, 0)));   // share vertex (4, 0)
  expect_regions(o, inner_ring(m->soup), outer_ring(m->soup), +1, 1, 0);
  EXPECT_EQ(count_labels(o), 2u);
  expect_G(o, radial(0));   // the arc only
}

// ==========================================================================================
// Sphere (closed, genus 0: one solve) and two components
// ==========================================================================================

TYPED_TEST(OraclesSphere, LatitudeLoop)
{
  auto m = make_mesh<TypeParam>(make_uv_sphere(kLat, kLon, seed(51)));
  // polar angle 60 deg: the cap is 25% of the area
  const Outcome o = expect_closed_bounding(*m, loop_chain(sphere_ring(kLat, kLon, 4)), select(m->soup, [](double, double p, int) { return p < 4; }),
                                           select(m->soup, [](double, double p, int) { return p > 4; }), +1, 1, 0);
  EXPECT_FALSE(o.rep.lp_ran);
}

TYPED_TEST(OraclesSphere, BrokenLatitudeLoop)
{
  auto m = make_mesh<TypeParam>(make_uv_sphere(kLat, kLon, seed(52)));
  const auto away = far_from({{6, 6}}, 3.0, kLon);
  const auto north = select(m->soup, [&](double q, double p, int k) { return p < 6 && away(q, p, k); });
  const auto south = select(m->soup, [&](double q, double p, int k) { return p > 6 && away(q, p, k); });
  // equator, gap q = 5..7
  const Outcome o = expect_open_curve(*m, path_chain(loop_with_gap(sphere_ring(kLat, kLon, 6), 5, 2)), north, south, +1,
                                      std::nullopt, std::nullopt, {}, 2);
  EXPECT_FALSE(o.rep.lp_ran);
}

namespace {
// the chain c on the second component of combine(a, b), whose vertices come `offset` later
Soup_chain shifted(const Soup_chain& c, Index offset)
{
  Soup_chain r;
  for(const auto& kv : c) r[{kv.first.first + offset, kv.first.second + offset}] = kv.second;
  return r;
}
} // namespace

TYPED_TEST(OraclesTwoComponents, EachNormalizedIndependently)
{
  const int n = 12;
  auto m = make_mesh<TypeParam>(combine(make_disk(n, seed(61)), make_disk(n, seed(62)), 2.0, 0, 0));
  // component 0: small CCW loop; component 1: CCW loop enclosing 69%
  const Outcome o = closed_run(*m, sum(loop_chain(disk_rect_loop(n, 3, 3, 7, 7)),
                                       shifted(loop_chain(disk_rect_loop(n, 1, 1, 11, 11)), Index(n + 1) * Index(n + 1))));
  expect_regions(o, inside_rect(m->soup, 3, 3, 7, 7, component(0)), outside_rect(m->soup, 3, 3, 7, 7, component(0)), +1, 1, 0);
  expect_regions(o, inside_rect(m->soup, 1, 1, 11, 11, component(1)), outside_rect(m->soup, 1, 1, 11, 11, component(1)), +1, 0, -1);
  expect_G(o, {});
  EXPECT_EQ(o.rep.components, 2u);
}

TYPED_TEST(OraclesTwoComponents, TorusAndDisk)
{
  auto m = make_mesh<TypeParam>(combine(make_torus(kNu, kNv, seed(63)), make_disk(10, seed(64)), 3.0, 0, 0));
  // a meridian, and a CW loop on the disk
  const Outcome o = closed_run(*m, sum(meridian(6), shifted(loop_chain(reversed(disk_rect_loop(10, 2, 2, 5, 5))), Index(kNu) * Index(kNv))));
  int lt = 0;
  EXPECT_TRUE(region_label(o, select(m->soup, component(0)), lt));
  EXPECT_EQ(lt, 0);
  expect_regions(o, inside_rect(m->soup, 2, 2, 5, 5, component(1)), outside_rect(m->soup, 2, 2, 5, 5, component(1)), -1, -1, 0);
  expect_G(o, meridian(6));
}

TYPED_TEST(OraclesTwoComponents, BrokenLoopsOnTwoTori)
{
  // two tori, each with a broken meridian and a contractible loop: endpoints, Hodge step and LP
  // on a disconnected mesh. On the second torus the curve is reversed, so its inside is -1.
  auto m = make_mesh<TypeParam>(combine(make_torus(kNu, kNv, seed(65)), make_torus(kNu, kNv, seed(66)), 4.0, 0, 0));
  const Index off = Index(kNu) * Index(kNv);
  const Outcome o = checked_run(*m, sum(t12_chain(), shifted(scaled(t12_chain(), -1), off)));
  expect_regions(o, t12_inside(m->soup, 0), t12_outside(m->soup, 0), +1, 1, 0);
  expect_regions(o, t12_inside(m->soup, 1), t12_outside(m->soup, 1), -1, -1, 0);
  expect_G(o, sum(meridian(0), shifted(scaled(meridian(0), -1), off)));
  EXPECT_EQ(o.rep.interior_endpoints, 4u);
  EXPECT_TRUE(o.rep.lp_ran);
}

// ==========================================================================================
// Metamorphic checks
// ==========================================================================================

namespace {
// W(f) - W(ref) over a set of faces
std::vector<int> differences(const Outcome& o, const std::vector<Index>& F)
{
  std::vector<int> d;
  for(Index f : F) d.push_back(o.W[f] - o.W[F.front()]);
  return d;
}
std::vector<int> negated(std::vector<int> v)
{
  for(int& x : v) x = -x;
  return v;
}
std::vector<Index> concat(std::vector<Index> a, const std::vector<Index>& b)
{
  a.insert(a.end(), b.begin(), b.end());
  return a;
}
// g of `b` equal to `factor` times g of `a` on every edge, to tol
void expect_g_scaled(const Outcome& a, const Outcome& b, double factor, double tol)
{
  for(const auto& kv : a.g) EXPECT_NEAR(b.g.at(kv.first), factor * kv.second, tol);
}
} // namespace

TYPED_TEST(OraclesMetamorphic, ReversalNegatesWDifferencesAndG_Torus)
{
  auto m = torus<TypeParam>(seed(71));
  const Soup_chain c = t12_chain();
  const Outcome o = checked_run(*m, c), r = checked_run(*m, scaled(c, -1));
  const auto F = concat(t12_inside(m->soup), t12_outside(m->soup));
  EXPECT_EQ(differences(r, F), negated(differences(o, F)));
  expect_regions(r, t12_inside(m->soup), t12_outside(m->soup), -1, -1, 0);
  expect_G(r, scaled(o.G, -1));
  expect_g_scaled(o, r, -1, kTolG);
}

TYPED_TEST(OraclesMetamorphic, ReversalNegatesWDifferences_Disk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(72)));
  const Soup_chain c = d_loop_with_gap(2);
  const Outcome o = checked_run(*m, c), r = checked_run(*m, scaled(c, -1));
  const auto F = select(m->soup, far_from({{9, 4}}, 3.0));
  EXPECT_EQ(differences(r, F), negated(differences(o, F)));
  // w is linear in the chain (single solve): w_r + w_o is constant
  double lo = 1e300, hi = -1e300;
  for(Index f = 0; f < m->soup.num_faces(); ++f)
    for(int k = 0; k < 3; ++k)
      if(!std::isnan(o.w[f][k])) { lo = std::min(lo, o.w[f][k] + r.w[f][k]); hi = std::max(hi, o.w[f][k] + r.w[f][k]); }
  EXPECT_LT(hi - lo, kTolW);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_Disk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(73)));
  const Soup_chain c = loop_chain(d_loop(), 2);
  const Outcome o = expect_closed_bounding(*m, c, d_inside(m->soup), d_outside(m->soup), +2, 2, 0);
  EXPECT_TRUE(o.B == c);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_TorusLoop)
{
  auto m = torus<TypeParam>(seed(74));
  expect_closed_bounding(*m, scaled(torus_square(4, 3, 10, 8), 2), t6_inside(m->soup), t6_outside(m->soup), +2, 2, 0);
}

TYPED_TEST(OraclesMetamorphic, MultiplicityTwoDoubles_BrokenMeridian)
{
  auto m = torus<TypeParam>(seed(75));
  const Soup_chain c1 = broken_meridian(6, 4, 2);
  const Outcome o1 = checked_run(*m, c1), o2 = checked_run(*m, scaled(c1, 2));
  expect_constant_W(o2);
  expect_G(o1, meridian(6));
  expect_G(o2, meridian(6, 2));
  expect_g_scaled(o1, o2, 2, 2 * kTolG);
}

namespace {
// the same solve on two meshes of one surface whose soup faces correspond: the same labels, G and
// LP path (and g to kTolG)
void expect_same_solution(const Outcome& a, const Outcome& b)
{
  EXPECT_EQ(b.W, a.W) << "labels changed";
  expect_G(b, a.G);
  EXPECT_EQ(b.rep.lp_ran, a.rep.lp_ran);
  expect_g_scaled(a, b, 1, kTolG);
}

template <class TM>
void similarity_case(const Soup& base, const Soup_chain& c, double scale)
{
  SCOPED_TRACE("scale " + std::to_string(scale));
  auto m0 = make_mesh<TM>(base);
  auto m1 = make_mesh<TM>(transformed(base, scale, {0.3, -1.0, 0.7}, 1.1, {5 * scale, -2 * scale, 0.5 * scale}));
  expect_same_solution(checked_run(*m0, c), checked_run(*m1, c));
}
} // namespace

TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_TorusScaleUp)
{
  similarity_case<TypeParam>(make_torus(kNu, kNv, seed(76)), t12_chain(), 1e3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_TorusScaleDown)
{
  similarity_case<TypeParam>(make_torus(kNu, kNv, seed(77)), t12_chain(), 1e-3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_DiskScaleUp)
{
  similarity_case<TypeParam>(make_disk(kDiskN, seed(78)), d_loop_with_gap(1), 1e3);
}
TYPED_TEST(OraclesMetamorphic, SimilarityInvariance_AnnulusScaleDown)
{
  similarity_case<TypeParam>(make_annulus(kNr, kNt, seed(79)), sum(radial(0), core_circle()), 1e-3);
}

namespace {
// c and c + far_loop on m: the same G, expected_G; the faces inside far_loop's rectangle (x0,y0)-(x1,y1)
// one above those outside it that `keep` accepts
template <class TM>
void far_loop_case(const Built_mesh<TM>& m, const Soup_chain& c, const Soup_chain& expected_G, const Soup_chain& far_loop,
                   const std::array<double, 4>& rect, const Face_filter& keep)
{
  const Outcome o = checked_run(m, c), f = checked_run(m, sum(c, far_loop));
  expect_G(o, expected_G);
  expect_G(f, o.G);
  expect_regions(f, inside_rect(m.soup, rect[0], rect[1], rect[2], rect[3]), outside_rect(m.soup, rect[0], rect[1], rect[2], rect[3], keep),
                 +1, 1, 0);
}
} // namespace

TYPED_TEST(OraclesMetamorphic, FarBoundingLoopDoesNotChangeG_Torus)
{
  auto m = torus<TypeParam>(seed(80));
  far_loop_case(*m, broken_meridian(6, 4, 2), meridian(6), torus_square(14, 3, 19, 8), {14, 3, 19, 8},
                [](double x, double, int) { return x > 9 && x < 22; });
}

TYPED_TEST(OraclesMetamorphic, FarBoundingLoopDoesNotChangeG_Annulus)
{
  auto m = annulus<TypeParam>(seed(81));
  std::vector<Index> l;   // CCW quadrilateral in (k, t): k 2..6, t 20..26
  for(int k = 2; k < 6; ++k) l.push_back(annulus_vid(kNr, kNt, k, 20));
  for(int t = 20; t < 26; ++t) l.push_back(annulus_vid(kNr, kNt, 6, t));
  for(int k = 6; k > 2; --k) l.push_back(annulus_vid(kNr, kNt, k, 26));
  for(int t = 26; t > 20; --t) l.push_back(annulus_vid(kNr, kNt, 2, t));
  far_loop_case(*m, broken_radial(), radial(0), loop_chain(l), {2, 20, 6, 26}, [](double, double t, int) { return t > 4 && t < 44; });
}

namespace {
template <class TM>
void permutation_case(const Soup& base, const Soup_chain& c, unsigned pseed)
{
  const Permuted_soup p = permuted(base, pseed);
  Soup_chain pc;
  for(const auto& kv : c) add_segment(pc, p.new_vertex[kv.first.first], p.new_vertex[kv.first.second], kv.second);
  auto m0 = make_mesh<TM>(base);
  auto m1 = make_mesh<TM>(p.soup);
  // the generated mesh is numbered coherently and keeps its order in the solver's tables; the permuted
  // one is scattered and renumbered (locality_order.h), so both paths are compared below
  EXPECT_TRUE(SWN::Surface_winding_numbers_solver<TM>(m0->tm).tables().input_face.empty());
  EXPECT_FALSE(SWN::Surface_winding_numbers_solver<TM>(m1->tm).tables().input_face.empty());
  const Outcome o0 = checked_run(*m0, c), o1 = checked_run(*m1, pc);
  std::size_t differing = 0;
  for(Index f = 0; f < base.num_faces(); ++f)
    if(o1.W[p.new_face[f]] != o0.W[f]) ++differing;
  EXPECT_EQ(differing, 0u) << "labels changed when renumbering vertices and faces";
  Soup_chain G1;   // G of the permuted run, in the original numbering
  std::vector<Index> old_vertex(p.new_vertex.size());
  for(Index i = 0; i < p.new_vertex.size(); ++i) old_vertex[p.new_vertex[i]] = i;
  for(const auto& kv : o1.G) add_segment(G1, old_vertex[kv.first.first], old_vertex[kv.first.second], kv.second);
  expect_G(o0, G1);
}
} // namespace

TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Torus)
{
  permutation_case<TypeParam>(make_torus(kNu, kNv, seed(83)), t12_chain(), 1);
}
TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Disk)
{
  permutation_case<TypeParam>(make_disk(kDiskN, seed(84)), d_loop_with_gap(2), 2);
}
TYPED_TEST(OraclesMetamorphic, RenumberingInvariance_Annulus)
{
  permutation_case<TypeParam>(make_annulus(kNr, kNt, seed(85)), sum(core_circle(), broken_radial()), 3);
}

TYPED_TEST(OraclesMetamorphic, MeshStructuresAgree)
{
  // Same soup through the other data structure gives identical labels and G.
  const Soup s = make_torus(kNu, kNv, seed(82));
  auto a = make_mesh<TypeParam>(s);
  auto b = make_mesh<SM>(s);
  const Outcome oa = checked_run(*a, t12_chain()), ob = checked_run(*b, t12_chain());
  EXPECT_EQ(oa.W, ob.W);
  expect_G(oa, ob.G);
}

// ==========================================================================================
// API: solver class, chain helpers
// ==========================================================================================

TYPED_TEST(OraclesApi, SolverClassReusedForManyCurves)
{
  auto m = torus<TypeParam>(seed(91));
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const std::vector<Soup_chain> curves = {meridian(6), torus_square(4, 3, 10, 8), t12_chain(),
                                          broken_meridian(6, 4, 2), meridian(6)};
  for(std::size_t i = 0; i < curves.size(); ++i)
  {
    SCOPED_TRACE("curve " + std::to_string(i));
    Outcome s = run_with_solver(*m, solver, curves[i]);
    check_common(s);
    const Outcome f = checked_run(*m, curves[i]);
    EXPECT_EQ(s.W, f.W);
    expect_G(s, f.G);
    EXPECT_TRUE(s.B == f.B);
  }
}

TYPED_TEST(OraclesApi, SolverClassOnDisk)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(92)));
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const Soup_chain c1 = loop_chain(d_loop()), c2 = d_loop_with_gap(2);
  for(const Soup_chain* c : {&c1, &c2, &c1})
  {
    Outcome s = run_with_solver(*m, solver, *c);
    check_common(s);
    const auto away = far_from({{9, 4}}, 3.0);
    expect_regions(s, d_inside(m->soup, away), d_outside(m->soup, away), +1, 1, 0);
  }
}

TYPED_TEST(OraclesApi, ChainHelpersMatchSoupChains)
{
  using GT = boost::graph_traits<TypeParam>;
  auto m = torus<TypeParam>(seed(93));
  const std::vector<Index> loop = torus_rect_loop(kNu, kNv, 4, 3, 10, 8);
  const Soup_chain expected = sum(loop_chain(loop), meridian(6, 2));

  auto to_soup = [&](const std::unordered_map<typename GT::edge_descriptor, int>& mp) {
    Soup_chain r;
    for(const auto& kv : mp)
      if(kv.second != 0) { auto ks = m->key(kv.first); r[ks.first] = kv.second * ks.second; }
    return r;
  };
  auto zero_chain = [&] {
    std::unordered_map<typename GT::edge_descriptor, int> c;
    for(auto e : edges(m->tm)) c[e] = 0;
    return c;
  };

  // vertex polylines (closed by repeating the first vertex)
  std::unordered_map<typename GT::edge_descriptor, int> c1 = zero_chain();
  auto pm1 = boost::make_assoc_property_map(c1);
  auto closed_polyline = [&](const std::vector<Index>& l) {
    std::vector<typename GT::vertex_descriptor> pl;
    for(Index v : l) pl.push_back(m->vertex[v]);
    pl.push_back(pl.front());
    return pl;
  };
  EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m->tm, closed_polyline(loop), pm1));
  for(int k = 0; k < 2; ++k) EXPECT_TRUE(SWN::add_vertex_polyline_to_chain(m->tm, closed_polyline(torus_meridian(kNu, kNv, 6)), pm1));
  EXPECT_TRUE(to_soup(c1) == expected) << to_string(to_soup(c1)) << "\nvs " << to_string(expected);

  // non-adjacent consecutive vertices: false, nothing added
  const auto before = c1;
  std::vector<typename GT::vertex_descriptor> bad = {m->vertex[torus_vid(kNu, kNv, 0, 0)], m->vertex[torus_vid(kNu, kNv, 0, 1)],
                                                     m->vertex[torus_vid(kNu, kNv, 5, 5)]};
  EXPECT_FALSE(SWN::add_vertex_polyline_to_chain(m->tm, bad, pm1));
  EXPECT_TRUE(c1 == before);

  // halfedges: same chain; opposite halfedges cancel
  std::unordered_map<typename GT::edge_descriptor, int> c2 = zero_chain();
  auto pm2 = boost::make_assoc_property_map(c2);
  std::vector<typename GT::halfedge_descriptor> hs;
  for(std::size_t k = 0; k < loop.size(); ++k) hs.push_back(m->halfedge_of(loop[k], loop[(k + 1) % loop.size()]));
  const std::vector<Index> mer = torus_meridian(kNu, kNv, 6);
  for(int rep = 0; rep < 2; ++rep)
    for(std::size_t k = 0; k < mer.size(); ++k) hs.push_back(m->halfedge_of(mer[k], mer[(k + 1) % mer.size()]));
  auto h0 = m->halfedge_of(torus_vid(kNu, kNv, 20, 1), torus_vid(kNu, kNv, 21, 1));
  hs.push_back(h0);
  hs.push_back(opposite(h0, m->tm));
  SWN::add_halfedges_to_chain(m->tm, hs, pm2);
  EXPECT_TRUE(to_soup(c2) == expected) << to_string(to_soup(c2));

  // and the solver gives the same result from the helper-built chain
  const Outcome o = checked_run(*m, expected);
  expect_G(o, meridian(6, 2));
  expect_regions(o, t6_inside(m->soup), t6_outside(m->soup), +1, 1, 0);
}

// ==========================================================================================
// Surface_mesh specifics: native property maps, garbage
// ==========================================================================================

TEST(OraclesSurfaceMesh, NativePropertyMaps)
{
  auto m = make_mesh<SM>(make_disk(kDiskN, seed(101)));
  SM& sm = m->tm;
  auto chain = sm.add_property_map<SM::Edge_index, int>("e:chain", 0).first;
  auto labels = sm.add_property_map<SM::Face_index, int>("f:W", kIntSentinel).first;
  auto G = sm.add_property_map<SM::Edge_index, int>("e:G", kIntSentinel).first;
  auto B = sm.add_property_map<SM::Edge_index, int>("e:B", kIntSentinel).first;
  auto g = sm.add_property_map<SM::Edge_index, double>("e:g", kRealSentinel).first;
  auto w = sm.add_property_map<SM::Halfedge_index, double>("h:w", kRealSentinel).first;
  std::vector<SM::Vertex_index> pl;
  for(Index v : d_loop()) pl.push_back(m->vertex[v]);
  pl.push_back(pl.front());
  ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(sm, pl, chain));
  SWN::Solve_report rep;
  const bool ok = CGAL::surface_winding_numbers(sm, chain, labels,
      SWN::parameters::nonbounding_chain_map(G,
      SWN::parameters::nonbounding_chain_real_map(g,
      SWN::parameters::bounding_chain_map(B,
      SWN::parameters::winding_number_map(w,
      SWN::parameters::report(std::ref(rep)))))));
  ASSERT_TRUE(ok) << rep.error;
  for(Index f = 0; f < m->soup.num_faces(); ++f)
  {
    const bool in = in_rect(m->soup.fparam[f][0], m->soup.fparam[f][1], 4, 4, 14, 14);
    EXPECT_EQ(labels[m->face[f]], in ? 1 : 0);
  }
  for(auto e : edges(sm))
  {
    EXPECT_EQ(G[e], 0);
    EXPECT_EQ(B[e], chain[e]);
  }
  for(auto h : halfedges(sm))
    if(!is_border(h, sm)) { EXPECT_FALSE(w[h] == kRealSentinel); }
}

TEST(OraclesSurfaceMesh, MeshWithGarbage)
{
  // A Surface_mesh with removed-but-not-collected elements (index holes) must give the same result.
  auto m = make_mesh<SM>(make_disk(kDiskN, seed(102)));
  const Soup_chain c = loop_chain(d_loop());
  const Outcome clean = checked_run(*m, c);
  SM& sm = m->tm;
  auto a = sm.add_vertex(Point_3(5, 5, 0)), b = sm.add_vertex(Point_3(6, 5, 0)), d = sm.add_vertex(Point_3(5, 6, 0));
  auto f = sm.add_face(a, b, d);
  ASSERT_NE(f, SM::null_face());
  CGAL::Euler::remove_face(halfedge(f, sm), sm);
  ASSERT_TRUE(sm.has_garbage());
  ASSERT_EQ(sm.number_of_faces(), m->soup.num_faces());
  const Outcome dirty = checked_run(*m, c);
  EXPECT_EQ(dirty.W, clean.W);
  expect_G(dirty, clean.G);
  for(Index i = 0; i < clean.w.size(); ++i)
    for(int k = 0; k < 3; ++k) EXPECT_NEAR(dirty.w[i][k], clean.w[i][k], kTolW);
}

// ==========================================================================================
// Bad input: false, report.error set, outputs untouched
// ==========================================================================================

namespace {
template <class TM>
void expect_rejected(Raw_maps<TM>& r, const TM& tm, const char* what)
{
  const bool ok = r.call(tm);
  EXPECT_FALSE(ok) << what << ": accepted";
  EXPECT_FALSE(r.rep.success) << what;
  EXPECT_FALSE(r.rep.error.empty()) << what << ": empty error";
  EXPECT_NE(r.rep.error, "<report not written>") << what << ": report not written";
  EXPECT_TRUE(r.outputs_untouched()) << what << ": outputs were written";
}

// the solve of the chain c on m is rejected
template <class TM>
void expect_chain_rejected(const Built_mesh<TM>& m, const Soup_chain& c, const char* what)
{
  Raw_maps<TM> r(m.tm);
  set_chain(m, c, r.chain);
  expect_rejected(r, m.tm, what);
}

// the disk (random diagonals when jittered) with vertex (i, j) moved to p, and the chain c
template <class TM>
void disk_with_a_moved_vertex_case(unsigned seed, double jitter, int i, int j, const Point_3& p, const Soup_chain& c,
                                   const char* what)
{
  auto m = make_mesh<TM>(make_disk(kDiskN, seed, jitter, jitter > 0));
  put(get(CGAL::vertex_point, m->tm), m->vertex[disk_vid(kDiskN, i, j)], p);
  expect_chain_rejected(*m, c, what);
}
} // namespace

// Faces of more than three sides are triangulated internally (issue 32): a loop around the inner 2 x 2
// cells of a 4 x 4 disk of quads (some cells cut into two triangles) gives exactly those cells label 1.
TYPED_TEST(OraclesApi, QuadAndMixedMeshesLabelWholeFaces)
{
  typedef boost::graph_traits<TypeParam> GT;
  const int n = 4;
  std::vector<Point_3> pts;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) pts.emplace_back(double(i) / n, double(j) / n, 0.);
  for(bool mixed : {false, true})
  {
    std::vector<std::vector<Index>> polygons;
    std::vector<bool> inside;
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        const Index a = disk_vid(n, i, j), b = disk_vid(n, i + 1, j), c = disk_vid(n, i + 1, j + 1), d = disk_vid(n, i, j + 1);
        const bool in = i >= 1 && i < 3 && j >= 1 && j < 3;
        if(mixed && (i + j) % 2 == 0) { polygons.push_back({a, b, c}); polygons.push_back({a, c, d}); inside.push_back(in); }
        else polygons.push_back({a, b, c, d});
        inside.push_back(in);
      }
    TypeParam tm;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polygons, tm);
    ASSERT_EQ(num_faces(tm), polygons.size());
    const std::vector<typename GT::vertex_descriptor> vd(vertices(tm).begin(), vertices(tm).end());   // soup order
    std::map<typename GT::edge_descriptor, int> chain_storage;
    for(auto e : edges(tm)) chain_storage[e] = 0;
    std::vector<typename GT::vertex_descriptor> polyline;
    const std::vector<Index> loop = disk_rect_loop(n, 1, 1, 3, 3);
    for(std::size_t k = 0; k <= loop.size(); ++k) polyline.push_back(vd[loop[k % loop.size()]]);
    auto chain = boost::make_assoc_property_map(chain_storage);
    ASSERT_TRUE(SWN::add_vertex_polyline_to_chain(tm, polyline, chain));
    std::map<typename GT::face_descriptor, int> label_storage;
    SWN::Solve_report report;
    ASSERT_TRUE(CGAL::surface_winding_numbers(tm, chain, boost::make_assoc_property_map(label_storage),
                                              SWN::parameters::report(std::ref(report)))) << report.error;
    EXPECT_EQ(report.faces, polygons.size());
    std::size_t k = 0;
    for(auto f : faces(tm)) EXPECT_EQ(label_storage[f], inside[k++] ? 1 : 0) << (mixed ? "mixed" : "quads") << ", face " << k - 1;
  }
}

TYPED_TEST(OraclesBadInput, EmptyMesh)
{
  TypeParam tm;
  Raw_maps<TypeParam> r(tm);
  expect_rejected(r, tm, "empty mesh");
}

TYPED_TEST(OraclesBadInput, ChainOnBorderEdge)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(111)));
  Soup_chain c = loop_chain(d_loop());
  add_segment(c, disk_vid(kDiskN, 3, 0), disk_vid(kDiskN, 4, 0));   // bottom border edge
  expect_chain_rejected(*m, c, "chain on a border edge");
}

TYPED_TEST(OraclesBadInput, NaNCoordinate)
{
  disk_with_a_moved_vertex_case<TypeParam>(seed(112), 0.2, 7, 7, Point_3(std::numeric_limits<double>::quiet_NaN(), 0.35, 0),
                                           loop_chain(d_loop()), "NaN coordinate");
}

TYPED_TEST(OraclesBadInput, InfiniteCoordinate)
{
  auto m = make_mesh<TypeParam>(make_torus(kNu, kNv, seed(113)));
  put(get(CGAL::vertex_point, m->tm), m->vertex[torus_vid(kNu, kNv, 3, 3)], Point_3(0, std::numeric_limits<double>::infinity(), 0));
  expect_chain_rejected(*m, meridian(6), "infinite coordinate");
}

TYPED_TEST(OraclesBadInput, ZeroAreaFace)
{
  // regular disk, every cell split along (i,j)-(i+1,j+1): moving (7,7) onto the line x = 8/n
  // makes the triangle (7,7),(8,7),(8,8) exactly degenerate.
  const double h = 1.0 / kDiskN;
  disk_with_a_moved_vertex_case<TypeParam>(seed(114), 0.0, 7, 7, Point_3(8 * h, 7.5 * h, 0),
                                           loop_chain(disk_rect_loop(kDiskN, 12, 12, 16, 16)), "zero-area face");
}

TYPED_TEST(OraclesBadInput, CoincidentVertices)
{
  const Soup disk = make_disk(kDiskN, seed(115));
  disk_with_a_moved_vertex_case<TypeParam>(seed(115), 0.2, 7, 7, disk.points[disk_vid(kDiskN, 8, 7)],
                                           loop_chain(disk_rect_loop(kDiskN, 12, 12, 16, 16)), "coincident vertices (zero-area faces)");
}

TYPED_TEST(OraclesBadInput, SolverClassReportsError)
{
  auto m = make_mesh<TypeParam>(make_disk(kDiskN, seed(116)));
  Raw_maps<TypeParam> r(m->tm);
  Soup_chain c;
  add_segment(c, disk_vid(kDiskN, 0, 3), disk_vid(kDiskN, 0, 4));   // left border edge
  set_chain(*m, c, r.chain);
  SWN::Surface_winding_numbers_solver<TypeParam> solver(m->tm);
  const bool ok = r.call_solver(solver);
  EXPECT_FALSE(ok);
  EXPECT_FALSE(r.rep.error.empty());
  EXPECT_TRUE(r.outputs_untouched());
}

// ==========================================================================================
// Self-tests of the harness: the checks above must be able to fail.
// ==========================================================================================

namespace {
// Runs f with gtest's failure reporting intercepted; true iff some failure message contains `what`.
template <class F>
bool fails_with(F f, const std::string& what)
{
  ::testing::TestPartResultArray results;
  {
    ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    f();
  }
  for(int i = 0; i < results.size(); ++i)
    if(std::string(results.GetTestPartResult(i).message()).find(what) != std::string::npos) return true;
  return false;
}
} // namespace

TEST(OraclesHarness, SoupChainRoundTripThroughMeshEdges)
{
  // set_chain (soup -> mesh, relative to the reference halfedges) and Built_mesh::key (mesh ->
  // soup) are inverse, on both data structures, for both orientations of every edge.
  auto check = [](auto& m) {
    Soup_chain c;
    add_loop(c, torus_rect_loop(kNu, kNv, 4, 3, 10, 8));
    add_loop(c, reversed(torus_meridian(kNu, kNv, 6)), 3);
    std::unordered_map<typename std::decay_t<decltype(m)>::edge_descriptor, int> mp;
    for(auto e : edges(m.tm)) mp[e] = 0;
    set_chain(m, c, mp);
    Soup_chain back;
    for(auto e : edges(m.tm))
      if(mp[e] != 0) { auto ks = m.key(e); back[ks.first] = mp[e] * ks.second; }
    EXPECT_TRUE(back == c) << to_string(back) << "\nvs " << to_string(c);
    // the reference halfedge agrees with the library's helper
    std::unordered_map<typename std::decay_t<decltype(m)>::edge_descriptor, int> lib;
    for(auto e : edges(m.tm)) lib[e] = 0;
    auto pm = boost::make_assoc_property_map(lib);
    std::vector<typename std::decay_t<decltype(m)>::halfedge_descriptor> hs;
    for(const auto& kv : c)
      for(int k = 0; k < std::abs(kv.second); ++k)
        hs.push_back(kv.second > 0 ? m.halfedge_of(kv.first.first, kv.first.second)
                                   : m.halfedge_of(kv.first.second, kv.first.first));
    SWN::add_halfedges_to_chain(m.tm, hs, pm);
    for(auto e : edges(m.tm)) EXPECT_EQ(lib[e], mp[e]);
  };
  auto a = make_mesh<SM>(make_torus(kNu, kNv, 5));
  auto b = make_mesh<PH>(make_torus(kNu, kNv, 5));
  check(*a);
  check(*b);
}

TEST(OraclesHarness, ChecksDetectCorruptedOutcomes)
{
  auto m = make_mesh<SM>(make_disk(kDiskN, 7));
  Soup_chain c;
  add_loop(c, d_loop());
  const Outcome good = run(*m, c);
  check_common(good);
  const auto in = d_inside(m->soup), out = d_outside(m->soup);

  Outcome bad = good;   // a wrong label breaks B == JW
  bad.W[in.front()] += 1;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "B != JW"));

  bad = good;   // G that is not the rounding of g
  bad.G[*good.all_edges.begin()] = 1;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "G != R(g)"));

  bad = good;   // NaN away from endpoints
  bad.w[0][0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "interior endpoint"));

  bad = good;   // a B that is not closed
  bad.B.erase(bad.B.begin());
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "interior vertex"));

  bad = good;   // normalization: shift all labels
  for(int& l : bad.W) l += 5;
  EXPECT_TRUE(fails_with([&] { check_common(bad); }, "largest-area label"));

  bad = good;   // wrong difference / wrong absolute value
  EXPECT_TRUE(fails_with([&] { expect_regions(bad, d_inside(m->soup), d_outside(m->soup), -1); }, "W(A)=1 W(B)=0"));
  EXPECT_TRUE(fails_with([&] { expect_regions(bad, d_inside(m->soup), d_outside(m->soup), 1, 2, 1); }, "absolute label"));

  bad = good;   // B = chain - G on curve edges
  bad.G = c;
  EXPECT_TRUE(fails_with([&] { check_closed_decomposition(bad); }, "chain - G"));

  bad = good;   // w not two-valued
  bad.w[in.front()][0] += 1e-3;
  EXPECT_TRUE(fails_with([&] { expect_w_two_valued(bad, d_inside(m->soup), d_outside(m->soup), 1.0, kTolW); }, "w not constant on region A"));
}
