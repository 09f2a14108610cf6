// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// thrown out of Boykov_kolmogorov_flow::run() when its stop flag is raised
struct Max_flow_stopped {};

// Boost.Graph's Boykov-Kolmogorov maximum flow behind the interface of Warm_push_relabel: arcs with
// residual capacities both ways, a signed terminal capacity per node (> 0: from the source, < 0: to
// the sink), run(), the flow of each arc and the source side of a minimum cut.
// run() can be stopped from another thread: Boost's algorithm reads every residual capacity through
// a property map, and ours checks a flag first and throws Max_flow_stopped when it is raised (the
// algorithm's state lives in local containers, which the exception unwinds).
// The graph is a compressed sparse row graph with its edge data in flat arrays: with an
// adjacency_list, every edge's properties were a heap block of their own, and on the 1.15M-face
// certificate of benchmark/residual_solvers.md the flow spent most of its time missing the cache.
template <typename Int>
class Boykov_kolmogorov_flow
{
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, boost::no_property,
                                             boost::no_property, std::size_t, std::size_t> Graph;
  typedef typename boost::graph_traits<Graph>::edge_descriptor Edge;
  typedef typename boost::property_map<Graph, boost::edge_index_t>::const_type Edge_index;

  // the residual capacities, read and written by Boost's algorithm; every read checks the stop flag
  struct Stoppable_residual_map
  {
    typedef Edge key_type;
    typedef Int value_type;
    typedef Int& reference;
    typedef boost::read_write_property_map_tag category;
    Int* residual;
    Edge_index index;
    const std::atomic<bool>* stop;
    friend Int get(const Stoppable_residual_map& m, const Edge& e)
    {
      if(m.stop->load(std::memory_order_relaxed)) throw Max_flow_stopped();
      return m.residual[get(m.index, e)];
    }
    friend void put(const Stoppable_residual_map& m, const Edge& e, Int value) { m.residual[get(m.index, e)] = value; }
  };

public:
  // n nodes (the source and the sink are two more)
  explicit Boykov_kolmogorov_flow(std::size_t n) : n_(n) {}

  // an arc u -> v with residual capacities c_uv (u -> v) and c_vu (v -> u); its net flow u -> v is
  // flow(i) after run(), i being the number of arcs added before it
  void add_arc(std::size_t u, std::size_t v, Int c_uv, Int c_vu) { arcs_.push_back(add(u, v, c_uv, c_vu)); }

  // terminal capacity of v: t > 0 from the source to v, t < 0 from v to the sink
  void set_terminal(std::size_t v, Int t)
  {
    if(t > 0) sources_.push_back(add(n_, v, t, 0));
    else if(t < 0) add(v, n_ + 1, -t, 0);
  }

  // runs the maximum flow; true if it uses up every capacity from the source. If `stop` is given and
  // becomes true while it runs, it throws Max_flow_stopped (the flow is then lost).
  bool run(const std::atomic<bool>* stop = nullptr)
  {
    static const std::atomic<bool> never(false);
    // half-edges h (h ^ 1 is the reverse of h) sorted by tail: half h is edge position_[h] of the graph
    const std::size_t nh = tail_.size(), nv = n_ + 2;
    std::vector<std::size_t> fill(nv + 1, 0);
    for(std::size_t h = 0; h < nh; ++h) ++fill[tail_[h] + 1];
    for(std::size_t v = 0; v < nv; ++v) fill[v + 1] += fill[v];
    position_.resize(nh);
    std::vector<std::pair<std::size_t, std::size_t>> sorted(nh);
    for(std::size_t h = 0; h < nh; ++h)
    {
      position_[h] = fill[tail_[h]]++;
      sorted[position_[h]] = std::make_pair(tail_[h], tail_[h ^ 1]);
    }
    Graph g(boost::edges_are_sorted, sorted.begin(), sorted.end(), nv);
    std::vector<std::pair<std::size_t, std::size_t>>().swap(sorted);
    std::vector<Edge> edge_at(nh);
    for(Edge e : boost::make_iterator_range(edges(g))) edge_at[get(boost::edge_index, g, e)] = e;
    std::vector<Int> capacity(nh);
    std::vector<Edge> reverse(nh);
    for(std::size_t h = 0; h < nh; ++h)
    {
      capacity[position_[h]] = cap_[h];
      reverse[position_[h]] = edge_at[position_[h ^ 1]];
    }
    residual_.assign(nh, Int(0));
    color_.assign(nv, boost::white_color);
    std::vector<Edge> predecessor(nv);
    std::vector<long> distance(nv, 0);
    const auto edge_index = get(boost::edge_index, g);
    const auto vertex_index = get(boost::vertex_index, g);
    value_ = boost::boykov_kolmogorov_max_flow(
      g, boost::make_iterator_property_map(capacity.begin(), edge_index),
      Stoppable_residual_map{residual_.data(), edge_index, stop != nullptr ? stop : &never},
      boost::make_iterator_property_map(reverse.begin(), edge_index),
      boost::make_iterator_property_map(predecessor.begin(), vertex_index),
      boost::make_iterator_property_map(color_.begin(), vertex_index),
      boost::make_iterator_property_map(distance.begin(), vertex_index), vertex_index, n_, n_ + 1);
    for(std::size_t h : sources_)
      if(residual_[position_[h]] != 0) return false;
    return true;
  }

  // the value of the maximum flow (after run())
  Int value() const { return value_; }
  // net flow u -> v on arc i (after run())
  Int flow(std::size_t i) const { return cap_[arcs_[i]] - residual_[position_[arcs_[i]]]; }
  // after run(): true if v can be reached from the source in the residual graph (the source side of
  // a minimum cut)
  bool source_side(std::size_t v) const { return color_[v] == boost::black_color; }

private:
  // the half-edges u -> v (returned) and v -> u
  std::size_t add(std::size_t u, std::size_t v, Int c, Int c_back)
  {
    const std::size_t h = tail_.size();
    tail_.push_back(u);
    tail_.push_back(v);
    cap_.push_back(c);
    cap_.push_back(c_back);
    return h;
  }

  std::size_t n_;
  std::vector<std::size_t> tail_, position_, arcs_, sources_;
  std::vector<Int> cap_, residual_;
  std::vector<boost::default_color_type> color_;
  Int value_ = 0;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_BOYKOV_KOLMOGOROV_FLOW_H
