// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Step of polylines_to_chain(): the straight walk through faces between two points of the surface, along
// the section of the surface by the plane through the two points that contains the mean of their normals.

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_SURFACE_WALK_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_SURFACE_WALK_H

#include <CGAL/Surface_winding_numbers/internal/unit_scale.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// the length of a vector, without overflow or underflow of its square
template <class Vector>
double length(const Vector& v)
{
  return std::hypot(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
}

// the mean length of the edges of tm
template <class TriangleMesh, class VertexPointMap>
double mean_edge_length(const TriangleMesh& tm, VertexPointMap vpm)
{
  double sum = 0;
  for(auto e : edges(tm)) sum += length(get(vpm, target(e, tm)) - get(vpm, source(e, tm)));
  return num_edges(tm) == 0 ? 0. : sum / double(num_edges(tm));
}

// The unit scale (unit_scale()) of the vertex points of `g` read through `vpm`; `finite` tells whether
// every coordinate is finite.
template <class Graph, class VertexPointMap>
double mesh_unit_scale(const Graph& g, VertexPointMap vpm, bool& finite)
{
  std::vector<double> xyz;
  xyz.reserve(3 * num_vertices(g));
  finite = true;
  for(auto v : vertices(g))
  {
    const auto& p = get(vpm, v);
    for(double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())})
    {
      finite = finite && std::isfinite(x);
      xyz.push_back(x);
    }
  }
  return unit_scale(xyz.data(), xyz.size() / 3);
}

// The vertex points of a vertex point map multiplied by `scale` (a power of two: exact), as a readable
// property map: the geometric queries (AABB trees, closest points, rays, walks) run on it at unit scale,
// where squared lengths neither overflow nor underflow, and their answers (faces, barycentric
// coordinates) are those of the input.
template <class VertexPointMap, class Point>
struct Scaled_point_map
{
  typedef typename boost::property_traits<VertexPointMap>::key_type key_type;
  typedef Point value_type;
  typedef Point reference;
  typedef boost::readable_property_map_tag category;

  VertexPointMap vpm;
  double scale = 1.;

  friend Point get(const Scaled_point_map& m, const key_type& k)
  {
    const auto& p = get(m.vpm, k);
    return Point(m.scale * CGAL::to_double(p.x()), m.scale * CGAL::to_double(p.y()), m.scale * CGAL::to_double(p.z()));
  }
};

// A point of the surface: a vertex, a point on an edge (at `t` from source(h) to target(h), 0 < t < 1)
// or a point inside a face.
template <class TriangleMesh, class Point>
struct Surface_spot
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  enum Kind { VERTEX, EDGE, FACE };
  Kind kind = FACE;
  typename Traits::vertex_descriptor v = Traits::null_vertex();
  typename Traits::halfedge_descriptor h = Traits::null_halfedge();
  typename Traits::face_descriptor f = Traits::null_face();
  double t = 0;
  Point p;
};

template <class TriangleMesh, class VertexPointMap, class GT>
class Surface_walk
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  typedef typename GT::Point_3 Point;
  typedef typename GT::Vector_3 Vector;

public:
  typedef Surface_spot<TriangleMesh, Point> Spot;
  // barycentric coordinates below this are zero, and vertices closer than this times the mean edge length
  // to a walk's plane are on it
  static constexpr double snap_tolerance = 1e-9;

  Surface_walk(const TriangleMesh& tm, VertexPointMap vpm, double scale) : tm_(tm), vpm_(vpm), scale_(scale) {}

  Point point(vertex_descriptor v) const { return get(vpm_, v); }

  Vector face_normal(face_descriptor f) const
  {
    const halfedge_descriptor h = halfedge(f, tm_);
    const Point &p = point(source(h, tm_)), &q = point(target(h, tm_)), &r = point(target(next(h, tm_), tm_));
    const Vector n = CGAL::cross_product(q - p, r - p);
    const double l = std::sqrt(CGAL::to_double(n.squared_length()));
    return l > 0 ? n / l : n;
  }

  // the spot of a face location: a vertex or an edge point if coordinates are zero, or below
  // `snap_tolerance` (relative to the face: the point is then on its border up to rounding)
  template <class Location>
  Spot spot(const Location& loc) const
  {
    Spot s;
    s.f = loc.first;
    const halfedge_descriptor h0 = halfedge(s.f, tm_);
    const std::array<halfedge_descriptor, 3> hs = {h0, next(h0, tm_), next(next(h0, tm_), tm_)};
    int zeros = 0, nonzero = 0, zero = 0;
    std::array<double, 3> w;
    for(int k = 0; k < 3; ++k)
    {
      w[k] = double(loc.second[k]);
      if(!(w[k] > snap_tolerance)) { ++zeros; zero = k; w[k] = 0; }
      else nonzero = k;
    }
    if(zeros == 3) { zeros = 0; w = {double(loc.second[0]), double(loc.second[1]), double(loc.second[2])}; }
    const double total = w[0] + w[1] + w[2];
    for(double& x : w) x /= total;
    s.p = CGAL::ORIGIN;
    Vector sum = NULL_VECTOR;
    for(int k = 0; k < 3; ++k) sum = sum + w[k] * (point(source(hs[k], tm_)) - CGAL::ORIGIN);
    s.p = CGAL::ORIGIN + sum;
    if(zeros == 2) { s.kind = Spot::VERTEX; s.v = source(hs[nonzero], tm_); s.p = point(s.v); }
    else if(zeros == 1)
    {
      s.kind = Spot::EDGE;
      s.h = hs[(zero + 1) % 3];   // the side opposite to vertex `zero`, from vertex zero+1 to vertex zero+2
      s.t = w[(zero + 2) % 3];
    }
    return s;
  }

  // the faces a walk may leave a spot through
  std::vector<face_descriptor> faces_of(const Spot& s) const
  {
    std::vector<face_descriptor> r;
    if(s.kind == Spot::FACE) r.push_back(s.f);
    else if(s.kind == Spot::EDGE)
    {
      for(halfedge_descriptor g : {s.h, opposite(s.h, tm_)})
        if(!is_border(g, tm_)) r.push_back(face(g, tm_));
    }
    else
      for(halfedge_descriptor g : halfedges_around_target(halfedge(s.v, tm_), tm_))
        if(!is_border(g, tm_)) r.push_back(face(g, tm_));
    return r;
  }

  // Walks from `from` to the face `fb` of the point `b`, in the plane through from.p and b containing
  // `normal`. Appends the spots where the walk crosses edges or vertices (not `from`, not b) to `out`;
  // returns false (out then holds a partial walk) if the walk reaches the border, turns back or goes astray.
  bool walk(const Spot& from, face_descriptor fb, const Point& b, const Vector& normal, std::vector<Spot>& out) const
  {
    const Point a = from.p;
    const Vector d = b - a;
    Vector m = CGAL::cross_product(d, normal);
    const double lm = std::sqrt(CGAL::to_double(m.squared_length()));
    const double ld = std::sqrt(CGAL::to_double(d.squared_length()));
    if(!(lm > 1e-12 * ld)) return false;
    m = m / lm;
    const double reach = 2 * ld + 4 * scale_;
    const double tiny = 1e-9 * ld * scale_;   // progress lost to rounding when a point is on an edge
    // vertices closer to the plane than rounding are on it: the walk goes through them, and along the
    // edges that lie in the plane
    auto side = [&](vertex_descriptor v) {
      const double x = CGAL::to_double((point(v) - a) * m);
      return std::abs(x) <= snap_tolerance * scale_ ? 0. : x;
    };
    Spot x = from;
    face_descriptor previous = Traits::null_face();
    const std::size_t max_steps = num_faces(tm_) + 2;
    for(std::size_t step = 0; step < max_steps; ++step)
    {
      const std::vector<face_descriptor> around = faces_of(x);
      std::vector<face_descriptor> candidates;
      for(face_descriptor g : around)
      {
        if(g == fb) return true;
        if(g != previous) candidates.push_back(g);
      }
      bool found = false;
      double best = 0;
      Spot next_spot;
      face_descriptor through = Traits::null_face();
      for(face_descriptor g : candidates)
        for(const Spot& y : crossings(g, x, side))
        {
          const double progress = CGAL::to_double((y.p - x.p) * d);
          const bool forced = candidates.size() == 1 && x.kind == Spot::EDGE;   // the only way on
          if(!found ? (forced || progress > -tiny) : progress > best)
          {
            found = true;
            best = progress;
            next_spot = y;
            through = g;
          }
        }
      if(!found) return false;
      if(std::sqrt(CGAL::to_double((next_spot.p - a).squared_length())) > reach) return false;
      out.push_back(next_spot);
      previous = through;
      x = next_spot;
    }
    return false;
  }

private:
  // the points where the plane (signed distance `side`) crosses the border of face g, other than x
  template <class Side>
  std::vector<Spot> crossings(face_descriptor g, const Spot& x, const Side& side) const
  {
    std::vector<Spot> r;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(g, tm_), tm_))
    {
      const vertex_descriptor u = source(h, tm_), w = target(h, tm_);
      const double su = side(u), sw = side(w);
      if(su == 0)
      {
        if(x.kind == Spot::VERTEX && x.v == u) continue;
        Spot s;
        s.kind = Spot::VERTEX;
        s.v = u;
        s.p = point(u);
        r.push_back(s);
      }
      else if((su < 0 && sw > 0) || (su > 0 && sw < 0))
      {
        if(x.kind == Spot::EDGE && edge(x.h, tm_) == edge(h, tm_)) continue;
        Spot s;
        s.kind = Spot::EDGE;
        s.h = h;
        s.t = su / (su - sw);
        s.p = point(u) + s.t * (point(w) - point(u));
        r.push_back(s);
      }
    }
    return r;
  }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  double scale_;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif
