#!/usr/bin/env bash
# On an offline, bare GPU machine (like benchmarks/gpu_device.sh, with .gl/ and .gpu/ carried):
# the same Sponza frames timed under two or more environment settings side by side, so that a
# change the engine makes per device (VCT_CONE_LANES, VCT_NODE_GROUP_SIZE, ...) is measured on
# one warm GPU in one run, the settings taking turns.
#
#   bash benchmarks/gpu_device_compare.sh [--rounds N] [--here] [--options "ARGS"] SETTING SETTING...
#   SETTING: space-separated NAME=VALUE pairs for `env`, or '-' for none (vct's own choice)
#   --here: a dry run on this machine's build/ (no unpacking), at 320x180 and 64³/128³
#   --options: more `vct render` options for every frame (e.g. "--bounces 2")
#
# After twenty untimed full frames (the clock's ramp, docs/benchmark.md "On a GPU") and one untimed
# frame per setting, each round renders, for every setting in turn, the second frame of Sponza
# 1920x1080 after the camera moved and after the light moved, at 256³ and 512³. Writes $OUT/gpu_compare/ (default /tmp/vct_gpu):
# compare.md, the median GPU milliseconds of each pass that differs and of the frame per setting,
# with whether the settings' images are bit-identical (md5 of the HDR output); every timings JSON;
# steps.log. Archived as $OUT/gpu_compare.tar after every step.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$PWD
rounds=3 here=0 options=""
while [ $# -gt 0 ]; do
    case "$1" in
        --rounds) rounds=$2; shift 2 ;;
        --here) here=1; shift ;;
        --options) options=$2; shift 2 ;;
        *) break ;;
    esac
done
[ $# -ge 2 ] || { echo "usage: gpu_device_compare.sh [--rounds N] SETTING SETTING... ('-' for none)" >&2; exit 2; }
settings=("$@")
out=${OUT:-/tmp/vct_gpu}/gpu_compare
mkdir -p "$out"
step() {
    echo "== $*" | tee -a "$out/steps.log"
    (cd "$out/.." && tar -cf gpu_compare.tar.part gpu_compare && mv gpu_compare.tar.part gpu_compare.tar)
}

width=1920 height=1080 levels=(8 9)
if [ "$here" = 1 ]; then
    width=320 height=180 levels=(6 7)
    export VCT_BACKEND=${VCT_BACKEND:-egl}
else
    . benchmarks/gpu_device_setup.sh
fi

render() {  # setting, then vct render's options
    local setting=$1
    shift
    local assignments=()
    [ "$setting" != - ] && read -ra assignments <<<"$setting"
    env "${assignments[@]}" timeout 60 build/vct render -q --scene sponza --width "$width" --height "$height" "$@"
}

clock() { nvidia-smi --query-gpu=clocks.sm --format=csv,noheader 2>/dev/null | head -1; }
before=$(clock)
render - --voxel-levels "${levels[0]}" --frames 20 --full-frames --out "$out/warm_up.png" >/dev/null 2>&1
step "warmed up (SM clock $before -> $(clock))"

declare -A scenario_options=([camera_moved]="--camera-path orbit" [light_moved]="--light-path orbit")
# On the H200 the first frames after the warm-up were slow in every pass, twice (a G-buffer of
# 49–82 ms against 14.9): each setting first renders once untimed.
for setting in "${settings[@]}"; do
    # shellcheck disable=SC2086
    render "$setting" --voxel-levels "${levels[0]}" --frames 2 --camera-path orbit $options --out "$out/untimed.png" >/dev/null 2>&1
done
rm -f "$out/untimed.png"
for round in $(seq "$rounds"); do
    for level in "${levels[@]}"; do
        for scenario in camera_moved light_moved; do
            for index in "${!settings[@]}"; do
                name="s${index}_${scenario}_L${level}_r${round}"
                # shellcheck disable=SC2086
                render "${settings[$index]}" --voxel-levels "$level" --frames 2 ${scenario_options[$scenario]} $options \
                    --out "$out/$name.png" --hdr-out "$out/$name.pfm" --timings "$out/$name.json" >"$out/$name.log" 2>&1 ||
                    step "FAILED: ${settings[$index]} $scenario 2^$level: $(tail -1 "$out/$name.log")"
                # Only the image's digest is kept: the images would not travel back.
                md5sum <"$out/$name.pfm" 2>/dev/null | cut -d' ' -f1 >"$out/$name.md5"
                rm -f "$out/$name.pfm" "$out/$name.png"
            done
        done
    done
    step "round $round done (SM clock $(clock))"
done

# Medians per setting, and whether each setting's image matches the first's.
python3 - "$out" "$rounds" "$width" "$height" "${levels[*]}" "$options" "${settings[@]}" >"$out/compare.md" <<'EOF'
import json, statistics, sys
out, rounds, width, height = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
levels, options, settings = [int(l) for l in sys.argv[5].split()], sys.argv[6], sys.argv[7:]
print("# The same Sponza frames under each setting (%sx%s%s, second frames, GPU ms, median of %d)"
      % (width, height, ", " + options if options else "", rounds))
print()
for i, s in enumerate(settings):
    print("- s%d: `%s`" % (i, s if s != "-" else "(vct's own choice)"))
print()
for level in levels:
    for scenario in ("camera_moved", "light_moved"):
        runs = {}
        for i in range(len(settings)):
            passes, totals, digests = {}, [], set()
            for r in range(1, rounds + 1):
                name = "%s/s%d_%s_L%d_r%d" % (out, i, scenario, level, r)
                try:
                    d = json.load(open(name + ".json"))
                    digests.add(open(name + ".md5").read().strip())
                except (OSError, ValueError):
                    continue
                totals.append(d["total_gpu_ms"])
                for p in d["passes"]:
                    passes.setdefault(p["name"], []).append(p["gpu_ms"])
            runs[i] = (passes, totals, digests)
        print("## %s, 2^%d" % (scenario, level))
        print()
        print("| pass | " + " | ".join("s%d" % i for i in runs) + " |")
        print("|---|" + "---:|" * len(runs))
        names = list(dict.fromkeys(n for p, _, _ in runs.values() for n in p))  # the frame's order
        for n in names:
            medians = [statistics.median(runs[i][0][n]) if runs[i][0].get(n) else 0.0 for i in runs]
            if max(medians) > 0.05:
                print("| %s | %s |" % (n, " | ".join("%.3f" % m for m in medians)))
        print("| **frame** | %s |" % " | ".join("%.3f" % statistics.median(t) if t else "-" for _, t, _ in runs.values()))
        first = runs[0][2]
        print("| same bits as s0 | %s |" % " | ".join(
            ("yes" if d == first and len(d) == 1 else "no (%d hashes)" % len(d | first)) for _, _, d in runs.values()))
        print()
EOF
rm -f "$out/warm_up.png"
step "compare.md written"
cat "$out/compare.md"
