// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_LABEL_CONFIDENCE_H
#define CGAL_SURFACE_WINDING_NUMBERS_LABEL_CONFIDENCE_H

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {

/// \ingroup PkgSurfaceWindingNumbersRef
/// One region of the labels: a maximal set of faces connected across edges where the input curves, the
/// nonbounding loops \f$ G \f$ and the jump of the labels are all zero (the label is constant on it).
/// See \ref SWNConfidence.
struct Label_region
{
  int label = 0;                ///< the label W of its faces
  std::size_t faces = 0;        ///< its number of faces (triangles of the internal triangulation for polygon faces)
  double area = 0;              ///< its area, in the mesh's units
  std::size_t component = 0;    ///< the connected component of the mesh it lies in (numbered by their first face)
  /// the flip cost: how much Eq. 11's objective, evaluated on the integer nonbounding loops, grows when the
  /// region's label changes by `flip_delta` and the loops change with it (\f$ G - \delta\,\mathcal{J} 1_C \f$),
  /// everything else fixed; in units of the mean interior edge length, input edges weighted by epsilon.
  /// Infinite when neither direction keeps \f$ G \f$ within Eq. 11's bounds on the input edges.
  double flip_cost = std::numeric_limits<double>::infinity();
  int flip_delta = 0;           ///< the cheaper direction, +1 or -1 (0 when the flip cost is infinite)
  double boundary_length = 0;   ///< the length of its boundary, in mean interior edge lengths
  bool largest_in_component = false;   ///< the region of largest area of its component
};

/// \ingroup PkgSurfaceWindingNumbersRef
/// The confidence of a solve's labels, region by region (named parameter `label_confidence`; see
/// \ref SWNConfidence for what it means and what it does not promise).
struct Label_confidence
{
  /// the regions, numbered in the order of their first face (the values of `region_map`)
  std::vector<Label_region> regions;
  /// the region whose flip gives the second-best labeling (`second_best_label_map`): the cheapest finite flip
  /// among the regions that are not the largest of their component and cover at least 0.5 % of the mesh's
  /// area; `std::size_t(-1)` when there is none
  std::size_t second_best_region = std::size_t(-1);
  /// the flip cost of that region (infinite when there is none)
  double second_best_cost = std::numeric_limits<double>::infinity();
};

} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
