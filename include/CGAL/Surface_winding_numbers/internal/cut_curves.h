// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT
//
// Steps of conforming_cut() on the curves: their points deduplicated and located on edges, their segments
// told apart (along an edge or inside a face), the points inserted on the edges, and the segments added to
// the chain once the faces are cut (internal/cut_faces.h).

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_CURVES_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_CURVES_H

#include <CGAL/Surface_winding_numbers/chain_helpers.h>
#include <CGAL/Surface_winding_numbers/internal/cut_faces.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Why the curves were refused: the curve and the point (or the segment) at fault.
struct Cut_refusal
{
  std::size_t curve = 0, index = 0;
  std::string message;
};

// The points of the curves, deduplicated: vertices by a vertex map, points of one edge closer than the
// snapping tolerance along it as one point. Fills `points`, the edges with points on them (`cut_edges`, their
// points sorted along the reference halfedge; `edge_of`: edge -> Cut_edge + 1, 0 for none) and every curve
// as indices into `points`. Returns false, with the curve and the point at fault, for a location without
// face, with a negative or non-finite coordinate, or strictly inside its face.
template <class FT, class TriangleMesh, class CurveRange, class EdgeOfMap>
bool locate_cut_points(const TriangleMesh& tm, const CurveRange& curves, EdgeOfMap edge_of,
                       std::vector<Cut_point<TriangleMesh, FT> >& points, std::vector<Cut_edge<TriangleMesh> >& cut_edges,
                       std::vector<std::vector<std::size_t> >& curve_points, Cut_refusal& refusal)
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  const FT snap(cut_snap_tolerance);   // relative to the face or the edge
  const auto reference = reference_halfedge_marks(tm);
  auto vertex_point = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);   // point + 1, 0: none
  std::size_t c = 0;
  for(const auto& curve : curves)
  {
    curve_points.emplace_back();
    std::size_t j = 0;
    for(const auto& location : curve)
    {
      const face_descriptor f = location.first;
      std::array<FT, 3> w;
      int zeros = 0;
      bool valid = f != Traits::null_face();
      FT sum(0);
      for(int k = 0; k < 3; ++k)
      {
        w[k] = FT(location.second[k]);
        valid = valid && CGAL::is_finite(w[k]) && !(w[k] < -snap);
        sum += w[k];
      }
      valid = valid && sum > FT(0);
      // coordinates within the snapping tolerance of 0 are 0: the point is on the border up to rounding
      for(int k = 0; valid && k < 3; ++k)
        if(!(w[k] > snap * sum)) { w[k] = FT(0); ++zeros; }
      if(valid && zeros < 3)
      {
        sum = w[0] + w[1] + w[2];
        for(int k = 0; k < 3; ++k) w[k] = w[k] / sum;
      }
      if(!valid || zeros == 0 || zeros == 3)
      {
        refusal.curve = c;
        refusal.index = j;
        refusal.message = !valid ? "a point has no face, or negative or non-finite coordinates"
                                 : "a point lies strictly inside a face (only vertices and points on edges are supported)";
        return false;
      }
      // vertex k of the face is source(h[k]); coordinate k belongs to it
      const halfedge_descriptor h0 = halfedge(f, tm);
      const std::array<halfedge_descriptor, 3> h = {h0, next(h0, tm), next(next(h0, tm), tm)};
      std::size_t id = points.size();
      if(zeros == 2)
      {
        int k = 0;
        while(w[k] == FT(0)) ++k;
        const vertex_descriptor v = source(h[k], tm);
        if(get(vertex_point, v) != 0) id = get(vertex_point, v) - 1;
        else
        {
          put(vertex_point, v, id + 1);
          points.emplace_back();
          points.back().vertex = v;
        }
      }
      else
      {
        int k = 0;
        while(w[k] != FT(0)) ++k;
        halfedge_descriptor e = h[(k + 1) % 3];   // the side opposite to vertex k
        FT at_source = w[(k + 1) % 3], at_target = w[(k + 2) % 3];
        if(!get(reference, e)) { e = opposite(e, tm); std::swap(at_source, at_target); }
        if(get(edge_of, edge(e, tm)) == 0)
        {
          cut_edges.push_back({e, source(e, tm), target(e, tm), {}});
          put(edge_of, edge(e, tm), cut_edges.size());
        }
        auto& ce = cut_edges[get(edge_of, edge(e, tm)) - 1];
        for(std::size_t p : ce.points)   // one point for points on an edge closer than the tolerance
          if(CGAL::abs(points[p].at_target - at_target) <= snap) id = p;
        if(id == points.size())
        {
          points.emplace_back();
          points.back().edge = get(edge_of, edge(e, tm)) - 1;
          points.back().at_source = at_source;
          points.back().at_target = at_target;
          ce.points.push_back(id);
        }
      }
      curve_points.back().push_back(id);
      ++j;
    }
    ++c;
  }
  for(auto& ce : cut_edges)
    std::sort(ce.points.begin(), ce.points.end(), [&](std::size_t p, std::size_t q) {
      return points[p].at_target < points[q].at_target ||
             (points[p].at_target == points[q].at_target && points[q].at_source < points[p].at_source);
    });
  return true;
}

// the faces on the two sides of an edge with points on it (one on the border)
template <class TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_of_cut_edge(const TriangleMesh& tm, const Cut_edge<TriangleMesh>& ce)
{
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> r;
  for(auto g : {ce.h, opposite(ce.h, tm)})
    if(!is_border(g, tm)) r.push_back(face(g, tm));
  return r;
}

// the index of face f among the faces to cut, added if it is not there (`face_of`: face -> Cut_face + 1)
template <class TriangleMesh, class FaceOfMap>
std::size_t add_cut_face(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                         FaceOfMap face_of, std::vector<Cut_face<TriangleMesh> >& cut_faces)
{
  if(get(face_of, f) == 0)
  {
    const auto h0 = halfedge(f, tm);
    Cut_face<TriangleMesh> cf;
    cf.f = f;
    cf.side = {h0, next(h0, tm), next(next(h0, tm), tm)};
    for(int k = 0; k < 3; ++k) cf.corner[k] = source(cf.side[k], tm);
    cut_faces.push_back(cf);
    put(face_of, f, cut_faces.size());
  }
  return get(face_of, f) - 1;
}

// The segments between consecutive points of every curve: along an edge (`Cut_segment::edge` if it has points
// on it), or inside a face (`Cut_segment::face`, the face added to the faces to cut). Segments whose two
// points are one are skipped (counted in `skipped`). Returns false, with the curve and the segment at fault,
// for two points on no common face.
template <class FT, class TriangleMesh, class EdgeOfMap, class FaceOfMap>
bool sort_cut_segments(const TriangleMesh& tm, EdgeOfMap edge_of, FaceOfMap face_of,
                       std::vector<Cut_point<TriangleMesh, FT> >& points, const std::vector<Cut_edge<TriangleMesh> >& cut_edges,
                       const std::vector<std::vector<std::size_t> >& curve_points, std::vector<Cut_segment>& segments,
                       std::vector<Cut_face<TriangleMesh> >& cut_faces, std::size_t& skipped, Cut_refusal& refusal)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::size_t none = std::size_t(-1);
  for(std::size_t c = 0; c < curve_points.size(); ++c)
    for(std::size_t j = 0; j + 1 < curve_points[c].size(); ++j)
    {
      const std::size_t a = curve_points[c][j], b = curve_points[c][j + 1];
      if(a == b) { ++skipped; continue; }
      Cut_segment s{a, b, c, j, none, none};
      const auto &pa = points[a], &pb = points[b];
      bool found = false;
      if(pa.edge == none && pb.edge == none)   // two vertices: along their edge
      {
        const auto h = halfedge(pa.vertex, pb.vertex, tm);
        found = h.second;
        if(found && get(edge_of, edge(h.first, tm)) != 0) s.edge = get(edge_of, edge(h.first, tm)) - 1;
      }
      else if(pa.edge == pb.edge)   // two points on one edge
      {
        s.edge = pa.edge;
        found = true;
      }
      else if(pa.edge != none && pb.edge != none)   // points on two edges: inside their common face
      {
        for(face_descriptor f : faces_of_cut_edge(tm, cut_edges[pa.edge]))
          for(face_descriptor g : faces_of_cut_edge(tm, cut_edges[pb.edge]))
            if(f == g && !found) { s.face = add_cut_face(tm, f, face_of, cut_faces); found = true; }
      }
      else   // a vertex and a point on an edge: along the edge if the vertex ends it, else inside a face
      {
        const std::size_t e = pa.edge != none ? pa.edge : pb.edge;
        const vertex_descriptor v = pa.edge != none ? pb.vertex : pa.vertex;
        const auto& ce = cut_edges[e];
        if(v == ce.source || v == ce.target) { s.edge = e; found = true; }
        else
          for(halfedge_descriptor g : {ce.h, opposite(ce.h, tm)})
            if(!is_border(g, tm) && target(next(g, tm), tm) == v && !found) { s.face = add_cut_face(tm, face(g, tm), face_of, cut_faces); found = true; }
      }
      if(!found)
      {
        refusal.curve = c;
        refusal.index = j;
        refusal.message = "the segment does not lie in a single face (its two points share no face)";
        return false;
      }
      points[a].used = points[b].used = true;
      segments.push_back(s);
    }
  return true;
}

// the faces on both sides of every edge that receives a point of a segment are cut (their sides change)
template <class TriangleMesh, class FT, class FaceOfMap>
void add_faces_of_used_edges(const TriangleMesh& tm, const std::vector<Cut_point<TriangleMesh, FT> >& points,
                             const std::vector<Cut_edge<TriangleMesh> >& cut_edges, FaceOfMap face_of,
                             std::vector<Cut_face<TriangleMesh> >& cut_faces)
{
  for(const auto& ce : cut_edges)
  {
    bool used = false;
    for(std::size_t p : ce.points) used = used || points[p].used;
    if(used)
      for(auto f : faces_of_cut_edge(tm, ce)) add_cut_face(tm, f, face_of, cut_faces);
  }
}

// Inserts a vertex (CGAL::Euler::split_edge()) at every used point on an edge, at the combination of the
// edge's ends with the point's coordinates, between the nearest points of the edge already inserted; both
// halves keep the chain (`flow`, halfedge -> value) of the edge.
template <class TriangleMesh, class VertexPointMap, class FT, class FlowMap>
void insert_edge_points(TriangleMesh& tm, VertexPointMap vpm, std::vector<Cut_point<TriangleMesh, FT> >& points,
                        const std::vector<Cut_edge<TriangleMesh> >& cut_edges, FlowMap flow)
{
  typedef boost::graph_traits<TriangleMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  for(std::size_t p = 0; p < points.size(); ++p)
  {
    auto& point = points[p];
    if(point.edge == std::size_t(-1) || !point.used) continue;
    // the sub-edge between the nearest points already inserted on both sides
    const auto& ce = cut_edges[point.edge];
    vertex_descriptor before = ce.source, after = ce.target;
    const auto at = std::find(ce.points.begin(), ce.points.end(), p);
    for(auto q = ce.points.begin(); q != at; ++q)
      if(points[*q].vertex != Traits::null_vertex()) before = points[*q].vertex;
    for(auto q = ce.points.end(); q != at + 1;)
      if(points[*--q].vertex != Traits::null_vertex()) after = points[*q].vertex;
    const halfedge_descriptor h = halfedge(before, after, tm).first;
    const halfedge_descriptor hnew = CGAL::Euler::split_edge(h, tm);   // hnew: before -> new, h: new -> after
    point.vertex = target(hnew, tm);
    const Point &ps = get(vpm, ce.source), &pt = get(vpm, ce.target);
    put(vpm, point.vertex, Point(point.at_source * ps.x() + point.at_target * pt.x(),
                                 point.at_source * ps.y() + point.at_target * pt.y(),
                                 point.at_source * ps.z() + point.at_target * pt.z()));
    put(flow, hnew, get(flow, h));
    put(flow, opposite(hnew, tm), get(flow, opposite(h, tm)));
  }
}

// Adds every segment to the chain (`flow`, +1 along it) on the edges of the cut mesh it runs along: its
// chord through the crossings (inside a face, `chord_of` the chord of each segment), or the pieces of its
// edge between the points inserted there.
template <class TriangleMesh, class FT, class FlowMap>
void add_segments_to_flow(const TriangleMesh& tm, const std::vector<Cut_point<TriangleMesh, FT> >& points,
                          const std::vector<Cut_edge<TriangleMesh> >& cut_edges, const std::vector<Cut_segment>& segments,
                          const std::vector<Cut_face<TriangleMesh> >& cut_faces, const std::vector<std::size_t>& chord_of,
                          FlowMap flow)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<FlowMap>::value_type Chain_value;
  const std::size_t none = std::size_t(-1);
  for(const auto& s : segments)
  {
    const vertex_descriptor va = points[s.a].vertex, vb = points[s.b].vertex;
    std::vector<vertex_descriptor> path{va, vb};
    if(s.face != none)   // its chord, through the crossings
    {
      const auto& cf = cut_faces[s.face];
      const std::size_t c = chord_of[&s - segments.data()];
      const std::size_t i = std::size_t(std::find(cf.chords.begin(), cf.chords.end(), c) - cf.chords.begin());
      path.assign(1, points[segments[c].a].vertex);
      for(const auto& x : cf.crossings[i]) path.push_back(cf.inner_vertex[x.second]);
      path.push_back(points[segments[c].b].vertex);
      if(path.front() != va) std::reverse(path.begin(), path.end());
    }
    else if(s.edge != none)
    {
      const auto& ce = cut_edges[s.edge];
      std::vector<vertex_descriptor> along{ce.source};
      for(std::size_t p : ce.points)
        if(points[p].used) along.push_back(points[p].vertex);
      along.push_back(ce.target);
      auto ia = std::find(along.begin(), along.end(), va), ib = std::find(along.begin(), along.end(), vb);
      if(ib < ia) path.assign(std::make_reverse_iterator(ia + 1), std::make_reverse_iterator(ib));
      else path.assign(ia, ib + 1);
    }
    for(std::size_t k = 0; k + 1 < path.size(); ++k)
    {
      const auto h = halfedge(path[k], path[k + 1], tm);
      CGAL_assertion(h.second);
      put(flow, h.first, get(flow, h.first) + Chain_value(1));
    }
  }
}

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_CUT_CURVES_H
