// Surface winding numbers on a polygon soup: a torus made of quadrilaterals, given as points and
// polygons (no FaceGraph), with a broken loop around a block of 3 x 2 quads. The labels come out per
// input polygon; the loop's gap is closed; the bounding chain and G are keyed by vertex pairs.
// Checks its own result and exits with 1 if it is wrong.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/property_map.h>
#include <CGAL/surface_winding_numbers.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <iostream>
#include <map>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace SWN = CGAL::Surface_winding_numbers;

int main()
{
  const int nu = 24, nv = 12;   // quads around the axis and around the tube
  const double pi = 3.14159265358979323846;
  std::vector<K::Point_3> points;
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      points.emplace_back((1 + 0.4 * std::cos(v)) * std::cos(u), (1 + 0.4 * std::cos(v)) * std::sin(u), 0.4 * std::sin(v));
    }
  auto vid = [&](int i, int j) { return std::size_t(((j % nv + nv) % nv) * nu + (i % nu + nu) % nu); };
  std::vector<std::vector<std::size_t>> polygons;
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i) polygons.push_back({vid(i, j), vid(i + 1, j), vid(i + 1, j + 1), vid(i, j + 1)});

  // a counter-clockwise loop around the quads 4 <= i < 7, 2 <= j < 4, one edge missing
  std::vector<std::size_t> loop;
  for(int i = 4; i < 7; ++i) loop.push_back(vid(i, 2));
  for(int j = 2; j < 4; ++j) loop.push_back(vid(7, j));
  for(int i = 7; i > 4; --i) loop.push_back(vid(i, 4));
  for(int j = 4; j > 2; --j) loop.push_back(vid(4, j));
  std::vector<std::pair<std::size_t, std::size_t>> curve;
  for(std::size_t k = 1; k < loop.size(); ++k) curve.emplace_back(loop[k], loop[(k + 1) % loop.size()]);

  std::vector<int> labels(polygons.size());
  std::map<std::pair<std::size_t, std::size_t>, int> bounding, G;
  SWN::Solve_report report;
  if(!CGAL::polygon_soup_winding_numbers(points, polygons, curve, CGAL::make_property_map(labels),
                                         SWN::parameters::bounding_chain_map(boost::make_assoc_property_map(bounding),
                                         SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G),
                                         SWN::parameters::report(std::ref(report))))))
  {
    std::cerr << "failed: " << report.error << "\n";
    return 1;
  }
  int inside = 0, wrong = 0, closed_edges = 0, G_edges = 0;
  for(int j = 0; j < nv; ++j)
    for(int i = 0; i < nu; ++i)
    {
      const bool in = i >= 4 && i < 7 && j >= 2 && j < 4;
      const int W = labels[std::size_t(j * nu + i)];
      inside += W == 1;
      wrong += W != (in ? 1 : 0);
    }
  for(const auto& e : bounding) closed_edges += e.second != 0;
  for(const auto& e : G) G_edges += e.second != 0;
  std::cout << report.faces << " quads, " << report.edges << " edges, genus " << report.genus << ": " << inside
            << " quads with W = 1, bounding chain of " << closed_edges << " edges (the loop, closed), G on " << G_edges
            << " edges\n";
  return wrong == 0 && inside == 6 && closed_edges == int(loop.size()) && G_edges == 0 ? 0 : 1;
}
