// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// The tool's labels per input face: after the conforming cut (and the refinement, and curves off the
// mesh) the solved mesh has more faces than the mesh file; every face is a piece of one input face
// (Cut_result::face_origin).

#ifndef CGAL_SWN_TOOL_IO_INPUT_FACES_H
#define CGAL_SWN_TOOL_IO_INPUT_FACES_H

#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace IO {

/// the area of the triangle `f` of `mesh`
template <class Point>
double face_area(const CGAL::Surface_mesh<Point>& mesh, typename CGAL::Surface_mesh<Point>::Face_index f)
{
  const auto h = mesh.halfedge(f);
  return std::sqrt(CGAL::to_double(
    CGAL::squared_area(mesh.point(mesh.source(h)), mesh.point(mesh.target(h)), mesh.point(mesh.target(mesh.next(h))))));
}

/*!
  \brief one label per input face: the label covering the largest area of its pieces (ties: the label of
  smallest magnitude, then the smallest).
  \param mesh the solved mesh (triangles)
  \param labels a readable map face -> integer label of `mesh`
  \param face_origin per face index of `mesh`, the index of the input face it is a piece of
  \param input_faces the number of input faces; every one has at least one piece
*/
template <class Point, class LabelMap>
std::vector<int> labels_per_input_face(const CGAL::Surface_mesh<Point>& mesh, const LabelMap& labels,
                                       const std::vector<std::size_t>& face_origin, std::size_t input_faces)
{
  std::vector<std::map<int, double> > area(input_faces);
  for(auto f : mesh.faces()) area[face_origin[std::size_t(f)]][int(get(labels, f))] += face_area(mesh, f);
  std::vector<int> out(input_faces, 0);
  for(std::size_t i = 0; i < input_faces; ++i)
  {
    double best = -1;
    for(const auto& la : area[i])
      if(la.second > best || (la.second == best && std::abs(la.first) < std::abs(out[i])))
      {
        out[i] = la.first;
        best = la.second;
      }
  }
  return out;
}

} // namespace IO
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SWN_TOOL_IO_INPUT_FACES_H
