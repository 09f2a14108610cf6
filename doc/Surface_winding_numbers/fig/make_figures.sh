#!/bin/sh
# Makes the pictures of the manual's examples of curves off the mesh (Surface_winding_numbers.txt):
# runs the examples curves_off_the_mesh and selection_and_segmentation and the swn tool on the bunny with
# star.svg, and renders their PLY outputs with render_ply.py (plain Python, no dependency).
#
# usage: doc/Surface_winding_numbers/fig/make_figures.sh BUILD_DIR   (from the repository root, with the
#        examples and the tool built in BUILD_DIR)
set -e
build=${1:?usage: make_figures.sh BUILD_DIR}
fig=$(dirname "$0")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$build/examples/curves_off_the_mesh" "$tmp/curves.ply"
python3 "$fig/render_ply.py" "$tmp/curves.ply" "$fig/curves_off_the_mesh.png" --direction 0,0,-1

"$build/tools/swn/swn" data/swn-demo/bunny.obj --stamp "$fig/star.svg" --direction 0,0,-1 --output-dir "$tmp/stamp" --quiet
python3 "$fig/render_ply.py" "$tmp/stamp/mesh.ply" "$fig/stamp_bunny.png" --direction 0,0,-1 --curves "$tmp/stamp/bounding.obj"

"$build/examples/selection_and_segmentation" "$tmp/selection"
python3 "$fig/render_ply.py" "$tmp/selection_labels.ply" "$fig/selection_and_segmentation.png" --direction 0,-0.3,-1
python3 "$fig/render_ply.py" "$tmp/selection_noisy.ply" "$fig/selection_noisy.png" --direction=-0.2,-0.1,-1 --size 400
python3 "$fig/render_ply.py" "$tmp/selection_cleaned.ply" "$fig/selection_cleaned.png" --direction=-0.2,-0.1,-1 --size 400
