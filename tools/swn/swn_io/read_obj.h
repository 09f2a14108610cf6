// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// OBJ reader: vertices, triangles, and the `l` (vertex polyline) and `c` (dual chain) records with the
// `#offset` directive, each with its line.

#ifndef CGAL_SWN_TOOL_IO_READ_OBJ_H
#define CGAL_SWN_TOOL_IO_READ_OBJ_H

#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>
#include <istream>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {


namespace internal {

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

  std::vector<std::size_t> t;   // the current face's vertices (reused)
  while(next_record(lr, line, tok, offset))
  {
    std::string_view kw = tok[0];
    if(kw == "v")
    {
      if(tok.size() > 8)
        lr.fail("vertex record with too many values (trailing junk?)");
      const std::array<double, 3> p = vertex_coordinates(tok, 1, lr);
      check_finite_point(p, file, lr.line_number(), soup.points.size());
      soup.points.push_back(p);
      soup.point_lines.push_back(lr.line_number());
    }
    else if(kw == "f")
    {
      std::size_t n = tok.size() - 1;
      if(n < 3)
        lr.fail(face_arity_message(number_of_faces(soup), n));
      t.resize(n);
      for(std::size_t k = 0; k < n; ++k)
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
      add_face(soup, t, lr.line_number());
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
          r = static_cast<long long>(is_l ? soup.points.size() : number_of_faces(soup)) + i;
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

  // the records are resolved once every vertex and face is known
  auto resolve = [&](const Pending& p, std::size_t size, const char* what, const char* record, const char* unit) {
    std::vector<std::size_t> r;
    for(long long i : p.idx)
    {
      if(static_cast<std::size_t>(i) >= size)
        throw Input_error(file, p.line, std::string(what) + " index " + std::to_string(i) + " (0-based) in '" + record +
                                            "' record is out of range (" + std::to_string(size) + " " + unit + ")");
      r.push_back(static_cast<std::size_t>(i));
    }
    return r;
  };
  for(const Pending& p : polylines)
    info.obj_polylines.push_back(Obj_polyline{resolve(p, soup.points.size(), "vertex", "l", "vertices"), p.line});
  for(const Pending& p : chains)
    info.obj_dual_chains.push_back(Obj_dual_chain{resolve(p, number_of_faces(soup), "face", "c", "faces"), p.line});
}

} // namespace internal


} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_OBJ_H
