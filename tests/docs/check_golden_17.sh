#!/usr/bin/env bash
# Chapter 17 draws what chapter 5 draws: its golden images are chapter 5's, byte for
# byte, but for the cost view of its own, tuned hierarchy (its README says so).
# Usage: check_golden_17.sh SOURCE_DIR
set -euo pipefail
cd "$1/tests/golden"
own=sphere-field-10000-tests.png
failed=0
for image in 05-raytracer-extensions/*.png 17-fast-hierarchy/*.png; do
  name=$(basename "$image")
  [ "$name" = "$own" ] && continue
  if ! cmp -s "05-raytracer-extensions/$name" "17-fast-hierarchy/$name"; then
    echo "FAIL: $name: chapter 17's golden image is not chapter 5's (or one of them is missing)"
    failed=1
  fi
done
if cmp -s "05-raytracer-extensions/$own" "17-fast-hierarchy/$own"; then
  echo "FAIL: $own: chapter 17's hierarchy draws the same heat map as chapter 5's"
  failed=1
fi
[ "$failed" = 0 ] && echo "chapter 17's golden images are chapter 5's, but for its own heat map $own"
exit "$failed"
