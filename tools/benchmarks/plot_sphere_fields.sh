#!/usr/bin/env bash
# Plots the SphereFieldSmall medians of Google Benchmark's JSON (scripts/benchmark):
# render time against the number of spheres, with and without the hierarchy.
# Usage: plot_sphere_fields.sh BENCHMARK.json OUTPUT.png
set -euo pipefail
json=$1
output=$2
data=$(mktemp)
trap 'rm -f "$data"' EXIT

# Each benchmark is an object with "name" and "real_time" on lines of their own.
awk -F'"' '
  /"name":/ { name = $4 }
  /"real_time":/ && name ~ /^SphereFieldSmall\/[0-9]+\/(bvh|no-bvh)\/real_time_median$/ {
    split(name, part, "/")
    value = $0; sub(/.*: */, "", value); sub(/,$/, "", value)
    time[part[2], part[3]] = value; counts[part[2]] = 1
  }
  END {
    for (n in counts) print n, ((n, "bvh") in time ? time[n, "bvh"] : "NaN"),
                             ((n, "no-bvh") in time ? time[n, "no-bvh"] : "NaN")
  }' "$json" | sort -n > "$data"

if [ ! -s "$data" ]; then
  echo "plot_sphere_fields.sh: no SphereFieldSmall medians in $json" >&2
  exit 1
fi

gnuplot <<GNUPLOT
set terminal pngcairo size 720,480 font "sans,11"
set output "$output"
set title "Chapter 5: the sphere fields at 150x150, one thread"
set xlabel "spheres"
set ylabel "render time (ms)"
set logscale xy
set key top left
set grid
set rmargin 6
plot "$data" using 1:3 with linespoints lw 2 pt 7 title "without the hierarchy", \
     "$data" using 1:2 with linespoints lw 2 pt 5 title "with the hierarchy"
GNUPLOT
