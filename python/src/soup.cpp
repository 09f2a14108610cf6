// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// `solve_on_soup()`: the package's CGAL::polygon_soup_winding_numbers() on (V, F) as they are (polygons,
// nonmanifold edges and vertices, nonorientable gluings), with curves along the soup's edges and dual
// chains; the outputs on the input's polygons, corners and edges, as numpy arrays.

#include "swn_python.h"

#include "swn_io/solver_choice.h"

#include <CGAL/Surface_winding_numbers/polygon_soup_winding_numbers.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace swn_python {

namespace SWN = CGAL::Surface_winding_numbers;
namespace IO = CGAL::Surface_winding_numbers::IO;

namespace {

typedef std::pair<std::size_t, std::size_t> Vertex_pair;

// the edges of the soup in the order they first appear (faces in order, each face's sides from corner k
// to corner k + 1), each oriented as in the first face that has it: the order of the Surface_mesh that
// build_oriented_mesh() makes of a triangle mesh
struct Soup_edges
{
  std::vector<std::array<std::size_t, 2>> edges;
  std::map<Vertex_pair, std::size_t> index;   // (min, max) -> edge

  template <class Polygons>
  explicit Soup_edges(const Polygons& polygons)
  {
    for(const auto& face : polygons)
      for(std::size_t k = 0; k < face.size(); ++k)
      {
        const std::size_t a = face[k], b = face[(k + 1) % face.size()];
        if(index.emplace(Vertex_pair((std::min)(a, b), (std::max)(a, b)), edges.size()).second) edges.push_back({a, b});
      }
  }
  // the edge of the key (i, j), i < j, and the sign of the direction i -> j along it
  std::pair<std::size_t, int> edge(const Vertex_pair& key) const
  {
    const std::size_t e = index.at(key);
    return {e, edges[e][0] == key.first ? 1 : -1};
  }
};

// the library's per-edge output (key (i, j), i < j, value signed from i to j), stored per edge of
// Soup_edges, signed along it
template <class T>
struct Edge_value_map
{
  typedef Vertex_pair key_type;
  typedef T value_type;
  typedef T reference;
  typedef boost::writable_property_map_tag category;
  const Soup_edges* edges;
  std::vector<T>* values;
  friend void put(const Edge_value_map& m, const Vertex_pair& key, T value)
  {
    const auto [e, sign] = m.edges->edge(key);
    (*m.values)[e] = sign > 0 ? value : -value;
  }
};

// w at corner k of polygon p (key (p, k)), stored at start[p] + k
struct Corner_map
{
  typedef Vertex_pair key_type;
  typedef double value_type;
  typedef double reference;
  typedef boost::writable_property_map_tag category;
  const std::vector<std::size_t>* start;
  std::vector<double>* w;
  friend void put(const Corner_map& m, const Vertex_pair& key, double value) { (*m.w)[(*m.start)[key.first] + key.second] = value; }
};

// the curves as directed edges of the soup, one per traversal; ValueError naming `curves[i]` if a vertex is
// out of range or two consecutive vertices are not joined by an edge
std::vector<Vertex_pair> curve_edges(const Curve_arrays& curves, const Soup_edges& edges, std::size_t nv)
{
  const auto vx = curves.vertices.unchecked<1>();
  const auto of = curves.offsets.unchecked<1>();
  const auto mu = curves.multiplicities.unchecked<1>();
  if(of.shape(0) != mu.shape(0) + 1 || of(0) != 0 || of(of.shape(0) - 1) != vx.shape(0))
    throw py::value_error("curves: offsets and multiplicities do not match the vertices");
  const std::int64_t limit = 10000000;   // traversals, counted with multiplicity: bounds the work
  std::int64_t traversals = 0;
  std::vector<Vertex_pair> result;
  for(py::ssize_t i = 0; i < mu.shape(0); ++i)
  {
    const std::string curve = "curves[" + std::to_string(i) + "]: ";
    if(of(i + 1) < of(i)) throw py::value_error(curve + "offsets decrease");
    const std::int64_t m = mu(i) < 0 ? -mu(i) : mu(i);
    if(mu(i) < -limit || mu(i) > limit || (traversals += m * (of(i + 1) - of(i))) > limit)
      throw py::value_error(curve + "more than 10^7 edge traversals on a polygon soup (multiplicity " +
                            std::to_string(mu(i)) + ")");
    for(std::int64_t k = of(i); k < of(i + 1); ++k)
    {
      if(vx(k) < 0 || std::size_t(vx(k)) >= nv)
        throw py::value_error(curve + "vertex index " + std::to_string(vx(k)) + " is out of range (" +
                              std::to_string(nv) + " vertices)");
      if(k == of(i)) continue;
      const std::size_t a = std::size_t(vx(k - 1)), b = std::size_t(vx(k));
      if(!edges.index.count(Vertex_pair((std::min)(a, b), (std::max)(a, b))))
        throw py::value_error(curve + "vertices " + std::to_string(a) + " and " + std::to_string(b) +
                              " are not joined by an edge of the mesh");
      for(std::int64_t r = 0; r < m; ++r) result.emplace_back(mu(i) > 0 ? a : b, mu(i) > 0 ? b : a);
    }
  }
  return result;
}

} // namespace

py::dict solve_on_soup(const Triangle_soup& soup, const Curve_arrays& curves, const Index_array& dual_pairs,
                       const Solve_options& o)
{
  const std::size_t nf = IO::number_of_faces(soup);
  const bool triangles = soup.polygons.empty();
  std::vector<std::size_t> start(nf + 1, 0);   // the first corner of every face
  for(std::size_t f = 0; f < nf; ++f) start[f + 1] = start[f] + (triangles ? 3 : soup.polygons[f].size());
  const Soup_edges edges = triangles ? Soup_edges(soup.triangles) : Soup_edges(soup.polygons);
  const std::vector<Vertex_pair> curve = curve_edges(curves, edges, soup.points.size());
  std::vector<Vertex_pair> dual;
  const auto d = dual_pairs.unchecked<2>();
  for(py::ssize_t k = 0; k < d.shape(0); ++k)
  {
    for(int c = 0; c < 2; ++c)
      if(d(k, c) < 0 || std::size_t(d(k, c)) >= nf)
        throw py::value_error("dual_chain: face index " + std::to_string(d(k, c)) + " is out of range (" +
                              std::to_string(nf) + " faces)");
    dual.emplace_back(std::size_t(d(k, 0)), std::size_t(d(k, 1)));
  }

  std::vector<K::Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<int> labels(nf, 0), G(edges.edges.size(), 0), bounding(edges.edges.size(), 0);
  std::vector<double> g(edges.edges.size(), 0.), w(start[nf], std::numeric_limits<double>::quiet_NaN());
  SWN::Solve_report report;
  SWN::Label_confidence confidence;
  std::vector<double> face_cost(o.confidence ? nf : 0, 0.);
  std::vector<std::size_t> region(o.confidence ? nf : 0, 0);
  std::vector<int> second_best(o.confidence ? nf : 0, 0);
  bool ok = false;
  {
    py::gil_scoped_release release;
    auto solve = [&](const auto& polygons, auto with_confidence) {
      return IO::with_solvers(o.lp_solver, o.linear_solver, [&](auto& lp, auto sparse_solver) {
        const auto np =
          SWN::parameters::dual_chain(dual,
          SWN::parameters::winding_number_map(Corner_map{&start, &w},
          SWN::parameters::nonbounding_chain_map(Edge_value_map<int>{&edges, &G},
          SWN::parameters::nonbounding_chain_real_map(Edge_value_map<double>{&edges, &g},
          SWN::parameters::bounding_chain_map(Edge_value_map<int>{&edges, &bounding},
          SWN::parameters::epsilon(o.epsilon,
          SWN::parameters::use_reduced_residual(o.reduced_residual,
          SWN::parameters::completed_homology_class(o.completed_homology_class,
          SWN::parameters::filter_nonbounding_loops(o.filter_nonbounding_loops,
          SWN::parameters::label_anchor_face(o.anchor_face < 0 ? std::size_t(-1) : std::size_t(o.anchor_face),
          SWN::parameters::concurrency(o.concurrency,
          SWN::parameters::lp_solver(std::ref(lp),
          SWN::parameters::report(std::ref(report))))))))))))))
            .verbose(o.verbose).sparse_linear_solver(sparse_solver);
        if constexpr(!decltype(with_confidence)::value)
          return CGAL::polygon_soup_winding_numbers(points, polygons, curve, CGAL::make_property_map(labels), np);
        else
          return CGAL::polygon_soup_winding_numbers(points, polygons, curve, CGAL::make_property_map(labels),
                                                    SWN::parameters::label_confidence(std::ref(confidence),
                                                    SWN::parameters::confidence_map(CGAL::make_property_map(face_cost),
                                                    SWN::parameters::region_map(CGAL::make_property_map(region),
                                                    SWN::parameters::second_best_label_map(CGAL::make_property_map(second_best), np)))));
      });
    };
    if(o.confidence)
    {
      // the confidence outputs (a second instantiation of the solve): on the faces as polygons, triangles included
      std::vector<std::vector<std::size_t>> polygons;
      for(const auto& t : soup.triangles) polygons.emplace_back(t.begin(), t.end());
      ok = solve(triangles ? polygons : soup.polygons, std::true_type());
    }
    else
      ok = triangles ? solve(soup.triangles, std::false_type()) : solve(soup.polygons, std::false_type());
  }
  if(!ok) raise_failure(report);

  std::vector<std::string> warnings;
  if(report.dropped_curve_edges > 0)
    warnings.push_back(std::to_string(report.dropped_curve_edges) + " curve edges at nonmanifold vertices were left "
                       "out (paper Sec. 2.2); the gaps they leave are closed like any other");
  if(report.inconsistent_curve_vertices > 0)
    warnings.push_back("the curve's normal flips at " + std::to_string(report.inconsistent_curve_vertices) +
                       " vertices of a nonorientable surface: it bounds no region consistently there (paper "
                       "Fig. 9); give it as a dual chain");
  py::array_t<std::int64_t> E({py::ssize_t(edges.edges.size()), py::ssize_t(2)});
  auto e = E.mutable_unchecked<2>();
  for(std::size_t k = 0; k < edges.edges.size(); ++k)
    for(int c = 0; c < 2; ++c) e(py::ssize_t(k), c) = std::int64_t(edges.edges[k][std::size_t(c)]);
  py::array corners = array_of(w);
  if(nf > 0 && start[nf] == nf * start[1])   // faces of one size k: an (m, k) array
    corners = corners.reshape(std::vector<py::ssize_t>{py::ssize_t(nf), py::ssize_t(start[1])});
  py::dict result;
  result["W"] = array_of(labels);
  result["w"] = corners;
  result["edges"] = E;
  result["bounding"] = array_of(bounding);
  result["G"] = array_of(G);
  result["g"] = array_of(g);
  result["report"] = report_dict(report);
  result["warnings"] = string_list(warnings);
  if(o.confidence) result["confidence"] = confidence_dict(confidence, face_cost, region, second_best);
  return result;
}

} // namespace swn_python
