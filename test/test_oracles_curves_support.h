// Shared by the test_oracles sources on curves off the mesh (polylines, stamping, selections): an
// icosphere, the solve, and the analytic cap of a circle of latitude.
#ifndef SWN_TEST_ORACLES_CURVES_SUPPORT_H
#define SWN_TEST_ORACLES_CURVES_SUPPORT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/surface_winding_numbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

namespace swn_curves_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 P3;
typedef CGAL::Surface_mesh<P3> Mesh;
typedef Mesh::Property_map<Mesh::Edge_index, int> Chain;
namespace SWN = CGAL::Surface_winding_numbers;

const double kPi = std::acos(-1.);

// the unit sphere: an icosahedron, Loop-subdivided `levels` times, its vertices put back on the sphere
inline Mesh unit_sphere(int levels)
{
  Mesh m;
  CGAL::make_icosahedron(m, P3(0, 0, 0), 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(levels));
  for(auto v : vertices(m))
  {
    const K::Vector_3 p = m.point(v) - CGAL::ORIGIN;
    m.point(v) = CGAL::ORIGIN + p / std::sqrt(p.squared_length());
  }
  return m;
}

inline Chain new_chain(Mesh& m) { return m.add_property_map<Mesh::Edge_index, int>("e:test_chain", 0).first; }

inline double mean_edge_length(const Mesh& m)
{
  double s = 0;
  for(auto e : edges(m)) s += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  return s / double(num_edges(m));
}

inline P3 centroid(const Mesh& m, Mesh::Face_index f)
{
  const auto h = halfedge(f, m);
  return CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
}

inline double face_area(const Mesh& m, Mesh::Face_index f)
{
  const auto h = halfedge(f, m);
  return std::sqrt(CGAL::squared_area(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m))));
}

// angle between the direction of p and `axis`
inline double polar_angle(const P3& p, const K::Vector_3& axis)
{
  const K::Vector_3 v = p - CGAL::ORIGIN;
  const double c = v * axis / std::sqrt(v.squared_length() * axis.squared_length());
  return std::acos(std::max(-1., std::min(1., c)));
}

// the labels of a solve (fails the test if the solve fails)
inline std::map<Mesh::Face_index, int> solve(Mesh& m, const Chain& chain)
{
  auto labels = m.add_property_map<Mesh::Face_index, int>("f:test_labels", 0).first;
  SWN::Solve_report report;
  const bool ok = CGAL::surface_winding_numbers(m, chain, labels, SWN::parameters::report(std::ref(report)));
  EXPECT_TRUE(ok) << report.error;
  std::map<Mesh::Face_index, int> r;
  for(auto f : faces(m)) r[f] = labels[f];
  m.remove_property_map(labels);
  return r;
}

// number of vertices where the chain has a nonzero boundary
inline std::size_t chain_endpoints(const Mesh& m, const Chain& chain)
{
  std::map<Mesh::Vertex_index, int> b;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    b[target(h, m)] += chain[e];
    b[source(h, m)] -= chain[e];
  }
  std::size_t n = 0;
  for(const auto& x : b) n += x.second != 0;
  return n;
}

// Checks that the faces within `angle` of `axis` (the cap) have label `inside` and the others 0, except
// in a band of half-width `band` (radians) around the cap's border; returns the area fraction of the
// faces with a nonzero label.
inline double expect_cap(const Mesh& m, const std::map<Mesh::Face_index, int>& labels, const K::Vector_3& axis,
                         double angle, double band, int inside)
{
  double total = 0, labelled = 0;
  std::size_t wrong = 0;
  for(auto f : faces(m))
  {
    const double a = face_area(m, f), theta = polar_angle(centroid(m, f), axis);
    total += a;
    if(labels.at(f) != 0) labelled += a;
    if(theta < angle - band && labels.at(f) != inside) ++wrong;
    if(theta > angle + band && labels.at(f) != 0) ++wrong;
  }
  EXPECT_EQ(wrong, 0u) << "faces away from the cap's border with the wrong label";
  return labelled / total;
}

inline double cap_fraction(double angle) { return (1 - std::cos(angle)) / 2; }

// a circle of polar angle `angle` around +z at radius `radius`, counter-clockwise seen from +z, closed
inline std::vector<P3> latitude_circle(double angle, double radius, int n)
{
  std::vector<P3> c;
  for(int i = 0; i <= n; ++i)
  {
    const double phi = 2 * kPi * (i % n) / n;
    c.emplace_back(radius * std::sin(angle) * std::cos(phi), radius * std::sin(angle) * std::sin(phi),
                   radius * std::cos(angle));
  }
  return c;
}

} // namespace swn_curves_test

#endif
