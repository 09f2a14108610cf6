// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_BOYKOV_KOLMOGOROV_FLOW_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_BOYKOV_KOLMOGOROV_FLOW_H

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Boost.Graph's Boykov-Kolmogorov maximum flow behind the interface of Warm_push_relabel: arcs with
// residual capacities both ways, a signed terminal capacity per node (> 0: from the source, < 0: to
// the sink), run(), the flow of each arc and the source side of a minimum cut.
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

public:
  // n nodes (the source and the sink are two more)
  explicit Boykov_kolmogorov_flow(std::size_t n) : n_(n), terminal_(n, Int(0)) {}

  // an arc u -> v with residual capacities c_uv (u -> v) and c_vu (v -> u); its net flow u -> v is
  // flow(i) after run(), i being the number of arcs added before it
  void add_arc(std::size_t u, std::size_t v, Int c_uv, Int c_vu) { arcs_.push_back(add(u, v, c_uv, c_vu)); }

  // arc i gets the residual capacities c_uv and c_vu of a new problem on the same graph (the graph
  // built by the first run() is kept)
  void reset_arc(std::size_t i, Int c_uv, Int c_vu)
  {
    cap_[arcs_[i]] = c_uv;
    cap_[arcs_[i] ^ 1] = c_vu;
  }
  // the number of arcs added
  std::size_t number_of_arcs() const { return arcs_.size(); }

  // terminal capacity of v: t > 0 from the source to v, t < 0 from v to the sink
  void set_terminal(std::size_t v, Int t) { terminal_[v] = t; }

  // runs the maximum flow; true if it uses up every capacity from the source. Every node has an
  // arc from the source and one to the sink (capacity 0 where its terminal capacity has the other
  // sign), so that the graph, built by the first run, serves every later one.
  bool run()
  {
    if(!built_) build();
    const std::size_t nh = position_.size(), nv = n_ + 2;
    for(std::size_t v = 0; v < n_; ++v)
    {
      cap_[first_terminal_ + 4 * v] = terminal_[v] > 0 ? terminal_[v] : Int(0);       // source -> v
      cap_[first_terminal_ + 4 * v + 2] = terminal_[v] < 0 ? -terminal_[v] : Int(0);  // v -> sink
    }
    for(std::size_t h = 0; h < nh; ++h) capacity_[position_[h]] = cap_[h];
    residual_.assign(nh, Int(0));
    color_.assign(nv, boost::white_color);
    predecessor_.assign(nv, Edge());
    distance_.assign(nv, 0);
    const auto edge_index = get(boost::edge_index, graph_);
    const auto vertex_index = get(boost::vertex_index, graph_);
    value_ = boost::boykov_kolmogorov_max_flow(
      graph_, boost::make_iterator_property_map(capacity_.begin(), edge_index),
      boost::make_iterator_property_map(residual_.begin(), edge_index),
      boost::make_iterator_property_map(reverse_.begin(), edge_index),
      boost::make_iterator_property_map(predecessor_.begin(), vertex_index),
      boost::make_iterator_property_map(color_.begin(), vertex_index),
      boost::make_iterator_property_map(distance_.begin(), vertex_index), vertex_index, n_, n_ + 1);
    for(std::size_t v = 0; v < n_; ++v)
      if(terminal_[v] > 0 && residual_[position_[first_terminal_ + 4 * v]] != 0) return false;
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

  // the terminal arcs of every node, then the graph: half-edges h (h ^ 1 is the reverse of h) sorted
  // by tail, half h being edge position_[h] of the graph
  void build()
  {
    built_ = true;
    first_terminal_ = tail_.size();
    for(std::size_t v = 0; v < n_; ++v)
    {
      add(n_, v, 0, 0);
      add(v, n_ + 1, 0, 0);
    }
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
    graph_ = Graph(boost::edges_are_sorted, sorted.begin(), sorted.end(), nv);
    std::vector<std::pair<std::size_t, std::size_t>>().swap(sorted);
    std::vector<std::size_t>().swap(tail_);
    std::vector<Edge> edge_at(nh);
    for(Edge e : boost::make_iterator_range(edges(graph_))) edge_at[get(boost::edge_index, graph_, e)] = e;
    capacity_.resize(nh);
    reverse_.resize(nh);
    for(std::size_t h = 0; h < nh; ++h) reverse_[position_[h]] = edge_at[position_[h ^ 1]];
  }

  std::size_t n_;
  std::vector<Int> terminal_;
  std::vector<std::size_t> tail_, position_, arcs_;
  std::vector<Int> cap_, capacity_, residual_;
  std::size_t first_terminal_ = 0;
  bool built_ = false;
  Graph graph_;
  std::vector<Edge> reverse_, predecessor_;
  std::vector<long> distance_;
  std::vector<boost::default_color_type> color_;
  Int value_ = 0;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_BOYKOV_KOLMOGOROV_FLOW_H
