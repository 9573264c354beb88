# shellcheck shell=bash disable=SC2034 # the arrays are for the sourcing scripts
# SPDX-License-Identifier: MIT
# Shared by .ci/fuzz.sh and tests/fuzz/campaign.sh (source it; it sets no shell options):
# the target list, the clang builds, the dictionaries and the seed directories.

fuzz_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
fuzz_dir="$fuzz_root/tests/fuzz"
fuzz_build="${MESHFAIR_FUZZ_BUILD_DIR:-$fuzz_root/build-fuzz}"
fuzz_cov_build="${MESHFAIR_FUZZ_COVERAGE_DIR:-$fuzz_root/build-cov}"

FUZZ_TARGETS=(fuzz_obj fuzz_off fuzz_ply_ascii fuzz_ply_le fuzz_ply_be fuzz_stl_ascii
    fuzz_stl_binary fuzz_front_door fuzz_recipe fuzz_roundtrip fuzz_solver fuzz_script
    fuzz_recovery)

# The libFuzzer options of every run, and of fuzzing runs (replays run each file whole;
# the targets ignore inputs beyond 64 KiB themselves).
FUZZ_REPLAY_OPTIONS=(-rss_limit_mb=256 -timeout=2)
FUZZ_OPTIONS=("${FUZZ_REPLAY_OPTIONS[@]}" -max_len=65536)
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# ASan's default 256 MB quarantine of freed memory alone would reach -rss_limit_mb.
export ASAN_OPTIONS="${ASAN_OPTIONS:-quarantine_size_mb=32}"

fuzz_cxx() {
    local c
    for c in "${CXX_FUZZ:-}" clang++-14 clang++; do
        if [ -n "$c" ] && command -v "$c" >/dev/null; then
            echo "$c"
            return
        fi
    done
    echo "fuzz: clang++-14 not found (apt-get install clang-14 libclang-rt-14-dev)" >&2
    return 1
}

# fuzz_build_engine DIR ENGINE BUILD_TYPE: configures (once) and builds the fuzz targets
# and the seed generator; incremental. A DIR configured by .ci/sanitize.sh (the sanitized
# tests' build, MESHFAIR_FUZZ_ENGINE=shared) keeps its configuration: only built.
fuzz_build_engine() {
    local dir=$1 engine=$2 type=$3 cxx
    if grep -q '^MESHFAIR_FUZZ_ENGINE:STRING=shared$' "$dir/CMakeCache.txt" 2>/dev/null; then
        cmake --build "$dir" -j"$(nproc)" --target fuzz_all
        return
    fi
    cxx=$(fuzz_cxx) || return 1
    mkdir -p "$dir"
    cmake -S "$fuzz_root" -B "$dir" -DCMAKE_BUILD_TYPE="$type" -DCMAKE_CXX_COMPILER="$cxx" \
        -DMESHFAIR_FUZZ=ON -DMESHFAIR_FUZZ_ENGINE="$engine" -DMESHFAIR_BUILD_TESTS=OFF \
        -DCMAKE_UNITY_BUILD=ON -DMESHFAIR_WERROR=ON -DMESHFAIR_BUILD_PYTHON=OFF \
        >"$dir/configure.log" 2>&1 || {
        cat "$dir/configure.log" >&2
        return 1
    }
    cmake --build "$dir" -j"$(nproc)" --target fuzz_all
}

fuzz_build_libfuzzer() { fuzz_build_engine "$fuzz_build" libfuzzer RelWithDebInfo; }
fuzz_build_coverage() { fuzz_build_engine "$fuzz_cov_build" coverage Debug; }

fuzz_binary() { echo "$1/tests/fuzz/$2"; }

# The -dict file of a target; the mesh targets that read every format get all four.
fuzz_dict() {
    case $1 in
        fuzz_obj) echo "$fuzz_dir/dict/obj.dict" ;;
        fuzz_off) echo "$fuzz_dir/dict/off.dict" ;;
        fuzz_ply_*) echo "$fuzz_dir/dict/ply.dict" ;;
        fuzz_stl_*) echo "$fuzz_dir/dict/stl.dict" ;;
        fuzz_recipe) echo "$fuzz_dir/dict/recipe.dict" ;;
        fuzz_script) echo "$fuzz_dir/dict/script.dict" ;;
        fuzz_recovery) echo "$fuzz_dir/dict/recovery.dict" ;;
        *)
            mkdir -p "$fuzz_build/dict"
            cat "$fuzz_dir"/dict/{obj,off,ply,stl}.dict >"$fuzz_build/dict/mesh.dict"
            echo "$fuzz_build/dict/mesh.dict"
            ;;
    esac
}

# Writes the library-generated seeds (small meshes in every format and encoding).
fuzz_generate() {
    rm -rf "$fuzz_build/generated"
    "$(fuzz_binary "$fuzz_build" fuzz_seedgen)" "$fuzz_build/generated" >/dev/null
}

# _fuzz_copy TAG PREFIX OUT DIR...: copies every file under each DIR (absent ones are
# skipped) into OUT as TAG-<parent>_<dir>-<path with / as _>, with the bytes PREFIX (a
# printf format) first.
_fuzz_copy() {
    local tag=$1 prefix=$2 out=$3 dir file name source
    shift 3
    for dir in "$@"; do
        [ -d "$dir" ] || continue
        source="$(basename "$(dirname "$dir")")_$(basename "$dir")"
        while IFS= read -r -d '' file; do
            name="$tag-$source-${file#"$dir"/}"
            name=${name//\//_}
            if [ -z "$prefix" ]; then
                cp "$file" "$out/$name"
            else
                # shellcheck disable=SC2059 # the prefix is a printf format on purpose
                {
                    printf "$prefix"
                    cat "$file"
                } >"$out/$name"
            fi
        done < <(find "$dir" -type f ! -name '*.md' -print0 | sort -z)
    done
}

# _fuzz_format_dirs FORMAT: sets FUZZ_DIRS to the directories of one format's mesh files
# from every source: tests/adversarial/<format>/ (if present), the committed corpus of
# that format's targets and the generated seeds.
_fuzz_format_dirs() {
    local adv="$fuzz_root/tests/adversarial" c="$fuzz_dir/corpus" g="$fuzz_build/generated"
    case $1 in
        obj) FUZZ_DIRS=("$adv/obj" "$c/fuzz_obj" "$g/obj") ;;
        off) FUZZ_DIRS=("$adv/off" "$c/fuzz_off" "$g/off") ;;
        ply) FUZZ_DIRS=("$adv/ply" "$c/fuzz_ply_ascii" "$c/fuzz_ply_le" "$c/fuzz_ply_be"
            "$g/ply_ascii" "$g/ply_le" "$g/ply_be") ;;
        stl) FUZZ_DIRS=("$adv/stl" "$c/fuzz_stl_ascii" "$c/fuzz_stl_binary" "$g/stl_ascii"
            "$g/stl_binary") ;;
    esac
}

# fuzz_seeds TARGET OUT: (re)builds the seed directory of a target. Needs fuzz_generate.
fuzz_seeds() {
    local t=$1 out=$2 adv="$fuzz_root/tests/adversarial" c="$fuzz_dir/corpus/$1"
    local g="$fuzz_build/generated" f k
    rm -rf "$out"
    mkdir -p "$out"
    _fuzz_copy committed '' "$out" "$c"
    case $t in
        fuzz_obj | fuzz_off) _fuzz_copy adversarial '' "$out" "$adv/${t#fuzz_}" ;;
        fuzz_ply_*) _fuzz_copy adversarial '' "$out" "$adv/ply" ;;
        fuzz_stl_*) _fuzz_copy adversarial '' "$out" "$adv/stl" ;;
        fuzz_recipe) _fuzz_copy adversarial '' "$out" "$adv/recipe" "$fuzz_root/assets/recipes" ;;
        fuzz_script) _fuzz_copy tests '' "$out" "$fuzz_root/tests/app/editor/scripts" ;;
        fuzz_recovery) _fuzz_copy generated '' "$out" "$g/recovery" ;;
    esac
    case $t in
        fuzz_obj | fuzz_off) _fuzz_copy generated '' "$out" "$g/${t#fuzz_}" ;;
        fuzz_ply_ascii | fuzz_ply_le | fuzz_ply_be)
            _fuzz_copy generated '' "$out" "$g/${t#fuzz_}" "$g/ply_body_${t#fuzz_ply_}"
            ;;
        fuzz_stl_ascii | fuzz_stl_binary) _fuzz_copy generated '' "$out" "$g/${t#fuzz_}" ;;
        fuzz_front_door)
            # The first byte picks the reader: '0' OBJ, '1' OFF, '2' PLY, '3' STL.
            k=0
            for f in obj off ply stl; do
                _fuzz_format_dirs $f
                _fuzz_copy "$f" "$k" "$out" "${FUZZ_DIRS[@]}"
                k=$((k + 1))
            done
            ;;
        fuzz_roundtrip)
            for f in obj off ply stl; do
                _fuzz_format_dirs $f
                _fuzz_copy "$f" '' "$out" "${FUZZ_DIRS[@]}"
            done
            ;;
        fuzz_solver)
            # The first byte picks the recipe's variants: none, and all of them.
            for f in obj off ply stl; do
                _fuzz_format_dirs $f
                _fuzz_copy "$f-00" '\000' "$out" "${FUZZ_DIRS[@]}"
                _fuzz_copy "$f-ff" '\377' "$out" "${FUZZ_DIRS[@]}"
            done
            ;;
    esac
}

# fuzz_stat LOG NAME: a final statistic of a -print_final_stats=1 run ("" if absent).
fuzz_stat() {
    sed -n "s/^stat::$2: *\([0-9]*\).*/\1/p" "$1" | tail -1
}

# fuzz_artifact LOG: the reproducer libFuzzer wrote, if any (slow units do not count).
fuzz_artifact() {
    sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$1" | grep -v '/slow-unit-' | tail -1 || true
}

# fuzz_crash_summary LOG: the lines that say what went wrong, and the top of the stack.
fuzz_crash_summary() {
    grep -a -E '^(==[0-9]+==ERROR|SUMMARY:|fuzz target check failed|.*runtime error:|==[0-9]+== ERROR: libFuzzer|terminate called|  what\(\)|standalone: crashed)' "$1" | head -8 || true
    grep -a -E '^ +#[0-9]+ ' "$1" |
        grep -a -v -E 'libFuzzer|compiler-rt|/usr/include|/lib/gcc/|libc\.so|__libc_start|_start ' |
        head -8 || true
}

# fuzz_replay BINARY LOG FILE...: runs the target once on each file (a libFuzzer binary,
# or the coverage build's plain driver). After a crash it goes on with the next file.
# Prints each file that crashed; returns 1 if any did.
fuzz_replay() {
    local bin=$1 log=$2 start=0 failed=0 crashed i
    shift 2
    local files=("$@")
    : >"$log"
    while [ "$start" -lt "${#files[@]}" ]; do
        if "$bin" "${FUZZ_REPLAY_OPTIONS[@]}" "${files[@]:start}" >>"$log" 2>&1; then
            break
        fi
        failed=1
        crashed=$(sed -n -e 's/^Running: //p' \
            -e 's/^standalone: crashed on \(.*\) (signal [0-9]*)$/\1/p' "$log" | tail -1)
        for ((i = start; i < ${#files[@]}; i++)); do
            [ "${files[i]}" = "$crashed" ] && break
        done
        echo "${crashed:-(unknown input)}"
        start=$((i + 1))
    done
    return "$failed"
}
