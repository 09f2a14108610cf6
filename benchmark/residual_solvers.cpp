// Residual solvers (Eq. 11) on a real case: LEMON network flows vs GLPK's simplex.
//
//   residual_solvers MESH [--curve FILE] [--glpk 0|1] [--repeat N] [--subdivide N] [--whole 0|1] [--simplex 0|1] [--multilevel 0|1] [--table 0|1] [--ml-radius R] [--ml-cluster C] [--ml-coarsest N] [--ml-refinements N] [--ml-descent N] [--ml-finest-radius R] [--mf-budget W] [--narrow-curve MAX_NODES] [--split-bands MIN_NODES] [--routing MIN_NODES] [--sequential] [--verbose]
//
// Reads the mesh and its curves like the swn tool (OBJ `l` lines and/or a curve file), cuts the mesh
// so that the curves lie on edges, optionally subdivides it N times 1-to-4 at the edge midpoints
// (the curves follow the split edges), then
//  1. runs the whole solve once per residual solver (LEMON network simplex and multilevel, then GLPK) and prints
//     the report's timings and whether labels and G agree with the first run;
//  2. solves the residual problem recorded from the pipeline alone with each solver (N repeats,
//     best time) and prints time, objective and largest bound violation.
// Not a test: see residual_solvers.md for the numbers and the build command.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/GLPK_linear_program_traits.h>
#include "swn_io/conforming_cut.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include <CGAL/Surface_winding_numbers/LEMON_residual_solver.h>

#include <array>
#include <chrono>
#include <map>
#include <utility>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SIO = CGAL::Surface_winding_numbers::IO;
typedef SWN::LEMON_residual_solver Lemon;

// a residual solver that keeps a copy of the problem and delegates to another solver
template <class Inner>
struct Recorder
{
  Inner& inner;
  SWN::Residual_problem problem;
  bool solve_residual(const SWN::Residual_problem& P, std::vector<double>& sigma)
  {
    problem = P;
    return inner.solve_residual(P, sigma);
  }
};

// one 1-to-4 midpoint subdivision; the chain follows the two halves of every split edge
void subdivide(Mesh& mesh, std::vector<int>& chain)
{
  std::map<std::pair<std::size_t, std::size_t>, int> value;   // directed (source, target) -> chain
  for(auto e : edges(mesh))
  {
    const int c = chain[std::size_t(e)];
    if(c == 0) continue;
    const auto h = halfedge(e, mesh);
    value[{std::size_t(source(h, mesh)), std::size_t(target(h, mesh))}] = c;
  }
  std::vector<K::Point_3> pts;
  for(auto v : vertices(mesh)) pts.push_back(mesh.point(v));
  std::vector<std::array<std::size_t, 3>> tris;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid;
  std::map<std::pair<std::size_t, std::size_t>, int> new_value;
  auto midpoint = [&](std::size_t a, std::size_t b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    auto it = mid.find(key);
    if(it != mid.end()) return it->second;
    const std::size_t m = pts.size();
    pts.push_back(CGAL::midpoint(pts[a], pts[b]));
    mid[key] = m;
    auto v = value.find({a, b});
    if(v != value.end()) { new_value[{a, m}] = v->second; new_value[{m, b}] = v->second; }
    v = value.find({b, a});
    if(v != value.end()) { new_value[{b, m}] = v->second; new_value[{m, a}] = v->second; }
    return m;
  };
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = std::size_t(v);
    const std::size_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    tris.push_back({t[0], ab, ca});
    tris.push_back({ab, t[1], bc});
    tris.push_back({ca, bc, t[2]});
    tris.push_back({ab, bc, ca});
  }
  Mesh out;
  std::vector<Mesh::Vertex_index> vs;
  for(const auto& p : pts) vs.push_back(out.add_vertex(p));
  for(const auto& t : tris) out.add_face(vs[t[0]], vs[t[1]], vs[t[2]]);
  chain.assign(num_edges(out), 0);
  for(auto e : edges(out))
  {
    const auto h = halfedge(e, out);
    const std::size_t a = std::size_t(source(h, out)), b = std::size_t(target(h, out));
    auto v = new_value.find({a, b});
    if(v != new_value.end()) chain[std::size_t(e)] += v->second;
    v = new_value.find({b, a});
    if(v != new_value.end()) chain[std::size_t(e)] -= v->second;
  }
  mesh = std::move(out);
}

static double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

int main(int argc, char** argv)
{
  std::string mesh_file, curve_file;
  bool run_glpk = true, run_whole = true, run_simplex = true, run_cut = true, run_table = false;
  Lemon::Options options;   // the library's defaults unless given
  int repeat = 3, subdivisions = 0;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool more = i + 1 < argc;
    if(a == "--curve" && more) curve_file = argv[++i];
    else if(a == "--glpk" && more) run_glpk = std::atoi(argv[++i]) != 0;
    else if(a == "--repeat" && more) repeat = std::atoi(argv[++i]);
    else if(a == "--subdivide" && more) subdivisions = std::atoi(argv[++i]);
    else if(a == "--whole" && more) run_whole = std::atoi(argv[++i]) != 0;
    else if(a == "--simplex" && more) run_simplex = std::atoi(argv[++i]) != 0;
    else if(a == "--multilevel" && more) run_cut = std::atoi(argv[++i]) != 0;
    else if(a == "--ml-radius" && more) options.band_radius = std::atoi(argv[++i]);
    else if(a == "--ml-cluster" && more) options.cluster_size = std::size_t(std::atol(argv[++i]));
    else if(a == "--ml-coarsest" && more) options.coarsest_nodes = std::size_t(std::atol(argv[++i]));
    else if(a == "--ml-refinements" && more) options.max_refinements = std::size_t(std::atol(argv[++i]));
    else if(a == "--mf-budget" && more) options.max_flow_budget = std::atof(argv[++i]);
    else if(a == "--narrow-curve" && more) options.narrow_curve_band_nodes = std::size_t(std::atol(argv[++i]));
    else if(a == "--split-bands" && more) options.split_band_nodes = std::size_t(std::atol(argv[++i]));
    else if(a == "--routing" && more) options.carried_flow_routing_nodes = std::size_t(std::atol(argv[++i]));
    else if(a == "--ml-descent" && more) options.descent_steps = std::size_t(std::atol(argv[++i]));
    else if(a == "--ml-finest-radius" && more) options.finest_band_radius = std::atoi(argv[++i]);
    else if(a == "--table" && more) run_table = std::atoi(argv[++i]) != 0;
    else if(a == "--sequential") options.concurrent = false;
    else if(a == "--verbose") options.verbose = true;
    else mesh_file = a;
  }
  if(mesh_file.empty()) { std::fprintf(stderr, "usage: residual_solvers MESH [--curve FILE] [--glpk 0|1] [--repeat N] [--subdivide N] [--whole 0|1] [--simplex 0|1] [--multilevel 0|1] [--table 0|1] [--ml-radius R] [--ml-cluster C] [--ml-coarsest N] [--ml-refinements N] [--ml-descent N] [--ml-finest-radius R] [--mf-budget W] [--narrow-curve MAX_NODES] [--split-bands MIN_NODES] [--routing MIN_NODES] [--sequential] [--verbose]\n"); return 2; }
  auto with_algorithm = [&](Lemon::Algorithm a) { Lemon::Options o = options; o.algorithm = a; return o; };

  Mesh input;
  const SIO::Mesh_read_info info = SIO::read_mesh(mesh_file, input);
  std::vector<SIO::Curve_set> curves;
  if(SIO::has_curve_records(info)) curves.push_back(SIO::curve_set_from_obj(info, input));
  if(!curve_file.empty()) curves.push_back(SIO::read_curve_file(curve_file, input));
  SIO::Cut_result<K::Point_3> cut = SIO::conforming_cut(input, curves);
  Mesh& mesh = cut.mesh;
  std::vector<int> chain_values(cut.chain.begin(), cut.chain.end());
  for(int k = 0; k < subdivisions; ++k) subdivide(mesh, chain_values);
  auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
  for(auto e : edges(mesh)) chain[e] = chain_values[std::size_t(e)];
  std::printf("mesh %s: %zu vertices, %zu faces, %zu edges after the cut\n", mesh_file.c_str(), std::size_t(num_vertices(mesh)),
              std::size_t(num_faces(mesh)), std::size_t(num_edges(mesh)));

  // 1. whole solves
  std::vector<int> labels0, G0;
  SWN::Residual_problem P;
  auto whole_np = [&](auto& solver, const char* name, const auto& extra) {
    auto labels = mesh.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
    auto G = mesh.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;
    SWN::Solve_report rep;
    const double t0 = now();
    const bool ok = CGAL::surface_winding_numbers(mesh, chain, labels,
                                                  SWN::parameters::lp_solver(std::ref(solver),
                                                  SWN::parameters::report(std::ref(rep),
                                                  SWN::parameters::nonbounding_chain_map(G, extra))));
    const double t = now() - t0;
    std::vector<int> l, g;
    for(auto f : faces(mesh)) l.push_back(labels[f]);
    for(auto e : edges(mesh)) g.push_back(G[e]);
    const bool first = labels0.empty();
    if(first) { labels0 = l; G0 = g; }
    std::size_t moved = 0;   // faces whose label differs from the reference
    for(std::size_t f = 0; f < l.size() && !first; ++f) moved += l[f] != labels0[f];
    std::printf("whole solve %-36s ok %d  total %8.3f s (report %8.3f)  jump Laplace %7.3f  hodge %7.3f  residual %8.3f s  "
                "second %7.3f  total/jump %5.1f  objective %.12f  %s (%zu faces differ)\n", name, int(ok), t,
                rep.time_total, rep.time_jump_laplace, rep.time_hodge, rep.time_residual, rep.time_second_solve,
                rep.time_total / rep.time_jump_laplace, rep.lp_objective,
                first ? "(reference labels/G)" : (l == labels0 && g == G0 ? "labels and G identical" : "LABELS OR G DIFFER"), moved);
    mesh.remove_property_map(labels);
    mesh.remove_property_map(G);
  };
  auto whole = [&](auto& solver, const char* name) { whole_np(solver, name, CGAL::parameters::default_values()); };
  std::vector<Lemon::Algorithm> algorithms = {Lemon::Options::NETWORK_SIMPLEX, Lemon::Options::MULTILEVEL};
  std::vector<const char*> names = {"lemon NetworkSimplex/BLOCK_SEARCH", "lemon Multilevel"};
  if(!run_cut) { algorithms.erase(algorithms.begin() + 1); names.erase(names.begin() + 1); }
  if(!run_simplex) { algorithms.erase(algorithms.begin()); names.erase(names.begin()); }
  const int n_algorithms = int(algorithms.size());
  for(int k = 0; k < (run_whole ? n_algorithms : 1); ++k)
  {
    Lemon lemon(with_algorithm(algorithms[k]));
    Recorder<Lemon> rec{lemon, {}};
    whole(rec, names[k]);
    if(k == 0) P = rec.problem;
  }
  if(run_table)
  {
    // the default residual solver with Eigen's LDLT instead of CHOLMOD, and the reduced residual
    Lemon lemon(options);
    whole_np(lemon, "lemon Multilevel + Eigen LDLT", CGAL::parameters::sparse_linear_solver(SWN::internal::Eigen_LDLT_sparse_solver()));
    whole_np(lemon, "lemon Multilevel, reduced residual", SWN::parameters::use_reduced_residual(true));
  }
  if(run_glpk && run_whole)
  {
    SWN::GLPK_linear_program_traits glpk;
    whole(glpk, "glpk dual simplex");
  }

  // 2. the residual problem alone
  std::size_t bounded = 0;
  for(std::size_t a = 0; a < P.number_of_arcs(); ++a) bounded += P.is_bounded(a);
  std::printf("residual problem: %zu faces, %zu arcs (%zu with bounds)\n", P.number_of_faces, P.number_of_arcs(), bounded);
  double best_objective = 0;
  for(int k = 0; k < n_algorithms; ++k)
  {
    Lemon lemon(with_algorithm(algorithms[k]));
    double best = 1e300;
    std::vector<double> sigma;
    bool ok = true;
    for(int r = 0; r < repeat; ++r)
    {
      const double t0 = now();
      ok = lemon.solve_residual(P, sigma) && ok;
      best = std::min(best, now() - t0);
    }
    const Lemon::Statistics& st = lemon.statistics();
    if(k == 0) best_objective = P.objective(sigma);
    std::printf("residual %-36s ok %d  best of %d %8.3f s (build %.3f, flow %.3f, recover %.3f)  objective %.13f  violation %.1e  "
                "nodes %zu  network arcs %zu  nonzero costs %zu  scale 2^%d/2^%d  certified %d  levels %zu  refinements %zu  descent steps %zu (%zu pieces)  largest band %zu  max flows %zu (%zu finished by BK)\n",
                names[k], int(ok), repeat, best, st.time_build, st.time_solve, st.time_recover, P.objective(sigma),
                P.max_violation(sigma), st.nodes, st.network_arcs, st.nonzero_cost_arcs, st.cost_exponent,
                st.capacity_exponent, int(st.certified), st.levels, st.refinements, st.descent_steps, st.descent_pieces, st.largest_band, st.certificates, st.max_flow_fallbacks);
  }
  if(run_glpk)
  {
    SWN::GLPK_linear_program_traits glpk;
    std::size_t nv = 0, nr = 0;
    const double t0 = now();
    std::vector<double> sigma = SWN::internal::solve_residual_with_lp(P, glpk, nv, nr);
    const double t = now() - t0;
    const double o = P.objective(sigma);
    std::printf("residual %-36s ok 1  once      %8.3f s  objective %.13f  violation %.1e  lemon - glpk = %.2e (relative %.2e)\n",
                "glpk dual simplex", t, o, P.max_violation(sigma), best_objective - o,
                o > 1e-9 ? (best_objective - o) / o : 0.);
  }
  return 0;
}
