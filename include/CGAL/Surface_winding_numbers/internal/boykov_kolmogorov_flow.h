// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Boost.Graph's Boykov-Kolmogorov maximum flow behind the interface of Warm_push_relabel: arcs with
// residual capacities both ways, a signed terminal capacity per node (> 0: from the source, < 0: to
// the sink), run(), the flow of each arc and the source side of a minimum cut.
template <typename Int>
class Boykov_kolmogorov_flow
{
  typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Traits;
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_color_t, boost::default_color_type,
    boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor,
    boost::property<boost::vertex_distance_t, long>>>,
    boost::property<boost::edge_capacity_t, Int,
    boost::property<boost::edge_residual_capacity_t, Int,
    boost::property<boost::edge_reverse_t, Traits::edge_descriptor>>>> Graph;
  typedef typename boost::graph_traits<Graph>::edge_descriptor Edge;

public:
  // n nodes (the source and the sink are two more)
  explicit Boykov_kolmogorov_flow(std::size_t n) : n_(n), g_(n + 2) {}

  // an arc u -> v with residual capacities c_uv (u -> v) and c_vu (v -> u); its net flow u -> v is
  // flow(i) after run(), i being the number of arcs added before it
  void add_arc(std::size_t u, std::size_t v, Int c_uv, Int c_vu) { arcs_.push_back(add(u, v, c_uv, c_vu)); }

  // terminal capacity of v: t > 0 from the source to v, t < 0 from v to the sink
  void set_terminal(std::size_t v, Int t)
  {
    if(t > 0) sources_.push_back(add(n_, v, t, 0));
    else if(t < 0) add(v, n_ + 1, -t, 0);
  }

  // runs the maximum flow; true if it uses up every capacity from the source
  bool run()
  {
    value_ = boost::boykov_kolmogorov_max_flow(g_, n_, n_ + 1);
    for(const Edge& e : sources_)
      if(get(boost::edge_residual_capacity, g_, e) != 0) return false;
    return true;
  }

  // the value of the maximum flow (after run())
  Int value() const { return value_; }
  // net flow u -> v on arc i (after run())
  Int flow(std::size_t i) const
  {
    return get(boost::edge_capacity, g_, arcs_[i]) - get(boost::edge_residual_capacity, g_, arcs_[i]);
  }
  // after run(): true if v can be reached from the source in the residual graph (the source side of
  // a minimum cut)
  bool source_side(std::size_t v) const { return get(boost::vertex_color, g_, v) == boost::black_color; }

private:
  Edge add(std::size_t u, std::size_t v, Int c, Int c_back)
  {
    const Edge e = boost::add_edge(u, v, g_).first, r = boost::add_edge(v, u, g_).first;
    put(boost::edge_capacity, g_, e, c); put(boost::edge_capacity, g_, r, c_back);
    put(boost::edge_reverse, g_, e, r); put(boost::edge_reverse, g_, r, e);
    return e;
  }

  std::size_t n_;
  Graph g_;
  std::vector<Edge> arcs_, sources_;
  Int value_ = 0;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H
