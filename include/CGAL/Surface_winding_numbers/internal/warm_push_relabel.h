// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_WARM_PUSH_RELABEL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_WARM_PUSH_RELABEL_H

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// Balancing a nearly balanced flow: every node carries a signed imbalance b (> 0: an excess it
// must send on, < 0: a deficit it can absorb), and the excesses are pushed along residual arcs to
// the deficits by the push-relabel method (Goldberg and Tarjan) in its first phase only, with the
// highest active label first and periodic global relabeling (exact distances to the deficits by a
// backward breadth-first search). This is the maximum flow from a source feeding every excess to
// a sink draining every deficit, started from all source arcs saturated.
//  * If every excess reaches a deficit, run() returns BALANCED and flow() is a circulation
//    correction.
//  * Otherwise the nodes that can no longer reach any deficit (source_side()) are the source side
//    of a minimum cut; after a global relabeling they are all out of play at once.
// Capacities are integers (`Int` signed). On some certificates of the residual solver push-relabel
// needs hundreds of global relabelings (433 on a level of 188k nodes, 4x the time of
// Boykov-Kolmogorov; benchmark/residual_solvers.md), hence the work budget of run().
template <typename Int>
class Warm_push_relabel
{
public:
  typedef std::uint32_t Index;

  explicit Warm_push_relabel(std::size_t n) : n_(n), b_(n, Int(0))
  {
    if(n + 2 >= std::size_t((std::numeric_limits<Index>::max)())) throw std::length_error("max flow: too many nodes");
  }

  // an arc u -> v with residual capacities c_uv (u -> v) and c_vu (v -> u); returns its index i,
  // whose net flow u -> v is flow(i) after run()
  std::size_t add_arc(std::size_t u, std::size_t v, Int c_uv, Int c_vu)
  {
    if(2 * (tail_.size() + 2) >= std::size_t((std::numeric_limits<Index>::max)()))
      throw std::length_error("max flow: too many arcs");
    tail_.push_back(Index(u)); tail_.push_back(Index(v));
    r_.push_back(c_uv); r_.push_back(c_vu);
    return tail_.size() / 2 - 1;
  }

  // arc i gets the residual capacities c_uv and c_vu of a new problem on the same graph (the
  // arrays built by the first run() are kept: no allocation)
  void reset_arc(std::size_t i, Int c_uv, Int c_vu)
  {
    r_[2 * i] = c_uv;
    r_[2 * i + 1] = c_vu;
  }
  // the number of arcs added
  std::size_t number_of_arcs() const { return r_.size() / 2; }

  // imbalance of v: t > 0 an excess, t < 0 a deficit
  void set_terminal(std::size_t v, Int t) { b_[v] = t; }

  enum Outcome { BALANCED, CUT, OVER_BUDGET, STOPPED };

  // pushes until every excess is absorbed (BALANCED), or no excess can reach a deficit any more
  // (CUT: source_side() is a minimum cut), or more than `work_limit` arcs were scanned
  // (OVER_BUDGET: flow() holds the progress made, a valid preflow); global relabelings count as
  // one scan of every node and arc. If `stop` is given, it is read before every discharge: once it
  // is true, run() returns STOPPED (flow() is then a valid preflow too).
  Outcome run(std::size_t work_limit = (std::numeric_limits<std::size_t>::max)(),
              const std::atomic<bool>* stop = nullptr)
  {
    build();
    const Index dead = Index(n_);
    label_.assign(n_, 0);
    current_.assign(first_.begin(), first_.end() - 1);
    bucket_.assign(n_, NONE);
    next_.assign(n_, NONE);
    global_relabel();
    // global relabeling after about as much work as a few sweeps over the graph
    const std::size_t relabel_period = 6 * n_ + first_[n_] / 2;
    std::size_t work = 0, total = 0;
    while(highest_ != NONE)
    {
      if(stop != nullptr && stop->load(std::memory_order_relaxed)) return STOPPED;
      const Index v = bucket_[highest_];
      if(v == NONE) { highest_ = highest_ == 0 ? NONE : highest_ - 1; continue; }
      bucket_[highest_] = next_[v];
      const std::size_t w = discharge(v);
      work += w;
      total += w;
      if(label_[v] < dead && b_[v] > 0) activate(v);
      if(total > work_limit) return OVER_BUDGET;
      if(work > relabel_period)
      {
        work = 0;
        total += n_ + first_[n_];   // a global relabeling scans every node and arc once
        global_relabel();
      }
    }
    for(std::size_t v = 0; v < n_; ++v)
      if(b_[v] > 0) { global_relabel(); return CUT; }   // the labels now mark the cut exactly
    return BALANCED;
  }

  // net flow u -> v pushed on arc i
  Int flow(std::size_t i) const { return cap0_[2 * i] - r_[2 * i]; }

  // after run() returned CUT: true if v can no longer reach a deficit (the source side of a
  // minimum cut)
  bool source_side(std::size_t v) const { return label_[v] >= Index(n_); }

private:
  static constexpr Index NONE = (std::numeric_limits<Index>::max)();

  // the arcs grouped by tail, once; later runs only copy the capacities
  void build()
  {
    cap0_ = r_;
    if(built_) return;
    built_ = true;
    const std::size_t na = tail_.size();
    head_.resize(na);
    for(std::size_t a = 0; a < na; ++a) head_[a] = tail_[a ^ 1];
    first_.assign(n_ + 1, 0);
    for(std::size_t a = 0; a < na; ++a) ++first_[tail_[a] + 1];
    for(std::size_t v = 0; v < n_; ++v) first_[v + 1] += first_[v];
    out_.resize(na);
    std::vector<Index> fill(first_.begin(), first_.end() - 1);
    for(std::size_t a = 0; a < na; ++a) out_[fill[tail_[a]]++] = Index(a);
    std::vector<Index>().swap(tail_);
  }

  // an active node is in exactly one bucket (its label's): labels change only in discharge(), which
  // pops the node first, and in global_relabel(), which rebuilds the buckets
  void activate(Index v)
  {
    next_[v] = bucket_[label_[v]];
    bucket_[label_[v]] = v;
    if(highest_ == NONE || label_[v] > highest_) highest_ = label_[v];
  }

  // exact distances to the nodes with a deficit along residual arcs (breadth-first, backwards);
  // nodes that cannot reach one get the label n (they are out of the game)
  void global_relabel()
  {
    const Index dead = Index(n_);
    std::fill(label_.begin(), label_.end(), dead);
    queue_.clear();
    for(std::size_t v = 0; v < n_; ++v)
      if(b_[v] < 0) { label_[v] = 0; queue_.push_back(Index(v)); }
    for(std::size_t h = 0; h < queue_.size(); ++h)
    {
      const Index w = queue_[h];
      for(Index k = first_[w]; k < first_[w + 1]; ++k)
      {
        const Index a = out_[k];   // w -> u; the arc u -> w is a ^ 1
        const Index u = head_[a];
        if(label_[u] != dead || r_[a ^ 1] == 0) continue;
        label_[u] = label_[w] + 1;
        queue_.push_back(u);
      }
    }
    std::fill(bucket_.begin(), bucket_.end(), NONE);
    highest_ = NONE;
    for(std::size_t v = 0; v < n_; ++v)
    {
      current_[v] = first_[v];
      if(b_[v] > 0 && label_[v] < dead) activate(Index(v));
    }
  }

  // pushes the excess of v along admissible arcs, relabels v when none is left; returns the work
  std::size_t discharge(Index v)
  {
    const Index dead = Index(n_);
    std::size_t work = 0;
    while(b_[v] > 0)
    {
      Index k = current_[v];
      const Index end = first_[v + 1];
      for(; k < end; ++k)
      {
        const Index a = out_[k];
        if(r_[a] == 0) continue;
        const Index w = head_[a];
        if(label_[w] + 1 != label_[v]) continue;
        const Int d = (std::min)(b_[v], r_[a]);
        r_[a] -= d;
        r_[a ^ 1] += d;
        b_[v] -= d;
        const bool was_active = b_[w] > 0;
        b_[w] += d;
        if(!was_active && b_[w] > 0) activate(w);
        if(b_[v] == 0) break;
      }
      work += k - current_[v];
      if(b_[v] == 0) { current_[v] = k; break; }
      // relabel: one more than the lowest neighbour along a residual arc
      Index lowest = dead;
      for(Index j = first_[v]; j < end; ++j)
        if(r_[out_[j]] > 0) lowest = (std::min)(lowest, label_[head_[out_[j]]]);
      work += end - first_[v] + 12;
      current_[v] = first_[v];
      label_[v] = lowest >= dead - 1 ? dead : lowest + 1;
      if(label_[v] == dead) break;
    }
    return work;
  }

  std::size_t n_;
  std::vector<Int> b_, r_, cap0_;
  std::vector<Index> tail_, head_, first_, out_;
  std::vector<Index> label_, current_, queue_;
  std::vector<Index> bucket_, next_;   // active nodes per label, as singly linked stacks
  Index highest_ = NONE;
  bool built_ = false;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_WARM_PUSH_RELABEL_H
