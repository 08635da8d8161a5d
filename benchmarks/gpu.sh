#!/usr/bin/env bash
# The engine on a GPU, in one command: build, run the whole test suite on the EGL backend, then
# warm the GPU up, time Sponza pass by pass in five scenarios (a full frame, the same with every
# pass finished before the next, a frame after the light moved, a frame after one step of the
# camera, the tenth frame of a camera moving in small steps) at 256³ and 512³, and write the table
# with the GL renderer's name.
#
#   bash benchmarks/gpu.sh              1920x1080, voxel levels 8 and 9 (on a GPU)
#   bash benchmarks/gpu.sh --small      320x180, voxel levels 6 and 7: the same steps, minutes on llvmpipe
#   options: --no-build (use the build/ already there: an offline machine, see docs/benchmark.md),
#            --no-tests (skip the test suite)
# Environment: VCT_BACKEND (default egl), VCT_ASSET_DIR (where Sponza is; docs/cli.md).
# Writes benchmarks/results/gpu_<renderer>.md and one timings JSON per scenario and level beside it
# (schema: docs/timings.md). <renderer> is made from the GL renderer string, so a dry run on
# llvmpipe never overwrites a GPU's results.
set -euo pipefail
cd "$(dirname "$0")/.."

width=1920 height=1080 levels=(8 9) build=1 tests=1
for option in "$@"; do
    case "$option" in
        --small) width=320 height=180 levels=(6 7) ;;
        --no-build) build=0 ;;
        --no-tests) tests=0 ;;
        *) echo "gpu.sh: unknown option '$option' (use --small, --no-build, --no-tests)" >&2; exit 2 ;;
    esac
done
export VCT_BACKEND="${VCT_BACKEND:-egl}"
[ "$build" = 1 ] && bash .ci/setup
[ -x build/vct ] || { echo "gpu.sh: build/vct is missing; run without --no-build or build it first" >&2; exit 1; }

out=benchmarks/results
mkdir -p "$out"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

tests_line="not run (--no-tests)"
if [ "$tests" = 1 ]; then
    echo "gpu.sh: the test suite on $VCT_BACKEND..." >&2
    if ctest --test-dir build --output-on-failure -j"$(nproc)" >"$scratch/ctest.log" 2>&1; then status=passed; else status=FAILED; fi
    tests_line="$status: $(grep -E 'tests passed|tests failed' "$scratch/ctest.log" | tail -1)"
    echo "gpu.sh: tests $tests_line" >&2
fi

# A GPU idles at a low clock and raises it only under sustained load (docs/benchmark.md, "On a
# GPU"): without this warm-up the first scenarios would be timed at a clock the later ones do not
# have. Twenty full frames keep it busy for seconds.
echo "gpu.sh: warming the GPU up (Sponza, 20 full frames)..." >&2
./build/vct render -q --scene sponza --voxel-levels "${levels[0]}" --width "$width" --height "$height" --frames 20 \
    --full-frames --out "$scratch/warm_up.png"

# full_finished: the full frame again with glFinish after every pass, so that each pass's time is
# its own (without it a pass's time can hold the tail of the one before); its total is not a
# frame's, the others' are.
# camera_moving: the tenth frame of an orbit of 0.01 rad a frame, where the indirect light carried
# over camera moves (--cone-carry) has settled; camera_moved is one 0.05-rad step from a fresh frame.
declare -A scenario_options=(
    [full]="--frames 2 --full-frames"
    [full_finished]="--frames 2 --full-frames --finish-each-pass"
    [light_moved]="--frames 2 --light-path orbit"
    [camera_moved]="--frames 2 --camera-path orbit"
    [camera_moving]="--frames 10 --camera-path orbit --camera-step 0.01"
)
scenarios=(full full_finished light_moved camera_moved camera_moving)
# A scenario that fails (vct refuses an image with non-finite values, say) leaves its column blank
# and is named under the table; the others are still measured, and the script exits non-zero.
failures=()
for level in "${levels[@]}"; do
    for scenario in "${scenarios[@]}"; do
        echo "gpu.sh: Sponza ${width}x${height}, 2^$level voxels, $scenario..." >&2
        # shellcheck disable=SC2086
        if ! ./build/vct render -q --scene sponza --voxel-levels "$level" --width "$width" --height "$height" \
            ${scenario_options[$scenario]} --out "$scratch/$scenario.png" --timings "$scratch/${scenario}_L$level.json" \
            2>"$scratch/error.log"; then
            failures+=("$scenario 2^$level: $(tail -1 "$scratch/error.log")")
            rm -f "$scratch/${scenario}_L$level.json"
        fi
        cat "$scratch/error.log" >&2
    done
done
first_json=$(ls "$scratch"/*.json 2>/dev/null | head -1)
[ -n "$first_json" ] || { echo "gpu.sh: every scenario failed: ${failures[*]}" >&2; exit 1; }

# The GL renderer string names the results: "NVIDIA H100 80GB HBM3/PCIe/SSE2" -> nvidia_h100_80gb_hbm3.
renderer=$(sed -n 's/^ *"renderer": "\(.*\)",*$/\1/p' "$first_json" | head -1)
label=$(echo "${renderer%%/*}" | tr 'A-Z' 'a-z' | sed 's/[^a-z0-9]\{1,\}/_/g; s/^_//; s/_$//' | cut -c1-40)
[ "$width" = 1920 ] || label="${label}_small"
for level in "${levels[@]}"; do
    for scenario in "${scenarios[@]}"; do  # a failed scenario's JSON from an earlier run goes too
        json="${scenario}_L$level.json"
        if [ -f "$scratch/$json" ]; then cp "$scratch/$json" "$out/gpu_${label}_$json"; else rm -f "$out/gpu_${label}_$json"; fi
    done
done

# Per-pass GPU milliseconds from a timings JSON (pretty-printed, keys sorted: each element of
# "passes" is cpu_ms, gpu_ms, name), and the frame's total: "name ms" lines, "total ms" last.
pass_times() {
    awk '
        /^  "passes": \[/ { inside = 1; next }
        inside && /^  \]/ { inside = 0 }
        inside && /"gpu_ms":/ { gsub(/[",]/, ""); gpu = $2 }
        inside && /"name":/ { gsub(/[",]/, ""); print $2, gpu }
        /^  "total_gpu_ms":/ { gsub(/[",]/, ""); total = $2 }
        END { print "total", total }
    ' "$1"
}

table="$out/gpu_${label}.md"
{
    echo "# vct on $renderer"
    echo
    echo "Written by \`benchmarks/gpu.sh$([ "$width" = 1920 ] || echo ' --small')\` on $(date -u +%Y-%m-%d) ($VCT_BACKEND backend)."
    echo "Sponza ${width}x${height}, the second frame of each scenario (the first builds everything; a"
    echo "full frame re-runs every pass as if the geometry changed; camera_moving is the tenth frame of"
    echo "0.01-rad steps of the camera instead; full_finished is the same frame as full with"
    echo "glFinish after every pass, whose per-pass times are each pass's own but whose total is not a"
    echo "frame's). GPU milliseconds per pass from timer queries; a pass the scenario does not need is"
    echo "skipped (blank). Test suite: $tests_line."
    echo
    passes=$(for json in "$scratch"/full_L*.json "$first_json"; do if [ -f "$json" ]; then pass_times "$json"; fi; done |
        awk '$1 != "total" && !seen[$1]++ { print $1 }')
    header="| pass |" rule="|---|"
    for level in "${levels[@]}"; do
        for scenario in "${scenarios[@]}"; do
            header="$header $scenario 2^$level |"
            rule="$rule---:|"
        done
    done
    echo "$header"
    echo "$rule"
    for pass in $passes total; do
        row="| $pass |"
        for level in "${levels[@]}"; do
            for scenario in "${scenarios[@]}"; do
                ms=""
                [ -f "$scratch/${scenario}_L$level.json" ] &&
                    ms=$(pass_times "$scratch/${scenario}_L$level.json" | awk -v p="$pass" '$1 == p { printf "%.3f", $2 }')
                row="$row ${ms} |"
            done
        done
        echo "$row"
    done
    echo
    echo "Timings JSONs: \`gpu_${label}_<scenario>_L<levels>.json\` beside this file."
    if [ ${#failures[@]} -gt 0 ]; then
        echo
        echo "Failed (blank columns):"
        for failure in "${failures[@]}"; do echo "- $failure"; done
    fi
} >"$table"
echo "gpu.sh: wrote $table" >&2
cat "$table"
[ ${#failures[@]} -eq 0 ]
