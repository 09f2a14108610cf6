// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// STL reader: vertices merged by exact equality of their coordinates, numbered by first occurrence.

#ifndef CGAL_SWN_TOOL_IO_READ_STL_H
#define CGAL_SWN_TOOL_IO_READ_STL_H

#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"

#include <CGAL/IO/STL.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {


namespace internal {

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
    // Binary data has no lines to report: CGAL's reader serves. It merges vertices as we do (exact
    // equality, numbered by first occurrence). A binary file may start with "solid", and CGAL's
    // reader then tries ASCII first and may keep what it read; the size already told us the file is
    // binary, so the 80 bytes of header (unused) are blanked before CGAL sees them.
    std::string blanked = data;
    std::fill(blanked.begin(), blanked.begin() + 80, '\0');
    std::istringstream in(blanked, std::ios::in | std::ios::binary);
    std::vector<std::array<double, 3> > points;
    std::vector<std::array<std::size_t, 3> > triangles;
    if(!CGAL::IO::read_STL(in, points, triangles))
      throw Input_error(file, 0, "CGAL::IO::read_STL() cannot read the binary STL data");
    info.merged_stl_vertices = 3 * triangles.size() - points.size();
    soup_from_points_and_polygons(points, triangles, file, soup);
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
          throw Input_error(file, facet_line, "facet " + std::to_string(facet) + " has " + std::to_string(nvert) +
                                                " vertices (STL facets are triangles)");
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

} // namespace internal


} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_STL_H
