// Benchmark generator: ground-truth regions (labels per face, thresholds of a smooth function) and the
// deletion of curve pieces (gaps).

#ifndef SWN_BENCH_GEN_REGIONS_H
#define SWN_BENCH_GEN_REGIONS_H

#include "gen_common.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace swn_bench {

// Face geometry used by the region draws: centroids, areas, the bounding-box diagonal.
struct Face_geometry
{
  std::vector<Point> centroid;
  std::vector<double> area;
  double total_area = 0, diagonal = 0;
};

inline Face_geometry face_geometry(const Mesh& m)
{
  Face_geometry g;
  g.centroid.resize(m.number_of_faces());
  g.area.resize(m.number_of_faces());
  for(FI f : m.faces())
  {
    const HI h = m.halfedge(f);
    g.centroid[std::size_t(f)] = CGAL::centroid(m.point(m.source(h)), m.point(m.target(h)), m.point(m.target(m.next(h))));
    g.area[std::size_t(f)] = PMP::face_area(f, m);
    g.total_area += g.area[std::size_t(f)];
  }
  const auto bb = CGAL::bounding_box(m.points().begin(), m.points().end());
  g.diagonal = std::sqrt(CGAL::squared_distance(bb.min(), bb.max()));
  return g;
}

// Labels 0, 1 (and 2 with probability 0.4) by thresholding `val` (per face) at area quantiles: the
// first level leaves 35-70 % of the area below it, the second lies in the upper part. Returns false
// when the region above the first level covers less than 5 % or more than 95 % of the area.
inline bool threshold_labels(const std::vector<double>& val, const Face_geometry& g, Rng& rng, std::vector<int>& gt)
{
  const std::size_t nf = val.size();
  std::vector<std::size_t> ord(nf);
  std::iota(ord.begin(), ord.end(), std::size_t(0));
  std::sort(ord.begin(), ord.end(), [&](std::size_t x, std::size_t y) { return val[x] < val[y]; });
  auto quantile = [&](double q) {
    double acc = 0;
    for(std::size_t i : ord) { acc += g.area[i]; if(acc >= q * g.total_area) return val[i]; }
    return val[ord.back()];
  };
  const double q1 = rng.uniform(0.35, 0.7);
  const double th1 = quantile(q1);
  const bool two = rng.coin(0.4);
  const double th2 = two ? quantile(q1 + rng.uniform(0.3, 0.8) * (1 - q1)) : 1e300;
  gt.assign(nf, 0);
  double a1 = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    gt[f] = (val[f] > th1 ? 1 : 0) + (val[f] > th2 ? 1 : 0);
    if(gt[f] > 0) a1 += g.area[f];
  }
  return a1 > 0.05 * g.total_area && a1 < 0.95 * g.total_area;
}

// The "full" suite's regions: a smooth random field in 3D (3-6 Gaussians centred on the surface,
// widths 10-30 % of the bounding-box diagonal, random signs) at the face centroids, thresholded.
inline std::vector<int> random_field_regions(const Mesh& m, const Face_geometry& g, Rng& rng)
{
  std::vector<int> gt;
  for(int attempt = 0; attempt < 20; ++attempt)
  {
    const int K = 3 + int(rng.index(4));
    std::vector<Point> c;
    std::vector<double> s, a;
    for(int k = 0; k < K; ++k)
    {
      c.push_back(m.point(VI(Mesh::size_type(rng.index(m.number_of_vertices())))));
      s.push_back(rng.uniform(0.10, 0.30) * g.diagonal);
      a.push_back((rng.coin() ? 1 : -1) * rng.uniform(0.5, 1.5));
    }
    std::vector<double> val(g.area.size());
    for(std::size_t f = 0; f < val.size(); ++f)
    {
      double x = 0;
      for(int k = 0; k < K; ++k) x += a[k] * std::exp(-CGAL::squared_distance(g.centroid[f], c[k]) / (2 * s[k] * s[k]));
      val[f] = x;
    }
    if(threshold_labels(val, g, rng, gt)) break;
  }
  return gt;
}

// The "paper" suite's regions (the paper's Sec. 5.2): sublevel sets of one low-frequency Laplacian
// eigenfunction, drawn among the `phi` given per vertex (the lowest nonconstant ones), at the face
// means of its vertex values.
inline std::vector<int> eigenfunction_regions(const Mesh& m, const std::vector<std::vector<double>>& phi,
                                              const Face_geometry& g, Rng& rng, int& which)
{
  std::vector<int> gt;
  for(int attempt = 0; attempt < 20; ++attempt)
  {
    which = int(rng.index(phi.size()));
    std::vector<double> val(g.area.size(), 0.);
    for(FI f : m.faces())
      for(VI v : CGAL::vertices_around_face(m.halfedge(f), m)) val[std::size_t(f)] += phi[std::size_t(which)][std::size_t(v)] / 3;
    if(threshold_labels(val, g, rng, gt)) break;
  }
  return gt;
}

// The region curve J(gt): on an interior edge e with h = halfedge(e), gt(face(h)) - gt(face(opposite(h)))
// (the library's convention: crossing from right to left, W rises by the chain value).
inline Chain region_chain(const Mesh& m, const std::vector<int>& gt)
{
  Chain region(m.number_of_edges(), 0);
  for(EI e : m.edges())
  {
    if(m.is_border(e)) continue;
    const HI h = m.halfedge(e);
    region[std::size_t(e)] = gt[std::size_t(m.face(h))] - gt[std::size_t(m.face(m.opposite(h)))];
  }
  return region;
}

// Deletion order of curve edges: random runs along the curve. `subset` lists the curve edges where the
// runs start and stay (a connected component of the curve, or all of it); each run has a length
// uniform in [run_min, run_max] times the subset's length and grows alternately at both ends along
// curve edges that are not deleted yet. Returns (edge, cumulative deleted length / subset length),
// up to half of the subset.
inline std::vector<std::pair<std::size_t, double>> deletion_order(const Mesh& m, const std::vector<std::size_t>& subset,
                                                           const std::vector<double>& len,
                                                           const std::vector<std::vector<std::size_t>>& at,
                                                           double run_min, double run_max, Rng& rng)
{
  double total = 0;
  for(std::size_t e : subset) total += len[e];
  std::vector<std::pair<std::size_t, double>> order;
  std::map<std::size_t, char> deleted;
  std::set<std::size_t> in_subset(subset.begin(), subset.end());
  double cum = 0;
  std::size_t remaining = subset.size();
  while(remaining > 0 && cum < 0.5 * total)
  {
    std::size_t e0;
    do e0 = subset[rng.index(subset.size())]; while(deleted.count(e0));
    const double run = rng.uniform(run_min, run_max) * total;
    double got = 0;
    const EI ee0(static_cast<Mesh::size_type>(e0));
    std::size_t ends[2] = {std::size_t(m.vertex(ee0, 0)), std::size_t(m.vertex(ee0, 1))};
    auto del = [&](std::size_t e) {
      deleted[e] = 1;
      --remaining;
      got += len[e];
      cum += len[e];
      order.push_back({e, cum / total});
    };
    del(e0);
    int side = 0, stuck = 0;
    while(got < run && stuck < 2 && cum < 0.5 * total)
    {
      std::size_t& x = ends[side];
      std::vector<std::size_t> cand;
      for(std::size_t e : at[x])
        if(!deleted.count(e) && in_subset.count(e)) cand.push_back(e);
      if(cand.empty()) { ++stuck; side = 1 - side; continue; }
      const std::size_t e = cand[rng.index(cand.size())];
      const EI ee(static_cast<Mesh::size_type>(e));
      x = std::size_t(m.vertex(ee, 0)) == x ? std::size_t(m.vertex(ee, 1)) : std::size_t(m.vertex(ee, 0));
      del(e);
      stuck = 0;
      side = 1 - side;
    }
  }
  return order;
}

// Deletion plan of the whole curve: (edge, fraction) pairs; gap level L deletes the edges whose
// fraction is <= L. mode "per-curve": every connected component of the curve loses the fraction L of
// its own length (runs of 5-15 % of the component), so no curve disappears entirely; mode "global":
// runs of 1-4 % of the total curve length anywhere until L of the total is gone.
inline std::vector<std::pair<std::size_t, double>> deletion_plan(const Mesh& m, const Chain& c, const std::string& mode, Rng& rng,
                                                          double& total)
{
  const std::size_t ne = m.number_of_edges();
  std::vector<double> len(ne, 0);
  std::vector<std::size_t> curve;
  std::vector<std::vector<std::size_t>> at(m.number_of_vertices());
  total = 0;
  for(EI e : m.edges())
    if(c[std::size_t(e)] != 0)
    {
      len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
      total += len[std::size_t(e)];
      curve.push_back(std::size_t(e));
      at[std::size_t(m.vertex(e, 0))].push_back(std::size_t(e));
      at[std::size_t(m.vertex(e, 1))].push_back(std::size_t(e));
    }
  if(curve.empty()) return {};
  if(mode == "global") return deletion_order(m, curve, len, at, 0.01, 0.04, rng);
  // connected components of the curve (edges sharing a vertex)
  std::map<std::size_t, std::size_t> comp;
  std::vector<std::vector<std::size_t>> comps;
  for(std::size_t e0 : curve)
  {
    if(comp.count(e0)) continue;
    comps.emplace_back();
    std::vector<std::size_t> stack{e0};
    comp[e0] = comps.size() - 1;
    while(!stack.empty())
    {
      const std::size_t e = stack.back();
      stack.pop_back();
      comps.back().push_back(e);
      const EI ee(static_cast<Mesh::size_type>(e));
      for(int k = 0; k < 2; ++k)
        for(std::size_t f : at[std::size_t(m.vertex(ee, k))])
          if(!comp.count(f)) { comp[f] = comps.size() - 1; stack.push_back(f); }
    }
  }
  std::vector<std::pair<std::size_t, double>> plan;
  for(auto& cc : comps)
  {
    std::sort(cc.begin(), cc.end());
    const auto o = deletion_order(m, cc, len, at, 0.05, 0.15, rng);
    plan.insert(plan.end(), o.begin(), o.end());
  }
  return plan;
}

} // namespace swn_bench

#endif // SWN_BENCH_GEN_REGIONS_H
