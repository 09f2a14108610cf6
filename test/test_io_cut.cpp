// Tests of the conforming cut: the library's CGAL::Surface_winding_numbers::conforming_cut() directly (on
// Surface_mesh and Polyhedron_3), and through the swn tool's curve files (tools/swn/swn_io/conforming_cut.h).

#include "swn_io/conforming_cut.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"

#include "test_io_support.h"

#include <CGAL/Surface_winding_numbers/conforming_cut.h>
#include <CGAL/surface_winding_numbers.h>

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

// ------------------------------------------------------------------------------------------------ conforming cut

namespace {

// the cut never makes a triangle out of three collinear points
void expect_no_degenerate_triangle(const Mesh& m)
{
  for(FI f : m.faces())
  {
    const auto t = triple(m, f);
    EXPECT_FALSE(CGAL::collinear(m.point(VI(static_cast<Mesh::size_type>(t[0]))), m.point(VI(static_cast<Mesh::size_type>(t[1]))),
                                 m.point(VI(static_cast<Mesh::size_type>(t[2])))))
      << "face " << f;
  }
}

} // namespace

TEST(ConformingCut, DemoCounts)
{
  struct Case { const char* mesh; const char* curve; std::size_t v_cut, f_cut; std::size_t endpoints; bool cut; };
  for(Case c : {Case{"bunny.obj", "bunny-brokenheart.txt", 14318, 28632, 2, true},
                Case{"bunny.obj", "bunny-heart.txt", 14321, 28638, 0, true},
                Case{"double-torus.obj", "double-torus.txt", 3070 + 87, 6318, 0, true},
                Case{"annulus.obj", "annulus.txt", 3649, 7104, 2, false}})
  {
    Mesh m;
    IO::read_mesh(demo + c.mesh, m);
    IO::Curve_set cs = IO::read_curve_file(demo + c.curve, m);
    auto r = IO::conforming_cut(m, cs);
    EXPECT_EQ(r.cut, c.cut) << c.curve;
    EXPECT_EQ(r.vertices_after_cut, c.v_cut) << c.curve;
    EXPECT_EQ(r.faces_after_cut, c.f_cut) << c.curve;
    // none of these needs the short-piece refinement
    EXPECT_EQ(r.refine_new_vertices, 0u) << c.curve;
    EXPECT_EQ(r.mesh.number_of_vertices(), c.v_cut);
    EXPECT_TRUE(r.mesh.is_valid(false));
    ASSERT_EQ(r.chain.size(), r.mesh.number_of_edges());
    std::size_t curve_edges = 0;
    for(int x : r.chain) curve_edges += (x != 0);
    EXPECT_EQ(curve_edges, cs.segments.size()) << c.curve;  // every segment became one edge
    EXPECT_EQ(count_nonzero(chain_boundary(r.mesh, r.chain)), c.endpoints) << c.curve;
    // existing vertices keep index and position
    for(VI v : m.vertices()) ASSERT_EQ(r.mesh.point(v), m.point(v));
    // each used edge point became a vertex at (1-t) first + t second
    auto ae = IO::authors_edge_numbering(m);
    for(std::size_t i = 0; i < cs.points.size(); ++i)
    {
      const auto& p = cs.points[i];
      if(p.kind != IO::Curve_point::EDGE || r.point_vertex[i] == std::size_t(-1)) continue;
      EXPECT_GE(r.point_vertex[i], m.number_of_vertices());
      Point a = m.point(VI(static_cast<Mesh::size_type>(ae[p.element].first)));
      Point b = m.point(VI(static_cast<Mesh::size_type>(ae[p.element].second)));
      Point q = r.mesh.point(VI(static_cast<Mesh::size_type>(r.point_vertex[i])));
      EXPECT_NEAR(q.x(), (1 - p.t) * a.x() + p.t * b.x(), 1e-15);
      EXPECT_NEAR(q.y(), (1 - p.t) * a.y() + p.t * b.y(), 1e-15);
      EXPECT_NEAR(q.z(), (1 - p.t) * a.z() + p.t * b.z(), 1e-15);
    }
  }
}

TEST(ConformingCut, AnnulusEndpointsOnBoundary)
{
  Mesh m;
  IO::read_mesh(demo + "annulus.obj", m);
  auto r = IO::conforming_cut(m, IO::read_curve_file(demo + "annulus.txt", m));
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[3612], -1);  // start on the outer boundary
  EXPECT_EQ(b[3632], 1);   // end on the inner boundary
  EXPECT_EQ(r.refined_pieces, 0u);
}

TEST(ConformingCut, TorusPhiRefinement)
{
  Mesh m;
  IO::read_mesh(demo + "torus.obj", m);
  IO::Curve_set cs = IO::read_curve_file(demo + "torus-phi.txt", m);
  auto r = IO::conforming_cut(m, cs);
  EXPECT_FALSE(r.cut);
  EXPECT_EQ(r.vertices_after_cut, 3840u);
  // the authors' reference output torus_w.obj has 3899 V / 7798 F (+59 from splitting)
  EXPECT_EQ(r.mesh.number_of_vertices(), 3899u);
  EXPECT_EQ(r.mesh.number_of_faces(), 7798u);
  EXPECT_EQ(r.refine_new_vertices, 59u);
  EXPECT_TRUE(r.mesh.is_valid(false));
  // refinement keeps the endpoints and the total boundary
  auto b0 = chain_boundary(m, IO::vertex_curve_chain(m, cs));
  auto b1 = chain_boundary(r.mesh, r.chain);
  for(std::size_t v = 0; v < b0.size(); ++v) ASSERT_EQ(b0[v], b1[v]);
  for(std::size_t v = b0.size(); v < b1.size(); ++v) ASSERT_EQ(b1[v], 0);
  // without refinement: unchanged mesh
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r0 = IO::conforming_cut(m, cs, o);
  EXPECT_EQ(r0.mesh.number_of_vertices(), 3840u);
}

TEST(ConformingCut, ShortPieceRule)
{
  // grid: single-edge piece 5->6 with two interior endpoints -> 8 sub-edges (7 new vertices, 14 new faces)
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  std::istringstream is("# swn polylines\n5 6\n");
  auto r = IO::conforming_cut(g, IO::read_curves(is, "one.txt", g));
  EXPECT_EQ(r.refined_pieces, 1u);
  EXPECT_EQ(r.refine_new_vertices, 7u);
  EXPECT_EQ(r.refine_new_faces, 14u);
  std::size_t curve_edges = 0;
  for(int x : r.chain) curve_edges += (x != 0);
  EXPECT_EQ(curve_edges, 8u);
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[5], -1);
  EXPECT_EQ(b[6], 1);
  EXPECT_EQ(count_nonzero(b), 2u);
  // a piece between two boundary vertices is not refined: 1 -> 5 -> 6 -> 2 (the tool refuses a curve along the
  // border, 0 -> 1: ToolCurves.CurveAlongTheBorderOfATriangleMeshIsBlamedAtItsLine)
  std::istringstream is2("# swn polylines\n1 5 6 2\n");
  auto r2 = IO::conforming_cut(g, IO::read_curves(is2, "bd.txt", g));
  EXPECT_EQ(r2.refined_pieces, 0u);
  EXPECT_EQ(r2.mesh.number_of_vertices(), 16u);
  // a closed loop is never refined
  std::istringstream is3("# swn polylines\n5 6 10 5\n");
  auto r3 = IO::conforming_cut(g, IO::read_curves(is3, "loop.txt", g));
  EXPECT_EQ(r3.refined_pieces, 0u);
  EXPECT_EQ(r3.mesh.number_of_vertices(), 16u);
  // a piece along the mesh boundary then inside: 0->1 (boundary edge) ->5 (interior endpoint), n=2:
  // 4 sub-edges each; splits of the boundary edge add one face, the others two (the library's cut: the
  // tool's refuses a curve along the border)
  Mesh m5 = g;
  auto chain5 = m5.add_property_map<Mesh::Edge_index, int>("e:chain5", 0).first;
  const std::vector<std::vector<CGAL::Polygon_mesh_processing::Face_location<Mesh, double> > > bd2{
    {CGAL::Polygon_mesh_processing::locate_vertex<double>(VI(0), m5), CGAL::Polygon_mesh_processing::locate_vertex<double>(VI(1), m5),
     CGAL::Polygon_mesh_processing::locate_vertex<double>(VI(5), m5)}};
  const auto r5 = CGAL::Surface_winding_numbers::conforming_cut(m5, bd2, chain5);
  EXPECT_EQ(r5.refined_pieces, 1u);
  EXPECT_EQ(r5.refinement_vertices, 6u);
  EXPECT_EQ(r5.refinement_faces, 9u);
  EXPECT_TRUE(m5.is_valid(false));
  std::vector<int> c5(m5.number_of_edges());
  for(auto e : m5.edges()) c5[std::size_t(e)] = chain5[e];
  auto b5 = chain_boundary(m5, c5);
  EXPECT_EQ(b5[0], -1);
  EXPECT_EQ(b5[5], 1);
  EXPECT_EQ(count_nonzero(b5), 2u);
  // two edges 5->6->7 with an interior start: n=2 -> 4 sub-edges each (6 new vertices)
  std::istringstream is4("# swn polylines\n5 6 7\n");
  auto r4 = IO::conforming_cut(g, IO::read_curves(is4, "two.txt", g));
  EXPECT_EQ(r4.refine_new_vertices, 6u);
}

TEST(ConformingCut, SmallCutOnGrid)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // edges (authors' numbering): 0:(0,1) 1:(1,5) 2:(5,0); face 0 = (0,1,5)
  // a chord from vertex 0 to the midpoint of 1-5, then along edge 1-5 to vertex 5 (through the new point)
  std::istringstream is("#offset 0\nv 0\ne 1 0.5\nv 5\nv 1\nl 0 1 2\nl 3 2\n");
  IO::Curve_set cs = IO::read_curves(is, "cut.txt", g);
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, cs, o);
  EXPECT_TRUE(r.cut);
  EXPECT_EQ(r.cut_new_vertices, 1u);
  EXPECT_EQ(r.cut_new_faces, 2u);  // both faces of edge 1-5 split in two
  EXPECT_EQ(r.point_vertex[1], 16u);
  EXPECT_EQ(r.mesh.point(VI(16)), Point(1, 0.5, 0));
  EXPECT_TRUE(r.mesh.is_valid(false));
  // face 0 keeps its slot
  auto t0 = triple(r.mesh, FI(0));
  EXPECT_TRUE(std::find(t0.begin(), t0.end(), std::size_t(0)) != t0.end());
  // chain: 0->16 (+1), 16->5 (+1), 1->16->5 (+1 each): boundary -1 at 0 and 1, +2 at 5
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(b[0], -1);
  EXPECT_EQ(b[1], -1);
  EXPECT_EQ(b[5], 2);
  EXPECT_EQ(b[16], 0);
  auto hb = r.mesh.halfedge(VI(16), VI(5));
  ASSERT_TRUE(hb.is_valid());
  auto e = r.mesh.edge(hb);
  int along = r.chain[std::size_t(e)] * ((std::size_t(hb) % 2 == 0) ? 1 : -1);
  EXPECT_EQ(along, 2);
  expect_no_degenerate_triangle(r.mesh);
  // total area unchanged
  auto area = [](const Mesh& m) {
    double a = 0;
    for(FI f : m.faces())
    {
      auto t = triple(m, f);
      a += std::sqrt(CGAL::squared_area(m.point(VI(static_cast<Mesh::size_type>(t[0]))),
                                        m.point(VI(static_cast<Mesh::size_type>(t[1]))),
                                        m.point(VI(static_cast<Mesh::size_type>(t[2])))));
    }
    return a;
  };
  EXPECT_NEAR(area(r.mesh), area(g), 1e-12);
}

TEST(ConformingCut, ManyPointsInOneFace)
{
  // points on all three sides of face 0 = (0,1,5) and a path through them: fan-free triangulation
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  std::istringstream is("#offset 0\ne 0 0.25\ne 0 0.75\ne 1 0.5\ne 2 0.3\ne 2 0.6\nl 0 2 3\nl 4 0\nl 1 2\n");
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, IO::read_curves(is, "many.txt", g), o);
  EXPECT_EQ(r.cut_new_vertices, 5u);
  EXPECT_TRUE(r.mesh.is_valid(false));
  // Euler: a disk keeps V - E + F = 1
  EXPECT_EQ(long(r.mesh.number_of_vertices()) - long(r.mesh.number_of_edges()) + long(r.mesh.number_of_faces()), 1);
  expect_no_degenerate_triangle(r.mesh);
  auto b = chain_boundary(r.mesh, r.chain);
  EXPECT_EQ(count_nonzero(b), 4u);
  // p0->p2 and p4->p1 cross inside face 0: a vertex at the crossing
  std::istringstream is2("#offset 0\ne 0 0.25\ne 0 0.75\ne 1 0.5\ne 2 0.3\ne 2 0.6\nl 0 2\n#\nl 4 1\n");
  r = IO::conforming_cut(g, IO::read_curves(is2, "cross.txt", g), o);
  EXPECT_EQ(r.cut_new_vertices, 5u);
  EXPECT_TRUE(r.mesh.is_valid(false));
  EXPECT_EQ(long(r.mesh.number_of_vertices()) - long(r.mesh.number_of_edges()) + long(r.mesh.number_of_faces()), 1);
  expect_no_degenerate_triangle(r.mesh);
  EXPECT_EQ(count_nonzero(chain_boundary(r.mesh, r.chain)), 4u);
}

TEST(ConformingCut, DuplicatePointsAndDegenerateSegments)
{
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  // points 1 and 2 are equal: one new vertex; segment 1->2 is skipped
  std::istringstream is("#offset 0\nv 0\ne 1 0.5\ne 1 0.5\nv 5\nl 0 1 2 3\n");
  IO::Cut_options o;
  o.refine_short_pieces = false;
  auto r = IO::conforming_cut(g, IO::read_curves(is, "dup.txt", g), o);
  EXPECT_EQ(r.cut_new_vertices, 1u);
  EXPECT_EQ(r.skipped_segments, 1u);
  EXPECT_EQ(r.point_vertex[1], r.point_vertex[2]);
}

// ------------------------------------------------------------------------------------------------ library conforming_cut()

namespace {

namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

// A closed curve around vertex 5 = (1, 1, 0) of grid4.off, crossing its six spokes at known parameters: the
// point on spoke k is at (1 - t[k]) * p5 + t[k] * p(ring[k]). The ring is counter-clockwise seen from +z (the
// side the faces face), so the inside of the curve, around vertex 5, is one higher than the outside.
const std::size_t ring[6] = {6, 10, 9, 4, 0, 1};
const double spoke_t[6] = {0.25, 0.5, 0.75, 0.375, 0.625, 0.5};

template <class TriangleMesh>
std::vector<PMP::Face_location<TriangleMesh, double> >
hexagon_around_vertex_5(const TriangleMesh& tm, const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& v)
{
  std::vector<PMP::Face_location<TriangleMesh, double> > curve;
  for(int k = 0; k <= 6; ++k)
  {
    auto h = halfedge(v[5], v[ring[k % 6]], tm).first;   // from vertex 5 to the ring
    // close the loop with the first point located from the other side of its edge
    curve.push_back(k < 6 ? PMP::locate_on_halfedge(h, spoke_t[k], tm)
                          : PMP::locate_on_halfedge(opposite(h, tm), 1 - spoke_t[0], tm));
  }
  return curve;
}

// the vertices of grid4.off by index: vertex i is at (i % 4, i / 4, 0)
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> grid_vertices(const TriangleMesh& tm)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> v(num_vertices(tm));
  for(auto x : vertices(tm))
    v.at(std::size_t(get(CGAL::vertex_point, tm, x).x() + 4 * get(CGAL::vertex_point, tm, x).y())) = x;
  return v;
}

// the boundary of the chain (arrivals minus departures) is zero everywhere, and the chain has `edges` edges
template <class TriangleMesh, class ChainMap>
void expect_closed_chain(const TriangleMesh& tm, const ChainMap& chain, int edges)
{
  std::map<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, int> boundary;
  int count = 0;
  for(auto e : CGAL::edges(tm))
  {
    const int c = get(chain, e);
    boundary[target(halfedge(e, tm), tm)] += c;
    boundary[source(halfedge(e, tm), tm)] -= c;
    count += (c != 0);
  }
  for(const auto& b : boundary) EXPECT_EQ(b.second, 0);
  EXPECT_EQ(count, edges);
}

} // namespace

TEST(LibraryConformingCut, LoopAcrossSpokesAtKnownParameters)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  const Point p5 = m.point(v[5]);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  const std::vector<std::vector<PMP::Face_location<Mesh, double> > > curves{hexagon_around_vertex_5(m, v)};

  const SWN::Conforming_cut_result<Mesh> r = SWN::conforming_cut(m, curves, chain);
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.cut_vertices, 6u);
  EXPECT_EQ(r.cut_faces, 12u);   // each of the six triangles around vertex 5: a triangle inside, a quad outside in two
  EXPECT_EQ(r.segments, 6u);
  EXPECT_EQ(r.refined_pieces, 0u);   // a closed loop has no endpoint
  EXPECT_EQ(m.number_of_vertices(), 16u + 6u);
  EXPECT_EQ(m.number_of_faces(), 18u + 12u);
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_triangle_mesh(m));
  // the new vertices lie at the given points (exactly: the parameters are binary fractions), in curve order
  ASSERT_EQ(r.curve_vertices.size(), 1u);
  ASSERT_EQ(r.curve_vertices[0].size(), 7u);
  EXPECT_EQ(r.curve_vertices[0][6], r.curve_vertices[0][0]);
  for(int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(std::size_t(r.curve_vertices[0][k]), 16u + k) << "new vertices are numbered in the order of the curve";
    const Point& q = m.point(v[ring[k]]);
    const double t = spoke_t[k];
    EXPECT_EQ(m.point(r.curve_vertices[0][k]), Point((1 - t) * p5.x() + t * q.x(), (1 - t) * p5.y() + t * q.y(), 0.));
  }
  // the chain runs once around the loop, from each point to the next
  expect_closed_chain(m, chain, 6);
  for(int k = 0; k < 6; ++k)
  {
    const auto h = m.halfedge(r.curve_vertices[0][k], r.curve_vertices[0][k + 1]);
    ASSERT_TRUE(h.is_valid());
    std::vector<Mesh::Halfedge_index> along{h};
    auto one = m.add_property_map<Mesh::Edge_index, int>("e:one", 0).first;
    SWN::add_halfedges_to_chain(m, along, one);
    EXPECT_EQ(chain[m.edge(h)], one[m.edge(h)]);
    m.remove_property_map(one);
  }
  // the winding numbers: the six triangles around vertex 5 are inside (1), everything else outside (0)
  auto labels = m.add_property_map<FI, int>("f:label", 0).first;
  SWN::Solve_report report;
  ASSERT_TRUE(CGAL::surface_winding_numbers(m, chain, labels, SWN::parameters::report(std::ref(report)))) << report.error;
  double inside_area = 0;
  for(FI f : m.faces())
  {
    const auto t = triple(m, f);
    const bool around_5 = std::find(t.begin(), t.end(), std::size_t(5)) != t.end();
    EXPECT_EQ(labels[f], around_5 ? 1 : 0) << "face " << f;
    if(around_5)
      inside_area += std::sqrt(CGAL::squared_area(m.point(VI(Mesh::size_type(t[0]))), m.point(VI(Mesh::size_type(t[1]))),
                                                  m.point(VI(Mesh::size_type(t[2])))));
  }
  // triangle (p5, a, b) with a, b at t_a, t_b along two spokes of a half-unit triangle: area t_a * t_b / 2
  double expected_area = 0;
  for(int k = 0; k < 6; ++k) expected_area += spoke_t[k] * spoke_t[(k + 1) % 6] / 2;
  EXPECT_NEAR(inside_area, expected_area, 1e-14);
}

TEST(LibraryConformingCut, PolyhedronAndExistingChain)
{
  // the same loop on a Polyhedron_3 with maps outside the mesh; the chain already holds a curve along
  // spokes 5->6 and 5->4, which the cut splits: both halves keep its value
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::edge_descriptor edge_descriptor;
  Mesh sm;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", sm));
  Polyhedron p;
  CGAL::copy_face_graph(sm, p);
  const auto v = grid_vertices(p);
  std::unordered_map<edge_descriptor, int> chain_values;
  auto chain = boost::make_assoc_property_map(chain_values);
  std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> before{halfedge(v[6], v[5], p).first,
                                                                         halfedge(v[5], v[4], p).first};
  SWN::add_halfedges_to_chain(p, before, chain);
  const std::vector<std::vector<PMP::Face_location<Polyhedron, double> > > curves{hexagon_around_vertex_5(p, v)};

  const auto r = SWN::conforming_cut(p, curves, chain, SWN::parameters::refine_short_pieces(false));
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.cut_vertices, 6u);
  EXPECT_EQ(r.cut_faces, 12u);
  EXPECT_EQ(p.size_of_vertices(), 22u);
  EXPECT_EQ(p.size_of_facets(), 30u);
  EXPECT_TRUE(p.is_valid() && p.is_pure_triangle());
  // the old curve 6 -> 5 -> 4 now runs 6 -> new -> 5 -> new -> 4; the loop adds 6 edges
  std::map<boost::graph_traits<Polyhedron>::vertex_descriptor, int> boundary;
  int edges_with_chain = 0;
  for(auto e : edges(p))
  {
    const int c = get(chain, e);
    boundary[target(halfedge(e, p), p)] += c;
    boundary[source(halfedge(e, p), p)] -= c;
    edges_with_chain += (c != 0);
  }
  EXPECT_EQ(edges_with_chain, 4 + 6);
  for(const auto& b : boundary)
    EXPECT_EQ(b.second, b.first == v[6] ? -1 : (b.first == v[4] ? 1 : 0));
  const auto on_old_curve = halfedge(r.curve_vertices[0][0], v[5], p);   // the point on spoke 5 -> 6, towards 5
  ASSERT_TRUE(on_old_curve.second);
  std::unordered_map<edge_descriptor, int> one_values;
  auto one = boost::make_assoc_property_map(one_values);
  std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> along{on_old_curve.first};
  SWN::add_halfedges_to_chain(p, along, one);
  EXPECT_EQ(get(chain, edge(on_old_curve.first, p)), get(one, edge(on_old_curve.first, p)));
}

TEST(LibraryConformingCut, RefusedCurvesLeaveEverythingUnchanged)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  chain[m.edge(m.halfedge(v[0], v[1]))] = 3;
  const Mesh before = m;
  auto unchanged = [&]() {
    EXPECT_EQ(m.number_of_vertices(), before.number_of_vertices());
    EXPECT_EQ(m.number_of_faces(), before.number_of_faces());
    for(VI x : m.vertices()) EXPECT_EQ(m.point(x), before.point(x));
    int nonzero = 0;
    for(auto e : m.edges()) nonzero += (chain[e] != 0);
    EXPECT_EQ(nonzero, 1);
    EXPECT_EQ(chain[m.edge(m.halfedge(v[0], v[1]))], 3);
  };
  typedef PMP::Face_location<Mesh, double> Location;
  auto on = [&](std::size_t a, std::size_t b, double t) { return PMP::locate_on_halfedge(m.halfedge(v[a], v[b]), t, m); };
  auto at = [&](std::size_t a) { return PMP::locate_vertex<double>(v[a], m); };

  // a point strictly inside a face
  const FI f0 = *m.faces().begin();
  std::vector<std::vector<Location> > inside{{at(0), Location(f0, {0.2, 0.3, 0.5})}};
  auto r = SWN::conforming_cut(m, inside, chain);
  EXPECT_EQ(r.error, r.INVALID_LOCATION);
  EXPECT_EQ(r.index, 1u);
  unchanged();
  // two points on no common face (the second segment of the curve)
  std::vector<std::vector<Location> > apart{{on(0, 1, 0.5), at(5), at(15)}};
  r = SWN::conforming_cut(m, apart, chain);
  EXPECT_EQ(r.error, r.NO_COMMON_FACE);
  EXPECT_EQ(r.curve, 0u);
  EXPECT_EQ(r.index, 1u);
  unchanged();
  // an open curve ending inside: its single edge is refined into 8 (as the tool does by default)
  std::vector<std::vector<Location> > short_piece{{at(5), at(6)}};
  r = SWN::conforming_cut(m, short_piece, chain);
  ASSERT_TRUE(bool(r));
  EXPECT_EQ(r.cut_vertices, 0u);
  EXPECT_EQ(r.refined_pieces, 1u);
  EXPECT_EQ(r.refinement_vertices, 7u);
  EXPECT_EQ(r.refinement_faces, 14u);
}

TEST(LibraryConformingCut, MinimumPieceEdgesAboveTheBoundIsRefused)
{
  // minimum_piece_edges = SIZE_MAX would split an edge 2^63 times: refused, nothing changed
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  typedef SWN::Conforming_cut_result<Mesh> Result;
  const std::size_t bound = Result::max_minimum_piece_edges;
  ASSERT_EQ(bound, 65536u);
  const std::vector<std::vector<PMP::Face_location<Mesh, double> > > short_piece{
    {PMP::locate_vertex<double>(v[5], m), PMP::locate_vertex<double>(v[6], m)}};
  for(std::size_t huge : {std::size_t(-1), std::size_t(1) << 63, bound + 1})
  {
    const auto r = SWN::conforming_cut(m, short_piece, chain, SWN::parameters::minimum_piece_edges(huge));
    EXPECT_EQ(r.error, Result::INVALID_PARAMETER);
    EXPECT_NE(r.message.find("minimum_piece_edges is " + std::to_string(huge)), std::string::npos) << r.message;
    EXPECT_EQ(m.number_of_vertices(), 16u);
    EXPECT_EQ(m.number_of_faces(), 18u);
    for(auto e : m.edges()) EXPECT_EQ(chain[e], 0);
  }
  // without the refinement the value is not used
  Mesh copy = m;
  auto copy_chain = copy.add_property_map<Mesh::Edge_index, int>("e:chain2", 0).first;
  const std::vector<std::vector<PMP::Face_location<Mesh, double> > > copy_piece{
    {PMP::locate_vertex<double>(VI(5), copy), PMP::locate_vertex<double>(VI(6), copy)}};
  EXPECT_TRUE(bool(SWN::conforming_cut(copy, copy_piece, copy_chain, SWN::parameters::refine_short_pieces(false,
                                         SWN::parameters::minimum_piece_edges(std::size_t(-1))))));
  // the bound itself: the one-edge piece becomes 2^16 edges
  const auto r = SWN::conforming_cut(m, short_piece, chain, SWN::parameters::minimum_piece_edges(bound));
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.refined_pieces, 1u);
  EXPECT_EQ(r.refinement_vertices, bound - 1);
  std::size_t curve_edges = 0;
  for(auto e : m.edges()) curve_edges += (chain[e] != 0);
  EXPECT_EQ(curve_edges, bound);
  // the tool's cut of a curve file: std::invalid_argument, the setting named
  Mesh g;
  IO::read_mesh(tdata + "grid4.off", g);
  std::istringstream is("# swn polylines\n5 6\n");
  IO::Cut_options options;
  options.min_piece_edges = std::size_t(-1);
  const auto curves = IO::read_curves(is, "one.txt", g);
  try
  {
    IO::conforming_cut(g, curves, options);
    ADD_FAILURE() << "no exception";
  }
  catch(const std::invalid_argument& e)
  {
    EXPECT_NE(std::string(e.what()).find("minimum_piece_edges"), std::string::npos) << e.what();
  }
}

TEST(LibraryConformingCut, CrossingSegmentsGetAVertexWhereTheyCross)
{
  Mesh m;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", m));
  const std::vector<VI> v = grid_vertices(m);
  auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  auto on = [&](std::size_t a, std::size_t b, double t) { return PMP::locate_on_halfedge(m.halfedge(v[a], v[b]), t, m); };
  // in face (0, 1, 5): the midpoint of 0-1 to the midpoint of 1-5, and vertex 1 to the midpoint of 5-0: they
  // cross at (0.75, 0.25)
  const std::vector<std::vector<PMP::Face_location<Mesh, double> > > crossing{
    {on(0, 1, 0.5), on(1, 5, 0.5)}, {PMP::locate_vertex<double>(v[1], m), on(5, 0, 0.5)}};
  const auto r = SWN::conforming_cut(m, crossing, chain, SWN::parameters::refine_short_pieces(false));
  ASSERT_TRUE(bool(r)) << r.message;
  EXPECT_EQ(r.crossing_vertices, 1u);
  EXPECT_EQ(r.cut_vertices, 4u);   // three on edges, one at the crossing
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(m) && CGAL::is_triangle_mesh(m));
  expect_no_degenerate_triangle(m);
  const VI x(Mesh::size_type(m.number_of_vertices() - 1));
  EXPECT_EQ(m.point(x), Point(0.75, 0.25, 0));
  // each curve runs through the crossing: four chain edges there, two in and two out
  int in = 0, out = 0;
  for(auto e : m.edges())
  {
    const int c = chain[e];
    if(m.target(m.halfedge(e)) == x) (c > 0 ? in : out) += std::abs(c);
    if(m.source(m.halfedge(e)) == x) (c > 0 ? out : in) += std::abs(c);
  }
  EXPECT_EQ(in, 2);
  EXPECT_EQ(out, 2);
}
