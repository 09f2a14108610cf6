// Copyright (c) 2026 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Curves on a polygon soup (a mesh file that is not an oriented 2-manifold triangle mesh): the curve files
// and OBJ records of read_curves.h, by vertices and by pairs of faces only, checked against the soup and
// turned into the input of CGAL::polygon_soup_winding_numbers().

#ifndef CGAL_SWN_TOOL_IO_SOUP_CURVES_H
#define CGAL_SWN_TOOL_IO_SOUP_CURVES_H

#include "swn_io/curve_set.h"
#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"
#include "swn_io/read_curves.h"

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief the edges of a soup as sorted vertex pairs `(i, j)`, `i < j`, each once.
*/
inline std::vector<std::pair<std::size_t, std::size_t> > soup_edges(const Triangle_soup& soup)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  auto add = [&](const auto& face) {
    for(std::size_t k = 0; k < face.size(); ++k)
    {
      const std::size_t a = face[k], b = face[(k + 1) % face.size()];
      edges.emplace_back((std::min)(a, b), (std::max)(a, b));
    }
  };
  for(const auto& t : soup.triangles) add(t);
  for(const auto& p : soup.polygons) add(p);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

namespace internal {

inline bool has_soup_edge(const std::vector<std::pair<std::size_t, std::size_t> >& edges, std::size_t a, std::size_t b)
{
  return std::binary_search(edges.begin(), edges.end(), std::make_pair((std::min)(a, b), (std::max)(a, b)));
}

/// Checks a curve read against a soup: vertex points in range, segments along edges of the soup, dual pairs
/// between faces in range, not empty.
inline void validate_soup_curve_set(const Curve_set& cs, const Triangle_soup& soup,
                                    const std::vector<std::pair<std::size_t, std::size_t> >& edges)
{
  const std::size_t nv = soup.points.size(), nf = number_of_faces(soup);
  for(const Curve_point& p : cs.points)
    if(p.kind != Curve_point::VERTEX || p.element >= nv)
      throw Input_error(cs.file, p.line, p.kind != Curve_point::VERTEX
                                           ? std::string("edge points need an oriented 2-manifold triangle mesh")
                                           : "vertex index " + std::to_string(p.element) + " is out of range (" +
                                               std::to_string(nv) + " vertices)");
  for(const Curve_dual_pair& d : cs.dual_pairs)
    if(d.face_a >= nf || d.face_b >= nf)
      throw Input_error(cs.file, d.line, "face index " + std::to_string((std::max)(d.face_a, d.face_b)) +
                                            " is out of range (" + std::to_string(nf) + " faces)");
  for(const Curve_segment& s : cs.segments)
  {
    const std::size_t a = cs.points[s.a].element, b = cs.points[s.b].element;
    if(a != b && !has_soup_edge(edges, a, b))
      throw Input_error(cs.file, s.line, "the segment from vertex " + std::to_string(a) + " to vertex " +
                                            std::to_string(b) + " is not an edge of the mesh (no face has these "
                                            "two vertices as consecutive corners)");
  }
  if(cs.segments.empty() && cs.dual_pairs.empty())
    throw Input_error(cs.file, 0, "the curve is empty (no segment)");
}

} // namespace internal

/*!
  \brief reads a curve file (formats as in `read_curve_file()` for meshes) against a polygon soup: vertex
  points, polylines, halfedges and dual chains (`c` records); edge points are an error.
  \throws Input_error on a missing file or any invalid input, with the file's line
*/
inline Curve_set read_curve_file(const std::string& filename, const Triangle_soup& soup,
                                 Curve_file_format format = Curve_file_format::AUTO)
{
  std::ifstream is = internal::open_input_file(filename, "a curve file");
  std::istringstream ss = internal::detect_curve_format(is, filename, format);
  const auto edges = soup_edges(soup);
  const std::size_t nv = soup.points.size();
  Curve_set cs;
  if(format == Curve_file_format::POLYLINES) cs = internal::read_polyline_curves(ss, filename, nv);
  else if(format == Curve_file_format::HALFEDGES)
    cs = internal::read_halfedge_curves(ss, filename, nv,
                                        [&](std::size_t a, std::size_t b) { return internal::has_soup_edge(edges, a, b); });
  else
    cs = internal::read_authors_curves(ss, filename, nv, number_of_faces(soup), 0,
                                       [](std::size_t, int) { return std::size_t(0); });
  internal::validate_soup_curve_set(cs, soup, edges);
  return cs;
}

/*!
  \brief the inline `l` and `c` records of an OBJ file read as a soup, as a `Curve_set` checked against the soup
  (empty if there are none).
*/
inline Curve_set curve_set_from_obj(const Mesh_read_info& info, const Triangle_soup& soup)
{
  Curve_set cs = internal::obj_curve_records(info);
  if(!cs.segments.empty() || !cs.dual_pairs.empty()) internal::validate_soup_curve_set(cs, soup, soup_edges(soup));
  return cs;
}

/*!
  \brief the input of `CGAL::polygon_soup_winding_numbers()`: directed edges (one per traversal) and pairs of
  faces of the dual chain.
*/
struct Soup_curve
{
  /// directed edges (source, target), one entry per traversal
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  /// pairs (a, b) of faces: +1 from a into b
  std::vector<std::pair<std::size_t, std::size_t> > dual_pairs;
};

/*!
  \brief concatenates curve sets checked against a soup into a `Soup_curve` (segments between a vertex and
  itself are skipped).
*/
inline Soup_curve soup_curve(const std::vector<Curve_set>& curves)
{
  Soup_curve c;
  for(const Curve_set& cs : curves)
  {
    for(const Curve_segment& s : cs.segments)
      if(cs.points[s.a].element != cs.points[s.b].element)
        c.edges.emplace_back(cs.points[s.a].element, cs.points[s.b].element);
    for(const Curve_dual_pair& d : cs.dual_pairs) c.dual_pairs.emplace_back(d.face_a, d.face_b);
  }
  return c;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_SOUP_CURVES_H
