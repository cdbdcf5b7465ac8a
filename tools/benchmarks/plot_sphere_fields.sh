#!/usr/bin/env bash
# Plots the sphere fields from the medians of Google Benchmark's JSON (scripts/benchmark):
# on the left, chapter 5's render time at 150x150 against the number of spheres, with
# and without the hierarchy (SphereFieldSmall); on the right, the primary rays traced a
# second by chapter 5's plain hierarchy, chapter 17's tuned one and Embree
# (SphereFieldPrimary: 600x600 = 360 000 rays, one thread). With MESHES.png, the same
# three on triangle meshes, tori of 10 000 to 1 000 000 triangles (MeshPrimary), there.
# Usage: plot_sphere_fields.sh BENCHMARK-05.json BENCHMARK-17.json OUTPUT.png [MESHES.png]
set -euo pipefail
json=$1
json_tuned=$2
output=$3
mesh_output=${4:-}
data=$(mktemp)
meshes=$(mktemp)
trap 'rm -f "$data" "$meshes"' EXIT

# Each benchmark is an object with "name" and "real_time" on lines of their own.
awk -F'"' '
  /"name":/ { name = $4 }
  FILENAME == ARGV[1] && /"real_time":/ && name ~ /^SphereFieldSmall\/[0-9]+\/(bvh|no-bvh)\/real_time_median$/ {
    split(name, part, "/")
    value = $0; sub(/.*: */, "", value); sub(/,$/, "", value)
    time[part[2], part[3]] = value; counts[part[2]] = 1
  }
  /"real_time":/ && name ~ /^SphereFieldPrimary\/[0-9]+\/(plain|tuned|embree)\/real_time_median$/ &&
    (FILENAME == ARGV[1] || name !~ /embree/) {
    split(name, part, "/")
    value = $0; sub(/.*: */, "", value); sub(/,$/, "", value)
    time[part[2], part[3]] = value; counts[part[2]] = 1
  }
  END {
    # Columns: spheres, ms with and without the hierarchy, million rays/s plain, tuned
    # and Embree.
    for (n in counts) print n, ((n, "bvh") in time ? time[n, "bvh"] : "NaN"),
                             ((n, "no-bvh") in time ? time[n, "no-bvh"] : "NaN"),
                             ((n, "plain") in time ? 360 / time[n, "plain"] : "NaN"),
                             ((n, "tuned") in time ? 360 / time[n, "tuned"] : "NaN"),
                             ((n, "embree") in time ? 360 / time[n, "embree"] : "NaN")
  }' "$json" "$json_tuned" | sort -n > "$data"

if [ ! -s "$data" ]; then
  echo "plot_sphere_fields.sh: no SphereFieldSmall medians in $json" >&2
  exit 1
fi

gnuplot <<GNUPLOT
set terminal pngcairo size 1100,460 font "sans,11"
set output "$output"
set multiplot layout 1,2
set rmargin 5
set xlabel "spheres"
set logscale x
set grid
set key top left
set title "Chapter 5: the sphere fields at 150x150, one thread"
set ylabel "render time (ms)"
set logscale y
plot "$data" using 1:3 with linespoints lw 2 pt 7 title "without the hierarchy", \
     "$data" using 1:2 with linespoints lw 2 pt 5 title "with the hierarchy"
set title "Primary rays, one thread: our hierarchies and Embree 3"
set ylabel "million rays a second"
unset logscale y
set yrange [0:*]
set key top right
plot "$data" using 1:6 with linespoints lw 2 pt 9 title "Embree", \
     "$data" using 1:5 with linespoints lw 2 pt 7 title "tuned (chapter 17)", \
     "$data" using 1:4 with linespoints lw 2 pt 5 title "plain (chapter 5)"
unset multiplot
GNUPLOT

[ -n "$mesh_output" ] || exit 0
# The tori: triangles, million rays a second plain, tuned and Embree.
awk -F'"' '
  /"name":/ { name = $4 }
  /"real_time":/ && name ~ /^MeshPrimary\/torus-[0-9]+\/(plain|tuned|embree)\/real_time_median$/ &&
    (FILENAME == ARGV[1] || name !~ /embree/) {
    split(name, part, "/"); sub(/torus-/, "", part[2])
    value = $0; sub(/.*: */, "", value); sub(/,$/, "", value)
    time[part[2], part[3]] = value; counts[part[2]] = 1
  }
  END {
    for (n in counts) print n, ((n, "plain") in time ? 360 / time[n, "plain"] : "NaN"),
                             ((n, "tuned") in time ? 360 / time[n, "tuned"] : "NaN"),
                             ((n, "embree") in time ? 360 / time[n, "embree"] : "NaN")
  }' "$json" "$json_tuned" | sort -n > "$meshes"
if [ ! -s "$meshes" ]; then
  echo "plot_sphere_fields.sh: no MeshPrimary medians in $json" >&2
  exit 1
fi
gnuplot <<GNUPLOT
set terminal pngcairo size 560,460 font "sans,11"
set output "$mesh_output"
set title "Primary rays on tori, one thread"
set xlabel "triangles"
set logscale x
set grid
set ylabel "million rays a second"
set yrange [0:*]
set key top right
plot "$meshes" using 1:4 with linespoints lw 2 pt 9 title "Embree", \
     "$meshes" using 1:3 with linespoints lw 2 pt 7 title "tuned (chapter 17)", \
     "$meshes" using 1:2 with linespoints lw 2 pt 5 title "plain (chapter 5)"
GNUPLOT
