// swn: surface winding numbers from the command line.
//
//   swn MESH [--curve FILE] [--output-dir DIR] [--epsilon X] [--lp-solver NAME]
//            [--linear-solver NAME] [--quiet] [--verbose]
//
// Reads a mesh (OFF, OBJ, PLY, STL; order kept) and curves (inline OBJ `l`/`c` lines and/or a curve
// file). An oriented 2-manifold triangle mesh is cut so that the curves lie on edges and solved as a
// Surface_mesh; any other file (polygons, nonmanifold, nonorientable) and dual chains are solved as a
// polygon soup (swn_soup_route.h). Every output of the method is written to DIR atomically.
// Exit codes: 0 success, 1 solver or output failure, 2 bad input.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/surface_winding_numbers.h>
#include <CGAL/Surface_winding_numbers/polygon_soup_winding_numbers.h>
#include <boost/property_map/property_map.hpp>

#include "swn_io/atomic_output_dir.h"
#include "swn_io/conforming_cut.h"
#include "swn_io/curves_off_mesh.h"
#include "swn_io/input_faces.h"
#include "swn_io/json.h"
#include "swn_io/read_curves.h"
#include "swn_io/read_mesh.h"
#include "swn_io/second_thread.h"
#include "swn_io/solver_choice.h"
#include "swn_io/soup_curves.h"
#include "swn_io/write_outputs.h"
#include "swn_io/write_soup_outputs.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <future>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SWN = CGAL::Surface_winding_numbers;
namespace SIO = CGAL::Surface_winding_numbers::IO;

static const char* usage =
  "usage: swn MESH [options]\n"
  "\n"
  "Computes surface winding numbers (Feng, Gillespie, Crane 2023) of curves on a surface mesh.\n"
  "\n"
  "  MESH                   mesh: .off .obj .ply .stl (vertex and face order are kept); `l` polylines and\n"
  "                         `c` dual chains in an OBJ file are read as curves (1-based, #offset honoured).\n"
  "                         A file that is not an oriented 2-manifold triangle mesh (polygons, nonmanifold\n"
  "                         edges or vertices, nonorientable gluings) or curves with dual chains are solved\n"
  "                         as a polygon soup: outputs on the file's faces, curve edges at nonmanifold\n"
  "                         vertices left out (warning), curves given by vertices or dual chains only\n"
  "  --curve FILE           curve file: the authors' format (v / e / l / c / #offset lines), or a file whose\n"
  "                         first line is `# swn polylines` (0-based vertex polylines, one per line) or\n"
  "                         `# swn halfedges` (lines `h SRC DST [multiplicity]`)\n"
  "  --polylines FILE       3D polylines (OBJ `v X Y Z` and 1-based `l` records) drawn off the mesh: each\n"
  "                         point is projected onto the surface (farther than the mean edge length: a gap),\n"
  "                         consecutive points are joined by a straight walk through faces; the counts\n"
  "                         (points off the surface, failed walks, vertices cut in) are printed and in\n"
  "                         summary.json, a polyline that loses points is a warning with its line\n"
  "  --stamp FILE.svg       a 2D drawing (SVG path with M/L/H/V/Z, polyline, polygon, line) stamped onto the\n"
  "                         mesh along --direction, centred and scaled to 80 % of the mesh's extent\n"
  "  --direction X,Y,Z      the direction the drawing is stamped along (default 0,0,-1): rays land on the\n"
  "                         front of the faces (the side their normals point to)\n"
  "  --output-dir DIR       write labels.txt, mesh.ply, w.obj, bounding.obj, nonbounding.obj,\n"
  "                         completed.obj and summary.json to DIR (created; written atomically)\n"
  "  --epsilon X            relative cost of residual jumps across the curve (default 0.01)\n"
  "  --lp-solver NAME       solver of the residual problem (Eq. 11), all exact: lemon (multilevel\n"
  "                         min-cost flow with an optimality certificate, the default when built with\n"
  "                         LEMON), lemon-simplex (LEMON's network simplex on the whole problem) or\n"
  "                         glpk (simplex)\n"
  "  --reduced-residual     approximate the residual LP by the paper's reduced problem (Sec. 6): gaps\n"
  "                         closed by shortest paths, one shift per region (faster, approximate)\n"
"  --completed-class      for broken curves, Eq. 11 integrates the 1-form of the curve with its gaps\n"
"                         closed by shortest paths that continue the curve's direction at their ends,\n"
"                         not the broken curve's harmonic part (not the paper's method;\n"
"                         benchmark/beyond_eq11.md)\n"
  "  --no-nonbounding-filter  label by rounding the jump-harmonic function u itself (paper Fig. 27): loops\n"
  "                         around handles are completed by contours of u instead of being filtered out\n"
  "  --anchor-face N        face N of the mesh file (1-based, the file's face order: line N of a per-face\n"
  "                         labels.txt) gets label 0 in its connected component (default: the label covering\n"
  "                         the largest area); after a cut, the largest of its pieces\n"
  "  --labels-per-input-face  labels.txt gets one line per face of the mesh file (the label covering the\n"
  "                         largest area of its pieces) instead of one per face of the cut mesh\n"
  "  --confidence           mesh.ply gets per-face `confidence` (the flip cost of the face's region) and\n"
  "                         `region`, summary.json every region with its flip cost (default: the\n"
  "                         second-best flip only)\n"
  "  --sequential           use one thread: check a large mesh's faces one check after the other,\n"
  "                         factorize the Hodge projection's matrix after the first solve and write\n"
  "                         w.obj after the other files (default: each on a second thread, beside\n"
  "                         the manifold check, the first solve and the other files)\n"
  "  --linear-solver NAME   sparse Cholesky solver: cholmod (SuiteSparse, the default when built with it)\n"
  "                         or ldlt (Eigen SimplicialLDLT)\n"
  "  --quiet                print nothing but errors\n"
  "  --verbose              print every step with its timing to stderr\n"
  "  --help                 this text\n"
  "\n"
  "Labels W are integers per face; in every connected component the label covering the largest area\n"
  "is 0 (or the label of the --anchor-face). Curves crossing an edge from right to left raise W by one:\n"
  "the inside of a counter-clockwise loop (seen from the side the faces are oriented towards) is +1.\n"
  "\n"
  "examples:\n"
  "  swn data/swn-demo/torus.obj --curve data/swn-demo/torus-phi.txt --output-dir out/torus\n"
  "  swn data/swn-demo/DoubleTorusWithLoops.obj --output-dir out/dt --verbose\n"
  "  swn data/swn-demo/bunny.obj --curve data/swn-demo/bunny-brokenheart.txt --output-dir out/bunny\n"
  "\n"
  "environment: none is read, and the tool sets no process-wide setting (the factorizations run on the\n"
  "tool's own threads, whatever the thread settings of the process's BLAS or OpenMP)\n\n"
  "limits: only regular files are read; a curve has at most 10^6 + 2 x (mesh edges) segments counted with\n"
  "multiplicity (multiplicity of an `h` line in [1, 1000]), which bounds the work and the outputs\n\n"
  "exit status: 0 success, 1 solver or output failure, 2 bad input (the message names file and line).\n"
  "SIGINT, SIGTERM, SIGHUP: the temporary outputs are removed and the tool ends by the signal\n";

namespace {

struct Usage_error : std::runtime_error
{
  explicit Usage_error(const std::string& s) : std::runtime_error(s) {}
};

struct Options
{
  std::string lp_solver = SIO::lp_solver_names().empty() ? std::string("none") : SIO::lp_solver_names().front();
  std::string mesh, curve, output_dir;
  SIO::Off_mesh_curves off_mesh;
  std::string linear_solver = SIO::linear_solver_names().front();
  double epsilon = 0.01;
  bool quiet = false, verbose = false, help = false, reduced_residual = false, sequential = false;
  bool completed_class = false;
  bool unfiltered = false;   // --no-nonbounding-filter
  std::size_t anchor_face = 0;   // --anchor-face: 1-based face of the mesh file, 0: none
  bool labels_per_input_face = false;   // --labels-per-input-face
  bool confidence = false;   // --confidence
};

Options parse_arguments(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    std::string a = argv[i], value;
    const std::size_t eq = a.find('=');
    const bool has_inline_value = a.rfind("--", 0) == 0 && eq != std::string::npos;
    if(has_inline_value) { value = a.substr(eq + 1); a = a.substr(0, eq); }
    auto next = [&]() -> std::string {
      if(has_inline_value) return value;
      if(i + 1 >= argc) throw Usage_error("option " + a + " needs a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") o.help = true;
    else if(a == "--curve") o.curve = next();
    else if(a == "--output-dir") o.output_dir = next();
    else if(a == "--polylines") o.off_mesh.polylines_file = next();
    else if(a == "--stamp") o.off_mesh.stamp_file = next();
    else if(a == "--direction")
    {
      const std::string v = next();
      std::istringstream in(v);
      char c1 = 0, c2 = 0;
      auto& d = o.off_mesh.direction;
      if(!(in >> d[0] >> c1 >> d[1] >> c2 >> d[2]) || c1 != ',' || c2 != ',' || !in.eof() ||
         !std::isfinite(d[0] + d[1] + d[2]) || (d[0] == 0 && d[1] == 0 && d[2] == 0))
        throw Usage_error("--direction needs three numbers X,Y,Z, not all zero, got '" + v + "'");
      const double largest = (std::max)({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
      for(double& x : d) x /= largest;   // only the direction counts: 1e300 or 1e-300 components neither overflow nor underflow
    }
    else if(a == "--lp-solver") o.lp_solver = next();
    else if(a == "--linear-solver") o.linear_solver = next();
    else if(a == "--quiet") o.quiet = true;
    else if(a == "--verbose") o.verbose = true;
    else if(a == "--reduced-residual") o.reduced_residual = true;
    else if(a == "--completed-class") o.completed_class = true;
    else if(a == "--no-nonbounding-filter") o.unfiltered = true;
    else if(a == "--sequential") o.sequential = true;
    else if(a == "--labels-per-input-face") o.labels_per_input_face = true;
    else if(a == "--confidence") o.confidence = true;
    else if(a == "--anchor-face")
    {
      const std::string v = next();
      char* end = nullptr;
      const long long n = std::strtoll(v.c_str(), &end, 10);
      if(v.empty() || *end != '\0' || n < 1)
        throw Usage_error("--anchor-face needs a face number (1-based, in the mesh file's order), got '" + v + "'");
      o.anchor_face = std::size_t(n);
    }
    else if(a == "--epsilon")
    {
      const std::string v = next();
      char* end = nullptr;
      o.epsilon = std::strtod(v.c_str(), &end);
      if(v.empty() || *end != '\0' || !(o.epsilon > 0) || !std::isfinite(o.epsilon))
        throw Usage_error("--epsilon needs a positive number, got '" + v + "'");
    }
    else if(a.rfind('-', 0) == 0 && a.size() > 1) throw Usage_error("unknown option " + a);
    else if(o.mesh.empty()) o.mesh = a;
    else throw Usage_error("unexpected argument '" + a + "' (only one mesh)");
  }
  if(o.help) return o;
  if(o.mesh.empty()) throw Usage_error("no mesh file given");
  if(!SIO::is_one_of(o.lp_solver, SIO::lp_solver_names()))
    throw Usage_error("unknown --lp-solver '" + o.lp_solver + "' (available: " + SIO::name_list(SIO::lp_solver_names()) + ")");
  if(!SIO::is_one_of(o.linear_solver, SIO::linear_solver_names()))
    throw Usage_error("unknown --linear-solver '" + o.linear_solver + "' (available: " +
                      SIO::name_list(SIO::linear_solver_names()) + ")");
  return o;
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}


// Calls run(lp, sparse_solver) with the residual solver and the sparse Cholesky solver chosen on the command
// line (checked by parse_arguments()); returns what run returns.
template <class Run>
bool with_solvers(const Options& opt, Run run)
{
  return SIO::with_solvers(opt.lp_solver, opt.linear_solver, run);
}

typedef std::map<int, std::pair<std::size_t, double> > Histogram;   // label -> (faces, area)

// the topology of the solved mesh in summary.json (both routes): the genus only where it is defined
void json_topology(SIO::Json& j, const SWN::Solve_report& report)
{
  j.key("euler_characteristic").value(report.euler_characteristic).key("orientable").value(report.orientable);
  if(report.genus >= 0) j.key("genus").value(report.genus);
  else j.key("genus").value(nullptr);
}

// the same on the console
std::string topology_text(const SWN::Solve_report& report)
{
  std::string s = "Euler characteristic " + std::to_string(report.euler_characteristic) + ", ";
  if(report.genus >= 0) return s + (report.orientable ? "orientable, genus " : "genus ") + std::to_string(report.genus);
  return s + (report.orientable ? "orientable" : "nonorientable") +
         (report.nonmanifold_vertices > 0 ? ", nonmanifold" : "") + " (genus not defined)";
}

// the parts of summary.json both routes write: the method and the labels
void json_method_and_labels(SIO::Json& j, const Options& opt, const SWN::Solve_report& report, const Histogram& histogram)
{
  j.key("method").begin_object()
    .key("epsilon").value(opt.epsilon)
    .key("homology_correction").value(report.homology_correction)
    .key("hodge_projection").value(report.hodge_projection)
    .key("lp_ran").value(report.lp_ran).key("reduced_residual").value(report.reduced_residual)
    .key("lp_variables").value(report.lp_variables).key("lp_rows").value(report.lp_rows)
    .key("lp_objective").value(report.lp_objective)
    .key("lp_solver").value(opt.lp_solver).key("linear_solver").value(opt.linear_solver)
    .end_object();
  j.key("labels").begin_array();
  for(const auto& h : histogram)
    j.begin_object().key("label").value(double(h.first)).key("faces").value(h.second.first)
      .key("area").value(h.second.second).end_object();
  j.end_array();
}

// what the library did with the curves off the mesh, one object per file
void json_off_mesh(SIO::Json& j, const std::vector<SIO::Off_mesh_report>& reports)
{
  j.key("curves_off_mesh").begin_array();
  for(const SIO::Off_mesh_report& r : reports)
  {
    j.begin_object().key("file").value(r.file).key("kind").value(std::string(r.stamp ? "stamp" : "polylines"))
      .key("polylines").value(r.polylines);
    if(r.stamp) j.key("stamped_polylines").value(r.stamped_polylines);
    j.key("points").value(r.points).key("points_off_surface").value(r.points_off_surface)
      .key("failed_walks").value(r.failed_walks).key("border_pieces").value(r.border_pieces)
      .key("crossing_vertices").value(r.crossing_vertices)
      .key("curves").value(r.curves).key("cut_vertices").value(r.cut_vertices).key("cut_faces").value(r.cut_faces)
      .key("refined_pieces").value(r.refined_pieces).key("refinement_vertices").value(r.refinement_vertices)
      .key("refinement_faces").value(r.refinement_faces).end_object();
  }
  j.end_array();
}

// the curves of an OBJ mesh's `l` records; a record that leaves the faces gets a hint at --polylines
SIO::Curve_set obj_mesh_curves(const SIO::Mesh_read_info& info, const Mesh& mesh)
{
  try
  {
    return SIO::curve_set_from_obj(info, mesh);
  }
  catch(const SIO::Input_error& e)
  {
    if(e.reason.find("share no face") == std::string::npos) throw;
    throw SIO::Input_error(e.file, e.line, e.reason + "; the `l` records of a mesh file run along its edges: for a stroke "
                           "drawn off the mesh, put its `v` and `l` records in a file of their own and give it with --polylines FILE");
  }
}

void print_summary(const Options& opt, const SIO::Mesh_read_info& info, const SWN::Solve_report& report,
                   const std::vector<SIO::Off_mesh_report>& off_mesh, const Histogram& histogram,
                   std::size_t G_edges, std::size_t bounding_edges, double seconds)
{
  if(opt.quiet) return;
  std::cout << "mesh: " << opt.mesh << ": " << info.number_of_vertices << " vertices, " << info.number_of_faces
            << " faces; solved on " << report.vertices << " vertices, " << report.faces << " faces, "
            << topology_text(report) << ", " << report.components << " component(s)\n";
  for(const SIO::Off_mesh_report& r : off_mesh) std::cout << SIO::summary_line(r) << "\n";
  std::cout << "curve: " << report.curve_edges << " edges, " << report.interior_endpoints << " interior endpoints\n"
            << "labels:";
  for(const auto& h : histogram) std::cout << "  W=" << h.first << ": " << h.second.first << " faces";
  std::cout << "\nnonbounding loops G: " << G_edges << " edges; bounding chain: " << bounding_edges << " edges\n"
            << "residual LP: " << (report.lp_ran ? "solved (" + std::to_string(report.lp_variables) + " variables)" : std::string("not needed"))
            << "; total " << seconds << " s\n";
  if(!opt.output_dir.empty()) std::cout << "outputs written to " << opt.output_dir << "/\n";
}

} // namespace

#include "swn_label_outputs.h"
#include "swn_soup_route.h"

int main(int argc, char** argv)
{
  Options opt;
  try
  {
    opt = parse_arguments(argc, argv);
  }
  catch(const Usage_error& e)
  {
    std::cerr << "swn: " << e.what() << "\n(swn --help for usage)\n";
    return 2;
  }
  if(opt.help) { std::cout << usage; return 0; }
  if(!opt.output_dir.empty()) SIO::Atomic_output_dir::remove_temporaries_on_signals();   // both routes: nothing left on SIGINT, SIGTERM, SIGHUP
  auto log = [&](const std::string& s) { if(opt.verbose) std::cerr << "[swn] " << s << "\n"; };

  const auto t_start = std::chrono::steady_clock::now();
  Mesh input;
  SIO::Triangle_soup soup;
  SIO::Mesh_read_info info;
  std::vector<SIO::Curve_set> curves;
  SIO::Cut_result<K::Point_3> cut;
  std::vector<SIO::Off_mesh_report> off_mesh;
  double t_read = 0, t_cut = 0;
  std::string not_a_mesh;   // why the input is solved as a polygon soup ("" for oriented 2-manifold triangle meshes)
  try
  {
    auto t0 = std::chrono::steady_clock::now();
    not_a_mesh = SIO::read_mesh_or_soup(opt.mesh, input, soup, info, !opt.sequential);
    if(opt.anchor_face > info.number_of_faces)
      throw SIO::Input_error(opt.mesh, 0, "--anchor-face " + std::to_string(opt.anchor_face) + " is out of range (the mesh has " +
                                            std::to_string(info.number_of_faces) + " faces, numbered from 1)");
    for(const std::string& w : info.warnings)
      if(!opt.quiet) std::cerr << "swn: warning: " << w << "\n";
    if(not_a_mesh.empty())
    {
      if(SIO::has_curve_records(info)) curves.push_back(obj_mesh_curves(info, input));
      if(!opt.curve.empty()) curves.push_back(SIO::read_curve_file(opt.curve, input));
    }
    else
    {
      if(SIO::has_curve_records(info)) curves.push_back(SIO::curve_set_from_obj(info, soup));
      if(!opt.curve.empty()) curves.push_back(SIO::read_curve_file(opt.curve, soup));
    }
    SIO::read_off_mesh_curves(opt.off_mesh);
    if(curves.empty() && opt.off_mesh.empty())
      throw SIO::Input_error(opt.mesh, 0, "no curve: give --curve FILE, --polylines FILE, --stamp FILE, or `l` lines in an OBJ mesh");
    t_read = seconds_since(t0);
    bool dual_chains = false;
    for(const SIO::Curve_set& c : curves) dual_chains = dual_chains || !c.dual_pairs.empty();
    if(not_a_mesh.empty() && dual_chains)
    {
      const auto edges = SIO::soup_edges(soup);
      for(const SIO::Curve_set& c : curves) SIO::internal::validate_soup_curve_set(c, soup, edges);
      not_a_mesh = "the curve has dual chains (c records)";
    }
    if(!not_a_mesh.empty() && !opt.off_mesh.empty())
      throw SIO::Input_error(opt.off_mesh.polylines_file.empty() ? opt.off_mesh.stamp_file : opt.off_mesh.polylines_file, 0,
                             "curves off the mesh need a triangle mesh to cut, and " + opt.mesh + " is solved as a soup (" +
                             not_a_mesh + ")");
    if(!not_a_mesh.empty())
      return run_on_soup(opt, soup, info, curves, not_a_mesh, t_start, t_read);
    soup = SIO::Triangle_soup();
    log("read " + std::to_string(num_vertices(input)) + " vertices, " + std::to_string(num_faces(input)) + " faces");
    t0 = std::chrono::steady_clock::now();
    cut = SIO::conforming_cut(input, curves);
    if(!opt.off_mesh.empty())
    {
      off_mesh = SIO::add_off_mesh_curves(cut, opt.off_mesh, opt.mesh, [&](const std::string& w) {
        if(!opt.quiet) std::cerr << "swn: warning: " << w << "\n";
      });
      for(const SIO::Off_mesh_report& r : off_mesh)
      {
        log(SIO::summary_line(r));
        for(const std::string& d : r.details) log(d);
      }
    }
    input = Mesh();   // the run goes on with the cut's copy: free the input's memory now
    curves.clear();
    t_cut = seconds_since(t0);
    log("curve on edges: " + std::to_string(cut.cut_new_vertices) + " vertices from the cut, " +
        std::to_string(cut.refine_new_vertices) + " from refining short pieces");
  }
  catch(const SIO::Input_error& e)
  {
    std::cerr << "swn: error: " << e.what() << "\n";
    return 2;
  }
  catch(const std::exception& e)
  {
    std::cerr << "swn: error: " << opt.mesh << ": " << e.what() << "\n";
    return 2;
  }

  // Progress lines on stderr for long runs, unless --quiet.
  if(!opt.quiet && num_faces(cut.mesh) > 200000) opt.verbose = true;

  // Solve on the mesh the curve lives on.
  Mesh& mesh = cut.mesh;
  auto chain = mesh.add_property_map<Mesh::Edge_index, int>("e:swn_chain", 0).first;
  for(auto e : edges(mesh)) chain[e] = cut.chain[std::size_t(e)];
  auto labels = mesh.add_property_map<Mesh::Face_index, int>("f:label", 0).first;
  auto w = mesh.add_property_map<Mesh::Halfedge_index, double>("h:w", 0.).first;
  auto G = mesh.add_property_map<Mesh::Edge_index, int>("e:G", 0).first;
  auto g = mesh.add_property_map<Mesh::Edge_index, double>("e:g", 0.).first;
  auto B = mesh.add_property_map<Mesh::Edge_index, int>("e:bounding", 0).first;
  auto confidence = mesh.add_property_map<Mesh::Face_index, double>("f:confidence", 0.).first;
  auto region = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:region", 0).first;
  SWN::Label_confidence regions;
  SWN::Solve_report report;
  const Mesh::Face_index anchor = anchor_piece(opt, mesh, cut.face_origin);
  const bool ok = with_solvers(opt, [&](auto& lp, auto sparse_solver) {
    return CGAL::surface_winding_numbers(
      mesh, chain, labels,
      SWN::parameters::label_anchor_face(anchor,
      SWN::parameters::label_confidence(std::ref(regions), SWN::parameters::confidence_map(confidence,
      SWN::parameters::region_map(region,
      SWN::parameters::winding_number_map(w, SWN::parameters::nonbounding_chain_map(G,
      SWN::parameters::nonbounding_chain_real_map(g, SWN::parameters::bounding_chain_map(B,
      SWN::parameters::epsilon(opt.epsilon, SWN::parameters::use_reduced_residual(opt.reduced_residual,
      SWN::parameters::filter_nonbounding_loops(!opt.unfiltered,
      SWN::parameters::completed_homology_class(opt.completed_class,
      SWN::parameters::concurrency(!opt.sequential,
      SWN::parameters::lp_solver(std::ref(lp),
      SWN::parameters::report(std::ref(report))))))))))))))))
        .verbose(opt.verbose).sparse_linear_solver(sparse_solver));
  });
  if(!ok)
  {
    const bool bad_input = report.invalid_input;
    std::cerr << "swn: error: " << (bad_input ? opt.mesh + ": " : std::string()) << report.error << "\n";
    return bad_input ? 2 : 1;
  }

  // Region statistics
  Histogram histogram;
  for(auto f : faces(mesh))
  {
    auto& entry = histogram[labels[f]];
    ++entry.first;
    entry.second += SIO::face_area(mesh, f);
  }
  std::size_t G_edges = 0, bounding_edges = 0;
  for(auto e : edges(mesh)) { G_edges += G[e] != 0; bounding_edges += B[e] != 0; }
  // the cut (and the refinement) split faces: outputs are on the solved mesh, labels.txt too unless asked
  const bool faces_changed = num_faces(mesh) != cut.input_faces;
  if(faces_changed && !opt.quiet)
    std::cout << "note: the curves were put on edges by splitting faces: " << cut.input_faces << " input faces, "
              << num_faces(mesh) << " solved faces; " << (opt.labels_per_input_face
                    ? "labels.txt has one label per input face (the label covering the largest area of its pieces)"
                    : "labels.txt and mesh.ply are on the solved faces (--labels-per-input-face: labels.txt per input face)")
              << "\n";

  double t_write = 0;
  if(!opt.output_dir.empty())
  {
    const auto t0 = std::chrono::steady_clock::now();
    try
    {
      SIO::Atomic_output_dir out(opt.output_dir);
      auto completed = mesh.add_property_map<Mesh::Edge_index, int>("e:completed", 0).first;
      for(auto e : edges(mesh)) completed[e] = B[e] + G[e];
      // w.obj, the largest file, is written on a second thread while this one writes the others (the
      // mesh and the maps are only read from here on). Declared after `out`: if a write fails, the
      // future waits for the other thread before `out` removes the temporary files.
      const std::string w_obj_path = out.path("w.obj");
      std::future<void> w_obj = SIO::internal::start_task(opt.sequential, [&] { SIO::write_w_obj(w_obj_path, mesh, w); });
      if(opt.labels_per_input_face)
        SIO::write_soup_labels(out.path("labels.txt"), SIO::labels_per_input_face(mesh, labels, cut.face_origin, cut.input_faces));
      else
        SIO::write_labels(out.path("labels.txt"), mesh, labels);
      std::vector<double> face_confidence;
      std::vector<std::size_t> face_region;
      if(opt.confidence)
        for(auto f : faces(mesh)) { face_confidence.push_back(confidence[f]); face_region.push_back(region[f]); }
      SIO::write_labeled_ply(out.path("mesh.ply"), mesh, labels, w, true, face_confidence, face_region);
      SIO::write_chain_obj(out.path("bounding.obj"), mesh, B);
      SIO::write_chain_obj(out.path("nonbounding.obj"), mesh, G);
      SIO::write_chain_obj(out.path("completed.obj"), mesh, completed);
      w_obj.get();   // rethrows a failed write
      t_write = seconds_since(t0);

      SIO::Json j;
      j.begin_object();
      j.key("version").value(std::string("0.1.0"));
      j.key("input").begin_object()
        .key("mesh").value(opt.mesh).key("curve").value(opt.curve)
        .key("vertices").value(info.number_of_vertices).key("faces").value(info.number_of_faces)
        .key("unreferenced_vertices").value(info.unreferenced_vertices)
        .key("duplicated_vertex_positions").value(info.duplicated_vertex_positions)
        .end_object();
      j.key("solved_mesh").begin_object()
        .key("vertices").value(report.vertices).key("edges").value(report.edges).key("faces").value(report.faces)
        .key("components").value(report.components);
      json_topology(j, report);
      j.key("border_edges").value(report.border_edges).key("border_loops").value(report.border_loops)
        .key("cut_new_vertices").value(cut.cut_new_vertices).key("refine_new_vertices").value(cut.refine_new_vertices)
        .key("faces_changed").value(faces_changed)
        .key("clamped_cotan_weights").value(report.degenerate_weights)
        .end_object();
      j.key("curve").begin_object()
        .key("edges").value(report.curve_edges).key("interior_endpoints").value(report.interior_endpoints)
        .key("nonbounding_edges").value(G_edges).key("bounding_edges").value(bounding_edges)
        .key("nonbounding_closing_units").value(report.nonbounding_closing_units)
        .end_object();
      json_off_mesh(j, off_mesh);
      json_method_and_labels(j, opt, report, histogram);
      j.key("labels_txt").value(std::string(opt.labels_per_input_face || !faces_changed ? "per input face" : "per solved face"));
      json_confidence(j, opt, regions);
      j.key("timings_seconds").begin_object()
        .key("read").value(t_read).key("curve_on_edges").value(t_cut).key("mesh_tables").value(report.time_mesh)
        .key("jump_laplace").value(report.time_setup + report.time_jump_laplace)
        .key("hodge").value(report.time_hodge).key("residual").value(report.time_residual)
        .key("second_solve").value(report.time_second_solve).key("labels").value(report.time_labels)
        .key("output_maps").value(report.time_output_maps).key("write").value(t_write).key("io").value(t_read + t_write)
        .key("total").value(seconds_since(t_start))
        .end_object();
      j.end_object();
      SIO::write_text_file(out.path("summary.json"), j.str());
      out.commit();
    }
    catch(const std::exception& e)
    {
      std::cerr << "swn: error: writing " << opt.output_dir << ": " << e.what() << "\n";
      return 1;
    }
  }

  print_summary(opt, info, report, off_mesh, histogram, G_edges, bounding_edges, seconds_since(t_start));
  return 0;
}
