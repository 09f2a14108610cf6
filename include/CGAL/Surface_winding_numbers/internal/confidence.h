// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Confidence of the labels, per region, on flat tables (doc: \ref SWNConfidence).
//
// Regions: the faces connected across interior edges where the input chain, the nonbounding chain G and
// the jump of the labels W are all zero; W is constant on a region. Flipping a region C by delta (W +=
// delta on C) keeps the decomposition "input = J W + G" only with G -= delta J 1_C, a chain homologous to
// G, so every flip is another completion of the same input with nonbounding loops of the same class. Its
// cost is the change of Eq. 11's objective evaluated on the integer chain G: the sum over interior edges
// of w_e |G_e| (w_e = epsilon x length on input edges, length elsewhere; lengths in units of the mean
// interior edge length), and it is infeasible when G leaves Eq. 11's bounds on an input edge (G_e of the
// sign of the input, |G_e| <= |input_e|). The flip cost of a region is that of its cheaper direction.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CONFIDENCE_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CONFIDENCE_H

#include <CGAL/Surface_winding_numbers/Label_confidence.h>
#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>
#include <CGAL/Surface_winding_numbers/internal/union_find.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

struct Label_regions
{
  std::vector<std::size_t> of_face;   // face -> region
  std::vector<double> area;           // per region, in the tables' (scaled) units
  std::vector<std::size_t> component; // per region: the mesh component
  std::vector<std::size_t> faces;     // per region: number of table faces
};

// The regions of the labels W (per table face) between the input `chain` and G (per table edge); regions are
// numbered in the order of their first face.
template <class IntG>
Label_regions label_regions(const Mesh_tables& m, const std::vector<double>& chain, const std::vector<IntG>& G,
                            const std::vector<int>& W)
{
  Union_find sets(m.nf);
  for(const Arc& a : m.arcs)
  {
    const std::size_t L = a.left_side / 3, R = a.right_side / 3;
    if(chain[a.edge] == 0 && G[a.edge] == 0 && W[L] == W[R]) sets.unite(L, R);
  }
  Label_regions r;
  r.of_face.assign(m.nf, 0);
  std::vector<std::size_t> id(m.nf, npos);   // root -> region
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    std::size_t& k = id[sets.find(f)];
    if(k == npos)
    {
      k = r.area.size();
      r.area.push_back(0.);
      r.component.push_back(m.face_component[f]);
      r.faces.push_back(0);
    }
    r.of_face[f] = k;
    r.area[k] += m.face_area(f);
    ++r.faces[k];
  }
  return r;
}

// Eq. 11 weight of every edge: epsilon x length on input edges, length elsewhere, in mean interior edge lengths.
inline std::vector<double> eq11_weights(const Mesh_tables& m, const std::vector<double>& chain, double epsilon)
{
  const double unit = mean_interior_edge_length(m);
  std::vector<double> w(m.ne, 0.);
  for(std::size_t e = 0; e < m.ne; ++e) w[e] = m.edge_length(e) / unit * (std::abs(chain[e]) > 0 ? epsilon : 1.);
  return w;
}

struct Flip
{
  double cost = std::numeric_limits<double>::infinity();   // Eq. 11 cost increase; infinite: no feasible flip
  int delta = 0;                                            // W += delta on the region
  double boundary = 0;                                      // length of the region's boundary (mean edge lengths)
};

// The cheaper feasible flip of every region (Eq. 11's cost and bounds on G - delta J 1_C).
template <class IntG>
std::vector<Flip> flip_costs(const Mesh_tables& m, const Label_regions& regions, const std::vector<double>& chain,
                             const std::vector<IntG>& G, const std::vector<double>& weight)
{
  const std::size_t n = regions.area.size();
  const double unit = mean_interior_edge_length(m);
  std::vector<double> cost[2] = {std::vector<double>(n, 0.), std::vector<double>(n, 0.)};   // delta = +1, -1
  std::vector<char> feasible[2] = {std::vector<char>(n, 1), std::vector<char>(n, 1)};
  std::vector<double> boundary(n, 0.);
  for(const Arc& a : m.arcs)
  {
    const std::size_t cl = regions.of_face[a.left_side / 3], cr = regions.of_face[a.right_side / 3];
    if(cl == cr) continue;
    const long g = long(G[a.edge]);
    const long in = std::lround(chain[a.edge]);
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t c = side == 0 ? cl : cr;
      const long j = side == 0 ? 1 : -1;   // (J 1_c)_e = 1_c(left) - 1_c(right)
      boundary[c] += m.edge_length(a.edge) / unit;
      for(int k = 0; k < 2; ++k)
      {
        const long delta = k == 0 ? 1 : -1;
        const long g2 = g - delta * j;
        cost[k][c] += weight[a.edge] * double(std::labs(g2) - std::labs(g));
        if(in != 0 && (g2 * in < 0 || std::labs(g2) > std::labs(in))) feasible[k][c] = 0;
      }
    }
  }
  std::vector<Flip> out(n);
  for(std::size_t c = 0; c < n; ++c)
  {
    out[c].boundary = boundary[c];
    for(int k = 0; k < 2; ++k)
      if(feasible[k][c] && cost[k][c] < out[c].cost) { out[c].cost = cost[k][c]; out[c].delta = k == 0 ? 1 : -1; }
  }
  return out;
}

// The region whose flip makes the second-best labeling: the cheapest feasible flip among the regions that
// are not the largest of their component and cover at least `min_area_fraction` of the total area (ties:
// the larger region); npos if there is none.
inline std::size_t second_best_region(const Label_regions& regions, const std::vector<Flip>& flips,
                                      double min_area_fraction)
{
  std::map<std::size_t, std::size_t> largest;   // component -> region
  double total = 0;
  for(std::size_t c = 0; c < regions.area.size(); ++c)
  {
    total += regions.area[c];
    const auto it = largest.emplace(regions.component[c], c).first;
    if(regions.area[c] > regions.area[it->second]) it->second = c;
  }
  std::size_t best = npos;
  for(std::size_t c = 0; c < regions.area.size(); ++c)
  {
    if(largest[regions.component[c]] == c || regions.area[c] < min_area_fraction * total || !std::isfinite(flips[c].cost))
      continue;
    if(best == npos || flips[c].cost < flips[best].cost ||
       (flips[c].cost == flips[best].cost && regions.area[c] > regions.area[best]))
      best = c;
  }
  return best;
}

// Everything the confidence outputs need, from a solve's input chain, G and labels (per table element).
struct Confidence
{
  Label_regions regions;
  std::vector<Flip> flips;
  std::size_t second_best = npos;
};

// Regions smaller than this fraction of the total area are no candidates for the second-best labeling:
// the flip cost grows with the boundary, so slivers are always cheap.
constexpr double second_best_min_area_fraction = 0.005;

// Curve values on edges across which nothing may jump (the core drops them) are ignored.
template <class IntG>
Confidence label_confidence(const Mesh_tables& m, std::vector<double> chain, const std::vector<IntG>& G,
                            const std::vector<int>& W, double epsilon)
{
  for(std::size_t e = 0; e < m.ne; ++e)
    if(m.jump_forbidden(e)) chain[e] = 0;
  Confidence c;
  c.regions = label_regions(m, chain, G, W);
  c.flips = flip_costs(m, c.regions, chain, G, eq11_weights(m, chain, epsilon));
  c.second_best = second_best_region(c.regions, c.flips, second_best_min_area_fraction);
  return c;
}

// The public description of `c` for the labels W it was computed from (areas back in the mesh's units).
inline Label_confidence public_confidence(const Mesh_tables& m, const Confidence& c, const std::vector<int>& W)
{
  Label_confidence out;
  const std::size_t n = c.regions.area.size();
  out.regions.resize(n);
  std::vector<std::size_t> largest(m.n_components, npos);
  for(std::size_t k = 0; k < n; ++k)
  {
    Label_region& r = out.regions[k];
    r.faces = c.regions.faces[k];
    r.area = c.regions.area[k] / (m.point_scale * m.point_scale);
    r.component = c.regions.component[k];
    r.flip_cost = c.flips[k].cost;
    r.flip_delta = c.flips[k].delta;
    r.boundary_length = c.flips[k].boundary;
    std::size_t& l = largest[r.component];
    if(l == npos || c.regions.area[k] > c.regions.area[l]) l = k;
  }
  for(std::size_t l : largest)
    if(l != npos) out.regions[l].largest_in_component = true;
  for(std::size_t f = 0; f < m.nf; ++f) out.regions[c.regions.of_face[f]].label = W[f];
  out.second_best_region = c.second_best;
  if(c.second_best != npos) out.second_best_cost = c.flips[c.second_best].cost;
  return out;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
