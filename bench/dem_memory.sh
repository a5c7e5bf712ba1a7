#!/bin/sh
# bench/dem_memory.sh: the memory a DEM cell takes once meshed (lib/scene/dem.cpp's
# kBytesPerCell, with which a DEM too large for the machine is refused before it is
# read). find_min_max_view_angle loads an N x N ASCII grid as its scene (the mesh, its
# facet records and Embree's BVH) for N = 300 and 1200; the peak resident memory of
# each (GNU time's %M), and the difference over the difference in cells, are printed.
#
#   bench/dem_memory.sh [BIN_DIR]    (default build/bin; needs /usr/bin/time)
set -eu
src=$(cd "$(dirname "$0")/.." && pwd)
bin=$(cd "${1:-$src/build/bin}" && pwd)
[ -x /usr/bin/time ] || { echo "dem_memory.sh: needs GNU time (apt-get install time)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/tests/data/scene/flat.prj" "$work/g.prj"
peak_kib() {  # peak_kib N: KiB of resident memory at the peak, loading an N x N DEM
    awk -v n="$1" 'BEGIN { printf "ncols %d\nnrows %d\nxllcorner -77.7\nyllcorner 43.0\ncellsize 0.00001\n", n, n
        for (r = 0; r < n; r++) { s = ""; for (c = 0; c < n; c++) s = s sprintf("%.1f ", (r * 7 + c * 3) % 50); print s } }' \
        > "$work/g.asc"
    /usr/bin/time -f %M -o "$work/rss" "$bin/find_min_max_view_angle" --origin 43.0,-77.7 \
        "$src/tests/data/trace/box.adv" "$work/g.asc" --material-id 1 > /dev/null
    cat "$work/rss"
}
small=$(peak_kib 300)
large=$(peak_kib 1200)
echo "DEM 300 x 300: peak $small KiB; 1200 x 1200: peak $large KiB" \
    "; per cell: $(echo "$small $large" | awk '{ printf "%.0f", ($2 - $1) * 1024 / (1199 * 1199 - 299 * 299) }') bytes"
