#!/usr/bin/env bash
# Light seen far away at a grazing angle, and through an opening: two rooms side by side
# (benchmarks/scenes/two_rooms_*.obj), the sun straight down into room A, room B roofed, so that
# all of room B's light is one bounce off room A's sunlit floor. The camera stands in room B and
# looks at its back wall, 4-8 m from that floor. The indirect light there against the path
# tracer's, per 3x3 cell, with the wall between the rooms (a 2 x 2 m opening) and without it, at
# 128³ and 256³ voxels: the known limit "light through openings" of docs/frame.md, reduced to
# geometry whose answer is easy to reason about.
#   bash benchmarks/openings.sh          (about a minute on llvmpipe)
# Writes benchmarks/results/openings_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"
view=(--sun-dir 0,-1,0.05 --sun-irradiance 10 --eye 4.3,2,0 --target 8,1.5,0 --fov 70 --width 320 --height 180)
for scene in two_rooms_opening two_rooms_no_wall; do
  echo "openings: $scene, reference..." >&2
  ./build/vct -q reference --scene "benchmarks/scenes/$scene.obj" "${view[@]}" --spp 512 --bounces 1 \
    --out "$work/$scene-reference.pfm"
  for levels in 7 8; do
    echo "openings: $scene, engine at $((1 << levels))³..." >&2
    ./build/vct -q render --scene "benchmarks/scenes/$scene.obj" "${view[@]}" --voxel-levels "$levels" \
      --hdr-out "$work/$scene-$levels.pfm" --out "$work/$scene-$levels.png" --timings "$work/$scene-$levels-timings.json"
    # Room B gets no direct light, so the final images compare as indirect light.
    ./build/vct -q compare "$work/$scene-$levels.pfm" "$work/$scene-reference.pfm" --regions 3x3 \
      --json "$work/$scene-$levels.json" >/dev/null
  done
done
/usr/bin/python3 - "$work" "$out" <<'PY'
import datetime, json, sys
sys.path.insert(0, "benchmarks")
from report import renderer_of, write_report
work, out = sys.argv[1], sys.argv[2]
renderer, tag = renderer_of(f"{work}/two_rooms_opening-8-timings.json")
lines = ["# Openings: light from a sunlit floor seen far away at a grazing angle", "",
         f"Renderer: {renderer}, measured {datetime.date.today()} by `bash benchmarks/openings.sh`. Room B of "
         "`benchmarks/scenes/two_rooms_*.obj` seen from (4.3, 2, 0) towards its back wall; all its light is one "
         "bounce off room A's sunlit floor. Engine (default settings, 320×180) against `vct reference --bounces 1 "
         "--spp 512`; ratios of mean luminance, per 3×3 cell (row 0 at the top: the back wall's upper half and the "
         "side walls; row 1: the back wall's middle; row 2: the floor, which one bounce leaves dark, and the side "
         "walls' feet). Cells whose reference mean is at most 5 % of the image's are in parentheses.", "",
         "| scene | voxels | image | row 0 | row 1 | row 2 |", "|---|---|---|---|---|---|"]
for scene, name in (("two_rooms_opening", "wall with a 2 × 2 m opening"), ("two_rooms_no_wall", "no wall")):
    for levels in (7, 8):
        regions = json.load(open(f"{work}/{scene}-{levels}.json"))["regions"]
        def cell(c):
            text = "–" if c.get("ratio") is None else f"{c['ratio']:.2f}"
            return text if c.get("significant") else f"({text})"
        rows = [" ".join(cell(c) for c in regions["cells"] if c["row"] == r) for r in range(3)]
        ratio = regions["mean_a"] / regions["mean_b"]
        lines.append(f"| {name} | {2 ** levels}³ | {ratio:.3f} | {rows[0]} | {rows[1]} | {rows[2]} |")
write_report(f"{out}/openings_{tag}.md", lines)
PY
