// swn: the run on a polygon soup, for mesh files that are not oriented 2-manifold triangle meshes (polygons,
// nonmanifold edges and vertices, nonorientable gluings) and for curves given as dual chains. Included by
// swn.cpp after its helpers (Options, with_solvers(), json_method_and_labels(), print_summary()).
//
// The soup is solved as it is, by CGAL::polygon_soup_winding_numbers(): no cut, so the curves must run
// along the soup's edges (vertex points) or be dual chains. Every output is on the input's faces and
// vertices: labels.txt has one line per input face, mesh.ply and w.obj keep the input's polygons.

#ifndef SWN_TOOL_SOUP_ROUTE_H
#define SWN_TOOL_SOUP_ROUTE_H

namespace {

double soup_face_area(const SIO::Triangle_soup& soup, const std::vector<std::size_t>& face)
{
  const std::array<double, 3> n = SIO::internal::newell_normal(soup, face);
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

int run_on_soup(const Options& opt, const SIO::Triangle_soup& soup, const SIO::Mesh_read_info& info,
                const std::vector<SIO::Curve_set>& curves, const std::string& why,
                std::chrono::steady_clock::time_point t_start, double t_read)
{
  if(opt.verbose) std::cerr << "[swn] solved as a polygon soup: " << why << "\n";
  const SIO::Soup_curve curve = SIO::soup_curve(curves, soup);
  std::vector<K::Point_3> points;
  points.reserve(soup.points.size());
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  const std::size_t nf = SIO::number_of_faces(soup);
  std::vector<int> labels(nf, 0);
  SIO::Soup_corner_values w;
  SIO::Soup_edge_chain G, B;
  std::map<std::pair<std::size_t, std::size_t>, double> g;
  std::vector<double> confidence(nf, 0.);
  std::vector<std::size_t> region(nf, 0);
  SWN::Label_confidence regions;
  SWN::Solve_report report;
  auto solve_on = [&](const auto& polygons) {
    return with_solvers(opt, [&](auto& lp, auto sparse_solver) {
      return CGAL::polygon_soup_winding_numbers(
        points, polygons, curve.edges, CGAL::make_property_map(labels),
        SWN::parameters::dual_chain(curve.dual_pairs,
        SWN::parameters::label_confidence(std::ref(regions),
        SWN::parameters::confidence_map(CGAL::make_property_map(confidence),
        SWN::parameters::region_map(CGAL::make_property_map(region),
        SWN::parameters::winding_number_map(boost::make_assoc_property_map(w),
        SWN::parameters::nonbounding_chain_map(boost::make_assoc_property_map(G),
        SWN::parameters::nonbounding_chain_real_map(boost::make_assoc_property_map(g),
        SWN::parameters::bounding_chain_map(boost::make_assoc_property_map(B),
        SWN::parameters::epsilon(opt.epsilon, SWN::parameters::use_reduced_residual(opt.reduced_residual,
        SWN::parameters::filter_nonbounding_loops(!opt.unfiltered,
        SWN::parameters::completed_homology_class(opt.completed_class,
        SWN::parameters::concurrency(!opt.sequential,
        SWN::parameters::lp_solver(std::ref(lp),
        SWN::parameters::label_anchor_face(opt.anchor_face - 1,
        SWN::parameters::report(std::ref(report)))))))))))))))))
          .verbose(opt.verbose).sparse_linear_solver(sparse_solver));
    });
  };
  const bool ok = soup.polygons.empty() ? solve_on(soup.triangles) : solve_on(soup.polygons);
  if(!ok)
  {
    const bool bad_input = report.invalid_input;
    std::cerr << "swn: error: " << (bad_input ? opt.mesh + ": " : std::string()) << report.error << "\n";
    return bad_input ? 2 : 1;
  }
  if(!opt.quiet)
  {
    if(report.dropped_curve_edges > 0)
      std::cerr << "swn: warning: " << report.dropped_curve_edges << " curve edges at nonmanifold vertices were left "
                << "out (paper Sec. 2.2); the gaps they leave are closed like any other\n";
    if(report.inconsistent_curve_vertices > 0)
      std::cerr << "swn: warning: the curve's normal cannot be chosen consistently at " << report.inconsistent_curve_vertices
                << " vertices (on a nonorientable surface the jumps of consecutive curve edges add up instead of "
                << "cancelling there): it bounds no region consistently (paper Fig. 9); give the curve as a dual chain "
                << "(c records) with a consistent normal\n";
    if(report.nonmanifold_label_jumps > 0)
      std::cerr << "swn: warning: the labels differ across " << report.nonmanifold_label_jumps << " nonmanifold edges, "
                << "where the method allows no jump: there they depend on which flaps are taken as one sheet (a curve "
                << "that crosses a spine between two flaps whose faces run along it the same way has its higher side "
                << "swapped there: give it as a dual chain (c records) or orient the flaps as one sheet; a flap the "
                << "curve does not cover may also close the region along another path)\n";
  }

  Histogram histogram;
  for(std::size_t f = 0; f < nf; ++f)
  {
    auto& entry = histogram[labels[f]];
    ++entry.first;
    entry.second += soup_face_area(soup, SIO::internal::soup_face(soup, f));
  }
  std::size_t G_edges = 0, bounding_edges = 0;
  SIO::Soup_edge_chain completed = B;
  for(const auto& e : G) { G_edges += e.second != 0; completed[e.first] += e.second; }
  for(const auto& e : B) bounding_edges += e.second != 0;

  if(!opt.output_dir.empty())
  {
    const auto t0 = std::chrono::steady_clock::now();
    try
    {
      SIO::Atomic_output_dir out(opt.output_dir);
      SIO::write_soup_labels(out.path("labels.txt"), labels);
      SIO::write_soup_ply(out.path("mesh.ply"), soup, labels, w, opt.confidence ? confidence : std::vector<double>(),
                          opt.confidence ? region : std::vector<std::size_t>());
      SIO::write_soup_w_obj(out.path("w.obj"), soup, w);
      SIO::write_soup_chain_obj(out.path("bounding.obj"), soup, B);
      SIO::write_soup_chain_obj(out.path("nonbounding.obj"), soup, G);
      SIO::write_soup_chain_obj(out.path("completed.obj"), soup, completed);
      const double t_write = seconds_since(t0);
      SIO::Json j;
      j.begin_object();
      j.key("version").value(std::string("0.1.0"));
      j.key("input").begin_object()
        .key("mesh").value(opt.mesh).key("curve").value(opt.curve)
        .key("vertices").value(info.number_of_vertices).key("faces").value(info.number_of_faces)
        .key("unreferenced_vertices").value(info.unreferenced_vertices)
        .key("duplicated_vertex_positions").value(info.duplicated_vertex_positions)
        .key("polygon_soup").value(why)
        .end_object();
      j.key("solved_mesh").begin_object()
        .key("vertices").value(report.vertices).key("edges").value(report.edges).key("faces").value(report.faces)
        .key("components").value(report.components);
      json_topology(j, report);
      j.key("border_edges").value(report.border_edges).key("border_loops").value(report.border_loops)
        .key("nonmanifold_vertices").value(report.nonmanifold_vertices)
        .key("nonmanifold_edges").value(report.nonmanifold_edges)
        .key("nonorientable_edges").value(report.nonorientable_edges)
        .key("clamped_cotan_weights").value(report.degenerate_weights)
        .end_object();
      j.key("curve").begin_object()
        .key("edges").value(report.curve_edges).key("dual_pairs").value(curve.dual_pairs.size())
        .key("interior_endpoints").value(report.interior_endpoints)
        .key("dropped_curve_edges").value(report.dropped_curve_edges)
        .key("inconsistent_curve_vertices").value(report.inconsistent_curve_vertices)
        .key("nonmanifold_label_jumps").value(report.nonmanifold_label_jumps)
        .key("nonbounding_edges").value(G_edges).key("bounding_edges").value(bounding_edges)
        .key("nonbounding_closing_units").value(report.nonbounding_closing_units)
        .end_object();
      json_method_and_labels(j, opt, report, histogram);
      j.key("labels_txt").value(std::string("per input face"));   // no cut on this route
      json_confidence(j, opt, regions);
      j.key("timings_seconds").begin_object()
        .key("read").value(t_read).key("mesh_tables").value(report.time_mesh)
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
  print_summary(opt, info, report, {}, histogram, G_edges, bounding_edges, seconds_since(t_start));
  return 0;
}

} // namespace

#endif
