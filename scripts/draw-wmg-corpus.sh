#!/bin/sh
# Draws every corpora/wmg scenery for docs/wmg-semantics.md ("The corpus sceneries"): the map each
# file builds at the centre of its space, its actors where a run starts them and its roads' names,
# as `scenfuzz map FILE --svg` draws them. Run from the repository's root after a change to the
# corpus, the WMG translation or the map drawing; tests/fuzz/wmg_pictures_test.cpp checks that
# the pictures are current.
set -eu
scenfuzz=${1:-build/ci/bin/scenfuzz}
mkdir -p docs/pictures/wmg
for file in corpora/wmg/*.sdl; do
  name=$(basename "$file" .sdl)
  "$scenfuzz" map "$file" --svg "docs/pictures/wmg/$name.svg" > /dev/null
done
