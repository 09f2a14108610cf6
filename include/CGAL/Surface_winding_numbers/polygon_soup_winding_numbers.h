// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_POLYGON_SOUP_WINDING_NUMBERS_H
#define CGAL_SURFACE_WINDING_NUMBERS_POLYGON_SOUP_WINDING_NUMBERS_H

#include <CGAL/Surface_winding_numbers/Solve_report.h>
#include <CGAL/Surface_winding_numbers/Surface_winding_numbers_solver.h>
#include <CGAL/Surface_winding_numbers/internal/polygon_tables.h>
#include <CGAL/Surface_winding_numbers/parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>
#include <boost/range/irange.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgSurfaceWindingNumbersRef

\brief computes the surface winding numbers of curves on a polygon soup: the same method and outputs as
`CGAL::surface_winding_numbers()`, on a surface given as points and polygons (\cgal's polygon soup
conventions, as read by `CGAL::IO::read_polygon_soup()`), without building a `FaceGraph`.

The polygons are glued along the edges they share (two polygons that both use the vertices `i` and `j`
as consecutive corners), with no other requirement (\ref SWNNonmanifold): an edge may be shared by more
than two polygons (a nonmanifold edge), polygons may meet at a vertex only (a nonmanifold vertex), and
two polygons may traverse their common edge the same way (a nonorientable gluing, as on a Möbius strip).
As in the paper (Sec. 2.2), curve edges at a nonmanifold vertex are dropped (the report counts them in
`Solve_report::dropped_curve_edges`) and nothing jumps across the edges at such a vertex; the gaps
this makes are closed like any other. Polygons with more than three
corners are triangulated internally (a quadrilateral along its shorter diagonal, a larger polygon by
ear clipping in the plane of its Newell normal); no curve runs along the diagonals and the residual
function may not jump across them, so that the labels are constant on each polygon and every output
lives on the input's polygons, corners and edges.

\tparam PointRange a model of `RandomAccessContainer` whose value type is a point type with `x()`,
        `y()` and `z()`
\tparam PolygonRange a model of `ConstRange` whose value type is a range of `std::size_t` (indices into
        `points`), for instance `std::vector<std::vector<std::size_t> >` or `std::vector<std::array<std::size_t, 3> >`
\tparam CurveRange a model of `ConstRange` of directed edges: each value `c` gives one traversal of the
        edge from `std::get<0>(c)` to `std::get<1>(c)` (a `std::pair` or `std::array` of two vertex
        indices); an edge traversed several times appears several times
\tparam LabelMap a model of `WritablePropertyMap` with key `std::size_t` (the polygon's index) and an
        integer value type, for instance `CGAL::make_property_map(std::vector<int>&)` on a vector of
        `polygons.size()` elements
\tparam NamedParameters a sequence of named parameters

\param points the vertices
\param polygons the faces, each a sequence of at least three distinct vertex indices
\param curve the input curves, as directed edges of the soup (each must join consecutive corners of a
       polygon): the polygon to the left of the edge (the one that traverses it in the same direction) gets
       the higher winding number. On an edge whose two polygons traverse it the same way, that is the polygon
       that comes first in `polygons`; on a nonorientable surface, curves are better given as the named
       parameter `dual_chain`.
\param labels receives W for every polygon
\param np an optional sequence of named parameters: those of `CGAL::surface_winding_numbers()` (`epsilon`,
       `lp_solver`, `use_reduced_residual`, `completed_homology_class`, `filter_nonbounding_loops`, `concurrency`, `report`, `verbose`,
       `label_anchor_face` (here a polygon index; `std::size_t(-1)`: none), `label_confidence`,
       `sparse_linear_solver`), and
       `dual_chain`: a range of pairs `(a, b)` of polygon indices (as `std::pair` or `std::array`), each
       adding a jump of +1 from polygon `a` into polygon `b` across the edge they share (paper Sec. 3.7, the
       input of choice on nonorientable surfaces), added to `curve`; with
       the output maps keyed as follows: `nonbounding_chain_map`, `nonbounding_chain_real_map` and
       `bounding_chain_map` have the key `std::pair<std::size_t, std::size_t>` (the two vertices `(i, j)` of
       an edge, `i < j`; the value is signed from `i` to `j`) and are written for every edge;
       `winding_number_map` has the key `std::pair<std::size_t, std::size_t>` (a polygon and the position
       of a corner in it) and receives w at that corner; `confidence_map`, `region_map` and
       `second_best_label_map` have the key `std::size_t` (a polygon) and receive the values of the
       polygon's region (\ref SWNConfidence; a polygon is never split between regions: its triangles share
       its label, and no curve or nonbounding loop runs along its diagonals). The regions' `faces` count
       the triangles of the internal triangulation.

\returns `true` on success. On failure (bad indices, polygons with fewer than three vertices or a repeated
vertex, non-finite coordinates, a degenerate triangle, a curve edge that is not an edge of the soup, a pair
of `dual_chain` that are not polygons sharing an edge, a curve along the border, a failed solve), no
output map is written and the named parameter `report` tells why, naming the polygon, edge or vertex.

\sa `CGAL::surface_winding_numbers()`
*/
template <class PointRange, class PolygonRange, class CurveRange, class LabelMap,
          class NamedParameters = parameters::Default_named_parameters>
bool polygon_soup_winding_numbers(const PointRange& points, const PolygonRange& polygons, const CurveRange& curve,
                                  LabelMap labels, const NamedParameters& np = parameters::default_values())
{
  namespace SWN = Surface_winding_numbers;
  namespace SI = Surface_winding_numbers::internal;
  namespace snp = Surface_winding_numbers::internal_np;
  typedef typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t, NamedParameters,
                                                       CGAL::Default>::type Solver_param;
  typedef typename CGAL::Default::Get<std::remove_cv_t<std::remove_reference_t<Solver_param>>,
                                      SI::Default_sparse_solver>::type LA;
  typedef std::pair<std::size_t, std::size_t> Vertex_pair;
  SWN::Solve_report rep;
  SI::run_and_report(rep, [&] {
    SI::Stopwatch clock;
    std::vector<double> xyz;
    xyz.reserve(3 * points.size());
    for(const auto& p : points)
      for(double c : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}) xyz.push_back(c);
    SI::Winding_number_core<LA> core(SI::polygon_mesh_tables(std::move(xyz), polygons));
    const double time_mesh = clock.lap();
    const SI::Mesh_tables& m = core.tables();
    std::map<Vertex_pair, std::size_t> edge_of;   // the input's edges
    auto key = [&](std::size_t e) {
      return Vertex_pair((std::min)(m.ev[2 * e], m.ev[2 * e + 1]), (std::max)(m.ev[2 * e], m.ev[2 * e + 1]));
    };
    for(std::size_t e = 0; e < m.ne; ++e)
      if(!m.is_virtual(e)) edge_of[key(e)] = e;
    std::vector<double> chain(m.ne, 0.);
    for(const auto& c : curve)
    {
      const std::size_t a = std::size_t(std::get<0>(c)), b = std::size_t(std::get<1>(c));
      const auto it = edge_of.find(Vertex_pair((std::min)(a, b), (std::max)(a, b)));
      if(it == edge_of.end())
        throw SWN::Invalid_input("the curve edge (" + std::to_string(a) + ", " + std::to_string(b) +
                                 ") is not an edge of the polygons");
      chain[it->second] += m.ev[2 * it->second] == a ? 1. : -1.;
    }
    if constexpr(!parameters::is_default_parameter<NamedParameters, snp::dual_chain_t>::value)
      SI::add_dual_chain(m, parameters::get_parameter(np, snp::dual_chain), chain);
    std::size_t anchor = SI::npos;
    if constexpr(!parameters::is_default_parameter<NamedParameters, snp::label_anchor_face_t>::value)
    {
      const std::size_t p = std::size_t(parameters::get_parameter(np, snp::label_anchor_face));
      if(p != SI::npos && p >= m.number_of_polygons())
        throw SWN::Invalid_input("label_anchor_face: polygon " + std::to_string(p) + " is out of range (" +
                                 std::to_string(m.number_of_polygons()) + " polygons)");
      if(p != SI::npos) anchor = m.polygon_triangle(p);
    }
    const SI::Core_result r = SI::solve_with_parameters(core, chain, np, rep, anchor);
    rep.time_mesh = time_mesh;
    typedef typename boost::property_traits<LabelMap>::value_type Label;
    for(std::size_t p = 0; p < m.number_of_polygons(); ++p) put(labels, p, static_cast<Label>(r.labels[m.polygon_triangle(p)]));
    auto write_edges = [&](auto tag, const auto& values) {
      if constexpr(!parameters::is_default_parameter<NamedParameters, decltype(tag)>::value)
      {
        auto map = parameters::get_parameter(np, tag);
        typedef typename boost::property_traits<decltype(map)>::value_type V;
        for(const auto& kv : edge_of)
          put(map, kv.first, static_cast<V>(m.ev[2 * kv.second] == kv.first.first ? values[kv.second] : -values[kv.second]));
      }
    };
    write_edges(snp::nonbounding_chain_map, r.G);
    write_edges(snp::nonbounding_chain_real_map, r.g);
    write_edges(snp::bounding_chain_map, r.bounding);
    SI::write_confidence(m, r, chain, np, boost::irange(std::size_t(0), m.number_of_polygons()),
                         [](std::size_t p) { return p; });
    if constexpr(!parameters::is_default_parameter<NamedParameters, snp::winding_number_map_t>::value)
    {
      auto map = parameters::get_parameter(np, snp::winding_number_map);
      typedef typename boost::property_traits<decltype(map)>::value_type V;
      std::size_t p = 0;
      for(const auto& polygon : polygons)
      {
        for(std::size_t k = 0; k < std::size_t(std::distance(polygon.begin(), polygon.end())); ++k)
          put(map, Vertex_pair(p, k), static_cast<V>(r.w[m.polygon_corner_at(p, k)]));
        ++p;
      }
    }
  });
  SI::write_report(np, rep);
  return rep.success;
}

} // namespace CGAL

#endif
