// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// OFF reader (ASCII; the ST/C/N prefixes accepted), each vertex and face with its line.

#ifndef CGAL_SWN_TOOL_IO_READ_OFF_H
#define CGAL_SWN_TOOL_IO_READ_OFF_H

#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"

#include <array>
#include <cstddef>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {


namespace internal {

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
    const std::array<double, 3> p = vertex_coordinates(tok, 0, lr);
    check_finite_point(p, file, lr.line_number(), soup.points.size());
    soup.points.push_back(p);
    soup.point_lines.push_back(lr.line_number());
  }
  std::vector<std::size_t> t;   // the current face's vertices (reused)
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
    if(k < 3)
      lr.fail(face_arity_message(static_cast<std::size_t>(j), static_cast<std::size_t>(k)));
    t.resize(static_cast<std::size_t>(k));
    for(std::size_t c = 0; c < t.size(); ++c)
    {
      long long i;
      if(!parse_int(tok[c + 1], i))
        lr.fail("cannot parse face index " + quote(tok[c + 1]));
      if(i < 0)
        lr.fail("negative face index " + std::to_string(i));
      t[c] = static_cast<std::size_t>(i);
    }
    for(std::size_t c = t.size() + 1; c < tok.size(); ++c)  // optional colour
    {
      double x;
      if(!parse_double(tok[c], x))
        lr.fail("trailing junk " + quote(tok[c]) + " after the face indices");
    }
    add_face(soup, t, lr.line_number());
  }
  if(next_content())
    lr.fail("trailing junk after the last face (" + quote(tok[0]) + ")");
}

} // namespace internal


} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_OFF_H
