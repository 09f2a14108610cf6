// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Order-preserving, validating readers for triangle meshes in OFF, OBJ, PLY and STL.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_IO_READ_MESH_H
#define CGAL_SURFACE_WINDING_NUMBERS_IO_READ_MESH_H

#include <CGAL/Surface_winding_numbers/IO/errors.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>

#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

/*!
  \file read_mesh.h

  Readers for triangle meshes that keep the file's numbering: vertex `i` of the file becomes
  `Surface_mesh` vertex index `i` and face `j` of the file becomes face index `j`. In addition the halfedge
  of every face, `halfedge(f, mesh)`, points to the face's **first** vertex as written in the file, so that
  `vertices_around_face(halfedge(f, mesh), mesh)` lists the face's vertices in file order (this is what the
  authors' edge numbering of `curve_io.h` relies on).

  Validation: the readers report, and never repair. They throw `Input_error` (with file name and 1-based line
  number where a line exists) on: a missing or unreadable file, an unparsable line, an index out of range, a
  face that is not a triangle, a NaN or infinite coordinate, a face with a repeated vertex, a mesh without
  faces, and a surface that is not an oriented 2-manifold (an edge shared by more than two faces, two faces
  traversing an edge in the same direction, or a vertex where several fans of faces meet). Unreferenced
  vertices are kept as isolated vertices and reported in `Mesh_read_info`, as are exactly duplicated vertex
  positions and (STL only) merged vertices. Indices quoted in messages are 0-based vertex/face indices.
*/

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
  /// faces with exactly zero area (collinear corners); kept
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
  /// 1-based line of each triangle (0 for binary data)
  std::vector<std::size_t> triangle_lines;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

inline std::string face_arity_message(std::size_t face, std::size_t n)
{
  if(n < 3)
    return "face " + std::to_string(face) + " has " + std::to_string(n) +
           (n == 1 ? " vertex" : " vertices") + " (a face needs at least 3)";
  return "face " + std::to_string(face) + " has " + std::to_string(n) +
         " vertices: only triangle meshes are supported";
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

// ------------------------------------------------------------------------------------------------ OBJ

inline bool obj_ignored_keyword(std::string_view kw)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "mtllib", "usemtl", "o", "g", "s", "p", "mg", "maplib", "usemap", "lod", "bevel",
    "c_interp", "d_interp", "shadow_obj", "trace_obj", "ctech", "stech", "cstype", "deg", "bmat", "step",
    "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp", "end", "con", "call", "csh"};
  for(const char* k : ignored)
    if(kw == k) return true;
  return false;
}

// Parses the vertex part of an OBJ index token ("12", "12/", "12/5", "12/5/3", "12//3").
inline bool obj_index_token(std::string_view tok, long long& idx)
{
  std::size_t slash = tok.find('/');
  std::string_view head = tok.substr(0, slash);
  if(!parse_int(head, idx)) return false;
  if(slash == std::string_view::npos) return true;
  // the remaining fields must be empty or integers, at most two of them
  std::string_view rest = tok.substr(slash + 1);
  int fields = 0;
  while(true)
  {
    ++fields;
    std::size_t s2 = rest.find('/');
    std::string_view f = rest.substr(0, s2);
    long long dummy;
    if(!f.empty() && !parse_int(f, dummy)) return false;
    if(s2 == std::string_view::npos) break;
    rest = rest.substr(s2 + 1);
  }
  return fields <= 2;
}

inline void read_OBJ_soup(std::istream& is, const std::string& file, Triangle_soup& soup, Mesh_read_info& info)
{
  Line_reader lr(is, file);
  std::string line;
  std::vector<std::string_view> tok;
  long long offset = -1;

  struct Pending { std::vector<long long> idx; std::size_t line; };
  std::vector<Pending> polylines, chains;

  while(lr.next(line))
  {
    split_tokens(line, tok);
    if(tok.empty()) continue;
    std::string_view kw = tok[0];
    if(kw[0] == '#')
    {
      if(kw == "#offset")
      {
        long long k;
        if(tok.size() != 2 || !parse_int(tok[1], k))
          lr.fail("malformed '#offset' directive (expected '#offset INTEGER')");
        offset = k;
      }
      continue;
    }
    if(kw == "v")
    {
      if(tok.size() < 4)
        lr.fail("vertex record with fewer than 3 coordinates");
      if(tok.size() > 8)
        lr.fail("vertex record with too many values (trailing junk?)");
      std::array<double, 3> p;
      for(std::size_t k = 1; k < tok.size(); ++k)
      {
        double x;
        if(!parse_double(tok[k], x))
          lr.fail("cannot parse number " + quote(tok[k]) + " in vertex record");
        if(k <= 3) p[k - 1] = x;
      }
      check_finite_point(p, file, lr.line_number(), soup.points.size());
      soup.points.push_back(p);
      soup.point_lines.push_back(lr.line_number());
    }
    else if(kw == "f")
    {
      std::size_t n = tok.size() - 1;
      if(n != 3)
        lr.fail(face_arity_message(soup.triangles.size(), n));
      std::array<std::size_t, 3> t;
      for(std::size_t k = 0; k < 3; ++k)
      {
        long long i;
        if(!obj_index_token(tok[k + 1], i))
          lr.fail("cannot parse face index " + quote(tok[k + 1]));
        long long r;
        if(i > 0) r = i - 1;
        else if(i < 0) r = static_cast<long long>(soup.points.size()) + i;
        else lr.fail("face index 0 is invalid (OBJ indices start at 1)");
        if(r < 0)
          lr.fail("relative face index " + std::to_string(i) + " points before the first vertex");
        t[k] = static_cast<std::size_t>(r);
      }
      soup.triangles.push_back(t);
      soup.triangle_lines.push_back(lr.line_number());
    }
    else if(kw == "l" || kw == "c")
    {
      bool is_l = (kw == "l");
      if(tok.size() < 3)
        lr.fail(std::string("an '") + std::string(kw) + "' record needs at least two indices");
      Pending p; p.line = lr.line_number();
      for(std::size_t k = 1; k < tok.size(); ++k)
      {
        long long i;
        bool ok = is_l ? obj_index_token(tok[k], i) : parse_int(tok[k], i);
        if(!ok)
          lr.fail("cannot parse index " + quote(tok[k]) + " in '" + std::string(kw) + "' record");
        long long r;
        if(i < 0)  // OBJ relative index
          r = static_cast<long long>(is_l ? soup.points.size() : soup.triangles.size()) + i;
        else
          r = i + offset;
        if(r < 0)
          lr.fail("index " + std::to_string(i) + " in '" + std::string(kw) + "' record is out of range (offset " +
                  std::to_string(offset) + ")");
        p.idx.push_back(r);
      }
      (is_l ? polylines : chains).push_back(std::move(p));
    }
    else if(obj_ignored_keyword(kw))
      continue;
    else
      lr.fail("unknown OBJ record " + quote(kw));
  }
  if(is.bad())
    throw Input_error(file, 0, "read error");

  for(const Pending& p : polylines)
  {
    Obj_polyline pl; pl.line = p.line;
    for(long long i : p.idx)
    {
      if(static_cast<std::size_t>(i) >= soup.points.size())
        throw Input_error(file, p.line, "vertex index " + std::to_string(i) + " (0-based) in 'l' record is out of range (" +
                                            std::to_string(soup.points.size()) + " vertices)");
      pl.vertices.push_back(static_cast<std::size_t>(i));
    }
    info.obj_polylines.push_back(std::move(pl));
  }
  for(const Pending& p : chains)
  {
    Obj_dual_chain dc; dc.line = p.line;
    for(long long i : p.idx)
    {
      if(static_cast<std::size_t>(i) >= soup.triangles.size())
        throw Input_error(file, p.line, "face index " + std::to_string(i) + " (0-based) in 'c' record is out of range (" +
                                            std::to_string(soup.triangles.size()) + " faces)");
      dc.faces.push_back(static_cast<std::size_t>(i));
    }
    info.obj_dual_chains.push_back(std::move(dc));
  }
}

// ------------------------------------------------------------------------------------------------ OFF

inline void read_OFF_soup(std::istream& is, const std::string& file, Triangle_soup& soup, Mesh_read_info&)
{
  Line_reader lr(is, file);
  std::string line;
  std::vector<std::string_view> tok;

  // returns false at end of file; skips blank and comment-only lines
  auto next_content = [&]() -> bool {
    while(lr.next(line))
    {
      std::string_view s = strip_comment(line);
      split_tokens(s, tok);
      if(!tok.empty()) return true;
    }
    return false;
  };

  if(!next_content())
    throw Input_error(file, 0, "empty file (no OFF header)");
  // header: [ST][C][N][4][n]OFF, possibly followed by the counts on the same line
  std::string head(tok[0]);
  std::size_t first_count = 1;
  {
    bool ok = head.size() >= 3 && head.compare(head.size() - 3, 3, "OFF") == 0;
    std::string prefix = ok ? head.substr(0, head.size() - 3) : std::string();
    if(ok)
    {
      std::size_t p = 0;
      if(prefix.compare(0, 2, "ST") == 0) p = 2;
      if(p < prefix.size() && prefix[p] == 'C') ++p;
      if(p < prefix.size() && prefix[p] == 'N') ++p;
      if(p < prefix.size() && (prefix[p] == '4' || prefix[p] == 'n'))
        lr.fail("OFF variant " + quote(head) + " (4D or nD) is not supported");
      ok = (p == prefix.size());
    }
    if(!ok)
      lr.fail("missing OFF header (first line is " + quote(tok[0]) + ")");
    if(tok.size() > 1 && lower(tok[1]) == "binary")
      lr.fail("binary OFF is not supported");
  }
  if(tok.size() == first_count)
  {
    if(!next_content())
      throw Input_error(file, lr.line_number(), "unexpected end of file: missing vertex/face counts");
    first_count = 0;
  }
  if(tok.size() - first_count < 2 || tok.size() - first_count > 3)
    lr.fail("expected 'NV NF [NE]' counts");
  long long nv, nf, ne = 0;
  if(!parse_int(tok[first_count], nv) || !parse_int(tok[first_count + 1], nf) ||
     (tok.size() - first_count == 3 && !parse_int(tok[first_count + 2], ne)) || nv < 0 || nf < 0 || ne < 0)
    lr.fail("cannot parse the vertex/face counts");
  soup.points.reserve(reserve_cap(nv));
  soup.triangles.reserve(reserve_cap(nf));

  for(long long i = 0; i < nv; ++i)
  {
    if(!next_content())
      throw Input_error(file, lr.line_number(), "unexpected end of file: expected " + std::to_string(nv) +
                                                     " vertices, found " + std::to_string(i));
    if(tok.size() < 3)
      lr.fail("vertex record with fewer than 3 coordinates");
    std::array<double, 3> p;
    for(std::size_t k = 0; k < tok.size(); ++k)
    {
      double x;
      if(!parse_double(tok[k], x))
        lr.fail("cannot parse number " + quote(tok[k]) + " in vertex record");
      if(k < 3) p[k] = x;
    }
    check_finite_point(p, file, lr.line_number(), soup.points.size());
    soup.points.push_back(p);
    soup.point_lines.push_back(lr.line_number());
  }
  for(long long j = 0; j < nf; ++j)
  {
    if(!next_content())
      throw Input_error(file, lr.line_number(), "unexpected end of file: expected " + std::to_string(nf) +
                                                     " faces, found " + std::to_string(j));
    long long k;
    if(!parse_int(tok[0], k) || k < 0)
      lr.fail("cannot parse the vertex count " + quote(tok[0]) + " of a face");
    if(static_cast<std::size_t>(k) + 1 > tok.size())
      lr.fail("face record announces " + std::to_string(k) + " vertices but has fewer indices");
    if(k != 3)
      lr.fail(face_arity_message(static_cast<std::size_t>(j), static_cast<std::size_t>(k)));
    std::array<std::size_t, 3> t;
    for(std::size_t c = 0; c < 3; ++c)
    {
      long long i;
      if(!parse_int(tok[c + 1], i))
        lr.fail("cannot parse face index " + quote(tok[c + 1]));
      if(i < 0)
        lr.fail("negative face index " + std::to_string(i));
      t[c] = static_cast<std::size_t>(i);
    }
    for(std::size_t c = 4; c < tok.size(); ++c)  // optional colour
    {
      double x;
      if(!parse_double(tok[c], x))
        lr.fail("trailing junk " + quote(tok[c]) + " after the face indices");
    }
    soup.triangles.push_back(t);
    soup.triangle_lines.push_back(lr.line_number());
  }
  if(next_content())
    lr.fail("trailing junk after the last face (" + quote(tok[0]) + ")");
}

// ------------------------------------------------------------------------------------------------ STL

inline void add_stl_triangle(const std::array<std::array<double, 3>, 3>& tri, std::size_t line, std::size_t facet,
                             const std::string& file, Triangle_soup& soup,
                             std::map<std::array<double, 3>, std::size_t>& index, Mesh_read_info& info)
{
  std::array<std::size_t, 3> t;
  for(int k = 0; k < 3; ++k)
  {
    for(int c = 0; c < 3; ++c)
      if(!std::isfinite(tri[k][c]))
        throw Input_error(file, line, "facet " + std::to_string(facet) + " has a non-finite coordinate");
    std::array<double, 3> p = tri[k];
    for(int c = 0; c < 3; ++c) if(p[c] == 0.) p[c] = 0.;  // -0 == +0
    auto ins = index.emplace(p, soup.points.size());
    if(ins.second)
    {
      soup.points.push_back(p);
      soup.point_lines.push_back(line);
    }
    else
      ++info.merged_stl_vertices;
    t[k] = ins.first->second;
  }
  soup.triangles.push_back(t);
  soup.triangle_lines.push_back(line);
}

inline void read_STL_soup(std::istream& is, const std::string& file, Triangle_soup& soup, Mesh_read_info& info)
{
  std::string data = read_whole_stream(is);
  if(is.bad())
    throw Input_error(file, 0, "read error");
  std::map<std::array<double, 3>, std::size_t> index;

  bool binary = false;
  std::uint32_t count = 0;
  if(data.size() >= 84)
  {
    const unsigned char* c = reinterpret_cast<const unsigned char*>(data.data()) + 80;
    count = std::uint32_t(c[0]) | (std::uint32_t(c[1]) << 8) | (std::uint32_t(c[2]) << 16) | (std::uint32_t(c[3]) << 24);
    if(84 + 50 * static_cast<std::uint64_t>(count) == data.size())
      binary = true;
  }
  std::size_t first = 0;
  while(first < data.size() && is_space(data[first])) ++first;
  bool ascii = !binary && data.compare(first, 5, "solid") == 0;
  if(!binary && !ascii)
  {
    if(data.size() >= 84)
      throw Input_error(file, 0, "not a valid STL file: binary size " + std::to_string(data.size()) +
                                     " does not match the " + std::to_string(count) + " announced facets");
    throw Input_error(file, 0, "not a valid STL file (too short for binary STL, no 'solid' keyword)");
  }
  if(binary)
  {
    const char* d = data.data() + 84;
    auto rd = [](const char* p) {
      unsigned char b[4];
      std::memcpy(b, p, 4);
      std::uint32_t u = std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
      float f;
      std::memcpy(&f, &u, 4);
      return static_cast<double>(f);
    };
    for(std::uint32_t i = 0; i < count; ++i, d += 50)
    {
      std::array<std::array<double, 3>, 3> tri;
      for(int k = 0; k < 3; ++k)
        for(int c = 0; c < 3; ++c)
          tri[k][c] = rd(d + 12 + 12 * k + 4 * c);
      add_stl_triangle(tri, 0, i, file, soup, index, info);
    }
  }
  else
  {
    // ASCII: a token stream with line numbers
    std::istringstream ss(data);
    Line_reader lr(ss, file);
    std::string line;
    std::vector<std::string_view> tok;
    std::vector<std::pair<std::string, std::size_t> > toks;  // (lower-cased token, line)
    while(lr.next(line))
    {
      split_tokens(line, tok);
      for(std::string_view t : tok) toks.emplace_back(std::string(t), lr.line_number());
    }
    std::size_t p = 0, facet = 0;
    std::size_t last_line = lr.line_number();
    auto line_at = [&](std::size_t q) { return q < toks.size() ? toks[q].second : last_line; };
    auto expect = [&](const char* kw) {
      if(p >= toks.size() || lower(toks[p].first) != kw)
        throw Input_error(file, line_at(p), std::string("expected '") + kw + "'" +
                                                (p < toks.size() ? ", found " + quote(toks[p].first) : std::string(" before end of file")));
      ++p;
    };
    auto number = [&]() {
      double x;
      if(p >= toks.size() || !parse_double(toks[p].first, x))
        throw Input_error(file, line_at(p), "cannot parse number" + (p < toks.size() ? " " + quote(toks[p].first) : std::string()));
      ++p;
      return x;
    };
    bool any_solid = false;
    while(p < toks.size())
    {
      expect("solid");
      any_solid = true;
      // optional name: everything up to the next 'facet'/'endsolid' on the same line
      std::size_t solid_line = toks[p - 1].second;
      while(p < toks.size() && toks[p].second == solid_line && lower(toks[p].first) != "facet" &&
            lower(toks[p].first) != "endsolid")
        ++p;
      while(p < toks.size() && lower(toks[p].first) == "facet")
      {
        std::size_t facet_line = toks[p].second;
        ++p;
        expect("normal");
        number(); number(); number();
        expect("outer");
        expect("loop");
        std::array<std::array<double, 3>, 3> tri;
        std::size_t nvert = 0;
        while(p < toks.size() && lower(toks[p].first) == "vertex")
        {
          std::size_t vline = toks[p].second;
          ++p;
          for(std::size_t c = 0; c < 3; ++c)
            if(p + c >= toks.size() || toks[p + c].second != vline)
              throw Input_error(file, vline, "'vertex' record with fewer than 3 coordinates");
          std::array<double, 3> v;
          v[0] = number(); v[1] = number(); v[2] = number();
          if(nvert < 3) tri[nvert] = v;
          ++nvert;
        }
        if(nvert != 3)
          throw Input_error(file, facet_line, face_arity_message(facet, nvert));
        expect("endloop");
        expect("endfacet");
        add_stl_triangle(tri, facet_line, facet, file, soup, index, info);
        ++facet;
      }
      expect("endsolid");
      std::size_t end_line = toks[p - 1].second;
      while(p < toks.size() && toks[p].second == end_line && lower(toks[p].first) != "solid")
        ++p;  // optional name
    }
    if(!any_solid)
      throw Input_error(file, 0, "empty STL file");
  }
  if(info.merged_stl_vertices > 0)
    info.warnings.push_back("STL: " + std::to_string(info.merged_stl_vertices) +
                            " corner records merged into " + std::to_string(soup.points.size()) +
                            " vertices (exactly equal coordinates)");
}

// ------------------------------------------------------------------------------------------------ PLY

enum class Ply_type { NONE, INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64 };

inline Ply_type ply_type(std::string_view s)
{
  if(s == "char" || s == "int8") return Ply_type::INT8;
  if(s == "uchar" || s == "uint8") return Ply_type::UINT8;
  if(s == "short" || s == "int16") return Ply_type::INT16;
  if(s == "ushort" || s == "uint16") return Ply_type::UINT16;
  if(s == "int" || s == "int32") return Ply_type::INT32;
  if(s == "uint" || s == "uint32") return Ply_type::UINT32;
  if(s == "float" || s == "float32") return Ply_type::FLOAT32;
  if(s == "double" || s == "float64") return Ply_type::FLOAT64;
  return Ply_type::NONE;
}

inline std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
    case Ply_type::INT8: case Ply_type::UINT8: return 1;
    case Ply_type::INT16: case Ply_type::UINT16: return 2;
    case Ply_type::INT32: case Ply_type::UINT32: case Ply_type::FLOAT32: return 4;
    case Ply_type::FLOAT64: return 8;
    default: return 0;
  }
}

inline bool ply_is_integer(Ply_type t) { return t != Ply_type::FLOAT32 && t != Ply_type::FLOAT64; }

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::NONE;
  bool is_list = false;
  Ply_type count_type = Ply_type::NONE;
};

struct Ply_element
{
  std::string name;
  long long count = 0;
  std::size_t line = 0;
  std::vector<Ply_property> props;
};

// Value source for the PLY body: ASCII tokens or binary bytes.
class Ply_body
{
public:
  Ply_body(const std::string& data, std::size_t pos, int format, std::size_t first_line, const std::string& file)
    : data_(data), pos_(pos), format_(format), line_(first_line), file_(file)
  {}

  // reads one scalar as double (exact for all integer types)
  double read(Ply_type t)
  {
    if(format_ == 0) return read_ascii(t);
    std::size_t n = ply_size(t);
    if(pos_ + n > data_.size())
      throw Input_error(file_, 0, "unexpected end of binary PLY data");
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    bool big = (format_ == 2);
    std::uint64_t u = 0;
    for(std::size_t i = 0; i < n; ++i)
      u |= std::uint64_t(b[big ? i : n - 1 - i]) << (8 * (n - 1 - i));
    switch(t)
    {
      case Ply_type::INT8: return static_cast<double>(static_cast<std::int8_t>(u));
      case Ply_type::UINT8: return static_cast<double>(static_cast<std::uint8_t>(u));
      case Ply_type::INT16: return static_cast<double>(static_cast<std::int16_t>(u));
      case Ply_type::UINT16: return static_cast<double>(static_cast<std::uint16_t>(u));
      case Ply_type::INT32: return static_cast<double>(static_cast<std::int32_t>(u));
      case Ply_type::UINT32: return static_cast<double>(static_cast<std::uint32_t>(u));
      case Ply_type::FLOAT32: { std::uint32_t v = static_cast<std::uint32_t>(u); float f; std::memcpy(&f, &v, 4); return f; }
      case Ply_type::FLOAT64: { double d; std::memcpy(&d, &u, 8); return d; }
      default: return 0;
    }
  }

  // line of the last value read (0 for binary)
  std::size_t line() const { return format_ == 0 ? token_line_ : 0; }

  // fails if anything but whitespace remains
  void check_end()
  {
    if(format_ != 0)
    {
      if(pos_ != data_.size())
        throw Input_error(file_, 0, "trailing junk after the binary PLY data (" + std::to_string(data_.size() - pos_) + " bytes)");
      return;
    }
    std::string_view t;
    if(next_token(t))
      throw Input_error(file_, token_line_, "trailing junk " + quote(t) + " after the last PLY element");
  }

private:
  bool next_token(std::string_view& t)
  {
    while(pos_ < data_.size() && is_space(data_[pos_]))
    {
      if(data_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if(pos_ >= data_.size()) return false;
    std::size_t b = pos_;
    while(pos_ < data_.size() && !is_space(data_[pos_]))
    {
      if(data_[pos_] == '\0')
        throw Input_error(file_, line_, "binary data (NUL byte) in an ASCII PLY file");
      ++pos_;
    }
    t = std::string_view(data_).substr(b, pos_ - b);
    token_line_ = line_;
    return true;
  }

  double read_ascii(Ply_type t)
  {
    std::string_view tok;
    if(!next_token(tok))
      throw Input_error(file_, line_, "unexpected end of file in the PLY data");
    if(ply_is_integer(t))
    {
      long long i;
      if(!parse_int(tok, i))
        throw Input_error(file_, token_line_, "cannot parse integer " + quote(tok));
      return static_cast<double>(i);
    }
    double x;
    if(!parse_double(tok, x))
      throw Input_error(file_, token_line_, "cannot parse number " + quote(tok));
    return x;
  }

  const std::string& data_;
  std::size_t pos_;
  int format_;  // 0 ascii, 1 little endian, 2 big endian
  std::size_t line_;
  std::size_t token_line_ = 0;
  const std::string& file_;
};

inline void read_PLY_soup(std::istream& is, const std::string& file, Triangle_soup& soup, Mesh_read_info&)
{
  std::string data = read_whole_stream(is);
  if(is.bad())
    throw Input_error(file, 0, "read error");
  // header, line by line
  std::size_t pos = 0, line_no = 0;
  auto header_line = [&](std::string& out) -> bool {
    if(pos >= data.size()) return false;
    std::size_t e = data.find('\n', pos);
    if(e == std::string::npos) e = data.size();
    out = data.substr(pos, e - pos);
    pos = (e < data.size()) ? e + 1 : e;
    ++line_no;
    if(!out.empty() && out.back() == '\r') out.pop_back();
    if(out.size() > 4096 || out.find('\0') != std::string::npos)
      throw Input_error(file, line_no, "malformed PLY header line");
    return true;
  };
  std::string line;
  std::vector<std::string_view> tok;
  if(!header_line(line) || line != "ply")
    throw Input_error(file, 1, "missing 'ply' magic line");
  int format = -1;
  std::vector<Ply_element> elements;
  bool ended = false;
  while(header_line(line))
  {
    split_tokens(line, tok);
    if(tok.empty()) continue;
    if(tok[0] == "end_header") { ended = true; break; }
    if(tok[0] == "comment" || tok[0] == "obj_info") continue;
    if(tok[0] == "format")
    {
      if(tok.size() != 3 || tok[2] != "1.0")
        throw Input_error(file, line_no, "malformed 'format' line");
      if(tok[1] == "ascii") format = 0;
      else if(tok[1] == "binary_little_endian") format = 1;
      else if(tok[1] == "binary_big_endian") format = 2;
      else throw Input_error(file, line_no, "unknown PLY format " + quote(tok[1]));
    }
    else if(tok[0] == "element")
    {
      Ply_element el;
      if(tok.size() != 3 || !parse_int(tok[2], el.count) || el.count < 0)
        throw Input_error(file, line_no, "malformed 'element' line");
      el.name = std::string(tok[1]);
      el.line = line_no;
      elements.push_back(el);
    }
    else if(tok[0] == "property")
    {
      if(elements.empty())
        throw Input_error(file, line_no, "'property' before any 'element'");
      Ply_property pr;
      if(tok.size() == 5 && tok[1] == "list")
      {
        pr.is_list = true;
        pr.count_type = ply_type(tok[2]);
        pr.type = ply_type(tok[3]);
        pr.name = std::string(tok[4]);
        if(pr.count_type == Ply_type::NONE || !ply_is_integer(pr.count_type) || pr.type == Ply_type::NONE)
          throw Input_error(file, line_no, "malformed list property");
      }
      else if(tok.size() == 3)
      {
        pr.type = ply_type(tok[1]);
        pr.name = std::string(tok[2]);
        if(pr.type == Ply_type::NONE)
          throw Input_error(file, line_no, "unknown property type " + quote(tok[1]));
      }
      else
        throw Input_error(file, line_no, "malformed 'property' line");
      elements.back().props.push_back(pr);
    }
    else
      throw Input_error(file, line_no, "unknown PLY header keyword " + quote(tok[0]));
  }
  if(!ended)
    throw Input_error(file, line_no, "unexpected end of file in the PLY header (no 'end_header')");
  if(format < 0)
    throw Input_error(file, line_no, "PLY header without 'format' line");

  Ply_body body(data, pos, format, line_no + 1, file);
  bool seen_vertex = false, seen_face = false;
  for(const Ply_element& el : elements)
  {
    int ix = -1, iy = -1, iz = -1, iface = -1;
    if(el.name == "vertex")
    {
      if(seen_vertex) throw Input_error(file, el.line, "second 'vertex' element");
      seen_vertex = true;
      for(std::size_t k = 0; k < el.props.size(); ++k)
      {
        const Ply_property& p = el.props[k];
        if(p.is_list) continue;
        if(p.name == "x") ix = int(k);
        else if(p.name == "y") iy = int(k);
        else if(p.name == "z") iz = int(k);
      }
      if(ix < 0 || iy < 0 || iz < 0)
        throw Input_error(file, el.line, "the 'vertex' element lacks an x, y or z property");
      soup.points.reserve(reserve_cap(el.count));
    }
    else if(el.name == "face")
    {
      if(seen_face) throw Input_error(file, el.line, "second 'face' element");
      seen_face = true;
      for(std::size_t k = 0; k < el.props.size(); ++k)
        if(el.props[k].is_list && (el.props[k].name == "vertex_indices" || el.props[k].name == "vertex_index"))
          iface = int(k);
      if(iface < 0)
        throw Input_error(file, el.line, "the 'face' element lacks a 'vertex_indices' list property");
      if(!ply_is_integer(el.props[iface].type))
        throw Input_error(file, el.line, "face vertex indices must have an integer type");
      soup.triangles.reserve(reserve_cap(el.count));
    }
    for(long long i = 0; i < el.count; ++i)
    {
      std::array<double, 3> p{0, 0, 0};
      std::size_t nlist = 0;
      std::array<std::size_t, 3> t{0, 0, 0};
      std::size_t first_line = 0;
      for(std::size_t k = 0; k < el.props.size(); ++k)
      {
        const Ply_property& pr = el.props[k];
        if(!pr.is_list)
        {
          double x = body.read(pr.type);
          if(k == 0) first_line = body.line();
          if(int(k) == ix) p[0] = x;
          else if(int(k) == iy) p[1] = x;
          else if(int(k) == iz) p[2] = x;
          continue;
        }
        double c = body.read(pr.count_type);
        if(k == 0) first_line = body.line();
        if(c < 0)
          throw Input_error(file, body.line(), "negative list length");
        std::size_t n = static_cast<std::size_t>(c);
        if(int(k) == iface)
        {
          nlist = n;
          if(n != 3)
            throw Input_error(file, body.line(), face_arity_message(soup.triangles.size(), n));
        }
        for(std::size_t m = 0; m < n; ++m)
        {
          double x = body.read(pr.type);
          if(int(k) == iface)
          {
            if(x < 0)
              throw Input_error(file, body.line(), "negative face index " + std::to_string(static_cast<long long>(x)));
            t[m] = static_cast<std::size_t>(x);
          }
        }
      }
      if(el.name == "vertex")
      {
        check_finite_point(p, file, first_line, soup.points.size());
        soup.points.push_back(p);
        soup.point_lines.push_back(first_line);
      }
      else if(el.name == "face")
      {
        (void)nlist;
        soup.triangles.push_back(t);
        soup.triangle_lines.push_back(first_line);
      }
    }
  }
  body.check_end();
  if(!seen_vertex)
    throw Input_error(file, 0, "PLY file without a 'vertex' element");
}

// ------------------------------------------------------------------------------------------------ checks

inline std::string edge_name(std::size_t a, std::size_t b)
{
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

// a corner without twin: its halfedge is on the border (check_triangle_soup())
constexpr std::uint32_t no_twin = (std::numeric_limits<std::uint32_t>::max)();

/// Validates a triangle soup: index range, repeated vertices, non-empty, oriented 2-manifold. Fills the
/// statistics of `info`. Throws `Input_error` on the first problem, scanning faces in order.
/// `twin[3 f + k]` gets the corner whose halfedge runs along that of corner k of face f (from its vertex
/// k to vertex k + 1) the other way, or `no_twin` on a border (for triangle_soup_to_mesh()).
inline void check_triangle_soup(const Triangle_soup& soup, const std::string& file, Mesh_read_info& info,
                                std::vector<std::uint32_t>& twin)
{
  const std::size_t nv = soup.points.size(), nf = soup.triangles.size();
  auto fline = [&](std::size_t f) { return f < soup.triangle_lines.size() ? soup.triangle_lines[f] : 0; };
  auto vline = [&](std::size_t v) { return v < soup.point_lines.size() ? soup.point_lines[v] : 0; };
  if(nf == 0)
    throw Input_error(file, 0, nv == 0 ? "empty mesh (no vertices and no faces)" : "the mesh has no faces");
  if(nv >= (std::size_t(1) << 32) || nf >= (std::size_t(1) << 30))
    throw Input_error(file, 0, "mesh too large");

  for(std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = soup.triangles[f];
    for(int k = 0; k < 3; ++k)
      if(t[k] >= nv)
        throw Input_error(file, fline(f), "face " + std::to_string(f) + " refers to vertex " + std::to_string(t[k]) +
                                              " (0-based) but there are only " + std::to_string(nv) + " vertices");
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      throw Input_error(file, fline(f), "face " + std::to_string(f) + " has a repeated vertex (" + std::to_string(t[0]) +
                                            ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")");
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
      if(opp2 != nf || (same != nf && opp1 != nf))
      {
        std::size_t f0 = std::min(same, opp1), f1 = (opp2 != nf) ? opp2 : std::max(same, opp1);
        throw Input_error(file, fline(f), "non-manifold edge " + edge_name(std::min(a, b), std::max(a, b)) +
                                              ": shared by more than two faces (faces " + std::to_string(f0) + ", " +
                                              std::to_string(f1) + " and " + std::to_string(f) + ")");
      }
      if(same != nf)
        throw Input_error(file, fline(f), "faces " + std::to_string(same) + " and " + std::to_string(f) +
                                              " both traverse edge " + edge_name(a, b) +
                                              " in the same direction: the surface is not consistently oriented "
                                              "(or not orientable)");
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
        throw Input_error(file, vline(v), "non-manifold vertex " + std::to_string(v) +
                                              ": the faces around it form several separate fans (faces " +
                                              std::to_string(root[v] / 3) + " and " + std::to_string(f) + ")");
    }

  // statistics
  info.number_of_vertices = nv;
  info.number_of_faces = nf;
  std::vector<std::size_t> unref;
  for(std::size_t v = 0; v < nv; ++v)
    if(root[v] == none) unref.push_back(v);
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
  std::size_t degenerate = 0;
  for(const auto& t : soup.triangles)
  {
    const auto &p = soup.points[t[0]], &q = soup.points[t[1]], &r = soup.points[t[2]];
    double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    double c0 = u[1] * w[2] - u[2] * w[1], c1 = u[2] * w[0] - u[0] * w[2], c2 = u[0] * w[1] - u[1] * w[0];
    if(c0 == 0 && c1 == 0 && c2 == 0) ++degenerate;
  }
  info.degenerate_faces = degenerate;
  if(degenerate > 0)
    info.warnings.push_back(std::to_string(degenerate) + " faces have zero area (collinear corners); kept");
}

} // namespace internal
/// \endcond

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
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::size_type size_type;
  std::vector<std::uint32_t> twin;
  internal::check_triangle_soup(soup, file, info, twin);
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
  \brief reads a triangle soup from a stream in the given format ("obj", "off", "ply", "stl"), keeping the
  file's order. OBJ `l`/`c` records are stored in `info`. No manifold checks are done here.
  \throws Input_error on malformed input.
*/
inline void read_triangle_soup(std::istream& is, const std::string& format, const std::string& file,
                               Triangle_soup& soup, Mesh_read_info& info)
{
  std::string fmt = internal::lower(format);
  info.file = file;
  info.format = fmt;
  if(fmt == "obj") internal::read_OBJ_soup(is, file, soup, info);
  else if(fmt == "off") internal::read_OFF_soup(is, file, soup, info);
  else if(fmt == "ply") internal::read_PLY_soup(is, file, soup, info);
  else if(fmt == "stl") internal::read_STL_soup(is, file, soup, info);
  else throw Input_error(file, 0, "unsupported mesh format " + internal::quote(format) + " (use obj, off, ply or stl)");
}

/*!
  \brief reads a triangle mesh from a stream, keeping vertex and face order, and validates it.

  \param is the stream (opened in binary mode for binary PLY/STL)
  \param format "obj", "off", "ply" or "stl" (case-insensitive)
  \param file the name used in error messages
  \param mesh the output mesh (cleared first)
  \returns statistics, warnings and, for OBJ, the inline `l` and `c` records
  \throws Input_error on any invalid input (see the file documentation)
*/
template <class Point>
Mesh_read_info read_mesh(std::istream& is, const std::string& format, const std::string& file,
                         CGAL::Surface_mesh<Point>& mesh)
{
  Mesh_read_info info;
  Triangle_soup soup;
  read_triangle_soup(is, format, file, soup, info);
  triangle_soup_to_mesh(soup, mesh, info, file);
  return info;
}

/*!
  \brief returns the lower-cased extension of `filename` without the dot ("" if none).
*/
inline std::string mesh_file_format(const std::string& filename)
{
  std::string ext = std::filesystem::path(filename).extension().string();
  if(!ext.empty() && ext[0] == '.') ext.erase(0, 1);
  return internal::lower(ext);
}

/*!
  \brief reads a triangle mesh file (OFF, OBJ, PLY or STL, chosen by the extension), keeping the file's
  vertex and face order, and validates it.

  Vertex `i` of the file is `Surface_mesh` vertex `i`, face `j` is face `j`, and `halfedge(f, mesh)` points to
  the first vertex of face `f` as written in the file.
  \returns statistics, warnings and, for OBJ, the inline `l` and `c` records
  \throws Input_error on a missing file or any invalid input (see the file documentation)
*/
template <class Point>
Mesh_read_info read_mesh(const std::string& filename, CGAL::Surface_mesh<Point>& mesh)
{
  std::error_code ec;
  if(!std::filesystem::exists(filename, ec))
    throw Input_error(filename, 0, "no such file");
  if(std::filesystem::is_directory(filename, ec))
    throw Input_error(filename, 0, "is a directory, not a mesh file");
  std::ifstream is(filename, std::ios::binary);
  if(!is)
    throw Input_error(filename, 0, "cannot open file for reading");
  std::string fmt = mesh_file_format(filename);
  if(fmt != "obj" && fmt != "off" && fmt != "ply" && fmt != "stl")
    throw Input_error(filename, 0, "unknown mesh file extension " + internal::quote(fmt) + " (use .obj, .off, .ply or .stl)");
  return read_mesh(is, fmt, filename, mesh);
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_IO_READ_MESH_H
