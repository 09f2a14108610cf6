// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Disjoint sets over 0..n-1, shared by the mesh readers' checks, the mesh tables and the residual
// solver's descent steps.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_UNION_FIND_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_UNION_FIND_H

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Disjoint sets over 0..n-1 (path halving); the representative of a set is its smallest element.
class Union_find
{
public:
  explicit Union_find(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    while(parent_[x] != x) { parent_[x] = parent_[parent_[x]]; x = parent_[x]; }
    return x;
  }
  void unite(std::size_t a, std::size_t b)
  {
    const std::size_t x = find(a), y = find(b);
    if(x != y) parent_[(std::max)(x, y)] = (std::min)(x, y);
  }
private:
  std::vector<std::size_t> parent_;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_UNION_FIND_H
