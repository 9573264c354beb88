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

# strip NAME MESH CASE ROTATION ZOOM METHOD...: docs/images/quality-NAME.png, the camera
# turned by the quaternion ROTATION ([w, x, y, z]) and brought ZOOM times closer.
strip() {
    local name=$1 mesh=$2 case=$3 rotation=$4 zoom=$5
    shift 5
    local tiles=() k=0
    "$meshfair" --offscreen "$meshes/$mesh/clean.obj" --size 480x360 \
        --save-view "$tmp/framed.json" --screenshot "$tmp/framing.png" >/dev/null
    python3 - "$tmp/framed.json" "$rotation" "$zoom" "$tmp/view.json" <<'PY'
import json, sys
view = json.load(open(sys.argv[1]))
view["rotation"] = json.loads(sys.argv[2])
view["distance"] /= float(sys.argv[3])
json.dump(view, open(sys.argv[4], "w"))
PY
    for method in clean noisy "$@"; do
        local file="$meshes/$mesh/$case/$method.obj"
        [ "$method" = clean ] && file="$meshes/$mesh/clean.obj"
        "$meshfair" --offscreen "$file" --view "$tmp/view.json" --mode smooth,boundary \
            --size 480x360 --screenshot "$tmp/$k.png" >/dev/null
        convert "$tmp/$k.png" -gravity north -fill white -font DejaVu-Sans -pointsize 18 \
            -annotate +0+6 "$method" "$tmp/$k.png"
        tiles+=("$tmp/$k.png")
        k=$((k + 1))
    done
    convert "${tiles[@]}" +append "$out/quality-$name.png"
    echo "wrote $out/quality-$name.png"
}

strip cad-part cad-part gaussian-normal-0.4 '[0.86, -0.28, 0.36, 0.21]' 1.1 \
    bilateral sdfilter denoise
strip scan-patch scan-patch gaussian-scan-0.4 '[0.82, -0.57, 0, 0]' 1.7 \
    bilateral sdfilter relax denoise
strip bunny bunny gaussian-normal-0.4 '[1, 0, 0, 0]' 1.5 bilateral sdfilter relax denoise-organic
