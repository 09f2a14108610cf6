// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_UNIT_SCALE_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_UNIT_SCALE_H

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// The power of two that brings the largest extent of the bounding box of the n points `xyz` (x, y, z
// of each point in a row) into [1, 2). Multiplying by it is exact, and afterwards products of
// coordinate differences (areas, cotangents) neither overflow nor underflow, whatever the unit of the
// input: every quantity the method uses is invariant under scaling (cotangents, ratios of areas and
// lengths), so meshes at 1e160 or 1e-160 are solved like their unit-size copies. 1 for an empty,
// flat-to-a-point or non-finite box.
inline double unit_scale(const double* xyz, std::size_t n)
{
  if(n == 0) return 1.;
  double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
  for(std::size_t i = 0; i < n; ++i)
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = (std::min)(lo[k], xyz[3 * i + k]);
      hi[k] = (std::max)(hi[k], xyz[3 * i + k]);
    }
  double half_extent = 0;   // halves: no overflow near DBL_MAX
  for(int k = 0; k < 3; ++k) half_extent = (std::max)(half_extent, hi[k] / 2 - lo[k] / 2);
  if(!(half_extent > 0) || !std::isfinite(half_extent)) return 1.;
  int e;
  std::frexp(half_extent, &e);   // half_extent in [2^(e-1), 2^e): the extent is in [2^e, 2^(e+1))
  return std::ldexp(1., -e);
}

// Brings the points to a unit bounding box (unit_scale()) and returns the factor; a no-op on meshes of
// extent in [1, 2).
inline double scale_to_unit(std::vector<double>& xyz)
{
  const double s = unit_scale(xyz.data(), xyz.size() / 3);
  if(s != 1.)
    for(double& x : xyz) x *= s;
  return s;
}

// The zero-area test of faces, shared by the library and the tool's readers: twice the area of the
// triangle (p, q, r) at round-off level of its longest squared side (collinear or coincident corners).
// Scale invariant once the points are brought to a unit box by unit_scale().
inline bool zero_area_triangle(const double* p, const double* q, const double* r)
{
  const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  const double c[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double l2 = (std::max)({a[0] * a[0] + a[1] * a[1] + a[2] * a[2], b[0] * b[0] + b[1] * b[1] + b[2] * b[2],
                                c[0] * c[0] + c[1] * c[1] + c[2] * c[2]});
  return !(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) > 16 * DBL_EPSILON * l2);
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
