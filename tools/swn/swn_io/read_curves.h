// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Readers for input curves (authors' curve files, OBJ `l` records, vertex polylines, halfedge chains) into
// a Curve_set, checked against the mesh.

#ifndef CGAL_SWN_TOOL_IO_READ_CURVES_H
#define CGAL_SWN_TOOL_IO_READ_CURVES_H

#include "swn_io/curve_set.h"
#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/*!
  \file read_curves.h

  Curves are read into a `Curve_set`: a list of points (mesh vertices, or points on mesh edges) and a list
  of directed segments between them, plus the dual pairs of `c` records. Every point and segment remembers the
  1-based line it came from, so that later stages (conforming cut, chain construction) can report errors with
  file and line.

  <b>Curve file formats and how the format is chosen</b> (`read_curve_file()` with `Curve_file_format::AUTO`):
  the first line of the file decides. If it is a comment whose words after the `#` are exactly
  `swn polylines` (resp. `swn halfedges`), compared case-insensitively and ignoring extra blanks, the file is a
  vertex-polyline file (resp. a halfedge-chain file). Otherwise it is read as an authors' curve file.

  - <b>Authors' curve file</b> (the `--curve` file of the authors' demo; notes section 5.2), one record per line:
    - `#offset K`: K is added to every later index (vertices, edges, nodes, faces). The default is `-1`
      (1-based indices); the demo files start with `#offset 0`.
    - `v I`: a node at mesh vertex I.
    - `e J T`: a node on edge J of the authors' edge numbering (`authors_edge_numbering()`), at
      `(1-T)*first(J) + T*second(J)`. T must lie in [0,1]; **T == 0 and T == 1 are read as the vertex
      first(J), resp. second(J)** (a vertex point), any other T outside (0,1) is an error.
    - `l N0 N1 ... Nk` (k >= 1): the segments N0->N1, ..., N(k-1)->Nk between nodes, numbered from 0 in order of
      appearance, with the current offset added. They are resolved after the whole file is read, so an `l`
      may name a node defined further down.
    - `c F0 F1 ... Fk`: a dual chain, recorded as the pairs (F0,F1), ..., (F(k-1),Fk).
    - `f ...`: face points are not supported: `Input_error`.
    - `n ...` lines and comments (`#...`, including the switched-off segments `#l ...`) are ignored; any
      other first word is an error.
  - <b>Vertex polylines</b> (`# swn polylines`): one polyline per line, whitespace-separated **0-based** vertex
    indices, at least two per line; `#` starts a comment. A closed loop repeats its first index at the end.
  - <b>Halfedge chain</b> (`# swn halfedges`): lines `h SRC DST [M]` with 0-based vertices; SRC->DST must be an
    edge of the mesh; the optional multiplicity M is an integer in [1, 1000] (default 1); `#` starts a comment.

  Limits: a curve has at most `max_curve_segments()` segments counted with multiplicity (10^6 plus two per
  mesh edge), so that the work and the output stay proportional to the mesh and the file; more is an
  `Input_error` on the line where the limit is passed.

  Errors (all `Input_error` with file and line): unparsable number, index out of range, trailing junk, t outside
  [0,1], a segment whose two points share no face, a face point, an unknown record, and an empty curve (no
  segment and no dual pair at all; reported with line 0). Files are read in a single pass; nothing loops on bad
  input.
*/

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

namespace internal {

/// The most curve segments, counted with multiplicity, a curve file may give on a mesh with `edges` edges:
/// 10^6 plus two per edge. The work and the output grow with this number, not with the size of the file
/// (a line `h A B 1000` is a thousand segments), so a few kilobytes must not ask for gigabytes.
inline std::size_t max_curve_segments(std::size_t edges) { return 1000000 + 2 * edges; }

inline std::string too_many_segments(std::size_t edges)
{
  return "the curve has more than " + std::to_string(max_curve_segments(edges)) +
         " segments (counted with multiplicity; the limit is 10^6 + 2 x " + std::to_string(edges) + " mesh edges)";
}

template <class Point>
void faces_of_point(const CGAL::Surface_mesh<Point>& mesh,
                    const std::vector<typename CGAL::Surface_mesh<Point>::Halfedge_index>& ae,
                    const Curve_point& p, std::vector<std::size_t>& out)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  out.clear();
  if(p.kind == Curve_point::VERTEX)
  {
    typename Mesh::Vertex_index v(static_cast<typename Mesh::size_type>(p.element));
    if(mesh.halfedge(v) == Mesh::null_halfedge()) return;
    for(auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
      if(!mesh.is_border(h)) out.push_back(std::size_t(mesh.face(h)));
  }
  else
  {
    auto h = ae[p.element];
    if(!mesh.is_border(h)) out.push_back(std::size_t(mesh.face(h)));
    if(!mesh.is_border(mesh.opposite(h))) out.push_back(std::size_t(mesh.face(mesh.opposite(h))));
  }
  std::sort(out.begin(), out.end());
}

inline std::string describe_point(const Curve_point& p)
{
  if(p.kind == Curve_point::VERTEX) return "vertex " + std::to_string(p.element);
  std::ostringstream s;
  s.precision(17);
  s << "edge " << p.element << " at t=" << p.t;
  return s.str();
}

/// Checks point ranges, that every segment's points share a face, and that the curve is not empty.
template <class Point>
void validate_curve_set(const Curve_set& cs, const CGAL::Surface_mesh<Point>& mesh,
                        const std::vector<typename CGAL::Surface_mesh<Point>::Halfedge_index>& ae)
{
  for(const Curve_point& p : cs.points)
  {
    if(p.kind == Curve_point::VERTEX && p.element >= mesh.number_of_vertices())
      throw Input_error(cs.file, p.line, "vertex index " + std::to_string(p.element) + " is out of range (" +
                                            std::to_string(mesh.number_of_vertices()) + " vertices)");
    if(p.kind == Curve_point::EDGE)
    {
      if(p.element >= ae.size())
        throw Input_error(cs.file, p.line, "edge index " + std::to_string(p.element) + " is out of range (" +
                                              std::to_string(ae.size()) + " edges)");
      if(!(p.t > 0. && p.t < 1.))
        throw Input_error(cs.file, p.line, "edge parameter t must lie in (0,1)");
    }
  }
  for(const Curve_dual_pair& d : cs.dual_pairs)
    if(d.face_a >= mesh.number_of_faces() || d.face_b >= mesh.number_of_faces())
      throw Input_error(cs.file, d.line, "face index " + std::to_string(std::max(d.face_a, d.face_b)) +
                                            " is out of range (" + std::to_string(mesh.number_of_faces()) + " faces)");
  if(cs.segments.size() > max_curve_segments(mesh.number_of_edges()))
    throw Input_error(cs.file, cs.segments[max_curve_segments(mesh.number_of_edges())].line,
                      too_many_segments(mesh.number_of_edges()));
  std::vector<std::size_t> fa, fb, common;
  for(const Curve_segment& s : cs.segments)
  {
    if(s.a >= cs.points.size() || s.b >= cs.points.size())
      throw Input_error(cs.file, s.line, "segment refers to point " + std::to_string(std::max(s.a, s.b)) +
                                            " but only " + std::to_string(cs.points.size()) + " points are defined");
    const Curve_point& p = cs.points[s.a];
    const Curve_point& q = cs.points[s.b];
    faces_of_point(mesh, ae, p, fa);
    faces_of_point(mesh, ae, q, fb);
    common.clear();
    std::set_intersection(fa.begin(), fa.end(), fb.begin(), fb.end(), std::back_inserter(common));
    bool same = p.kind == q.kind && p.element == q.element && (p.kind == Curve_point::VERTEX || p.t == q.t);
    if(common.empty() && !same)
      throw Input_error(cs.file, s.line, "the segment from " + describe_point(p) + " to " + describe_point(q) +
                                            " does not lie in a single face (its points share no face)");
  }
  if(cs.segments.empty() && cs.dual_pairs.empty())
    throw Input_error(cs.file, 0, "the curve is empty (no segment)");
}

inline std::size_t add_offset(long long idx, long long offset, const Line_reader& lr, const char* what)
{
  long long r;
  if(!add_index_offset(idx, offset, r))
    lr.fail(std::string(what) + " index " + std::to_string(idx) + " is out of range (offset " + std::to_string(offset) + ")");
  return static_cast<std::size_t>(r);
}

inline long long int_token(std::string_view tok, const Line_reader& lr)
{
  long long i;
  if(!parse_int(tok, i))
    lr.fail("cannot parse integer " + quote(tok));
  return i;
}

inline Curve_file_format detect_format_from_first_line(const std::string& first)
{
  std::string_view s(first);
  std::vector<std::string_view> tok;
  split_tokens(s, tok);
  if(tok.empty() || tok[0][0] != '#') return Curve_file_format::AUTHORS;
  std::vector<std::string> words;
  if(tok[0].size() > 1) words.push_back(lower(tok[0].substr(1)));
  for(std::size_t k = 1; k < tok.size(); ++k) words.push_back(lower(tok[k]));
  if(words.size() == 2 && words[0] == "swn")
  {
    if(words[1] == "polylines") return Curve_file_format::POLYLINES;
    if(words[1] == "halfedges") return Curve_file_format::HALFEDGES;
  }
  return Curve_file_format::AUTHORS;
}

// The authors' format over nv vertices and nf faces; edge points refer to n_edges edges of the authors'
// numbering, and edge_end(e, k) is the vertex first(e) (k = 0) or second(e) (k = 1). Without edges (a
// polygon soup) edge points are an error.
template <class EdgeEnd>
Curve_set read_authors_curves(std::istream& is, const std::string& file, std::size_t nv, std::size_t nf,
                              std::size_t n_edges, EdgeEnd edge_end)
{
  Curve_set cs;
  cs.file = file;
  Line_reader lr(is, file);
  std::string line;
  std::vector<std::string_view> tok;
  long long offset = -1;
  struct Pending { std::vector<std::size_t> nodes; std::size_t line; };
  std::vector<Pending> pending;

  while(next_record(lr, line, tok, offset))
  {
    std::string_view kw = tok[0];
    if(kw == "v")
    {
      if(tok.size() < 2) lr.fail("'v' record without a vertex index");
      if(tok.size() > 2) lr.fail("trailing junk " + quote(tok[2]) + " after the vertex index");
      std::size_t v = add_offset(int_token(tok[1], lr), offset, lr, "vertex");
      if(v >= nv)
        lr.fail("vertex index " + std::to_string(v) + " (0-based) is out of range (" + std::to_string(nv) + " vertices)");
      Curve_point p;
      p.kind = Curve_point::VERTEX; p.element = v; p.line = lr.line_number();
      cs.points.push_back(p);
    }
    else if(kw == "e")
    {
      if(tok.size() < 3) lr.fail("'e' record needs an edge index and a parameter t");
      if(tok.size() > 3) lr.fail("trailing junk " + quote(tok[3]) + " after the edge parameter");
      std::size_t e = add_offset(int_token(tok[1], lr), offset, lr, "edge");
      if(n_edges == 0)
        lr.fail("edge points ('e' records) need a triangle mesh that is an oriented 2-manifold (this mesh is read as "
                "a polygon soup): give the curve by vertices");
      if(e >= n_edges)
        lr.fail("edge index " + std::to_string(e) + " (0-based) is out of range (" + std::to_string(n_edges) + " edges)");
      double t;
      if(!parse_double(tok[2], t))
        lr.fail("cannot parse the edge parameter " + quote(tok[2]));
      if(!(t >= 0. && t <= 1.))
        lr.fail("edge parameter t = " + std::string(tok[2]) + " is not in [0,1]");
      Curve_point p;
      p.line = lr.line_number();
      if(t == 0. || t == 1.)
      {
        p.kind = Curve_point::VERTEX;
        p.element = edge_end(e, t == 0. ? 0 : 1);
      }
      else
      {
        p.kind = Curve_point::EDGE; p.element = e; p.t = t;
      }
      cs.points.push_back(p);
    }
    else if(kw == "f")
      lr.fail("face points ('f' records) are not supported");
    else if(kw == "l")
    {
      if(tok.size() < 3) lr.fail("an 'l' record needs at least two node indices");
      Pending p; p.line = lr.line_number();
      for(std::size_t k = 1; k < tok.size(); ++k)
        p.nodes.push_back(add_offset(int_token(tok[k], lr), offset, lr, "node"));
      pending.push_back(std::move(p));
    }
    else if(kw == "c")
    {
      if(tok.size() < 3) lr.fail("a 'c' record needs at least two face indices");
      std::vector<std::size_t> faces;
      for(std::size_t k = 1; k < tok.size(); ++k)
      {
        std::size_t f = add_offset(int_token(tok[k], lr), offset, lr, "face");
        if(f >= nf)
          lr.fail("face index " + std::to_string(f) + " (0-based) is out of range (" + std::to_string(nf) + " faces)");
        faces.push_back(f);
      }
      for(std::size_t k = 0; k + 1 < faces.size(); ++k)
        cs.dual_pairs.push_back(Curve_dual_pair{faces[k], faces[k + 1], lr.line_number(), offset});
    }
    else if(kw == "n")
      continue;
    else
      lr.fail("unknown curve record " + quote(kw));
  }
  if(is.bad())
    throw Input_error(file, 0, "read error");
  for(const Pending& p : pending)
  {
    for(std::size_t n : p.nodes)
      if(n >= cs.points.size())
        throw Input_error(file, p.line, "node index " + std::to_string(n) + " (0-based) is out of range (" +
                                            std::to_string(cs.points.size()) + " nodes defined in the file)");
    for(std::size_t k = 0; k + 1 < p.nodes.size(); ++k)
      cs.segments.push_back(Curve_segment{p.nodes[k], p.nodes[k + 1], p.line});
  }
  return cs;
}

// Point index of vertex v in cs (one point per distinct vertex).
inline std::size_t vertex_point(Curve_set& cs, std::map<std::size_t, std::size_t>& index, std::size_t v, std::size_t line)
{
  auto ins = index.emplace(v, cs.points.size());
  if(ins.second)
  {
    Curve_point p;
    p.kind = Curve_point::VERTEX; p.element = v; p.line = line;
    cs.points.push_back(p);
  }
  return ins.first->second;
}

// Reads a curve file of 0-based vertex records, one per line ('#' starts a comment): `record(tok, lr, cs,
// vertex)` reads the tokens of a line into `cs`, where `vertex(token)` parses a vertex index, checks it and
// returns its point in `cs` (one point per vertex).
template <class Record>
Curve_set read_vertex_records(std::istream& is, const std::string& file, std::size_t nv, Record record)
{
  Curve_set cs;
  cs.file = file;
  Line_reader lr(is, file);
  std::string line;
  std::vector<std::string_view> tok;
  std::map<std::size_t, std::size_t> index;
  auto vertex = [&](std::string_view token) {
    const long long i = int_token(token, lr);
    if(i < 0 || static_cast<unsigned long long>(i) >= nv)
      lr.fail("vertex index " + std::to_string(i) + " is out of range (" + std::to_string(nv) + " vertices, 0-based)");
    return vertex_point(cs, index, static_cast<std::size_t>(i), lr.line_number());
  };
  while(lr.next(line))
  {
    split_tokens(strip_comment(line), tok);
    if(!tok.empty()) record(tok, lr, cs, vertex);
  }
  if(is.bad())
    throw Input_error(file, 0, "read error");
  return cs;
}

inline Curve_set read_polyline_curves(std::istream& is, const std::string& file, std::size_t nv)
{
  return read_vertex_records(is, file, nv,
                             [](const std::vector<std::string_view>& tok, const Line_reader& lr, Curve_set& cs, auto& vertex) {
    if(tok.size() < 2)
      lr.fail("a polyline needs at least two vertex indices");
    std::size_t prev = vertex(tok[0]);
    for(std::size_t k = 1; k < tok.size(); ++k)
    {
      const std::size_t pt = vertex(tok[k]);
      cs.segments.push_back(Curve_segment{prev, pt, lr.line_number()});
      prev = pt;
    }
  });
}

// is_edge(s, t): are the vertices s != t joined by an edge; `edges`: how many edges the surface has (for
// max_curve_segments())
template <class IsEdge>
Curve_set read_halfedge_curves(std::istream& is, const std::string& file, std::size_t nv, std::size_t edges, IsEdge is_edge)
{
  return read_vertex_records(is, file, nv,
                             [&](const std::vector<std::string_view>& tok, const Line_reader& lr, Curve_set& cs, auto& vertex) {
    if(tok[0] != "h")
      lr.fail("unknown record " + quote(tok[0]) + " (expected 'h SRC DST [MULTIPLICITY]')");
    if(tok.size() < 3)
      lr.fail("an 'h' record needs a source and a target vertex");
    if(tok.size() > 4)
      lr.fail("trailing junk " + quote(tok[4]) + " after the multiplicity");
    const long long m = tok.size() == 4 ? int_token(tok[3], lr) : 1;
    if(m < 1 || m > 1000)
      lr.fail("multiplicity " + std::to_string(m) + " is not in [1, 1000]");
    const std::size_t a = vertex(tok[1]), b = vertex(tok[2]);
    const std::size_t s = cs.points[a].element, t = cs.points[b].element;
    if(s == t || !is_edge(s, t))
      lr.fail("halfedge " + std::to_string(s) + " -> " + std::to_string(t) + " is not an edge of the mesh");
    if(cs.segments.size() + static_cast<std::size_t>(m) > max_curve_segments(edges))
      lr.fail(too_many_segments(edges));
    for(long long k = 0; k < m; ++k)
      cs.segments.push_back(Curve_segment{a, b, lr.line_number()});
  });
}

// The `l` and `c` records of an OBJ file as a Curve_set, unchecked.
inline Curve_set obj_curve_records(const Mesh_read_info& info)
{
  Curve_set cs;
  cs.file = info.file;
  std::map<std::size_t, std::size_t> index;
  for(const Obj_polyline& pl : info.obj_polylines)
    for(std::size_t k = 0; k < pl.vertices.size(); ++k)
    {
      std::size_t pt = vertex_point(cs, index, pl.vertices[k], pl.line);
      if(k > 0)
        cs.segments.push_back(Curve_segment{vertex_point(cs, index, pl.vertices[k - 1], pl.line), pt, pl.line});
    }
  for(const Obj_dual_chain& dc : info.obj_dual_chains)
    for(std::size_t k = 0; k + 1 < dc.faces.size(); ++k)
      cs.dual_pairs.push_back(Curve_dual_pair{dc.faces[k], dc.faces[k + 1], dc.line});
  return cs;
}

// Reads the whole stream, sets `format` from its first line and returns the text to read it from.
inline std::istringstream detect_curve_format(std::istream& is, const std::string& file, Curve_file_format& format)
{
  std::string all((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  if(is.bad()) throw Input_error(file, 0, "read error");
  std::string first = all.substr(0, all.find('\n'));
  if(!first.empty() && first.back() == '\r') first.pop_back();
  if(first.size() >= 3 && first.compare(0, 3, "\xEF\xBB\xBF") == 0) first.erase(0, 3);
  format = detect_format_from_first_line(first);
  return std::istringstream(std::move(all));
}

} // namespace internal


/*!
  \brief reads a curve from a stream, in the given format (`AUTO`: decided by the first line, see the file
  documentation), validates it against `mesh` and returns it.

  \param is the stream
  \param file the name used in error messages and stored in `Curve_set::file`
  \param mesh the mesh the indices refer to (as read by `read_mesh()`, for the authors' edge numbering)
  \param format the format, or `Curve_file_format::AUTO`
  \throws Input_error on any invalid input
*/
template <class Point>
Curve_set read_curves(std::istream& is, const std::string& file, const CGAL::Surface_mesh<Point>& mesh,
                      Curve_file_format format = Curve_file_format::AUTO)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  auto ae = authors_edge_halfedges(mesh);
  if(format == Curve_file_format::AUTO)
  {
    std::istringstream ss = internal::detect_curve_format(is, file, format);
    return read_curves(ss, file, mesh, format);
  }
  const std::size_t nv = mesh.number_of_vertices();
  Curve_set cs;
  if(format == Curve_file_format::POLYLINES) cs = internal::read_polyline_curves(is, file, nv);
  else if(format == Curve_file_format::HALFEDGES)
    cs = internal::read_halfedge_curves(is, file, nv, mesh.number_of_edges(), [&](std::size_t s, std::size_t t) {
      return CGAL::halfedge(typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(s)),
                            typename Mesh::Vertex_index(static_cast<typename Mesh::size_type>(t)), mesh).second;
    });
  else
    cs = internal::read_authors_curves(is, file, nv, mesh.number_of_faces(), ae.size(), [&](std::size_t e, int k) {
      return std::size_t(k == 0 ? mesh.source(ae[e]) : mesh.target(ae[e]));
    });
  internal::validate_curve_set(cs, mesh, ae);
  return cs;
}

/*!
  \brief reads a curve file (see the file documentation for the formats and the detection rule) and
  validates it against `mesh`.
  \throws Input_error on a missing file or any invalid input
*/
template <class Point>
Curve_set read_curve_file(const std::string& filename, const CGAL::Surface_mesh<Point>& mesh,
                          Curve_file_format format = Curve_file_format::AUTO)
{
  std::ifstream is = internal::open_input_file(filename, "a curve file");
  return read_curves(is, filename, mesh, format);
}

/*!
  \brief converts the inline `l` (vertex polylines) and `c` (dual chains) records of an OBJ file, as collected
  by `read_mesh()`, into a `Curve_set`, and validates it against `mesh` (consecutive polyline vertices must
  share a face, i.e. be adjacent).

  Returns an empty set (no exception) if the OBJ file has no `l` and no `c` record; use
  `has_curve_records()` to tell.
  \throws Input_error on a segment whose points share no face
*/
template <class Point>
Curve_set curve_set_from_obj(const Mesh_read_info& info, const CGAL::Surface_mesh<Point>& mesh)
{
  Curve_set cs = internal::obj_curve_records(info);
  if(cs.segments.empty() && cs.dual_pairs.empty())
    return cs;
  internal::validate_curve_set(cs, mesh, authors_edge_halfedges(mesh));
  return cs;
}

/*!
  \brief tells whether an OBJ file had inline curve records (`l` or `c`).
*/
inline bool has_curve_records(const Mesh_read_info& info)
{
  return !info.obj_polylines.empty() || !info.obj_dual_chains.empty();
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_CURVES_H
