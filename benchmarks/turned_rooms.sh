#!/usr/bin/env bash
# Leaks when no axis lines up with the walls: the two rooms of the leak tests
# (tests/gi_accuracy_test.cpp, closedRoomLeak: room A sunlit through a hole in its ceiling, room B
# closed, every surface a single-sided plane of albedo 0.8) turned about the vertical by 0°, 30°
# and 45°, with the wall between them a sheet or 1.3 voxels thick, under two suns that turn with
# the building: the tests' sun, and a low sun (17° elevation) that lights room B's end wall, a
# sheet, from outside. One bounce brings room B no light at all (the path tracer's column checks
# that the room is closed); the engine's indirect light there, mean and largest pixel, in % of the
# sunlit floor's radiance ρ/π·E·cosθ (the tests' measure; issue 12 asks at most 0.5 % and 2 %).
# Six directional values per brick sample are exact for surfaces that face an axis and leak for
# those that do not (docs/benchmark.md, "Leaks through walls that no axis lines up with").
#   bash benchmarks/turned_rooms.sh      (about two minutes on llvmpipe)
# Writes benchmarks/results/turned_rooms_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"
cases=()
for turn in 0 30 45; do
  for wall in 0 1.3; do
    for sun in tests low; do
      cases+=("$turn $wall $sun")
      name="t${turn}_w${wall}_$sun"
      mkdir -p "$work/$name"
      # The model, its camera and its sun, turned together (the tests' geometry: writeTwoRooms).
      read -r -a view < <(/usr/bin/python3 - "$turn" "$wall" "$sun" "$work/$name" <<'PY'
import math, sys
turn, wall_voxels, sun, folder = math.radians(float(sys.argv[1])), float(sys.argv[2]), sys.argv[3], sys.argv[4]
# The wall is wall_voxels of a 256³ grid over the turned building's largest extent.
w = wall_voxels * 2.0 / (256.0 - wall_voxels)
for _ in range(60):
    W = 2.0 + w
    corners = [(x - W / 2, z - 0.5) for x in (0.0, W) for z in (0.0, 1.0)]
    xs = [math.cos(turn) * x + math.sin(turn) * z for x, z in corners]
    zs = [-math.sin(turn) * x + math.cos(turn) * z for x, z in corners]
    w = wall_voxels * max(max(xs) - min(xs), max(zs) - min(zs), 1.0) / 256.0
W, a = 2.0 + w, 1.0 + w
def turned(p):
    x, y, z = p[0] - W / 2, p[1], p[2] - 0.5
    return (math.cos(turn) * x + math.sin(turn) * z, y, -math.sin(turn) * x + math.cos(turn) * z)
lines, count = ["mtllib rooms.mtl", "usemtl white"], 0
def quad(*corners):
    global count
    lines.extend("v %.7f %.7f %.7f" % turned(c) for c in corners)
    lines.append("f %d %d %d %d" % (count + 1, count + 2, count + 3, count + 4))
    count += 4
quad((0, 0, 0), (W, 0, 0), (W, 0, 1), (0, 0, 1))  # floor
quad((0, 0, 0), (0, 0, 1), (0, 1, 1), (0, 1, 0))  # outer walls
quad((W, 0, 0), (W, 1, 0), (W, 1, 1), (W, 0, 1))
quad((0, 0, 0), (0, 1, 0), (W, 1, 0), (W, 0, 0))
quad((0, 0, 1), (W, 0, 1), (W, 1, 1), (0, 1, 1))
quad((a, 1, 0), (a, 1, 1), (W, 1, 1), (W, 1, 0))  # ceiling over B
for x0, x1, z0, z1 in ((0, 1, 0, 0.3), (0, 1, 0.7, 1), (0, 0.3, 0.3, 0.7), (0.7, 1, 0.3, 0.7)):
    quad((x0, 1, z0), (x0, 1, z1), (x1, 1, z1), (x1, 1, z0))  # over A, round a hole
quad((1, 0, 0), (1, 1, 0), (1, 1, 1), (1, 0, 1))  # the wall between
if w > 0.0:
    quad((a, 0, 0), (a, 0, 1), (a, 1, 1), (a, 1, 0))
    quad((1, 1, 0), (1, 1, 1), (a, 1, 1), (a, 1, 0))
open(f"{folder}/rooms.obj", "w").write("\n".join(lines) + "\n")
open(f"{folder}/rooms.mtl", "w").write("newmtl white\nKd 0.8 0.8 0.8\n")
def direction(d):
    return (math.cos(turn) * d[0] + math.sin(turn) * d[2], d[1], -math.sin(turn) * d[0] + math.cos(turn) * d[2])
sun_dir = (0.3, -1.0, 0.2) if sun == "tests" else (-0.95, -0.3, 0.0)  # low: onto B's end wall (x = W) from outside
eye, target = turned((1.5, 0.7, 0.03)), turned((1.6, 0.2, 0.9))
print("--scene %s/rooms.obj --eye %.6f,%.6f,%.6f --target %.6f,%.6f,%.6f --sun-dir %.6f,%.6f,%.6f" %
      ((folder,) + eye + target + direction(sun_dir)))
PY
      )
      view+=(--sun-irradiance 10 --fov 100 --width 128 --height 96)
      echo "turned_rooms: turn $turn°, wall $wall voxels, $sun sun..." >&2
      ./build/vct -q render "${view[@]}" --aov gi --hdr-out "$work/$name/engine.pfm" --out "$work/$name/engine.png" \
        --timings "$work/timings.json"
      ./build/vct -q reference "${view[@]}" --spp 64 --bounces 1 --indirect-out "$work/$name/reference.pfm" \
        --out "$work/$name/reference-full.pfm"
    done
  done
done
/usr/bin/python3 - "$work" "$out" "${cases[@]}" <<'PY'
import math, sys
sys.path.insert(0, "benchmarks")
from report import read_pfm, renderer_of, report_head, write_report
work, out, cases = sys.argv[1], sys.argv[2], sys.argv[3:]
renderer, tag = renderer_of(f"{work}/timings.json")
lines = report_head(
    "Leaks through walls that no axis lines up with", renderer, "turned_rooms.sh",
    "Room B of the leak tests' two rooms (closed; room A sunlit through its ceiling), the building turned "
    "about the vertical with its camera and sun. Indirect light over room B's image (`vct render --aov gi`, "
    "128×96, default settings, 256³) in % of the sunlit floor's radiance ρ/π·E·cosθ; the path tracer's "
    "(`vct reference --bounces 1 --spp 64 --indirect-out`) is 0 where the room is closed. Suns in the "
    "building's frame: the tests' (0.3, −1, 0.2) and a low one, (−0.95, −0.3, 0), onto room B's end wall "
    "from outside. Issue 12's bounds: mean ≤ 0.5 %, largest pixel ≤ 2 %.",
    ["turn", "wall between", "sun", "engine mean", "engine largest pixel", "path tracer mean"])
for case in cases:
    turn, wall, sun = case.split()
    name = f"t{turn}_w{wall}_{sun}"
    elevation = math.atan2(1.0, math.hypot(0.3, 0.2)) if sun == "tests" else math.atan2(0.3, 0.95)
    lit_floor = 0.8 / math.pi * 10.0 * math.sin(elevation)
    def grey(path):
        _, _, pixels = read_pfm(path)
        values = [sum(p) / 3.0 for p in pixels]
        return sum(values) / len(values), max(values)
    engine_mean, engine_largest = grey(f"{work}/{name}/engine.pfm")
    reference_mean, _ = grey(f"{work}/{name}/reference.pfm")
    wall_text = "a sheet" if float(wall) == 0.0 else f"{wall} voxels"
    lines.append(f"| {turn}° | {wall_text} | {sun} | {100 * engine_mean / lit_floor:.3f} % | "
                 f"{100 * engine_largest / lit_floor:.2f} % | {100 * reference_mean / lit_floor:.3f} % |")
write_report(f"{out}/turned_rooms_{tag}.md", lines)
PY
