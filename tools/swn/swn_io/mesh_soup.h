// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// The triangle soup the mesh readers fill (points and triangles in file order, with their lines), what they
// report besides the mesh, and the soup's validation and conversion into a Surface_mesh that keeps the
// file's numbering.

#ifndef CGAL_SWN_TOOL_IO_MESH_SOUP_H
#define CGAL_SWN_TOOL_IO_MESH_SOUP_H

#include "swn_io/errors.h"
#include "swn_io/second_thread.h"

#include <CGAL/Surface_winding_numbers/internal/polygon_tables.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>
#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \brief an `l` record of an OBJ file: a polyline over mesh vertices.
*/
struct Obj_polyline
{
  /// 0-based mesh vertex indices (the `#offset` in force and OBJ relative indices already applied)
  std::vector<std::size_t> vertices;
  /// 1-based line of the record
  std::size_t line = 0;
};

/*!
  \brief a `c` record of an OBJ file: a dual chain over faces (a jump of +1 from each face to the next).
*/
struct Obj_dual_chain
{
  /// 0-based face indices (the `#offset` in force and OBJ relative indices already applied)
  std::vector<std::size_t> faces;
  /// 1-based line of the record
  std::size_t line = 0;
};

/*!
  \brief what a mesh reader found besides the mesh itself: statistics, warnings and inline curve records.
*/
struct Mesh_read_info
{
  /// the file name as given
  std::string file;
  /// "off", "obj", "ply" or "stl"
  std::string format;
  /// number of vertices of the mesh (isolated vertices included)
  std::size_t number_of_vertices = 0;
  /// number of faces of the mesh
  std::size_t number_of_faces = 0;
  /// vertices used by no face; they are kept as isolated vertices
  std::size_t unreferenced_vertices = 0;
  /// vertices whose position is exactly equal to the position of a vertex with a smaller index
  std::size_t duplicated_vertex_positions = 0;
  /// STL only: number of corner records merged into an existing vertex (exact equality of coordinates)
  std::size_t merged_stl_vertices = 0;
  /// faces whose Newell normal is exactly zero (a self-overlapping polygon whose triangles have an area),
  /// kept; faces with a triangle of zero area are refused (check_face_areas())
  std::size_t degenerate_faces = 0;
  /// human-readable warnings (one line each)
  std::vector<std::string> warnings;
  /// OBJ only: the `l` records, in file order
  std::vector<Obj_polyline> obj_polylines;
  /// OBJ only: the `c` records, in file order
  std::vector<Obj_dual_chain> obj_dual_chains;
};

/*!
  \brief a triangle soup with the source line of every vertex and face (0 when the data is binary).
*/
struct Triangle_soup
{
  /// vertex coordinates, in file order
  std::vector<std::array<double, 3> > points;
  /// 1-based line of each vertex (0 for binary data)
  std::vector<std::size_t> point_lines;
  /// the three 0-based vertex indices of each triangle, in file order
  std::vector<std::array<std::size_t, 3> > triangles;
  /// 1-based line of each face (0 for binary data)
  std::vector<std::size_t> triangle_lines;
  /// every face, in file order, once a face with more than three vertices has been met (`add_face()`);
  /// `triangles` is then empty. Empty for triangle meshes.
  std::vector<std::vector<std::size_t> > polygons;
};

/*!
  \brief the number of faces of `soup` (triangles, or polygons when it has any).
*/
inline std::size_t number_of_faces(const Triangle_soup& soup)
{
  return soup.polygons.empty() ? soup.triangles.size() : soup.polygons.size();
}

/*!
  \brief appends a face (at least three vertex indices, checked by the reader) read on `line`: to `triangles`
  while every face is a triangle, else to `polygons`, which then takes over the triangles read so far.
*/
inline void add_face(Triangle_soup& soup, const std::vector<std::size_t>& face, std::size_t line)
{
  if(face.size() == 3 && soup.polygons.empty())
    soup.triangles.push_back({face[0], face[1], face[2]});
  else
  {
    if(soup.polygons.empty())
    {
      soup.polygons.reserve(soup.triangles.size() + 1);
      for(const auto& t : soup.triangles) soup.polygons.push_back({t[0], t[1], t[2]});
      soup.triangles.clear();
      soup.triangles.shrink_to_fit();
    }
    soup.polygons.push_back(face);
  }
  soup.triangle_lines.push_back(line);
}


namespace internal {

inline std::string face_arity_message(std::size_t face, std::size_t n)
{
  return "face " + std::to_string(face) + " has " + std::to_string(n) + (n == 1 ? " vertex" : " vertices") +
         " (a face needs at least 3)";
}

inline void check_finite_point(const std::array<double, 3>& p, const std::string& file, std::size_t line,
                               std::size_t vertex)
{
  for(int k = 0; k < 3; ++k)
    if(!std::isfinite(p[k]))
      throw Input_error(file, line, "vertex " + std::to_string(vertex) + " has a non-finite coordinate (" +
                                        (std::isnan(p[k]) ? std::string("NaN") : std::string("inf")) + ")");
}

// Reasonable cap for reserve() calls driven by counts read from a file.
inline std::size_t reserve_cap(long long n) { return static_cast<std::size_t>(std::min<long long>(std::max<long long>(n, 0), 1 << 16)); }

inline std::string read_whole_stream(std::istream& is)
{
  std::string s((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  return s;
}

// A soup read by one of CGAL's readers (binary data: no lines): its points, checked finite, and its
// polygons (at least three vertices each).
template <class Point, class Polygon>
void soup_from_points_and_polygons(const std::vector<Point>& points, const std::vector<Polygon>& polygons,
                                   const std::string& file, Triangle_soup& soup)
{
  for(const Point& q : points)
  {
    const std::array<double, 3> p = {static_cast<double>(q[0]), static_cast<double>(q[1]), static_cast<double>(q[2])};
    check_finite_point(p, file, 0, soup.points.size());
    soup.points.push_back(p);
    soup.point_lines.push_back(0);
  }
  for(const Polygon& polygon : polygons)
  {
    if(polygon.size() < 3)
      throw Input_error(file, 0, face_arity_message(number_of_faces(soup), polygon.size()));
    add_face(soup, std::vector<std::size_t>(polygon.begin(), polygon.end()), 0);
  }
}

// ------------------------------------------------------------------------------------------------ checks

// the vertices of face f of the soup, in its order
inline std::vector<std::size_t> soup_face(const Triangle_soup& soup, std::size_t f)
{
  if(!soup.polygons.empty()) return soup.polygons[f];
  return std::vector<std::size_t>(soup.triangles[f].begin(), soup.triangles[f].end());
}

// Zero-area faces are refused with their line, by the library's criterion and scaling (the points brought
// to a unit bounding box: the test depends on the shape of the faces, not on the unit of the file). A face
// of more than three sides is refused when a triangle of the library's triangulation of it has zero area.
inline void check_face_areas(const Triangle_soup& soup, const std::string& file)
{
  namespace SWNI = CGAL::Surface_winding_numbers::internal;
  static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double), "points must be contiguous");
  const double s = SWNI::unit_scale(soup.points.empty() ? nullptr : soup.points[0].data(), soup.points.size());
  std::vector<double> xyz;
  std::vector<std::size_t> corners;
  const std::size_t nf = number_of_faces(soup);
  for(std::size_t f = 0; f < nf; ++f)
  {
    corners = soup_face(soup, f);
    xyz.resize(3 * corners.size());
    for(std::size_t c = 0; c < corners.size(); ++c)
      for(std::size_t k = 0; k < 3; ++k) xyz[3 * c + k] = s * soup.points[corners[c]][k];
    std::vector<std::size_t> local(corners.size());
    for(std::size_t c = 0; c < corners.size(); ++c) local[c] = c;
    for(const auto& t : SWNI::triangulate_polygon(xyz, local))
    {
      if(!SWNI::zero_area_triangle(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]])) continue;
      std::string listed;
      for(std::size_t c = 0; c < corners.size(); ++c) listed += (c ? ", " : "") + std::to_string(corners[c]);
      throw Input_error(file, f < soup.triangle_lines.size() ? soup.triangle_lines[f] : 0,
                        "face " + std::to_string(f) + " has zero area (degenerate " +
                            (corners.size() == 3 ? std::string("triangle): its vertices ") + listed + " are collinear or coincide"
                                                 : "polygon): three of its vertices " + listed +
                                                       " are collinear or coincide where it is triangulated"));
    }
  }
}

inline std::string edge_name(std::size_t a, std::size_t b)
{
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// a corner without twin: its halfedge is on the border (check_triangle_soup())
constexpr std::uint32_t no_twin = (std::numeric_limits<std::uint32_t>::max)();

/// Checks the faces of a soup (triangles or polygons): not empty, not too large, indices in range, no
/// repeated vertex in a face, and in a soup with polygons no zero-area face (check_face_areas(), which a
/// triangle soup gets once it is known whether it is a mesh). Throws `Input_error` on the first problem,
/// with the face's line.
inline void check_soup_faces(const Triangle_soup& soup, const std::string& file)
{
  const std::size_t nv = soup.points.size(), nf = number_of_faces(soup);
  auto fline = [&](std::size_t f) { return f < soup.triangle_lines.size() ? soup.triangle_lines[f] : 0; };
  if(nf == 0)
    throw Input_error(file, 0, nv == 0 ? "empty mesh (no vertices and no faces)" : "the mesh has no faces");
  if(nv >= (std::size_t(1) << 32) || nf >= (std::size_t(1) << 30))
    throw Input_error(file, 0, "mesh too large");
  std::vector<std::size_t> sorted;
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(soup.polygons.empty()) sorted.assign(soup.triangles[f].begin(), soup.triangles[f].end());
    else sorted = soup.polygons[f];
    for(std::size_t v : sorted)
      if(v >= nv)
        throw Input_error(file, fline(f), "face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                              " (0-based) but there are only " + std::to_string(nv) + " vertices");
    std::string listed;   // the face as written, for the message
    for(std::size_t v : sorted) listed += (listed.empty() ? "" : ", ") + std::to_string(v);
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw Input_error(file, fline(f), "face " + std::to_string(f) + " has a repeated vertex (" + listed + ")");
  }
  if(!soup.polygons.empty()) check_face_areas(soup, file);   // the library would refuse them without a line
}

/// Tells whether a triangle soup with checked faces is an oriented 2-manifold: returns "" if it is, else what
/// is wrong (the first problem in file order) and its line in `line`. `twin[3 f + k]` gets the corner whose
/// halfedge runs along that of corner k of face f (from its vertex k to vertex k + 1) the other way, or
/// `no_twin` on a border (for build_oriented_mesh()). Polygon soups are not triangle meshes: "faces with N
/// vertices".
inline std::string oriented_manifold_problem(const Triangle_soup& soup, std::vector<std::uint32_t>& twin, std::size_t& line)
{
  const std::size_t nv = soup.points.size(), nf = soup.triangles.size();
  auto fline = [&](std::size_t f) { return f < soup.triangle_lines.size() ? soup.triangle_lines[f] : 0; };
  auto vline = [&](std::size_t v) { return v < soup.point_lines.size() ? soup.point_lines[v] : 0; };
  line = 0;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
    if(soup.polygons[f].size() != 3)
    {
      line = fline(f);
      return "face " + std::to_string(f) + " has " + std::to_string(soup.polygons[f].size()) + " vertices";
    }
  // outgoing halfedges per vertex (CSR, in face order): (target, face)
  std::vector<std::uint32_t> start(nv + 1, 0);
  for(const auto& t : soup.triangles)
    for(int k = 0; k < 3; ++k) ++start[t[k] + 1];
  for(std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<std::pair<std::uint32_t, std::uint32_t> > out(3 * nf);
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for(std::size_t f = 0; f < nf; ++f)
      for(int k = 0; k < 3; ++k)
        out[fill[soup.triangles[f][k]]++] = {std::uint32_t(soup.triangles[f][(k + 1) % 3]), std::uint32_t(f)};
  }
  // edges: at most two faces, traversed in opposite directions; the problem is reported at the first face (in
  // file order) that creates it. Vertices: the faces around each vertex must form a single fan; the corners
  // of two faces glued along an edge are united as the second face of the pair is met (one scan for both)
  CGAL::Surface_winding_numbers::internal::Union_find uf(3 * nf);
  twin.assign(3 * nf, no_twin);
  auto local = [&](std::size_t f, std::size_t v) {
    const auto& t = soup.triangles[f];
    return 3 * f + (t[0] == v ? 0 : (t[1] == v ? 1 : 2));
  };
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = soup.triangles[f];
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = t[k], b = t[(k + 1) % 3];
      std::size_t same = nf, opp1 = nf, opp2 = nf;  // earlier faces with a->b, and with b->a
      for(std::uint32_t i = start[a]; i < start[a + 1] && out[i].second < f; ++i)
        if(out[i].first == b) { same = out[i].second; break; }
      for(std::uint32_t i = start[b]; i < start[b + 1] && out[i].second < f; ++i)
        if(out[i].first == a) { if(opp1 == nf) opp1 = out[i].second; else { opp2 = out[i].second; break; } }
      line = fline(f);
      if(opp2 != nf || (same != nf && opp1 != nf))
      {
        std::size_t f0 = std::min(same, opp1), f1 = (opp2 != nf) ? opp2 : std::max(same, opp1);
        return "non-manifold edge " + edge_name(std::min(a, b), std::max(a, b)) + ": shared by more than two faces (faces " +
               std::to_string(f0) + ", " + std::to_string(f1) + " and " + std::to_string(f) + ")";
      }
      if(same != nf)
        return "faces " + std::to_string(same) + " and " + std::to_string(f) + " both traverse edge " + edge_name(a, b) +
               " in the same direction: the surface is not consistently oriented (or not orientable)";
      if(opp1 != nf)
      {
        const std::size_t at_b = local(opp1, b);   // opp1's corner at b, whose halfedge runs b -> a
        uf.unite(3 * f + k, local(opp1, a));
        uf.unite(3 * f + (k + 1) % 3, at_b);
        twin[3 * f + k] = std::uint32_t(at_b);
        twin[at_b] = std::uint32_t(3 * f + k);
      }
    }
  }
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> root(nv, none);
  for(std::size_t f = 0; f < nf; ++f)
    for(int k = 0; k < 3; ++k)
    {
      std::size_t v = soup.triangles[f][k];
      std::size_t r = uf.find(3 * f + k);
      if(root[v] == none) root[v] = r;
      else if(root[v] != r)
      {
        line = vline(v);
        return "non-manifold vertex " + std::to_string(v) + ": the faces around it form several separate fans (faces " +
               std::to_string(root[v] / 3) + " and " + std::to_string(f) + ")";
      }
    }
  line = 0;
  return std::string();
}

/// Newell's normal of a face of the soup: twice its area vector (zero iff the face has zero area).
template <class Face>
std::array<double, 3> newell_normal(const Triangle_soup& soup, const Face& face)
{
  std::array<double, 3> n = {0, 0, 0};
  if(face.size() == 3)   // the cross product: exactly zero for collinear corners
  {
    const auto &p = soup.points[face[0]], &q = soup.points[face[1]], &r = soup.points[face[2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    return {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
  }
  for(std::size_t k = 0; k < face.size(); ++k)
  {
    const auto &p = soup.points[face[k]], &q = soup.points[face[(k + 1) % face.size()]];
    n[0] += (p[1] - q[1]) * (p[2] + q[2]);
    n[1] += (p[2] - q[2]) * (p[0] + q[0]);
    n[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return n;
}

/// Fills the statistics of `info` (vertex and face counts, unreferenced vertices, duplicated positions,
/// zero-area faces) and its warnings.
inline void soup_statistics(const Triangle_soup& soup, Mesh_read_info& info)
{
  const std::size_t nv = soup.points.size(), nf = number_of_faces(soup);
  info.number_of_vertices = nv;
  info.number_of_faces = nf;
  std::vector<char> used(nv, 0);
  std::size_t degenerate = 0;
  auto visit = [&](const auto& face) {
    for(std::size_t v : face) used[v] = 1;
    const std::array<double, 3> n = newell_normal(soup, face);
    degenerate += n[0] == 0 && n[1] == 0 && n[2] == 0;
  };
  for(const auto& t : soup.triangles) visit(t);
  for(const auto& p : soup.polygons) visit(p);
  std::vector<std::size_t> unref;
  for(std::size_t v = 0; v < nv; ++v)
    if(!used[v]) unref.push_back(v);
  info.unreferenced_vertices = unref.size();
  if(!unref.empty())
  {
    std::string s = std::to_string(unref.size()) + " unreferenced vertices kept as isolated vertices (";
    for(std::size_t k = 0; k < std::min<std::size_t>(unref.size(), 5); ++k)
      s += (k ? ", " : "") + std::to_string(unref[k]);
    s += unref.size() > 5 ? ", ...)" : ")";
    info.warnings.push_back(s);
  }
  std::vector<std::pair<std::array<double, 3>, std::size_t> > order(nv);
  for(std::size_t v = 0; v < nv; ++v) order[v] = {soup.points[v], v};
  std::sort(order.begin(), order.end());
  std::size_t dup = 0, dup_a = 0, dup_b = 0;
  for(std::size_t k = 1; k < nv; ++k)
    if(order[k].first == order[k - 1].first)
    {
      if(dup == 0) { dup_a = order[k - 1].second; dup_b = order[k].second; }
      ++dup;
    }
  info.duplicated_vertex_positions = dup;
  if(dup > 0)
    info.warnings.push_back(std::to_string(dup) + " vertices have exactly the same position as another vertex (e.g. " +
                            std::to_string(std::min(dup_a, dup_b)) + " and " + std::to_string(std::max(dup_a, dup_b)) +
                            "); kept as distinct vertices");
  info.degenerate_faces = degenerate;
  if(degenerate > 0)
    info.warnings.push_back(std::to_string(degenerate) + " faces have zero area (collinear corners); kept");
}

/// Validates a triangle soup as an oriented 2-manifold (check_soup_faces(), oriented_manifold_problem()) without
/// zero-area faces (check_face_areas()) and fills the statistics of `info`. Throws `Input_error` on the first problem.
inline void check_triangle_soup(const Triangle_soup& soup, const std::string& file, Mesh_read_info& info,
                                std::vector<std::uint32_t>& twin)
{
  check_soup_faces(soup, file);
  std::size_t line = 0;
  const std::string problem = oriented_manifold_problem(soup, twin, line);
  if(!problem.empty())
    throw Input_error(file, line, soup.polygons.empty() ? problem : problem + ": only triangle meshes are supported here");
  check_face_areas(soup, file);
  soup_statistics(soup, info);
}

} // namespace internal

/*!
  \brief builds `mesh` from a triangle soup that `internal::oriented_manifold_problem()` accepted, with the
  `twin` table it filled; same numbering as `triangle_soup_to_mesh()`.
*/
template <class Point>
void build_oriented_mesh(const Triangle_soup& soup, const std::vector<std::uint32_t>& twin, CGAL::Surface_mesh<Point>& mesh)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::size_type size_type;
  // The soup is a valid oriented 2-manifold (with border), so the halfedge structure is wired directly
  // (CGAL::Euler::add_face() searches and checks every edge again: half of the reading time at 1M
  // faces). Edges are created in the order Euler::add_face() creates them, face by face, the face's
  // halfedge first: the same indices as the face-by-face construction.
  mesh.clear();
  const std::size_t nv = soup.points.size(), nf = soup.triangles.size();
  mesh.reserve(static_cast<size_type>(nv), static_cast<size_type>(nf * 3 / 2 + 3), static_cast<size_type>(nf));
  for(const auto& p : soup.points)
    mesh.add_vertex(Point(p[0], p[1], p[2]));
  auto vertex = [&](std::size_t f, int k) { return Vertex_index(static_cast<size_type>(soup.triangles[f][k % 3])); };
  std::vector<Halfedge_index> he(3 * nf);   // by corner: the halfedge from vertex k to vertex k + 1
  for(std::size_t c = 0; c < 3 * nf; ++c)
    he[c] = twin[c] != internal::no_twin && twin[c] < c ? mesh.opposite(he[twin[c]]) : mesh.add_edge();
  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto fi = mesh.add_face();
    for(int k = 0; k < 3; ++k)
    {
      const Halfedge_index h = he[3 * f + k];
      mesh.set_target(h, vertex(f, k + 1));
      mesh.set_next(h, he[3 * f + (k + 1) % 3]);
      mesh.set_face(h, fi);
      mesh.set_halfedge(vertex(f, k + 1), h);
    }
    mesh.set_halfedge(fi, he[3 * f + 2]);   // the halfedge that points to the face's first vertex
  }
  // border halfedges: g runs b -> a opposite a face's a -> b; at a manifold border vertex exactly one
  // border halfedge leaves and one arrives, and halfedge(v) is the arriving one
  std::vector<Halfedge_index> border_out(nv);
  for(std::size_t c = 0; c < 3 * nf; ++c)
    if(twin[c] == internal::no_twin)
    {
      const Halfedge_index g = mesh.opposite(he[c]);
      mesh.set_target(g, vertex(c / 3, int(c % 3)));
      mesh.set_face(g, Mesh::null_face());
      border_out[soup.triangles[c / 3][(c + 1) % 3]] = g;
    }
  for(std::size_t c = 0; c < 3 * nf; ++c)
    if(twin[c] == internal::no_twin)
    {
      const Halfedge_index g = mesh.opposite(he[c]);
      const Vertex_index a = vertex(c / 3, int(c % 3));
      mesh.set_next(g, border_out[std::size_t(a)]);
      mesh.set_halfedge(a, g);
    }
}

/*!
  \brief builds `mesh` from a validated triangle soup, keeping the vertex and face numbering, with
  `halfedge(f, mesh)` pointing to the first vertex of each face.

  The soup is validated first (see the file documentation); `mesh` is cleared.
  \throws Input_error on invalid input, with the line of the offending face or vertex when known.
*/
template <class Point>
void triangle_soup_to_mesh(const Triangle_soup& soup, CGAL::Surface_mesh<Point>& mesh, Mesh_read_info& info,
                           const std::string& file)
{
  std::vector<std::uint32_t> twin;
  internal::check_triangle_soup(soup, file, info, twin);
  build_oriented_mesh(soup, twin, mesh);
}

/*!
  \brief builds `mesh` from `soup` if it is an oriented 2-manifold triangle mesh and returns ""; otherwise
  leaves `mesh` empty and returns why the soup is not one (`FILE:LINE: problem` when the line is known), for
  a solve as a polygon soup. Fills the statistics and warnings of `info` either way.
  \throws Input_error on faces no route takes (out-of-range indices, repeated vertices, no face) and on
  zero-area triangles of a triangle soup
  \param concurrent if `true`, the checks of a large soup (100,000 faces or more) run on two threads
*/
template <class Point>
std::string soup_to_mesh_or_problem(const Triangle_soup& soup, CGAL::Surface_mesh<Point>& mesh, Mesh_read_info& info,
                                    const std::string& file, bool concurrent = true)
{
  mesh.clear();
  internal::check_soup_faces(soup, file);
  auto areas_and_statistics = [&] {
    if(soup.polygons.empty())
      internal::check_face_areas(soup, file);   // the library refuses zero-area triangles: say where, now
    internal::soup_statistics(soup, info);
  };
  // on large inputs they run on a second thread beside the manifold check (chain10, 1.15M faces: the
  // reading step 1.45 -> 1.2 s); a face-area error still comes before the manifold problem
  std::future<void> beside = internal::start_task(!concurrent || number_of_faces(soup) < 100000, areas_and_statistics);
  std::vector<std::uint32_t> twin;
  std::size_t line = 0;
  const std::string problem = internal::oriented_manifold_problem(soup, twin, line);
  beside.get();   // rethrows a face-area error
  if(!problem.empty())
    return line > 0 ? file + ":" + std::to_string(line) + ": " + problem : problem;
  build_oriented_mesh(soup, twin, mesh);
  return problem;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_MESH_SOUP_H
