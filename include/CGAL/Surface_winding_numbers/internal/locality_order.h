// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// A cache-friendly numbering of the flat mesh tables. Every stage after the tables walks faces,
// sides and arcs and reads their neighbours (assembly, reduced coordinates, the residual network,
// its maximum flows); with the numbering a mesh file happens to have (remeshers and editors leave
// it close to random) nearly every such read is a cache miss. Faces are renumbered breadth first
// across their edges, each connected component from its first face along a Morton (Z-order) curve
// through the centroids; vertices and edges follow in the order those faces first use them, so that
// elements close on the surface are close in memory. Applied when the input's own numbering is
// scattered (numbering_is_scattered()). Measured in benchmark/RESULTS.md (Speed, 2026-12-02; Morton
// order then): the residual summed over the benchmark's cases with handles 87 -> 68 s, the 1.15M-face
// genus-10 case 134 -> 96 s; breadth first instead of Morton order: benchmark/SPEED.md ("Interactive
// re-solve").

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_LOCALITY_ORDER_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_LOCALITY_ORDER_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// New index of every vertex, edge and face (old index -> new index).
struct Table_numbering
{
  std::vector<std::size_t> vertex, edge, face;
};

// the 21 low bits of x, spread to every third bit of the result
inline std::uint64_t spread_bits_3(std::uint64_t x)
{
  x &= 0x1fffffu;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// The faces in breadth-first order across their edges (every face that shares an edge with one, in
// the order of its sides), each connected component from its first face in `seeds` ((key, face)
// pairs in the order to take them; only the faces are read).
inline std::vector<std::size_t> breadth_first_faces(const Mesh_tables& m,
                                                    const std::vector<std::pair<std::uint64_t, std::size_t>>& seeds)
{
  std::vector<std::size_t> first, edge_sides;   // edge -> sides (the tables are not finalized yet)
  group_by_key(m.fe, m.ne, first, edge_sides);
  std::vector<char> seen(m.nf, 0);
  std::vector<std::size_t> order;
  order.reserve(m.nf);
  for(const auto& seed : seeds)
  {
    if(seen[seed.second]) continue;
    seen[seed.second] = 1;
    order.push_back(seed.second);
    for(std::size_t q = order.size() - 1; q < order.size(); ++q)
      for(std::size_t s = 3 * order[q]; s < 3 * order[q] + 3; ++s)
        for(std::size_t j = first[m.fe[s]]; j < first[m.fe[s] + 1]; ++j)
          if(!seen[edge_sides[j] / 3]) { seen[edge_sides[j] / 3] = 1; order.push_back(edge_sides[j] / 3); }
  }
  return order;
}

// Faces breadth first across their edges, each connected component from its first face in Morton
// order of the centroids (21 bits per axis over the bounding box of the finite coordinates; ties and
// non-finite centroids keep their relative input order), then vertices and edges by first use in that
// face order; vertices and edges no face uses come last, in input order. Needs points, fv, fe and the
// sizes of m.
inline Table_numbering locality_numbering(const Mesh_tables& m)
{
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  for(std::size_t v = 0; v < m.nv; ++v)
  {
    const double* p = m.point(v);
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
    for(int k = 0; k < 3; ++k)
    {
      lo[k] = any ? std::min(lo[k], p[k]) : p[k];
      hi[k] = any ? std::max(hi[k], p[k]) : p[k];
    }
    any = true;
  }
  const double cells = double((1u << 21) - 1);
  std::vector<std::pair<std::uint64_t, std::size_t>> key(m.nf);
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    std::uint64_t code = 0;
    for(int k = 0; k < 3; ++k)
    {
      const double c = (m.points[3 * m.fv[3 * f] + k] + m.points[3 * m.fv[3 * f + 1] + k] +
                        m.points[3 * m.fv[3 * f + 2] + k]) / 3;
      const double t = hi[k] > lo[k] ? (c - lo[k]) / (hi[k] - lo[k]) : 0.;
      const double q = std::isfinite(t) ? std::min(std::max(t, 0.), 1.) * cells : 0.;
      code |= spread_bits_3(static_cast<std::uint64_t>(q)) << k;
    }
    key[f] = {code, f};
  }
  std::sort(key.begin(), key.end());
  const std::vector<std::size_t> order = breadth_first_faces(m, key);

  Table_numbering n;
  n.face.assign(m.nf, npos);
  n.vertex.assign(m.nv, npos);
  n.edge.assign(m.ne, npos);
  std::size_t nv = 0, ne = 0;
  for(std::size_t i = 0; i < m.nf; ++i)
  {
    const std::size_t f = order[i];
    n.face[f] = i;
    for(std::size_t k = 0; k < 3; ++k)
    {
      if(n.vertex[m.fv[3 * f + k]] == npos) n.vertex[m.fv[3 * f + k]] = nv++;
      if(n.edge[m.fe[3 * f + k]] == npos) n.edge[m.fe[3 * f + k]] = ne++;
    }
  }
  for(std::size_t& x : n.vertex) if(x == npos) x = nv++;
  for(std::size_t& x : n.edge) if(x == npos) x = ne++;
  return n;
}

// True when the numbering of m's faces is scattered: fewer than one in eight of the edges between two
// faces join faces at most 32 positions apart. Remeshers and editors leave such numberings (the
// benchmark's meshes: 6-8 %); meshes written by a generator or a subdivision scheme are coherent
// already (the authors' DoubleTorusWithLoops and torus: 22 % and 17 %), and are better left as they
// are: the multilevel residual solver's work depends on the numbering, and on those meshes it was
// 10-25 % faster in their own order than in Morton order (benchmark/RESULTS.md, Speed, 2026-12-02).
// Needs fe and nf (the side -> edge table).
inline bool numbering_is_scattered(const Mesh_tables& m)
{
  std::vector<std::size_t> first_face(m.ne, npos);
  std::size_t pairs = 0, near = 0;
  for(std::size_t s = 0; s < 3 * m.nf; ++s)
  {
    const std::size_t e = m.fe[s], f = s / 3;
    if(first_face[e] == npos) { first_face[e] = f; continue; }
    ++pairs;
    if(f - first_face[e] <= 32) ++near;   // sides are visited in face order: f >= first_face[e]
  }
  return 8 * near < pairs;
}

// The tables of m with its elements renumbered by n (points, fv, fe, ev moved, then finalized).
// Corners keep their order inside each face and edges their reference direction; input_vertex,
// input_edge and input_face record the old indices, which error messages report.
inline Mesh_tables renumbered_mesh_tables(const Mesh_tables& m, const Table_numbering& n)
{
  Mesh_tables r;
  r.nv = m.nv;
  r.ne = m.ne;
  r.nf = m.nf;
  r.points.resize(3 * m.nv);
  r.point_scale = m.point_scale;
  r.input_vertex.resize(m.nv);
  for(std::size_t v = 0; v < m.nv; ++v)
  {
    const std::size_t x = n.vertex[v];
    r.input_vertex[x] = m.input_vertex_index(v);
    for(int k = 0; k < 3; ++k) r.points[3 * x + k] = m.points[3 * v + k];
  }
  r.ev.resize(2 * m.ne);
  r.input_edge.resize(m.ne);
  for(std::size_t e = 0; e < m.ne; ++e)
  {
    const std::size_t x = n.edge[e];
    r.input_edge[x] = m.input_edge_index(e);
    r.ev[2 * x] = n.vertex[m.ev[2 * e]];
    r.ev[2 * x + 1] = n.vertex[m.ev[2 * e + 1]];
  }
  r.fv.resize(3 * m.nf);
  r.fe.resize(3 * m.nf);
  r.input_face.resize(m.nf);
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    const std::size_t x = n.face[f];
    r.input_face[x] = m.input_face_index(f);
    for(std::size_t k = 0; k < 3; ++k)
    {
      r.fv[3 * x + k] = n.vertex[m.fv[3 * f + k]];
      r.fe[3 * x + k] = n.edge[m.fe[3 * f + k]];
    }
  }
  finalize_mesh_tables(r);
  return r;
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_LOCALITY_ORDER_H
