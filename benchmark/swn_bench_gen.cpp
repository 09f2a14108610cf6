// swn_bench_gen: builds the meshes and the cases of the Surface Winding Numbers benchmark.
//
//   swn_bench_gen --suite quick|full|paper|ablation|large --out CASES_DIR [--mesh-cache DIR] [--cgal-data DIR] [--shard I/N]
//                 [--gaps per-curve|global] [--straighten on|off]
//   swn_bench_gen --info MESH...        genus, borders, components and size of mesh files
//
// A case is: a mesh (OFF, written once per mesh into the mesh cache), a curve file in the swn tool's
// `# swn halfedges` format, the ground-truth labels (one integer per face, in the mesh's face order),
// the planted nonbounding chain (same format) and meta.json. Everything derives from fixed seeds.
//
// Ground truth: the faces are labelled by thresholding a smooth function at one or two levels: a random
// field in 3D (suites quick, full, ablation, large) or a low-frequency Laplacian eigenfunction (suite
// paper); the region curve is the jump of these labels, J(gt): on an interior edge e with
// h = halfedge(e), chain(e) = gt(face(h)) - gt(face(opposite(h))) (the library's convention: crossing
// from right to left, W rises by the chain value). On surfaces that are not disks or spheres, a random
// nonempty subset of a homology basis of H1(M, border) is added with random signs: the greedy basis of
// Erickson and Whittlesey (shortest-path tree from a random root, maximum spanning cotree on the dual,
// border loops capped by virtual cones) for the handles, and shortest arcs between border loops, the
// loops straightened (suite paper: also routed off the region curve). Corruption: random runs along
// every connected curve are deleted until the gap level of its length is gone (--gaps global: runs
// anywhere); the levels are nested (the same deletion order).
//
// Options for ablations and calibration: --gap-levels L1,L2,... (instead of the suite's), --only
// simply-connected|handles, --regions field|eigen, --loops-off-regions on|off.

#include "gen_loops.h"
#include "gen_meshes.h"
#include "gen_regions.h"
#include "gen_spectral.h"
#include "swn_io/read_mesh.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <numeric>
#include <sstream>

using namespace swn_bench;

namespace {

struct Options
{
  std::string suite = "quick", out, mesh_cache, cgal_data;
  std::string gap_mode = "per-curve";   // per-curve | global
  bool straighten = true;
  int shard = 0, nshards = 1;
  std::vector<double> gap_levels;   // overrides the suite's gap levels (calibration)
  std::string only_class;           // "", "simply-connected" or "handles": the meshes of one class only
  std::string regions;              // "", "field" or "eigen": overrides the suite's region draws
  std::string loops_off_regions;    // "", "on" or "off": overrides the suite's routing of the planted loops
};

// The mesh of `spec`, from the cache or built by a fresh process of this program (with address-space
// randomization off when possible: CGAL's surface mesher orders some work by memory addresses, so a
// mesh built after another one in the same process, or with another memory layout, can differ
// slightly). Returns false when the mesh cannot be had.
bool cached_mesh(const Options& o, const Mesh_spec& spec, const std::string& mesh_file, Mesh& m)
{
  if(!fs::exists(mesh_file))
  {
    if(spec.kind == "file" && o.cgal_data.empty())
    {
      std::cerr << "[gen] skipping " << spec.name << ": no --cgal-data directory\n";
      return false;
    }
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    std::string cmd = "'" + self + "' --build-mesh '" + spec.name + "' --suite '" + o.suite + "' --cgal-data '" +
                      o.cgal_data + "' --mesh-out '" + mesh_file + "'";
    if(std::system("setarch \"$(uname -m)\" -R true >/dev/null 2>&1") == 0) cmd = "setarch \"$(uname -m)\" -R " + cmd;
    if(std::system(cmd.c_str()) != 0 || !fs::exists(mesh_file))
    {
      std::cerr << "[gen] skipping " << spec.name << ": the mesh could not be built\n";
      return false;
    }
  }
  CGAL::Surface_winding_numbers::IO::read_mesh(mesh_file, m);   // the exact mesh the solver will read
  return true;
}

// One region draw of a mesh: the ground truth, the planted chain and the full (unbroken) input.
struct Draw
{
  std::vector<int> gt;
  Chain region, full;
  Planted planted;
  int eigenfunction = -1;   // paper suite: which eigenfunction (0 = the lowest nonconstant one)
};

void write_case(const Options& o, const Suite& suite, const Mesh_spec& spec, const Mesh& m, const Topology& topo,
                const std::string& mesh_file, int rs, const Draw& d, double gap, const Chain& c, double removed,
                double curve_length, std::ofstream& index)
{
  std::size_t curve_edges = 0, planted_edges = 0, planted_shared = 0, planted_cancelled = 0;
  for(int v : d.full) curve_edges += v != 0;
  for(std::size_t e = 0; e < d.planted.chain.size(); ++e)
    if(d.planted.chain[e] != 0)
    {
      ++planted_edges;
      planted_shared += d.region[e] != 0;
      planted_cancelled += d.full[e] == 0;
    }
  std::ostringstream id;
  id << spec.name << "_r" << rs << "_g" << std::setw(2) << std::setfill('0') << int(std::lround(gap * 100));
  const std::string dir = fs::absolute(o.out + "/cases/" + id.str()).string();
  fs::create_directories(dir);
  write_halfedge_chain(m, c, dir + "/curve.txt");
  write_halfedge_chain(m, d.planted.chain, dir + "/planted.txt");
  {
    std::ofstream os(dir + "/labels_gt.txt");
    for(int l : d.gt) os << l << '\n';
  }
  const Planted& P = d.planted;
  std::ofstream js(dir + "/meta.json");
  js << std::setprecision(10) << "{\"case\": \"" << id.str() << "\", \"suite\": \"" << o.suite << "\", \"mesh\": \"" << spec.name
     << "\", \"mesh_file\": \"" << json_escape(mesh_file) << "\", \"source\": \""
     << (spec.kind == "file" ? "cgal-data:" + spec.file : spec.kind + (spec.cut.empty() ? "" : "+" + spec.cut))
     << "\", \"vertices\": " << m.number_of_vertices() << ", \"faces\": " << m.number_of_faces()
     << ", \"genus\": " << topo.genus << ", \"border_loops\": " << topo.border_loops
     << ", \"simply_connected\": " << (topo.simply_connected() ? "true" : "false")
     << ", \"region_seed\": " << rs << ", \"regions\": \"" << suite.regions << "\", \"eigenfunction\": " << d.eigenfunction
     << ", \"gap_level\": " << gap << ", \"gap_fraction\": " << (curve_length > 0 ? removed / curve_length : 0)
     << ", \"curve_edges_full\": " << curve_edges << ", \"curve_length\": " << curve_length
     << ", \"max_gt_label\": " << *std::max_element(d.gt.begin(), d.gt.end())
     << ", \"planted_loops\": " << P.loops << ", \"planted_arcs\": " << P.arcs
     << ", \"planted_edges\": " << planted_edges << ", \"basis_size\": " << P.basis_size
     << ", \"basis_dropped\": " << P.dropped << ", \"loops_straightened\": " << P.straightened
     << ", \"loops_rerouting_failed\": " << P.rerouting_failed
     << ", \"planted_shared_edges\": " << planted_shared << ", \"planted_cancelled_edges\": " << planted_cancelled
     << ", \"gap_mode\": \"" << o.gap_mode << "\", \"straighten\": " << (o.straighten ? "true" : "false")
     << ", \"loops_off_region_curves\": " << (suite.loops_off_region_curves ? "true" : "false")
     << ", \"planted_nontrivial\": " << (P.nontrivial ? "true" : "false") << "}\n";
  index << id.str() << '\t' << dir << '\n';
}

void generate(const Options& o)
{
  Suite suite = make_suite(o.suite);
  if(!o.gap_levels.empty()) suite.gaps = o.gap_levels;
  if(!o.regions.empty()) suite.regions = o.regions;
  if(!o.loops_off_regions.empty()) suite.loops_off_region_curves = o.loops_off_regions == "on";
  fs::create_directories(o.out);
  const std::string mesh_cache = o.mesh_cache.empty() ? o.out + "/meshes" : o.mesh_cache;
  fs::create_directories(mesh_cache);
  std::ofstream index(o.out + "/index.tsv");
  for(std::size_t mi = 0; mi < suite.meshes.size(); ++mi)
  {
    if(int(mi % std::size_t(o.nshards)) != o.shard) continue;
    const Mesh_spec& spec = suite.meshes[mi];
    const auto t0 = std::chrono::steady_clock::now();
    const std::string mesh_file = fs::absolute(mesh_cache + "/" + spec.name + "_" + std::to_string(spec.target_vertices) + ".off").string();
    Mesh m;
    if(!cached_mesh(o, spec, mesh_file, m)) continue;
    const Topology topo = topology(m);
    if(!o.only_class.empty() && topo.simply_connected() != (o.only_class == "simply-connected")) continue;
    const Face_geometry geo = face_geometry(m);
    std::vector<double> edge_len(m.number_of_edges());
    for(EI e : m.edges()) edge_len[std::size_t(e)] = std::sqrt(CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1))));
    std::vector<std::vector<double>> phi;
    if(suite.regions == "eigen") phi = low_frequency_eigenfunctions(m, 6);
    const double t_mesh = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::cerr << "[gen] " << spec.name << ": " << m.number_of_vertices() << " vertices, " << m.number_of_faces()
              << " faces, genus " << topo.genus << ", " << topo.border_loops << " border loop(s), "
              << topo.components << " component(s), " << t_mesh << " s\n";

    for(int rs = 0; rs < spec.region_seeds; ++rs)
    {
      Rng rng(hash_string((suite.regions == "eigen" ? "paper/" : "") + spec.name + "/regions/" + std::to_string(rs)));
      Draw d;
      d.gt = suite.regions == "eigen" ? eigenfunction_regions(m, phi, geo, rng, d.eigenfunction) : random_field_regions(m, geo, rng);
      d.region = region_chain(m, d.gt);
      d.planted = plant_loops(m, topo, edge_len, o.straighten, suite.loops_off_region_curves ? &d.region : nullptr, rng);
      d.full.assign(m.number_of_edges(), 0);
      for(std::size_t e = 0; e < d.full.size(); ++e) d.full[e] = d.region[e] + d.planted.chain[e];
      double curve_length = 0;
      Rng grng(hash_string(spec.name + "/gaps/" + std::to_string(rs)));
      const auto plan = deletion_plan(m, d.full, o.gap_mode, grng, curve_length);
      for(double gap : suite.gaps)
      {
        Chain c = d.full;
        double removed = 0;
        for(const auto& [e, frac] : plan)
          if(frac <= gap + 1e-12) { c[e] = 0; removed += edge_len[e]; }
        write_case(o, suite, spec, m, topo, mesh_file, rs, d, gap, c, removed, curve_length, index);
      }
    }
  }
}

void info(const std::vector<std::string>& files)
{
  for(const std::string& f : files)
  {
    try
    {
      Mesh m = read_model(f);
      const Topology t = topology(m);
      std::cout << fs::path(f).filename().string() << ": V " << m.number_of_vertices() << " F " << m.number_of_faces()
                << " genus " << t.genus << " border_loops " << t.border_loops << " min_area " << min_face_area(m) << "\n";
    }
    catch(const std::exception& e) { std::cout << f << ": error " << e.what() << "\n"; }
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  std::vector<std::string> info_files;
  bool info_mode = false;
  std::string build_mesh_name, mesh_out;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if(i + 1 >= argc) throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    try
    {
      if(a == "--suite") o.suite = next();
      else if(a == "--out") o.out = next();
      else if(a == "--mesh-cache") o.mesh_cache = next();
      else if(a == "--cgal-data") o.cgal_data = next();
      else if(a == "--shard")
      {
        const std::string s = next();
        const auto slash = s.find('/');
        o.shard = std::stoi(s.substr(0, slash));
        o.nshards = std::stoi(s.substr(slash + 1));
        if(o.nshards < 1 || o.shard < 0 || o.shard >= o.nshards) throw std::runtime_error("bad --shard " + s);
      }
      else if(a == "--gaps") { o.gap_mode = next(); if(o.gap_mode != "per-curve" && o.gap_mode != "global") throw std::runtime_error("--gaps per-curve|global"); }
      else if(a == "--straighten") { const std::string v = next(); if(v != "on" && v != "off") throw std::runtime_error("--straighten on|off"); o.straighten = v == "on"; }
      else if(a == "--gap-levels")
      {
        std::istringstream ls(next());
        std::string x;
        while(std::getline(ls, x, ',')) o.gap_levels.push_back(std::stod(x));
      }
      else if(a == "--only")
      {
        o.only_class = next();
        if(o.only_class != "simply-connected" && o.only_class != "handles") throw std::runtime_error("--only simply-connected|handles");
      }
      else if(a == "--regions")
      {
        o.regions = next();
        if(o.regions != "field" && o.regions != "eigen") throw std::runtime_error("--regions field|eigen");
      }
      else if(a == "--loops-off-regions")
      {
        o.loops_off_regions = next();
        if(o.loops_off_regions != "on" && o.loops_off_regions != "off") throw std::runtime_error("--loops-off-regions on|off");
      }
      else if(a == "--info") info_mode = true;
      else if(a == "--build-mesh") build_mesh_name = next();
      else if(a == "--mesh-out") mesh_out = next();
      else if(info_mode) info_files.push_back(a);
      else throw std::runtime_error("unknown argument " + a);
    }
    catch(const std::exception& e)
    {
      std::cerr << "swn_bench_gen: " << e.what() << "\n";
      return 2;
    }
  }
  try
  {
    if(info_mode) { info(info_files); return 0; }
    if(!build_mesh_name.empty())
    {
      // internal: build one mesh of the suite in this fresh process and write it (see generate())
      for(const Mesh_spec& spec : make_suite(o.suite).meshes)
        if(spec.name == build_mesh_name)
        {
          const Mesh m = build_mesh(spec, o.cgal_data);
          write_off(m, mesh_out);
          return 0;
        }
      throw std::runtime_error("no mesh " + build_mesh_name + " in suite " + o.suite);
    }
    if(o.out.empty()) throw std::runtime_error("--out is required");
    generate(o);
  }
  catch(const std::exception& e)
  {
    std::cerr << "swn_bench_gen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
