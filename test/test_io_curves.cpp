// Curves off the mesh made dependable (issue 42): the input face of every piece of the cut, and the
// reproducers of test/data/curves_off_mesh (README there) through the library.

#include "test_io_support.h"

#include <CGAL/Surface_winding_numbers/conforming_cut.h>
#include <CGAL/Surface_winding_numbers/polylines_to_chain.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <gtest/gtest.h>

#include <map>
#include <vector>

using namespace swn_test;

namespace {

namespace SWN = CGAL::Surface_winding_numbers;
namespace PMP = CGAL::Polygon_mesh_processing;

// every face maps to a face of the input, faces not cut to themselves, and the pieces of every input face
// tile it: their areas add up to its area
void expect_origins_tile_input(const Mesh& input, const Mesh& cut, const Mesh::Property_map<FI, FI>& origin)
{
  std::map<FI, double> area;
  std::size_t pieces = 0;
  for(FI f : cut.faces())
  {
    const FI g = origin[f];
    ASSERT_TRUE(std::size_t(g) < input.number_of_faces()) << "face " << f;
    if(std::size_t(f) < input.number_of_faces() && g != f)
      EXPECT_EQ(g, f) << "a face of the input keeps its descriptor and is a piece of itself";
    area[g] += PMP::face_area(f, cut);
    pieces += (g != f);
  }
  EXPECT_GT(pieces, 0u);
  for(FI g : input.faces())
    EXPECT_NEAR(area[g], PMP::face_area(g, input), 1e-12 * (1 + PMP::face_area(g, input))) << "input face " << g;
}

TEST(FaceOrigin, ConformingCutAndPolylinesToChainTileEveryInputFace)
{
  Mesh input;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(tdata + "grid4.off", input));
  // an open stroke (its ends inside: cut and refinement) and a closed one, through polylines_to_chain()
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const std::vector<std::vector<Point> > strokes{{Point(0.3, 0.4, 0), Point(2.6, 1.7, 0)},
                                                   {Point(0.5, 2.2, 0), Point(1.5, 2.3, 0), Point(1.2, 2.8, 0), Point(0.5, 2.2, 0)}};
    const auto r = SWN::polylines_to_chain(m, strokes, chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(r)) << r.error;
    EXPECT_GT(r.cut.cut_faces, 0u);
    EXPECT_GT(r.cut.refinement_faces, 0u);
    expect_origins_tile_input(input, m, origin);
  }
  // conforming_cut() directly: a segment between two edge midpoints of one face
  {
    Mesh m = input;
    auto chain = m.add_property_map<Mesh::Edge_index, int>("e:chain", 0).first;
    auto origin = m.add_property_map<FI, FI>("f:origin", FI()).first;
    const FI f = *m.faces().begin();
    const auto h = m.halfedge(f);
    const std::vector<std::vector<PMP::Face_location<Mesh, double> > > curves{
      {PMP::locate_on_halfedge(h, 0.5, m), PMP::locate_on_halfedge(m.next(h), 0.5, m)}};
    const auto r = SWN::conforming_cut(m, curves, chain, SWN::parameters::face_origin_map(origin));
    ASSERT_TRUE(bool(r)) << r.message;
    expect_origins_tile_input(input, m, origin);
  }
}

} // namespace
