// test_oracles: face selections, the solves with the checks of their kind of curve, the typed suites.
#ifndef SWN_TEST_ORACLES_CASES_H
#define SWN_TEST_ORACLES_CASES_H

#include "test_oracles_support.h"

namespace {

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

// Helpers of the suites (disk, torus, annulus, sphere, metamorphic checks, bad input)

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

namespace {
// the chain c on the second component of combine(a, b), whose vertices come `offset` later
Soup_chain shifted(const Soup_chain& c, Index offset)
{
  Soup_chain r;
  for(const auto& kv : c) r[{kv.first.first + offset, kv.first.second + offset}] = kv.second;
  return r;
}
} // namespace

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

#endif // SWN_TEST_ORACLES_CASES_H
