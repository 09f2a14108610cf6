// Benchmark (swn_bench_solve): simulated user hints on top of the library's per-region confidence
// (include/CGAL/Surface_winding_numbers/internal/confidence.h: regions, flip costs, second-best labeling).
// Everything is per table index of the solver's Mesh_tables.

#ifndef SWN_BENCH_CONFIDENCE_H
#define SWN_BENCH_CONFIDENCE_H

#include <CGAL/Surface_winding_numbers/internal/confidence.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numeric>
#include <vector>

namespace swn_bench {

namespace SWN_internal = CGAL::Surface_winding_numbers::internal;

// The offset (W - gt) covering the largest area of each component, as in the benchmark's error.
inline std::vector<long> best_offsets(const SWN_internal::Mesh_tables& m, const std::vector<double>& area,
                                      const std::vector<int>& W, const std::vector<int>& gt)
{
  std::vector<std::map<long, double>> hist(m.n_components);
  for(std::size_t f = 0; f < m.nf; ++f) hist[m.face_component[f]][long(W[f]) - long(gt[f])] += area[f];
  std::vector<long> off(m.n_components, 0);
  for(std::size_t c = 0; c < m.n_components; ++c)
  {
    double best = -1;
    for(const auto& kv : hist[c])
      if(kv.second > best) { best = kv.second; off[c] = kv.first; }
  }
  return off;
}

// A user hint on one region (cell): its faces get the label the ground truth gives most of its area
// (shifted by the component's offset); the rest is kept.
inline std::vector<int> relabel_cell(const SWN_internal::Mesh_tables& m, const SWN_internal::Label_regions& cells, std::size_t cell,
                                     const std::vector<double>& area, const std::vector<int>& W, const std::vector<int>& gt)
{
  const std::vector<long> off = best_offsets(m, area, W, gt);
  std::map<long, double> votes;
  for(std::size_t f = 0; f < m.nf; ++f)
    if(cells.of_face[f] == cell) votes[long(gt[f]) + off[m.face_component[f]]] += area[f];
  long label = 0;
  double best = -1;
  for(const auto& kv : votes)
    if(kv.second > best) { best = kv.second; label = kv.first; }
  std::vector<int> out = W;
  for(std::size_t f = 0; f < m.nf; ++f)
    if(cells.of_face[f] == cell) out[f] = int(label);
  return out;
}


// A user hint on the input: the user redraws one missing piece of the curve. The pieces are the
// maximal runs (edges sharing a vertex) of edges of the complete input `full` missing from `chain`;
// the one chosen borders the most mislabeled area (faces with `wrong` set), ties to the longer run.
// Returns its edges (empty when nothing is missing).
inline std::vector<std::size_t> missing_run_hint(const SWN_internal::Mesh_tables& m, const std::vector<long>& full,
                                                 const std::vector<double>& chain, const std::vector<char>& wrong,
                                                 const std::vector<double>& area)
{
  std::vector<std::size_t> uf(m.nv);
  std::iota(uf.begin(), uf.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; }
    return x;
  };
  std::vector<std::size_t> missing;
  for(std::size_t e = 0; e < m.ne; ++e)
    if(full[e] != 0 && chain[e] == 0)
    {
      missing.push_back(e);
      const std::size_t x = find(m.ev[2 * e]), y = find(m.ev[2 * e + 1]);
      if(x != y) uf[std::max(x, y)] = std::min(x, y);
    }
  std::map<std::size_t, std::pair<double, double>> score;   // run root -> (mislabeled area, length)
  for(std::size_t e : missing)
  {
    auto& sc = score[find(m.ev[2 * e])];
    sc.second += m.edge_length(e);
    const std::size_t a = m.edge_arc[e];
    if(a == std::size_t(-1)) continue;
    for(std::size_t side : {m.arcs[a].left_side, m.arcs[a].right_side})
      if(wrong[side / 3]) sc.first += area[side / 3];
  }
  if(score.empty()) return {};
  auto best = score.begin();
  for(auto it = score.begin(); it != score.end(); ++it)
    if(it->second > best->second) best = it;
  std::vector<std::size_t> run;
  for(std::size_t e : missing)
    if(find(m.ev[2 * e]) == best->first) run.push_back(e);
  return run;
}

} // namespace swn_bench

#endif // SWN_BENCH_CONFIDENCE_H
