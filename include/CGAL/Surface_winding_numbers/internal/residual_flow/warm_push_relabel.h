// Copyright (c) 2026 The CGAL Surface Winding Numbers project.
// SPDX-License-Identifier: MIT

#ifndef CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_WARM_PUSH_RELABEL_H
#define CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_WARM_PUSH_RELABEL_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Surface_winding_numbers {
namespace internal {

// asks the processor to fetch the cache line of p (a hint, no effect on the results)
inline void prefetch(const void* p)
{
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

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
// With the gap heuristic: when a relabeling leaves no node with some label, every node above it is
// put out of play at once (without it, push-relabel needed hundreds of global relabelings on the
// refused certificates of the residual solver, 433 on a level of 188k nodes, 4x the time of
// Boykov-Kolmogorov; benchmark/residual_solvers.md). Capacities are integers (`Int` signed); run()
// takes a work budget.
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
    if(built_) throw std::logic_error("max flow: arcs added after the first run");
    tail_.push_back(Index(u)); tail_.push_back(Index(v));
    cap0_.push_back(c_uv); cap0_.push_back(c_vu);
    return cap0_.size() / 2 - 1;
  }

  // arc i gets the residual capacities c_uv and c_vu of a new problem on the same graph (the
  // arrays built by the first run() are kept: no allocation)
  void reset_arc(std::size_t i, Int c_uv, Int c_vu)
  {
    cap0_[2 * i] = c_uv;
    cap0_[2 * i + 1] = c_vu;
  }
  // the number of arcs added
  std::size_t number_of_arcs() const { return cap0_.size() / 2; }

  // imbalance of v: t > 0 an excess, t < 0 a deficit
  void set_terminal(std::size_t v, Int t) { b_[v] = t; }

  enum Outcome { BALANCED, CUT, OVER_BUDGET };

  // pushes until every excess is absorbed (BALANCED), or no excess can reach a deficit any more
  // (CUT: source_side() is a minimum cut), or more than `work_limit` arcs were scanned
  // (OVER_BUDGET: flow() holds the progress made, a valid preflow); global relabelings count as
  // one scan of every node and arc.
  Outcome run(std::size_t work_limit = (std::numeric_limits<std::size_t>::max)())
  {
    start();
    const Index dead = Index(n_);
    // global relabeling after about as much work as a few sweeps over the graph
    const std::size_t relabel_period = 6 * n_ + first_[n_] / 2;
    std::size_t work = 0, total = 0;
    while(highest_ != NONE)
    {
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

  // The same maximum flow (same outcomes, same source side on a cut) by shortest augmenting paths
  // along the same distance labels: each excess in turn is sent along a path of admissible arcs
  // (the label one lower at each step) to a deficit, retreating from nodes without one (relabelled);
  // a global relabeling when a label is left empty (a gap) and as often as in run(). No excess is
  // spread over the nodes on the way: where the excesses must travel far, around the barriers of
  // the curves (the warm start's certificates), this moves each one along a few paths (the pushes of
  // run() were 50 times the length of such paths on a moved stroke, benchmark/SPEED.md).
  Outcome run_paths(std::size_t work_limit = (std::numeric_limits<std::size_t>::max)())
  {
    start();
    const Index dead = Index(n_);
    const std::size_t relabel_period = 6 * n_ + first_[n_] / 2;
    std::size_t work = 0, total = 0;
    std::vector<Index> sources, path;   // path: the half-arcs from the source to v
    for(std::size_t v = 0; v < n_; ++v)
      if(b_[v] > 0) sources.push_back(Index(v));
    for(const Index s : sources)
    {
      Index v = s;
      path.clear();
      while(b_[s] > 0 && label_[s] < dead)
      {
        if(b_[v] < 0)   // augment by what the source holds, the deficit absorbs and the path carries
        {
          Int d = (std::min)(b_[s], -b_[v]);
          for(const Index k : path) d = (std::min)(d, half_[k].r);
          std::size_t keep = path.size();   // the path up to its first saturated arc stays
          for(std::size_t q = 0; q < path.size(); ++q)
          {
            Half& h = half_[path[q]];
            h.r -= d;
            half_[h.rev].r += d;
            if(h.r == 0 && keep == path.size()) keep = q;
          }
          b_[s] -= d;
          b_[v] += d;
          work += path.size();
          path.resize(keep);
          v = path.empty() ? s : half_[path.back()].head;
          continue;
        }
        Index k = current_[v];
        const Index end = first_[v + 1];
        while(k < end && (half_[k].r == 0 || label_[half_[k].head] + 1 != label_[v])) ++k;
        work += k - current_[v] + 1;
        current_[v] = k;
        if(k < end)   // advance
        {
          path.push_back(k);
          v = half_[k].head;
          continue;
        }
        // retreat: v gets one more than its lowest neighbour along a residual arc
        Index lowest = dead;
        for(Index j = first_[v]; j < end; ++j)
          if(half_[j].r > 0) lowest = (std::min)(lowest, label_[half_[j].head]);
        work += end - first_[v] + 12;
        current_[v] = first_[v];
        const Index old = label_[v];
        label_[v] = lowest >= dead - 1 ? dead : lowest + 1;
        if(label_[v] != dead) ++count_[label_[v]];
        const bool gap = old != dead && --count_[old] == 0;
        if(!path.empty())
        {
          path.pop_back();
          v = path.empty() ? s : half_[path.back()].head;
        }
        if(gap || work > relabel_period)
        {
          gaps_ += gap ? 1 : 0;
          total += work + n_ + first_[n_];
          work = 0;
          if(total > work_limit) return OVER_BUDGET;
          global_relabel();
          path.clear();
          v = s;
        }
      }
      if(total + work > work_limit) return OVER_BUDGET;
    }
    for(std::size_t v = 0; v < n_; ++v)
      if(b_[v] > 0) { global_relabel(); return CUT; }   // the labels now mark the cut exactly
    return BALANCED;
  }

  // the number of gaps found by the last run() (see relabel())
  std::size_t gaps() const { return gaps_; }

  // net flow u -> v pushed on arc i
  Int flow(std::size_t i) const { return cap0_[2 * i] - half_[pos_[2 * i]].r; }

  // after run() returned CUT: true if v can no longer reach a deficit (the source side of a
  // minimum cut)
  bool source_side(std::size_t v) const { return label_[v] >= Index(n_); }

private:
  static constexpr Index NONE = (std::numeric_limits<Index>::max)();

  // the arrays of a run, sized; exact labels
  void start()
  {
    build();
    label_.assign(n_, 0);
    current_.assign(first_.begin(), first_.end() - 1);
    next_.assign(n_, NONE);
    // sized only: global_relabel() fills bucket_, count_ and level_, and link() sets before_ and after_
    bucket_.resize(n_);
    count_.resize(n_);
    level_.resize(n_);
    before_.resize(n_);
    after_.resize(n_);
    gaps_ = 0;
    global_relabel();
  }

  // the half-arcs laid out by tail, once (stable: each node's arcs in the order they were added), each
  // with its head and the position of its reverse next to its residual capacity, so that a node's
  // scan reads one contiguous block; later runs only scatter the new capacities
  void build()
  {
    if(!built_)
    {
      built_ = true;
      const std::size_t na = tail_.size();
      first_.assign(n_ + 1, 0);
      for(std::size_t a = 0; a < na; ++a) ++first_[tail_[a] + 1];
      for(std::size_t v = 0; v < n_; ++v) first_[v + 1] += first_[v];
      pos_.resize(na);
      std::vector<Index> fill(first_.begin(), first_.end() - 1);
      for(std::size_t a = 0; a < na; ++a) pos_[a] = fill[tail_[a]]++;
      half_.resize(na);
      for(std::size_t a = 0; a < na; ++a)
      {
        half_[pos_[a]].head = tail_[a ^ 1];
        half_[pos_[a]].rev = pos_[a ^ 1];
      }
      std::vector<Index>().swap(tail_);
    }
    for(std::size_t a = 0; a < cap0_.size(); ++a) half_[pos_[a]].r = cap0_[a];
  }

  // an active node is in exactly one bucket (its label's): labels change only in discharge(), which
  // pops the node first, and in global_relabel(), which rebuilds the buckets
  void activate(Index v)
  {
    next_[v] = bucket_[label_[v]];
    bucket_[label_[v]] = v;
    if(highest_ == NONE || label_[v] > highest_) highest_ = label_[v];
  }

  // v joins the list of the nodes with its label (< n)
  void link(Index v)
  {
    const Index d = label_[v];
    before_[v] = NONE;
    after_[v] = level_[d];
    if(after_[v] != NONE) before_[after_[v]] = v;
    level_[d] = v;
    ++count_[d];
    if(d > top_) top_ = d;
  }

  // v leaves the list of the nodes with its label (< n)
  void unlink(Index v)
  {
    const Index d = label_[v];
    if(before_[v] != NONE) after_[before_[v]] = after_[v];
    else level_[d] = after_[v];
    if(after_[v] != NONE) before_[after_[v]] = before_[v];
    --count_[d];
  }

  // v (not in a bucket) gets the higher label `fresh`. If v was the last node labelled d and keeps a
  // residual arc to a live node, no node above d can reach a deficit any more (a residual arc lowers
  // the label by at most one): the gap heuristic puts all of them, v included, out of play at once.
  // (A v without such an arc just dies; the next gap or global relabeling catches the others.)
  // Returns the work.
  std::size_t relabel(Index v, Index fresh)
  {
    const Index dead = Index(n_), d = label_[v];
    unlink(v);
    if(count_[d] != 0 || fresh == dead)
    {
      label_[v] = fresh;
      if(fresh != dead) link(v);
      return 0;
    }
    label_[v] = dead;
    ++gaps_;
    std::size_t work = top_ - d;
    for(Index k = d + 1; k <= top_; ++k)
    {
      for(Index u = level_[k]; u != NONE; u = after_[u]) { label_[u] = dead; ++work; }
      level_[k] = NONE;
      count_[k] = 0;
      bucket_[k] = NONE;
    }
    top_ = d;
    if(highest_ != NONE && highest_ > d) highest_ = d;
    return work;
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
    // the search is bound by memory latency on large graphs (each node of the queue, its arcs and its
    // neighbours' labels and reverse arcs lie anywhere): the nodes a few places ahead in the queue are
    // fetched in three stages, so that their data is in cache when their turn comes (residual alone,
    // best of five: 13-22 % faster on four of six mid-size benchmark cases, benchmark/residual_solvers.md)
    constexpr std::size_t ahead = 16;
    for(std::size_t h = 0; h < queue_.size(); ++h)
    {
      const std::size_t queued = queue_.size();
      if(h + 3 * ahead < queued) prefetch(first_.data() + queue_[h + 3 * ahead]);
      if(h + 2 * ahead < queued)
      {
        // a node's arcs may straddle two cache lines (a hint only: one past the end is harmless)
        const Index a = queue_[h + 2 * ahead];
        prefetch(half_.data() + first_[a]);
        prefetch(half_.data() + first_[a + 1] - (first_[a + 1] > first_[a] ? 1 : 0));
      }
      if(h + ahead < queued)
        for(Index k = first_[queue_[h + ahead]]; k < first_[queue_[h + ahead] + 1]; ++k)
        {
          prefetch(label_.data() + half_[k].head);
          prefetch(half_.data() + half_[k].rev);
        }
      const Index w = queue_[h];
      for(Index k = first_[w]; k < first_[w + 1]; ++k)
      {
        const Half& h = half_[k];   // w -> u; the arc u -> w is at h.rev
        const Index u = h.head;
        if(label_[u] != dead || half_[h.rev].r == 0) continue;
        label_[u] = label_[w] + 1;
        queue_.push_back(u);
      }
    }
    std::fill(bucket_.begin(), bucket_.end(), NONE);
    std::fill(count_.begin(), count_.end(), 0);
    std::fill(level_.begin(), level_.end(), NONE);
    highest_ = NONE;
    top_ = 0;
    for(std::size_t v = 0; v < n_; ++v)
    {
      current_[v] = first_[v];
      if(label_[v] == dead) continue;
      link(Index(v));
      if(b_[v] > 0) activate(Index(v));
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
        Half& h = half_[k];
        if(h.r == 0) continue;
        const Index w = h.head;
        if(label_[w] + 1 != label_[v]) continue;
        const Int d = (std::min)(b_[v], h.r);
        h.r -= d;
        half_[h.rev].r += d;
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
        if(half_[j].r > 0) lowest = (std::min)(lowest, label_[half_[j].head]);
      work += end - first_[v] + 12;
      current_[v] = first_[v];
      work += relabel(v, lowest >= dead - 1 ? dead : lowest + 1);
      if(label_[v] == dead) break;
    }
    return work;
  }

  struct Half
  {
    Int r;       // residual capacity
    Index head;
    Index rev;   // position of the reverse half-arc
  };

  std::size_t n_;
  std::vector<Int> b_, cap0_;        // imbalances; capacities as given, by arc (2i: u -> v, 2i + 1: v -> u)
  std::vector<Index> tail_, pos_;    // by arc: tail (until the first run), position in half_
  std::vector<Index> first_;         // by node: its first position in half_
  std::vector<Half> half_;
  std::vector<Index> label_, current_, queue_;
  std::vector<Index> bucket_, next_;   // active nodes per label, as singly linked stacks
  std::vector<Index> count_, level_, before_, after_;   // every live node per label (doubly linked), for the gap heuristic
  Index highest_ = NONE, top_ = 0;   // highest label with an active node; no live node is above top_
  std::size_t gaps_ = 0;
  bool built_ = false;
};

} // namespace internal
} // namespace Surface_winding_numbers
} // namespace CGAL

#endif // CGAL_SURFACE_WINDING_NUMBERS_INTERNAL_RESIDUAL_FLOW_WARM_PUSH_RELABEL_H
