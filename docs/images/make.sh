#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders the README's pictures with the editor's offscreen mode:
#   docs/images/make.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
meshfair="$root/${1:-build}/app/meshfair"
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=2

"$meshfair" --offscreen "$root/assets/bunny.obj" --ui --size 1280x800 \
    --screenshot "$out/editor.png"

# A quad torus (24 x 12 quads), written as OBJ, seen from above and to the side.
awk 'BEGIN {
    pi = atan2(0, -1); nu = 24; nv = 12; R = 1; r = 0.4
    for (j = 0; j < nv; ++j) for (i = 0; i < nu; ++i) {
        u = 2 * pi * i / nu; v = 2 * pi * j / nv
        printf "v %.9f %.9f %.9f\n", (R + r * cos(v)) * cos(u), (R + r * cos(v)) * sin(u), r * sin(v)
    }
    for (j = 0; j < nv; ++j) for (i = 0; i < nu; ++i) {
        a = j * nu + i; b = j * nu + (i + 1) % nu; c = ((j + 1) % nv) * nu + (i + 1) % nu
        d = ((j + 1) % nv) * nu + i
        printf "f %d %d %d %d\n", a + 1, b + 1, c + 1, d + 1
    }
}' >"$tmp/torus.obj"
cat >"$tmp/view.json" <<'VIEW'
{"target": [0, 0, 0], "distance": 4.2, "rotation": [0.88, -0.42, 0.12, 0.18],
 "projection": "perspective", "fov_y_degrees": 40, "scene_center": [0, 0, 0],
 "scene_radius": 1.5}
VIEW
"$meshfair" --offscreen "$tmp/torus.obj" --view "$tmp/view.json" --mode flat,wire \
    --size 640x400 --screenshot "$out/torus-wireframe.png"
# A region of a noisy bunny's flank smoothed live, with a centroid set, pins and anchors
# of their own weight, the energy plot and the legend.
cat >"$tmp/session.json" <<'SCRIPT'
{"actions": [
  {"noise": 0.3, "seed": 5}, {"tool": "rectangle"}, {"elements": "faces"},
  {"drag": [[430, 250], [700, 520]]}, {"create_set": "region", "name": "flank"},
  {"drag": [[520, 330], [560, 370]]}, {"create_set": "centroid"},
  {"elements": "vertices"}, {"drag": [[600, 420], [625, 445]]}, {"create_set": "pin"},
  {"drag": [[470, 430], [500, 460]]}, {"create_set": "anchor", "name": "stiff"},
  {"select": "clear"},
  {"solver": {"iterations_per_frame": 5, "centroid_mu": 4}}, {"play": 12},
  {"tool": "brush"}, {"move": [330, 330]}
]}
SCRIPT
"$meshfair" --offscreen "$root/assets/bunny.obj" --ui --size 1280x800 \
    --script "$tmp/session.json" --screenshot "$out/editor-session.png"
echo "wrote $out/editor.png, $out/editor-session.png and $out/torus-wireframe.png"
