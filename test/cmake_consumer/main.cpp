// Polyhedron_3 with external property maps: a loop on an octahedron's upper half.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/surface_winding_numbers.h>
#include <boost/property_map/property_map.hpp>
#include <iostream>
#include <map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef boost::graph_traits<Polyhedron>::edge_descriptor edge_descriptor;
typedef boost::graph_traits<Polyhedron>::face_descriptor face_descriptor;

int main()
{
  Polyhedron p;
  CGAL::make_icosahedron(p, K::Point_3(0, 0, 0), 1.);
  std::map<edge_descriptor, int> chain_storage;
  std::map<face_descriptor, int> label_storage;
  auto chain = boost::make_assoc_property_map(chain_storage);
  for(auto e : edges(p)) put(chain, e, 0);
  // the link of the first vertex, counter-clockwise: a loop around one vertex
  auto v0 = *vertices(p).begin();
  std::vector<boost::graph_traits<Polyhedron>::halfedge_descriptor> loop;
  for(auto h : CGAL::halfedges_around_target(v0, p)) loop.push_back(prev(h, p));
  CGAL::Surface_winding_numbers::add_halfedges_to_chain(p, loop, chain);
  if(!CGAL::surface_winding_numbers(p, chain, boost::make_assoc_property_map(label_storage))) return 1;
  std::map<int, int> hist;
  for(auto& fl : label_storage) ++hist[fl.second];
  for(auto& h : hist) std::cout << "W = " << h.first << ": " << h.second << " faces\n";
  return hist.size() == 2 && hist.begin()->second + hist.rbegin()->second == 20 ? 0 : 1;
}
