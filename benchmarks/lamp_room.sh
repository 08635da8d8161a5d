#!/usr/bin/env bash
# A lamp in a room, from its centre to a corner behind the camera: the one-bounce indirect light
# against the path tracer's, and what one narrow cone brings back from the eye against what the
# eye sees. A room of walls of no thickness (benchmarks/scenes/lamp_room.obj) lit by a point light
# of 2 W/sr at five places; the camera at one end looks at the far wall. The light of a lamp near
# an edge or a corner of the room lies in a small, steep hot spot, and the cones carry it across
# the room less faithfully than the even light of a lamp in the middle. Also: the sun (outside,
# through the roof's hole) and the lamp together against each alone (light must add up).
#   bash benchmarks/lamp_room.sh          (about two minutes on llvmpipe)
# Writes benchmarks/results/lamp_room_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"
scene=benchmarks/scenes/lamp_room.obj
view=(--eye 0,2,1.9 --target 0,1.5,-2 --fov 80 --width 160 --height 90)
sun=(--sun-dir 0.15,-1,0.1 --sun-irradiance 10)
declare -A lamps=([centre]=0,2,0 [below_roof]=0,3.5,0 [by_a_wall]=1.5,2,0 [far_corner]=1.5,3.5,-1.5
                  [near_corner]=1.5,3.5,1.5)
for name in centre below_roof by_a_wall far_corner near_corner; do
  echo "lamp_room: lamp $name..." >&2
  lamp=(--point-pos "${lamps[$name]}" --point-intensity 2)
  ./build/vct -q reference --scene "$scene" "${view[@]}" "${lamp[@]}" --spp 512 --bounces 1 \
    --out "$work/$name-reference.pfm" --indirect-out "$work/$name-reference-indirect.pfm"
  ./build/vct -q render --scene "$scene" "${view[@]}" "${lamp[@]}" --aov gi --hdr-out "$work/$name-gi.pfm" \
    --out "$work/$name.png" --timings "$work/timings.json"
  ./build/vct -q render --scene "$scene" "${view[@]}" "${lamp[@]}" --aov gi --cone-rays 16 \
    --hdr-out "$work/$name-gi-narrow.pfm" --out "$work/$name.png"
  ./build/vct -q compare "$work/$name-gi.pfm" "$work/$name-reference-indirect.pfm" --regions 3x3 \
    --json "$work/$name.json" >/dev/null
  ./build/vct -q compare "$work/$name-gi-narrow.pfm" "$work/$name-reference-indirect.pfm" --regions 3x3 \
    --json "$work/$name-narrow.json" >/dev/null
  # One narrow cone from the eye towards the far wall against what the eye sees there.
  eye=(--eye 0,2,-1.9 --target 0,2,2 --fov 60 --width 96 --height 54 "${lamp[@]}")
  ./build/vct -q render --scene "$scene" "${eye[@]}" --aov direct --hdr-out "$work/$name-eye.pfm" --out "$work/$name.png"
  ./build/vct -q render --scene "$scene" "${eye[@]}" --view cones --cone-rays 1 --hdr-out "$work/$name-cone.pfm" \
    --out "$work/$name.png"
done
echo "lamp_room: sun and lamp..." >&2
for lights in sun lamp both; do
  case $lights in
    sun) set -- "${sun[@]}" ;;
    lamp) set -- --point-pos 1.5,3.5,1.5 --point-intensity 2 ;;
    both) set -- "${sun[@]}" --point-pos 1.5,3.5,1.5 --point-intensity 2 ;;
  esac
  ./build/vct -q render --scene "$scene" "${view[@]}" "$@" --aov gi --hdr-out "$work/sum-$lights.pfm" --out "$work/sum.png"
done
/usr/bin/python3 - "$work" "$out" <<'PY'
import json, sys
sys.path.insert(0, "benchmarks")
from report import read_pfm, renderer_of, report_head, write_report
work, out = sys.argv[1], sys.argv[2]
renderer, tag = renderer_of(f"{work}/timings.json")
def mean(path):
    _, _, pixels = read_pfm(path)
    return sum(0.2126 * r + 0.7152 * g + 0.0722 * b for r, g, b in pixels) / len(pixels)
def regions(path):
    r = json.load(open(path))["regions"]
    cells = [c["ratio"] for c in r["cells"] if c.get("significant") and c.get("ratio") is not None]
    return f"{r['mean_a'] / r['mean_b']:.3f} [{min(cells):.2f}–{max(cells):.2f}]"
lines = report_head("A lamp in a room: indirect light and what a cone carries across it", renderer, "lamp_room.sh",
                    "`benchmarks/scenes/lamp_room.obj` (4 m, walls of no thickness, albedo 0.6) lit by a point "
                    "light of 2 W/sr; camera (0, 2, 1.9) → (0, 1.5, −2), 160×90, default settings. Indirect: "
                    "`--aov gi` against `vct reference --bounces 1 --spp 512 --indirect-out`, mean luminance ratio "
                    "[3×3 cells with at least 5 % of the mean]. One narrow cone: `--view cones --cone-rays 1` from "
                    "(0, 2, −1.9) towards the far wall (z = 2, 3.9 m away) over `--aov direct` of the same view "
                    "(1 = the cone brings back what the eye sees).",
                    ["lamp at", "indirect, cone set", "indirect, 16 narrow cones", "one narrow cone / eye"])
places = {"centre": "centre (0, 2, 0)", "below_roof": "below the roof (0, 3.5, 0)",
          "by_a_wall": "by a wall (1.5, 2, 0)", "far_corner": "far corner (1.5, 3.5, −1.5)",
          "near_corner": "corner behind the camera (1.5, 3.5, 1.5)"}
for name, place in places.items():
    cone = mean(f"{work}/{name}-cone.pfm") / mean(f"{work}/{name}-eye.pfm")
    lines.append(f"| {place} | {regions(f'{work}/{name}.json')} | {regions(f'{work}/{name}-narrow.json')} | {cone:.3f} |")
sun, lamp, both = (mean(f"{work}/sum-{k}.pfm") for k in ("sun", "lamp", "both"))
lines += ["", f"Sun (through the roof's hole, and on the walls' outer faces) and the lamp in the near corner: "
          f"indirect mean {sun:.5f} and {lamp:.5f} alone, {both:.5f} together = {both / (sun + lamp):.3f}× their sum."]
write_report(f"{out}/lamp_room_{tag}.md", lines)
PY
