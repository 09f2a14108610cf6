// swn_bench_solve: solves one benchmark case in process and prints one JSON line of metrics.
//
//   swn_bench_solve CASE_DIR MESH_FILE [--check-api] [--lp default|glpk|reduced] [--epsilon X]
//                   [--completed-class]
//
// Reads the mesh and CASE_DIR/curve.txt with the package's readers (IO::read_mesh, IO::read_curve_file,
// IO::vertex_curve_chain), runs the public API (Surface_winding_numbers_solver::solve with the default
// linear solvers), and compares with CASE_DIR/labels_gt.txt and CASE_DIR/planted.txt:
//
// * error_percent: mislabeled area in % of the total area; labels are compared up to one integer per
//   connected component (the offset that matches the largest area is chosen per component);
// * naive_error_percent: the same for the naive baseline, the rounding of the first jump-harmonic
//   function u (the generalized-winding-number approach, with the same shift tau as the library);
// * the nonbounding chain G: number of edges, whether it is closed (relative to the border), whether it
//   is homologous to the planted chain in H1(M, border) (G - planted = J F for a face function F);
// * Solve_report timings, construction time, peak memory (getrusage).
//
// * confidence (cases with handles, default residual solver; bench_confidence.h): the cheapest flip of a
//   region (a cell of constant W between input, G and label jumps) that is not the largest of its
//   component and covers >= 0.5 % of the area; the second-best labeling (that flip applied); simulated
//   single user hints: the least confident region labelled right, the largest mislabeled region
//   labelled right (local changes, no re-solve), one missing run of the input redrawn (re-solve).
//
// --check-api also runs the free function CGAL::surface_winding_numbers() and checks that it gives the
// same labels and G as the solver class.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include "swn_io/conforming_cut.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include <CGAL/Surface_winding_numbers/internal/cotan_weights.h>
#include <CGAL/Surface_winding_numbers/internal/jump_laplace.h>
#include <CGAL/Surface_winding_numbers/internal/nonbounding_chain.h>
#include <CGAL/Surface_winding_numbers/internal/winding_number.h>
#include "bench_confidence.h"

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SI = CGAL::Surface_winding_numbers::internal;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Mislabeled area (in % of the total) of `labels` against `gt`, up to one integer per component.
double error_percent(const SI::Mesh_tables& m, const std::vector<double>& area, const std::vector<int>& labels,
                     const std::vector<int>& gt)
{
  std::vector<std::map<long, double>> hist(m.n_components);
  std::vector<double> comp_area(m.n_components, 0.);
  double total = 0;
  for(std::size_t f = 0; f < m.nf; ++f)
  {
    const std::size_t c = m.face_component[f];
    hist[c][long(labels[f]) - long(gt[f])] += area[f];
    comp_area[c] += area[f];
    total += area[f];
  }
  double wrong = 0;
  for(std::size_t c = 0; c < m.n_components; ++c)
  {
    double best = 0;
    for(const auto& kv : hist[c]) best = std::max(best, kv.second);
    wrong += comp_area[c] - best;
  }
  return total > 0 ? 100. * wrong / total : 0.;
}

// Is D (per table edge, interior edges only) = J F for some face function F?
bool is_relative_boundary(const SI::Mesh_tables& m, const std::vector<long>& D)
{
  // F(left) - F(right) = D on every arc; propagate over the dual graph and check consistency
  std::vector<std::vector<std::pair<std::size_t, long>>> adj(m.nf);   // neighbour, F(nb) - F(f)
  for(const SI::Arc& a : m.arcs)
  {
    const std::size_t L = a.left_side / 3, R = a.right_side / 3;
    const long d = D[a.edge];
    adj[L].push_back({R, -d});
    adj[R].push_back({L, d});
  }
  std::vector<long> F(m.nf, 0);
  std::vector<char> seen(m.nf, 0);
  for(std::size_t f0 = 0; f0 < m.nf; ++f0)
  {
    if(seen[f0]) continue;
    seen[f0] = 1;
    std::vector<std::size_t> stack{f0};
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(const auto& [g, d] : adj[f])
      {
        if(!seen[g]) { seen[g] = 1; F[g] = F[f] + d; stack.push_back(g); }
        else if(F[g] != F[f] + d) return false;
      }
    }
  }
  return true;
}

std::vector<int> read_labels(const std::string& file, std::size_t n)
{
  std::ifstream is(file);
  if(!is) throw std::runtime_error("cannot read " + file);
  std::vector<int> l;
  l.reserve(n);
  int x;
  while(is >> x) l.push_back(x);
  if(l.size() != n) throw std::runtime_error(file + ": " + std::to_string(l.size()) + " labels for " + std::to_string(n) + " faces");
  return l;
}

// planted.txt: `# swn halfedges` lines `h SRC DST M` (may be empty)
std::vector<long> read_planted(const std::string& file, const Mesh& mesh)
{
  std::vector<long> c(mesh.number_of_edges(), 0);
  std::ifstream is(file);
  if(!is) throw std::runtime_error("cannot read " + file);
  std::string line;
  while(std::getline(is, line))
  {
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string h;
    std::size_t a, b;
    long mult = 1;
    ls >> h >> a >> b;
    if(!(ls >> mult)) mult = 1;
    const auto hb = CGAL::halfedge(Mesh::Vertex_index(Mesh::size_type(a)), Mesh::Vertex_index(Mesh::size_type(b)), mesh);
    if(!hb.second) throw std::runtime_error(file + ": not an edge: " + line);
    const auto e = mesh.edge(hb.first);
    c[std::size_t(e)] += (std::size_t(hb.first) % 2 == 0) ? mult : -mult;   // positive along the even halfedge
  }
  return c;
}

long peak_rss_kb()
{
  rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: swn_bench_solve CASE_DIR MESH_FILE [--check-api] [--lp default|glpk|reduced] [--epsilon X] [--completed-class]\n";
    return 2;
  }
  const std::string dir = argv[1], mesh_file = argv[2];
  bool check_api = false;
  std::string lp_name = "default";
  double epsilon = 0.01;
  bool completed_class = false;   // the named parameter completed_homology_class
  for(int i = 3; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--check-api") check_api = true;
    else if(a == "--lp" && i + 1 < argc) lp_name = argv[++i];
    else if(a == "--epsilon" && i + 1 < argc) epsilon = std::stod(argv[++i]);
    else if(a == "--completed-class") completed_class = true;
    else { std::cerr << "swn_bench_solve: unknown argument " << a << "\n"; return 2; }
  }

  std::ostringstream out;
  out << std::setprecision(6);
  try
  {
    const auto t_read0 = std::chrono::steady_clock::now();
    Mesh mesh;
    SWN::IO::read_mesh(mesh_file, mesh);
    const SWN::IO::Curve_set curve = SWN::IO::read_curve_file(dir + "/curve.txt", mesh);
    const std::vector<int> chain_e = SWN::IO::vertex_curve_chain(mesh, curve);
    const std::vector<int> gt = read_labels(dir + "/labels_gt.txt", mesh.number_of_faces());
    const std::vector<long> planted_e = read_planted(dir + "/planted.txt", mesh);
    const double t_read = seconds_since(t_read0);

    auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    for(auto e : mesh.edges()) chain[e] = chain_e[std::size_t(e)];
    auto labels = mesh.add_property_map<Mesh::Face_index, int>("f:W", 0).first;
    auto G = mesh.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;

    // the library: solver class (construction timed separately), default linear solvers
    const auto t_c0 = std::chrono::steady_clock::now();
    SWN::Surface_winding_numbers_solver<Mesh> solver(mesh);
    const double t_construct = seconds_since(t_c0);
    if(!solver.is_valid()) throw std::runtime_error("mesh rejected: " + solver.report().error);
    SWN::Solve_report rep;
    bool ok = false;
    std::string lp_backend = SI::Default_linear_program_traits::name();
    if(lp_name == "default")
      ok = solver.solve(chain, labels, SWN::parameters::nonbounding_chain_map(G, SWN::parameters::report(std::ref(rep), SWN::parameters::completed_homology_class(completed_class, SWN::parameters::epsilon(epsilon)))));
#ifdef CGAL_USE_GLPK
    else if(lp_name == "glpk")
    {
      SWN::GLPK_linear_program_traits lp;
      lp_backend = lp.name();
      ok = solver.solve(chain, labels, SWN::parameters::nonbounding_chain_map(G, SWN::parameters::report(std::ref(rep), SWN::parameters::lp_solver(std::ref(lp), SWN::parameters::epsilon(epsilon)))));
    }
#endif
    else if(lp_name == "reduced")   // the paper's reduced residual (Sec. 6) with the default solver
    {
      lp_backend += "+reduced";
      ok = solver.solve(chain, labels, SWN::parameters::nonbounding_chain_map(G, SWN::parameters::report(std::ref(rep), SWN::parameters::use_reduced_residual(true, SWN::parameters::epsilon(epsilon)))));
    }
    else throw std::runtime_error("unknown --lp " + lp_name);
    const long rss_after_swn = peak_rss_kb();

    const SI::Mesh_tables& m = solver.tables();
    std::vector<double> area(m.nf);
    for(std::size_t f = 0; f < m.nf; ++f)
    {
      const double *p = m.point(m.fv[3 * f]), *q = m.point(m.fv[3 * f + 1]), *r = m.point(m.fv[3 * f + 2]);
      const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      const double n[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      area[f] = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    // everything per table index
    std::vector<int> gt_t(m.nf), W(m.nf);
    for(auto f : mesh.faces()) { gt_t[solver.face_index(f)] = gt[std::size_t(f)]; W[solver.face_index(f)] = labels[f]; }
    std::vector<double> chain_t(m.ne, 0.);
    std::vector<long> G_t(m.ne, 0), P_t(m.ne, 0);
    for(auto e : mesh.edges())
    {
      chain_t[solver.edge_index(e)] = chain[e];
      G_t[solver.edge_index(e)] = G[e];
      P_t[solver.edge_index(e)] = planted_e[std::size_t(e)];
    }

    // naive baseline: round u + tau (u: the first jump Laplace solve, as in the pipeline)
    const auto t_n0 = std::chrono::steady_clock::now();
    std::vector<double> weight;
    SI::cotan_weights(m, weight);
    const std::vector<char> endpoint = SI::interior_endpoints(m, chain_t);
    SI::Jump_laplace_system<SI::Default_sparse_solver> L;
    const std::vector<std::size_t> order = SI::vertex_elimination_order(m);   // as the pipeline does
    L.jump_laplacian(m, weight, endpoint, &order);
    const std::vector<double> u = L.solve_jump_laplace(SI::reduced_coordinates(m, SI::arc_jumps_from_chain(m, chain_t), endpoint));
    const std::vector<double> tau_u = SI::shift_tau(m, chain_t, u);
    std::vector<int> naive = SI::round_labels(m, u, tau_u);
    SI::normalize_labels(m, naive);
    const double t_naive = seconds_since(t_n0);

    // metrics
    std::size_t planted_edges = 0, G_edges = 0;
    for(long x : P_t) planted_edges += x != 0;
    for(long x : G_t) G_edges += x != 0;
    std::vector<long> D(m.ne);
    for(std::size_t e = 0; e < m.ne; ++e) D[e] = G_t[e] - P_t[e];
    const bool G_closed = SI::is_relatively_closed(m, G_t);
    const bool G_homologous = ok && is_relative_boundary(m, D);
    const bool G_trivial = is_relative_boundary(m, G_t);
    std::size_t G_exact_edges = 0;   // edges where G equals the planted chain, among the planted edges
    for(std::size_t e = 0; e < m.ne; ++e) if(P_t[e] != 0 && G_t[e] == P_t[e]) ++G_exact_edges;
    // Eq. 11 cost of an integer nonbounding chain X: sum over interior edges of w_e |X_e|, with
    // w_e = epsilon * length on curve edges, length elsewhere (lengths in units of the mean interior
    // edge length). If SWN's G costs no more than the planted chain, the model itself prefers SWN's
    // answer (the ground truth is not the shortest decomposition: the ambiguity of the paper's Fig. 18).
    double mean_len = 0;
    for(const SI::Arc& a : m.arcs) mean_len += m.edge_length(a.edge);
    mean_len = m.arcs.empty() ? 1. : mean_len / double(m.arcs.size());
    double cost_G = 0, cost_P = 0;
    for(const SI::Arc& a : m.arcs)
    {
      const double w = m.edge_length(a.edge) / mean_len * (std::abs(chain_t[a.edge]) > 0 ? epsilon : 1.);
      cost_G += w * std::abs(double(G_t[a.edge]));
      cost_P += w * std::abs(double(P_t[a.edge]));
    }
    // FNV-1a hashes of the labels (by face) and of G (by edge) in the mesh's order: two builds agree on
    // a case when their hashes do (benchmark/compare.py)
    auto fnv = [](std::uint64_t h, long x) {
      for(int k = 0; k < 8; ++k) { h ^= std::uint64_t(x >> (8 * k)) & 0xff; h *= 1099511628211ull; }
      return h;
    };
    std::uint64_t labels_hash = 14695981039346656037ull, G_hash = labels_hash;
    for(auto f : mesh.faces()) labels_hash = fnv(labels_hash, labels[f]);
    for(auto e : mesh.edges()) G_hash = fnv(G_hash, G[e]);
    int max_label = 0, min_label = 0;
    for(int l : W) { max_label = std::max(max_label, l); min_label = std::min(min_label, l); }

    bool api_match = true;
    double t_api = 0;
    if(check_api)
    {
      auto W2 = mesh.add_property_map<Mesh::Face_index, int>("f:W2", 0).first;
      auto G2 = mesh.add_property_map<Mesh::Edge_index, int>("e:G2", 0).first;
      SWN::Solve_report rep2;
      const auto t_a0 = std::chrono::steady_clock::now();
      const bool ok2 = CGAL::surface_winding_numbers(mesh, chain, W2, SWN::parameters::nonbounding_chain_map(G2, SWN::parameters::report(std::ref(rep2), SWN::parameters::epsilon(epsilon))));
      t_api = seconds_since(t_a0);
      api_match = ok2 == ok;
      for(auto f : mesh.faces()) api_match = api_match && W2[f] == labels[f];
      for(auto e : mesh.edges()) api_match = api_match && G2[e] == G[e];
    }

    // confidence, second-best labeling, simulated hints (bench_confidence.h)
    std::ostringstream conf;
    if(ok && rep.lp_ran && lp_name == "default")
    {
      namespace SB = swn_bench;
      double total_area = 0;
      for(double a : area) total_area += a;
      auto err = [&](const std::vector<int>& L) { return error_percent(m, area, L, gt_t); };
      // the library's confidence (regions, flip costs, the second-best region)
      const SI::Confidence confidence = SI::label_confidence(m, chain_t, G_t, W, epsilon);
      const SI::Label_regions& cells = confidence.regions;
      const std::vector<SI::Flip>& flips = confidence.flips;
      const std::vector<long> off = SB::best_offsets(m, area, W, gt_t);
      std::vector<char> wrong(m.nf, 0);
      std::vector<double> cell_wrong(cells.area.size(), 0.);
      for(std::size_t f = 0; f < m.nf; ++f)
        if(long(W[f]) - long(gt_t[f]) != off[m.face_component[f]]) { wrong[f] = 1; cell_wrong[cells.of_face[f]] += area[f]; }
      std::size_t worst = 0, eligible = 0;
      std::vector<std::size_t> largest(m.n_components, std::size_t(-1));
      for(std::size_t c = 0; c < cells.area.size(); ++c)
        if(largest[cells.component[c]] == std::size_t(-1) || cells.area[c] > cells.area[largest[cells.component[c]]]) largest[cells.component[c]] = c;
      for(std::size_t c = 0; c < cells.area.size(); ++c)
      {
        if(cell_wrong[c] > cell_wrong[worst]) worst = c;
        eligible += c != largest[cells.component[c]] && cells.area[c] >= SI::second_best_min_area_fraction * total_area;
      }
      const std::size_t least = confidence.second_best;
      // decomposition check: input = J W + G on every interior edge where the input is complete
      std::size_t mismatch = 0;
      for(const SI::Arc& a : m.arcs)
        mismatch += std::lround(chain_t[a.edge]) != long(W[a.left_side / 3]) - long(W[a.right_side / 3]) + G_t[a.edge];
      conf << ", \"decomposition_mismatch_edges\": " << mismatch << ", \"cells\": " << cells.area.size()
           << ", \"cells_eligible\": " << eligible;
      if(least != std::size_t(-1) && std::isfinite(flips[least].cost))
      {
        std::vector<int> W2 = W;
        for(std::size_t f = 0; f < m.nf; ++f)
          if(cells.of_face[f] == least) W2[f] += flips[least].delta;
        conf << ", \"min_flip_cost\": " << flips[least].cost << ", \"min_flip_boundary\": " << flips[least].boundary
             << ", \"min_flip_area_percent\": " << 100. * cells.area[least] / total_area
             << ", \"error_second_best\": " << err(W2)
             << ", \"error_hint_least_confident\": " << err(SB::relabel_cell(m, cells, least, area, W, gt_t));
      }
      conf << ", \"worst_cell_wrong_percent\": " << 100. * cell_wrong[worst] / total_area
           << ", \"worst_cell_flip_cost\": " << (std::isfinite(flips[worst].cost) ? flips[worst].cost : -1.)
           << ", \"error_hint_largest_mislabeled\": " << err(SB::relabel_cell(m, cells, worst, area, W, gt_t));
      // the user redraws one missing piece of the input: re-solve
      std::vector<long> full(m.ne, 0);
      for(const SI::Arc& a : m.arcs) full[a.edge] = long(gt_t[a.left_side / 3]) - long(gt_t[a.right_side / 3]);
      for(std::size_t e = 0; e < m.ne; ++e) full[e] += P_t[e];
      const std::vector<std::size_t> run = SB::missing_run_hint(m, full, chain_t, wrong, area);
      double hint_err = err(W);
      if(!run.empty())
      {
        std::vector<char> in_run(m.ne, 0);
        for(std::size_t e : run) in_run[e] = 1;
        auto chain2 = mesh.add_property_map<Mesh::Edge_index, int>("e:chain_hint", 0).first;
        auto W3 = mesh.add_property_map<Mesh::Face_index, int>("f:W_hint", 0).first;
        for(auto e : mesh.edges())
          chain2[e] = in_run[solver.edge_index(e)] ? int(full[solver.edge_index(e)]) : chain[e];
        if(solver.solve(chain2, W3, SWN::parameters::completed_homology_class(completed_class, SWN::parameters::epsilon(epsilon))))
        {
          std::vector<int> Wh(m.nf);
          for(auto f : mesh.faces()) Wh[solver.face_index(f)] = W3[f];
          hint_err = err(Wh);
        }
      }
      conf << ", \"hint_run_edges\": " << run.size() << ", \"error_hint_missing_run\": " << hint_err;
    }

    out << "{\"ok\": " << (ok ? "true" : "false");
    if(!ok) out << ", \"error\": \"" << rep.error << "\"";
    out << ", \"lp_backend\": \"" << lp_backend << "\", \"epsilon\": " << epsilon << ", \"completed_homology_class\": " << (completed_class ? "true" : "false");
#ifdef CGAL_SWN_USE_CHOLMOD
    out << ", \"sparse_solver\": \"cholmod\"";
#else
    out << ", \"sparse_solver\": \"eigen-simplicial-ldlt\"";
#endif
    out << ", \"error_percent\": " << (ok ? error_percent(m, area, W, gt_t) : 100.)
        << ", \"naive_error_percent\": " << error_percent(m, area, naive, gt_t)
        << ", \"components\": " << rep.components << ", \"report_genus\": " << rep.genus
        << ", \"curve_edges\": " << rep.curve_edges << ", \"interior_endpoints\": " << rep.interior_endpoints
        << ", \"homology_correction\": " << (rep.homology_correction ? "true" : "false")
        << ", \"hodge_projection\": " << (rep.hodge_projection ? "true" : "false")
        << ", \"lp_ran\": " << (rep.lp_ran ? "true" : "false") << ", \"lp_variables\": " << rep.lp_variables
        << ", \"lp_rows\": " << rep.lp_rows << ", \"lp_objective\": " << rep.lp_objective
        << ", \"labels_hash\": \"" << std::hex << labels_hash << "\", \"G_hash\": \"" << G_hash << std::dec << "\""
        << ", \"min_label\": " << min_label << ", \"max_label\": " << max_label
        << ", \"planted_edges_read\": " << planted_edges << ", \"G_edges\": " << G_edges
        << ", \"G_closed\": " << (G_closed ? "true" : "false")
        << ", \"G_closing_units\": " << rep.nonbounding_closing_units
        << ", \"G_nonzero_in_homology\": " << (G_trivial ? "false" : "true")
        << ", \"G_homologous_to_planted\": " << (G_homologous ? "true" : "false")
        << ", \"G_planted_edges_matched\": " << G_exact_edges
        << ", \"cost_G\": " << cost_G << ", \"cost_planted\": " << cost_P
        << ", \"time_read\": " << t_read << ", \"time_construct\": " << t_construct
        << ", \"time_setup\": " << rep.time_setup << ", \"time_jump_laplace\": " << rep.time_jump_laplace
        << ", \"time_hodge\": " << rep.time_hodge << ", \"time_residual\": " << rep.time_residual
        << ", \"time_second_solve\": " << rep.time_second_solve << ", \"time_labels\": " << rep.time_labels
        << ", \"time_total\": " << rep.time_total << ", \"time_swn\": " << t_construct + rep.time_total
        << ", \"time_naive\": " << t_naive << ", \"peak_rss_mb\": " << double(rss_after_swn) / 1024.
        << ", \"peak_rss_mb_all\": " << double(peak_rss_kb()) / 1024.;
    out << conf.str();
    if(check_api) out << ", \"api_match\": " << (api_match ? "true" : "false") << ", \"time_api\": " << t_api;
    out << "}";
  }
  catch(const std::exception& e)
  {
    std::string msg = e.what();
    for(char& c : msg) if(c == '"' || c == '\\' || c == '\n') c = ' ';
    std::cout << "{\"ok\": false, \"error\": \"" << msg << "\"}" << std::endl;
    return 1;
  }
  std::cout << out.str() << std::endl;
  return 0;
}
