// Benchmark generator (swn_bench_gen): types, seeds, topology and integer chains on the mesh.

#ifndef SWN_BENCH_GEN_COMMON_H
#define SWN_BENCH_GEN_COMMON_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace swn_bench {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index VI;
typedef Mesh::Halfedge_index HI;
typedef Mesh::Edge_index EI;
typedef Mesh::Face_index FI;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

// ------------------------------------------------------------------------------------------------
// Deterministic seeds (std::mt19937_64 and std:: distributions are implementation-defined only for
// the distributions; we use our own uniform helpers so that the cases do not depend on the libstdc++
// version).
inline std::uint64_t hash_string(const std::string& s, std::uint64_t h = 1469598103934665603ull)
{
  for(unsigned char c : s) { h ^= c; h *= 1099511628211ull; }
  return h;
}

struct Rng
{
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double uniform() { return double(g() >> 11) * (1.0 / 9007199254740992.0); }   // [0,1)
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  std::size_t index(std::size_t n) { return std::size_t(uniform() * double(n)) % n; }
  bool coin(double p = 0.5) { return uniform() < p; }
};

// ------------------------------------------------------------------------------------------------
// Topology

struct Topology
{
  long chi = 0;
  int border_loops = 0, genus = 0, components = 0;
  bool simply_connected() const { return components == 1 && ((chi == 2 && border_loops == 0) || (chi == 1 && border_loops == 1)); }
};

inline std::vector<std::vector<HI>> border_loops(const Mesh& m)
{
  std::vector<std::vector<HI>> loops;
  std::vector<char> seen(m.number_of_halfedges(), 0);
  for(HI h : m.halfedges())
  {
    if(!m.is_border(h) || seen[std::size_t(h)]) continue;
    std::vector<HI> loop;
    HI x = h;
    do { seen[std::size_t(x)] = 1; loop.push_back(x); x = m.next(x); } while(x != h && !seen[std::size_t(x)]);
    loops.push_back(loop);
  }
  return loops;
}

inline Topology topology(const Mesh& m)
{
  Topology t;
  t.chi = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  t.border_loops = int(border_loops(m).size());
  auto fcc = m.property_map<FI, std::size_t>("f:tmp_cc");
  Mesh& mm = const_cast<Mesh&>(m);
  auto cc = mm.add_property_map<FI, std::size_t>("f:bench_cc", 0).first;
  t.components = int(PMP::connected_components(mm, cc));
  mm.remove_property_map(cc);
  (void)fcc;
  t.genus = int((2 * t.components - t.chi - t.border_loops) / 2);
  return t;
}

inline double mesh_area(const Mesh& m) { return PMP::area(m); }

// ------------------------------------------------------------------------------------------------
// Chains on the mesh (per edge index, along halfedge(e))

typedef std::vector<int> Chain;

// Positive along halfedge(e) for e enumerated by edges(m), i.e. along the even halfedge of the edge.
// (In CGAL 5.5, Edge_index(h) remembers h, so halfedge(edge(h)) == h: never compare with that.)
inline bool is_canonical(HI h) { return (std::size_t(h) & 1) == 0; }

inline void add_traversal(const Mesh& m, Chain& c, VI a, VI b, int value)
{
  const HI h = m.halfedge(a, b);
  if(h == Mesh::null_halfedge()) throw std::logic_error("not an edge");
  const EI e = m.edge(h);
  c[std::size_t(e)] += is_canonical(h) ? value : -value;
}

// Is the chain D (on interior edges) the jump J F of a face function F? (then D bounds, relative to
// the border: D is null-homologous in H1(M, border)). Border edges are ignored.
inline bool is_relative_boundary(const Mesh& m, const Chain& D)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<long> F(nf, 0);
  std::vector<char> seen(nf, 0);
  for(FI f0 : m.faces())
  {
    if(seen[std::size_t(f0)]) continue;
    seen[std::size_t(f0)] = 1;
    std::vector<FI> stack{f0};
    while(!stack.empty())
    {
      const FI f = stack.back();
      stack.pop_back();
      for(HI h : CGAL::halfedges_around_face(m.halfedge(f), m))
      {
        const HI o = m.opposite(h);
        if(m.is_border(o)) continue;
        const FI g = m.face(o);
        const EI e = m.edge(h);
        // left face of e is face(halfedge(e)); D = F(left) - F(right)
        const long d = D[std::size_t(e)];
        const long Fg = is_canonical(h) ? F[std::size_t(f)] - d : F[std::size_t(f)] + d;
        if(!seen[std::size_t(g)]) { seen[std::size_t(g)] = 1; F[std::size_t(g)] = Fg; stack.push_back(g); }
        else if(F[std::size_t(g)] != Fg) return false;
      }
    }
  }
  return true;
}

// Is the chain closed relative to the border (no endpoint off the border)?
inline bool is_closed(const Mesh& m, const Chain& c)
{
  std::vector<long> div(m.number_of_vertices(), 0);
  for(EI e : m.edges())
  {
    const HI h = m.halfedge(e);
    div[std::size_t(m.source(h))] -= c[std::size_t(e)];
    div[std::size_t(m.target(h))] += c[std::size_t(e)];
  }
  for(VI v : m.vertices())
    if(div[std::size_t(v)] != 0 && !m.is_border(v)) return false;
  return true;
}

// The chain of a cyclic vertex sequence (consecutive vertices adjacent).
inline Chain loop_chain(const Mesh& m, const std::vector<VI>& loop)
{
  Chain c(m.number_of_edges(), 0);
  for(std::size_t i = 0; i < loop.size(); ++i)
    if(loop[i] != loop[(i + 1) % loop.size()]) add_traversal(m, c, loop[i], loop[(i + 1) % loop.size()], 1);
  return c;
}

inline std::string json_escape(const std::string& s)
{
  std::string o;
  for(char c : s)
  {
    if(c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o;
}

inline void write_halfedge_chain(const Mesh& m, const Chain& c, const std::string& file)
{
  std::ofstream os(file);
  os << "# swn halfedges\n";
  for(EI e : m.edges())
  {
    const int v = c[std::size_t(e)];
    if(v == 0) continue;
    const HI h = m.halfedge(e);
    if(v > 0) os << "h " << std::size_t(m.source(h)) << ' ' << std::size_t(m.target(h)) << ' ' << v << '\n';
    else os << "h " << std::size_t(m.target(h)) << ' ' << std::size_t(m.source(h)) << ' ' << -v << '\n';
  }
  if(!os) throw std::runtime_error("cannot write " + file);
}

} // namespace swn_bench

#endif // SWN_BENCH_GEN_COMMON_H
