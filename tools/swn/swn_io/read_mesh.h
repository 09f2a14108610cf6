// Copyright (c) 2024 The CGAL Surface_winding_numbers contributors.
// SPDX-License-Identifier: MIT
//
// Order-preserving, validating readers for triangle meshes in OFF, OBJ, PLY and STL.

#ifndef CGAL_SWN_TOOL_IO_READ_MESH_H
#define CGAL_SWN_TOOL_IO_READ_MESH_H

#include "swn_io/errors.h"
#include "swn_io/mesh_soup.h"
#include "swn_io/read_obj.h"
#include "swn_io/read_off.h"
#include "swn_io/read_ply.h"
#include "swn_io/read_stl.h"

#include <CGAL/Surface_mesh.h>

#include <filesystem>
#include <fstream>
#include <istream>
#include <string>
#include <system_error>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/*!
  \file read_mesh.h

  Readers for triangle meshes that keep the file's numbering: vertex `i` of the file becomes
  `Surface_mesh` vertex index `i` and face `j` of the file becomes face index `j`. In addition the halfedge
  of every face, `halfedge(f, mesh)`, points to the face's **first** vertex as written in the file, so that
  `vertices_around_face(halfedge(f, mesh), mesh)` lists the face's vertices in file order (this is what the
  authors' edge numbering of `curve_io.h` relies on).

  Validation: the readers report, and never repair. They throw `Input_error` (with file name and 1-based line
  number where a line exists) on: a missing or unreadable file, an unparsable line, an index out of range, a
  face that is not a triangle, a NaN or infinite coordinate, a face with a repeated vertex, a face of zero
  area (collinear or coincident corners, tested in a unit bounding box: independent of the unit), a mesh without
  faces, and a surface that is not an oriented 2-manifold (an edge shared by more than two faces, two faces
  traversing an edge in the same direction, or a vertex where several fans of faces meet). Unreferenced
  vertices are kept as isolated vertices and reported in `Mesh_read_info`, as are exactly duplicated vertex
  positions and (STL only) merged vertices. Indices quoted in messages are 0-based vertex/face indices.

  Which parser reads what. CGAL 5.5's readers (`CGAL::IO::read_polygon_soup()` and the `read_OFF()`,
  `read_OBJ()`, `read_PLY()`, `read_STL()` it dispatches to) keep the vertex and face order of OFF, OBJ and
  PLY files, and number STL vertices by first occurrence as we do. But they report a problem only by
  returning `false` (and a message on `std::cerr` in verbose mode), never with its line; their OBJ reader
  refuses `l` records and knows no `#offset`; none of them notices trailing junk. So the text formats (OBJ,
  OFF, ASCII PLY, ASCII STL) are read by the parsers of this directory, for `FILE:LINE` messages and the
  OBJ curve records, and binary PLY and STL data, which have no line to report, by CGAL's readers
  (`read_ply.h`, `read_stl.h`; the PLY header is still parsed here, for its lines).
*/

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
  std::ifstream is = internal::open_input_file(filename, "a mesh file");
  std::string fmt = mesh_file_format(filename);
  if(fmt != "obj" && fmt != "off" && fmt != "ply" && fmt != "stl")
    throw Input_error(filename, 0, "unknown mesh file extension " + internal::quote(fmt) + " (use .obj, .off, .ply or .stl)");
  return read_mesh(is, fmt, filename, mesh);
}


/*!
  \brief reads a mesh from a stream in the format `fmt` (as `read_mesh()`) into `mesh` when it is an oriented 2-manifold triangle mesh, and
  otherwise keeps it as a soup: polygons with more than three vertices, edges shared by more than two faces,
  vertices where several fans meet, faces traversing an edge the same way.

  `soup` keeps the faces either way (free it when it is no longer needed).
  \returns "" when `mesh` was built, else why the file is not an oriented 2-manifold
  triangle mesh (the first problem in file order, as `read_mesh()` would report it); `mesh` is then empty and
  `soup` holds the checked faces. `info` gets the statistics, warnings and OBJ curve records either way.
  \throws Input_error on a missing file or invalid input (indices out of range, repeated vertices, faces with
  fewer than three vertices, non-finite coordinates, no face, a zero-area face, or a face
  of more than three sides with a zero-area triangle in the library's triangulation)
  \param concurrent as in `soup_to_mesh_or_problem()`
*/
template <class Point>
std::string read_mesh_or_soup(std::istream& is, const std::string& fmt, const std::string& filename,
                              CGAL::Surface_mesh<Point>& mesh, Triangle_soup& soup, Mesh_read_info& info,
                              bool concurrent = true)
{
  info = Mesh_read_info();
  soup = Triangle_soup();
  mesh.clear();
  read_triangle_soup(is, fmt, filename, soup, info);
  return soup_to_mesh_or_problem(soup, mesh, info, filename, concurrent);
}

/// `read_mesh_or_soup()` on the file `filename`, in the format its extension names
template <class Point>
std::string read_mesh_or_soup(const std::string& filename, CGAL::Surface_mesh<Point>& mesh, Triangle_soup& soup,
                              Mesh_read_info& info, bool concurrent = true)
{
  std::ifstream is = internal::open_input_file(filename, "a mesh file");
  const std::string fmt = mesh_file_format(filename);
  if(fmt != "obj" && fmt != "off" && fmt != "ply" && fmt != "stl")
    throw Input_error(filename, 0, "unknown mesh file extension " + internal::quote(fmt) + " (use .obj, .off, .ply or .stl)");
  return read_mesh_or_soup(is, fmt, filename, mesh, soup, info, concurrent);
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_READ_MESH_H
