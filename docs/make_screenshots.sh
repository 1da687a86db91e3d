#!/usr/bin/env bash
# Regenerates the pictures in docs/ with the inspector's headless mode (no display needed).
set -euo pipefail
cd "$(dirname "$0")/.."
bin=build/app/lloydscope
# From scattered sites (no first pass), as a lesson starts: see docs/guide.md.
$bin inspect assets/bumpy_disk.off --no-timings --no-resample --iteration 0 --screenshot docs/inspector_iteration0.png
$bin inspect assets/bumpy_disk.off --no-timings --iteration 10 --screenshot docs/inspector_iteration10.png
$bin inspect assets/bumpy_disk.off --no-timings --screenshot docs/inspector_converged.png
$bin inspect assets/bumpy_disk.off --no-timings --iteration 3 --select-cell 400 \
  --select-triangle 700 --screenshot docs/inspector_selection.png
$bin inspect assets/bumpy_disk.off --no-timings --no-resample --iteration 1 --presentation --stage centroids \
  --select-cell 400 --screenshot docs/inspector_lesson.png
$bin inspect assets/bumpy_disk.off --no-timings --compare-solvers --pane plots \
  --screenshot docs/inspector_compared.png
# The converged cells coloured by their site's valence, the irregular sites marked in 3D too.
$bin inspect assets/bumpy_disk.off --no-timings --fill valence --size 1280x800 \
  --screenshot docs/inspector_valence.png
# Results on two of the bench's inputs (CGAL's samples, extracted by ./build.sh into data/cgal).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for model in three_peaks lion-head; do
  $bin simplify data/cgal/$model.off -o "$tmp/$model.off" --vertices 1000 > /dev/null
  $bin inspect "$tmp/$model.off" --no-timings --screenshot docs/result_$model.png --size 1280x800
done
# The final result of the whole lion head at 1000 vertices, and where it strays farthest.
$bin inspect data/cgal/lion-head.off --simplify 1000 --final --no-timings \
  --screenshot docs/result_final_lion-head.png --size 1280x800
# A nearly closed disk, slit open (its seams in purple) and kept so, remeshed both ways.
$bin inspect data/cgal/mannequin-devil.off --simplify 650 --no-timings \
  --screenshot docs/result_mannequin_slit.png --size 1280x800
# A closed surface of genus 2, cut open and stitched back: its seams are purple in both views.
$bin inspect data/cgal/eight.off --no-timings --screenshot docs/result_eight_seams.png --size 1280x800
# A closed surface of genus 3 whose one cut has no conformal map: remeshed chart by chart.
$bin inspect data/cgal/elephant.off --simplify 1000 --final --no-timings \
  --screenshot docs/result_elephant_charts.png --size 1280x800
# A surface that curves much for its vertices: CGAL's armadillo halved along y (docs/clip_half.py,
# which needs python3) at 500 vertices, its final result's irregular vertices marked.
if command -v python3 > /dev/null; then
  python3 docs/clip_half.py data/cgal/armadillo.off "$tmp/armadillo_1.off" 1 > /dev/null
  $bin inspect "$tmp/armadillo_1.off" --sites 500 --fill valence --final --no-timings \
    --screenshot docs/result_armadillo_half_valence.png --size 1280x800
else
  echo "python3 not found: docs/result_armadillo_half_valence.png not remade" >&2
fi
