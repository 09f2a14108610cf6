// Polygon soups for the tests: a torus of quads and triangles, solving a soup through
// CGAL::polygon_soup_winding_numbers() with every output map, reading chain maps along directed edges.
#ifndef SWN_TEST_ORACLES_SOUP_H
#define SWN_TEST_ORACLES_SOUP_H

#include <CGAL/surface_winding_numbers.h>
#include <CGAL/property_map.h>

#include "mesh_generators.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace {
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;
using namespace swn_test;
typedef std::pair<std::size_t, std::size_t> Pair;
typedef std::vector<std::vector<std::size_t>> Polygons;

// A torus of nu x nv cells (jittered points of mesh_generators.h); each cell a quad, or two triangles
// where split(i, j) (alternating diagonals). cell[p] = (i, j) of polygon p.
struct Polygon_torus
{
  int nu, nv;
  std::vector<Point_3> points;
  Polygons polygons;
  std::vector<std::pair<int, int>> cell;

  template <class Split>
  Polygon_torus(int nu_, int nv_, Split split) : nu(nu_), nv(nv_), points(make_torus(nu_, nv_).points)
  {
    for(int j = 0; j < nv; ++j)
      for(int i = 0; i < nu; ++i)
      {
        const std::size_t a = torus_vid(nu, nv, i, j), b = torus_vid(nu, nv, i + 1, j), c = torus_vid(nu, nv, i + 1, j + 1),
                          d = torus_vid(nu, nv, i, j + 1);
        if(!split(i, j)) add({a, b, c, d}, i, j);
        else if((i + j) % 2 == 0) { add({a, b, c}, i, j); add({a, c, d}, i, j); }
        else { add({a, b, d}, i, j); add({b, c, d}, i, j); }
      }
  }
  void add(std::vector<std::size_t> p, int i, int j) { polygons.push_back(std::move(p)); cell.emplace_back(i, j); }
};

// the directed edges of a closed loop of vertex indices (with `gap` edges left out from `skip`)
std::vector<Pair> loop_edges(const std::vector<Index>& loop, std::size_t skip = 0, std::size_t gap = 0)
{
  std::vector<Pair> c;
  for(std::size_t k = 0; k < loop.size(); ++k)
    if(!(k >= skip && k < skip + gap)) c.emplace_back(loop[k], loop[(k + 1) % loop.size()]);
  return c;
}

struct Soup_answer
{
  bool ok = false;
  SWN::Solve_report report;
  std::vector<int> W;
  std::map<Pair, int> G, bounding;
  std::map<Pair, double> w;   // (polygon, corner) -> w
};

// `dual`: pairs of polygons (a, b), a jump of +1 from a into b (named parameter dual_chain)
Soup_answer solve_soup(const std::vector<Point_3>& points, const Polygons& polygons, const std::vector<Pair>& curve,
                       const std::vector<Pair>& dual = {})
{
  Soup_answer a;
  a.W.assign(polygons.size(), -99);
  a.ok = CGAL::polygon_soup_winding_numbers(points, polygons, curve, CGAL::make_property_map(a.W),
           SWN::parameters::dual_chain(dual,
           SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(a.G),
           SWN::parameters::bounding_chain_map(boost::make_assoc_property_map(a.bounding),
           SWN::parameters::winding_number_map(boost::make_assoc_property_map(a.w),
           SWN::parameters::report(std::ref(a.report)))))));
  return a;
}

// the value of a chain map on the directed edge a -> b (keys are (min, max), values signed from min to max)
int along(const std::map<Pair, int>& chain, std::size_t a, std::size_t b)
{
  const auto it = chain.find(Pair((std::min)(a, b), (std::max)(a, b)));
  if(it == chain.end()) return 0;
  return a < b ? it->second : -it->second;
}

} // namespace

#endif
