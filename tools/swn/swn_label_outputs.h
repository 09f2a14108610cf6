// swn: the tool's label options: --anchor-face (the face whose label is 0), and the confidence of the labels
// in summary.json. Included by swn.cpp after its helpers (Options, Mesh, SIO).

#ifndef SWN_TOOL_LABEL_OUTPUTS_H
#define SWN_TOOL_LABEL_OUTPUTS_H

namespace {

// the confidence of the labels (SWN::Label_confidence): the second-best flip, and with --confidence every region
void json_confidence(SIO::Json& j, const Options& opt, const SWN::Label_confidence& c)
{
  const bool second = c.second_best_region != std::size_t(-1);
  j.key("confidence").begin_object()
    .key("regions").value(c.regions.size())
    .key("second_best_region").value(second ? SIO::Json(c.second_best_region) : SIO::Json(nullptr))
    .key("second_best_cost").value(c.second_best_cost)
    .key("second_best_area").value(second ? c.regions[c.second_best_region].area : 0.);
  if(opt.confidence)
  {
    j.key("per_region").begin_array();
    for(const SWN::Label_region& r : c.regions)
      j.begin_object().key("label").value(double(r.label)).key("faces").value(r.faces).key("area").value(r.area)
        .key("component").value(r.component).key("flip_cost").value(r.flip_cost).key("flip_delta").value(double(r.flip_delta))
        .key("boundary_length").value(r.boundary_length).key("largest_in_component").value(r.largest_in_component)
        .end_object();
    j.end_array();
  }
  j.end_object();
}

// the face of `mesh` that --anchor-face names: the largest of the pieces of that input face (null_face(): none)
Mesh::Face_index anchor_piece(const Options& opt, const Mesh& mesh, const std::vector<std::size_t>& face_origin)
{
  Mesh::Face_index best = Mesh::null_face();
  double best_area = -1;
  if(opt.anchor_face == 0) return best;
  for(auto f : faces(mesh))
    if(face_origin[std::size_t(f)] == opt.anchor_face - 1 && SIO::face_area(mesh, f) > best_area)
    {
      best = f;
      best_area = SIO::face_area(mesh, f);
    }
  return best;
}

} // namespace

#endif
