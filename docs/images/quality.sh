#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Renders docs/quality.md's before/after strips from the meshes meshfair-quality writes:
#   build/app/meshfair-quality --write-meshes build/quality-meshes ...
#   docs/images/quality.sh [BUILD_DIR] [MESHES_DIR]   (defaults: build, BUILD_DIR/quality-meshes)
# Each strip: the clean mesh, the noisy one, then the methods, left to right, each rendered
# offscreen by the editor from one camera (the clean mesh's framing), labelled.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build="$root/${1:-build}"
meshes=${2:-$build/quality-meshes}
meshfair="$build/app/meshfair"
out="$root/docs/images"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export GALLIUM_DRIVER=llvmpipe LP_NUM_THREADS=2

# strip NAME MESH CASE VIEW_ROTATION METHOD...: docs/images/quality-NAME.png
strip() {
    local name=$1 mesh=$2 case=$3 rotation=$4
    shift 4
    local tiles=() k=0
    "$meshfair" --offscreen "$meshes/$mesh/clean.obj" --size 360x300 \
        --save-view "$tmp/framed.json" --screenshot "$tmp/framing.png" >/dev/null
    python3 - "$tmp/framed.json" "$rotation" "$tmp/view.json" <<'PY'
import json, sys
view = json.load(open(sys.argv[1]))
view["rotation"] = json.loads(sys.argv[2])
json.dump(view, open(sys.argv[3], "w"))
PY
    for method in clean noisy "$@"; do
        local file="$meshes/$mesh/$case/$method.obj"
        [ "$method" = clean ] && file="$meshes/$mesh/clean.obj"
        "$meshfair" --offscreen "$file" --view "$tmp/view.json" --mode smooth,boundary \
            --size 360x300 --screenshot "$tmp/$k.png" >/dev/null
        convert "$tmp/$k.png" -gravity north -fill white -pointsize 18 \
            -annotate +0+6 "$method" "$tmp/$k.png"
        tiles+=("$tmp/$k.png")
        k=$((k + 1))
    done
    convert "${tiles[@]}" +append "$out/quality-$name.png"
    echo "wrote $out/quality-$name.png"
}

strip cad-part cad-part gaussian-normal-0.4 '[0.86, -0.28, 0.36, 0.21]' bilateral sdfilter denoise
strip scan-patch scan-patch gaussian-scan-0.4 '[0.93, -0.35, 0.05, 0.1]' bilateral sdfilter relax denoise
strip bunny bunny gaussian-normal-0.4 '[1, 0, 0, 0]' bilateral sdfilter relax denoise-organic
