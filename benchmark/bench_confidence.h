// Benchmark (swn_bench_solve): per-region confidence of a solve, the second-best labeling and
// simulated user hints. Everything is per table index of the solver's Mesh_tables.
//
// Cells: the faces connected across interior edges where the input chain, the nonbounding chain G and
// the jump of the labels W are all zero; W is constant on a cell. Flipping a cell C by delta (W += delta
// on C) keeps the decomposition "input = J W + G" only with G -= delta J 1_C, a chain homologous to G, so
// every flip is another completion of the same input with nonbounding loops of the same class. Its
// cost is the change of Eq. 11's objective, sum over interior edges of w_e |G_e| (w_e = epsilon x length
// on input edges, length elsewhere; lengths in units of the mean interior edge length), and it is
// infeasible when G leaves Eq. 11's bounds on an input edge (G_e of the sign of the input, |G_e| <=
// |input_e|). The flip cost of a cell is that of its cheaper direction: a small cost says that another
// labeling of that region explains the input almost as well (the ambiguity of the paper's Fig. 18).
// This is the cost of a local move with everything else fixed, so it bounds from above what a re-solve
// with the cell's label constrained would cost.

#ifndef SWN_BENCH_CONFIDENCE_H
#define SWN_BENCH_CONFIDENCE_H

#include <CGAL/Surface_winding_numbers/internal/mesh_tables.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <numeric>
#include <vector>

namespace swn_bench {

namespace SWN_internal = CGAL::Surface_winding_numbers::internal;

struct Cells
{
  std::vector<std::size_t> of_face;   // face -> cell
  std::vector<double> area;           // per cell
  std::vector<std::size_t> component; // per cell: the mesh component
};

inline Cells label_cells(const SWN_internal::Mesh_tables& m, const std::vector<double>& chain, const std::vector<long>& G,
                         const std::vector<int>& W, const std::vector<double>& face_area)
{
  std::vector<std::size_t> uf(m.nf);
  std::iota(uf.begin(), uf.end(), std::size_t(0));
  auto find = [&](std::size_t x) {
    while(uf[x] != x) { uf[x] = uf[uf[x]]; x = uf[x]; }
    return x;
  };
  for(const SWN_internal::Arc& a : m.arcs)
  {
    const std::size_t L = a.left_side / 3, R = a.right_side / 3;
    if(chain[a.edge] != 0 || G[a.edge] != 0 || W[L] != W[R]) continue;
    const std::size_t x = find(L), y = find(R);
    if(x != y) uf[std::max(x, y)] = std::min(x, y);
  }
  Cells c;
  c.of_face.assign(m.nf, 0);
  std::map<std::size_t, std::size_t> id;
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    const auto it = id.emplace(find(f), id.size()).first;
    c.of_face[f] = it->second;
    if(c.area.size() <= it->second) { c.area.push_back(0.); c.component.push_back(m.face_component[f]); }
    c.area[it->second] += face_area[f];
  }
  return c;
}

// The mean interior edge length: the unit of the costs.
inline double mean_interior_edge_length(const SWN_internal::Mesh_tables& m)
{
  double mean_len = 0;
  for(const SWN_internal::Arc& a : m.arcs) mean_len += m.edge_length(a.edge);
  return m.arcs.empty() ? 1. : mean_len / double(m.arcs.size());
}

// Eq. 11 weight of an edge: epsilon x length on input edges, length elsewhere, in mean interior edge lengths.
inline std::vector<double> eq11_weights(const SWN_internal::Mesh_tables& m, const std::vector<double>& chain, double epsilon)
{
  const double unit = mean_interior_edge_length(m);
  std::vector<double> w(m.ne, 0.);
  for(std::size_t e = 0; e < m.ne; ++e) w[e] = m.edge_length(e) / unit * (std::abs(chain[e]) > 0 ? epsilon : 1.);
  return w;
}

// Eq. 11 cost of an integer chain X: sum of w_e |X_e| over the interior edges.
inline double eq11_cost(const SWN_internal::Mesh_tables& m, const std::vector<long>& X, const std::vector<double>& weight)
{
  double cost = 0;
  for(const SWN_internal::Arc& a : m.arcs) cost += weight[a.edge] * std::fabs(double(X[a.edge]));
  return cost;
}

struct Flip
{
  double cost = std::numeric_limits<double>::infinity();   // Eq. 11 cost increase; infinite: no feasible flip
  int delta = 0;                                            // W += delta on the cell
  double boundary = 0;                                      // length of the cell's boundary (mean edge lengths)
};

// The cheaper feasible flip of every cell.
inline std::vector<Flip> flip_costs(const SWN_internal::Mesh_tables& m, const Cells& cells, const std::vector<double>& chain,
                                    const std::vector<long>& G, const std::vector<double>& weight)
{
  const std::size_t n = cells.area.size();
  const double unit = mean_interior_edge_length(m);
  std::vector<double> cost[2] = {std::vector<double>(n, 0.), std::vector<double>(n, 0.)};   // delta = +1, -1
  std::vector<char> feasible[2] = {std::vector<char>(n, 1), std::vector<char>(n, 1)};
  std::vector<double> boundary(n, 0.);
  for(const SWN_internal::Arc& a : m.arcs)
  {
    const std::size_t cl = cells.of_face[a.left_side / 3], cr = cells.of_face[a.right_side / 3];
    if(cl == cr) continue;
    const long g = G[a.edge];
    const long in = std::lround(chain[a.edge]);
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t c = side == 0 ? cl : cr;
      const int j = side == 0 ? 1 : -1;   // (J 1_c)_e = 1_c(left) - 1_c(right)
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

// A user hint on one cell: its faces get the label the ground truth gives most of its area (shifted by
// the component's offset); the rest is kept.
inline std::vector<int> relabel_cell(const SWN_internal::Mesh_tables& m, const Cells& cells, std::size_t cell,
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
