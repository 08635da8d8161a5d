#!/usr/bin/env bash
# What a frame costs when only part of the scene changed (DESIGN §4, issue "skip what the scene
# doesn't need"): Sponza, the second frame of each scenario, as a ratio of a full frame measured in
# the same run, plus the work saved inside passes.
#   bash benchmarks/incremental.sh [levels] [width] [height]     (default: 8 640 360)
set -euo pipefail
cd "$(dirname "$0")/.."
level="${1:-8}"
width="${2:-640}"
height="${3:-360}"
backend="${VCT_BACKEND:-osmesa}"
bash .ci/setup >/dev/null
out=benchmarks/results
mkdir -p "$out"
common=(-q --backend "$backend" --scene sponza --voxel-levels "$level" --width "$width" --height "$height")
# The second frame of each, but camera moving: the tenth frame of an orbit of 0.01 rad a frame
# (the eye about 20 cm a frame on Sponza), where light carried over camera moves has settled.
declare -A options=(
  [full]="--frames 2 --full-frames"
  [nothing_changed]="--frames 2"
  [camera_moved]="--frames 2 --camera-path orbit"
  [camera_moving]="--frames 10 --camera-path orbit --camera-step 0.01"
  [light_moved]="--frames 2 --light-path orbit"
)
for scenario in full nothing_changed camera_moved camera_moving light_moved; do
  echo "scenario $scenario..." >&2
  # shellcheck disable=SC2086
  ./build/vct render "${common[@]}" ${options[$scenario]} --out "/tmp/vct_incremental_$scenario.png" \
    --timings "$out/incremental_$scenario.json"
done
/usr/bin/python3 - "$out" "$level" "$width" "$height" <<'PY'
import json, sys, datetime
out, level, width, height = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
names = ["full", "nothing_changed", "camera_moved", "camera_moving", "light_moved"]
runs = {n: json.load(open(f"{out}/incremental_{n}.json")) for n in names}
full = runs["full"]
def cost(r):  # GPU span of the frame; on llvmpipe compute runs at submission, so take the larger of span and Σ CPU
    return max(r["total_gpu_ms"], r["total_cpu_ms"])
tag = "llvmpipe" if "llvmpipe" in full["renderer"] else full["renderer"].split()[0].lower()
lines = [f"# Incremental frames: Sponza, {2**level}³ voxels, {width}×{height}", "",
         f"Renderer: {full['renderer']} ({full['backend']}), measured {datetime.date.today()}. Second frame of each "
         "scenario (camera moving: the tenth frame of a 0.01-rad-a-frame orbit; camera moved: one 0.05-rad step); "
         "cost = max(GPU span, Σ pass CPU time) because llvmpipe runs compute at submission. Produced by "
         "`bash benchmarks/incremental.sh`.", "",
         "| scenario | passes that ran | frame ms | ratio to a full frame |", "|---|---|---|---|"]
for n in names:
    r = runs[n]
    ran = [p["name"] for p in r["passes"]]
    lines.append(f"| {n.replace('_', ' ')} | {', '.join(ran) if ran else '(none)'} | {cost(r):.1f} | {cost(r) / cost(full):.3f} |")
s = runs["light_moved"]["statistics"]
c = runs["camera_moved"]["statistics"]
m = runs["camera_moving"]["statistics"]
touched, nodes = sum(s["touched_nodes_per_level"]), sum(s["nodes_per_level"])
taken, saved = c["cone_samples"], c["cone_samples_saved_by_empty_space_skipping"]
lines += ["", "Work saved inside passes (camera-moved frame for cones, light-moved frame for radiance):", "",
          f"- radiance filtered through {touched:,} of {nodes:,} nodes ({100*touched/nodes:.1f} %): the rest received no light",
          f"- cone samples taken {taken:,}; empty-space skipping saved {saved:,} more ({100*saved/(taken+saved):.1f} % of what a fixed-step march would take)",
          f"- sky pixels with no GI work: {c['sky_pixels_without_gi_work']:,}",
          f"- pixels that took the last frame's indirect light in the camera-moved frame (`--cone-carry`): "
          f"{c['pixels_with_carried_indirect_light']:,} of {int(width) * int(height) - c['sky_pixels_without_gi_work']:,}; "
          f"pixels traced {c['cone_traced_pixels']:,}; camera moving: "
          f"{m['pixels_with_carried_indirect_light']:,}, pixels traced {m['cone_traced_pixels']:,}",
          f"- light-view maps rendered in the light-moved frame: {s['light_views_rendered']} of {s['light_views']}"]
open(f"{out}/incremental_{tag}.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
