#!/usr/bin/env bash
# Light through a colonnade: a gallery lit only by one bounce off a sunlit courtyard floor, open
# on one side (benchmarks/scenes/colonnade_open.obj) and behind a row of black columns that block
# a third of the opening (colonnade.obj). The path tracer's light in the gallery falls by what the
# columns hide; the engine's should fall alike. Sponza's galleries see the courtyard through such
# arcades (CameraBalcony's vault, 0.6-0.7x the path tracer's in every hemisphere region).
# Engine (default settings but the narrow cones' aperture, 256³) against `vct reference
# --bounces 1 --spp 512`, 160x120, ratios of mean luminance and per 3x3 cell.
#   bash benchmarks/colonnade.sh          (about ten seconds on llvmpipe)
# Writes benchmarks/results/colonnade_<renderer>.md.
source "$(dirname "$0")/scratch_setup.sh"
view=(--sun-dir 0.25,-0.968,0.1 --sun-irradiance 10 --eye 0.8,1.2,-3 --target 1.5,3.2,3 --fov 70 --width 160 --height 120)
apertures=(1 0.5 0.25)
for scene in colonnade_open colonnade; do
  echo "colonnade: $scene, reference..." >&2
  ./build/vct -q reference --scene "benchmarks/scenes/$scene.obj" "${view[@]}" --spp 512 --bounces 1 \
    --out "$work/$scene-final.pfm" --indirect-out "$work/$scene-reference.pfm"
  for aperture in "${apertures[@]}"; do
    echo "colonnade: $scene, engine, aperture $aperture..." >&2
    ./build/vct -q render --scene "benchmarks/scenes/$scene.obj" "${view[@]}" --cone-aperture "$aperture" --aov gi \
      --hdr-out "$work/$scene-$aperture.pfm" --out "$work/$scene-$aperture.png" --timings "$work/$scene-$aperture-timings.json"
    ./build/vct -q compare "$work/$scene-$aperture.pfm" "$work/$scene-reference.pfm" --regions 3x3 \
      --json "$work/$scene-$aperture.json" >/dev/null
  done
done
/usr/bin/python3 - "$work" "$out" "${apertures[@]}" <<'PY'
import datetime, json, sys
sys.path.insert(0, "benchmarks")
from report import renderer_of, write_report
work, out, apertures = sys.argv[1], sys.argv[2], sys.argv[3:]
renderer, tag = renderer_of(f"{work}/colonnade-1-timings.json")
lines = ["# Light through a colonnade", "",
         f"Renderer: {renderer}, measured {datetime.date.today()} by `bash benchmarks/colonnade.sh`. A gallery "
         "(`benchmarks/scenes/colonnade_open.obj`) lit only by one bounce off a sunlit courtyard floor, and the "
         "same behind black columns that block a third of its opening (`colonnade.obj`), seen from inside towards "
         "its roof and back wall. Engine (`vct render --aov gi`, 256³, default settings but `--cone-aperture`, "
         "which scales the narrow cones' tan 0.03) against `vct reference --bounces 1 --spp 512 --indirect-out`, "
         "160×120: ratios of mean luminance, per 3×3 cell (row 0 at the top); cells whose reference mean is at "
         "most 5 % of the image's in parentheses. The last column is what the columns leave of the open gallery's "
         "light, the engine's over the path tracer's: 1 when the engine's cones are blocked by the columns as "
         "the path tracer's rays are.", "",
         "| aperture | scene | image | row 0 | row 1 | row 2 | columns' transmission, engine / reference |",
         "|---|---|---|---|---|---|---|"]
for aperture in apertures:
    ratios = {}
    for scene, name in (("colonnade_open", "open"), ("colonnade", "colonnade")):
        regions = json.load(open(f"{work}/{scene}-{aperture}.json"))["regions"]
        def cell(c):
            text = "–" if c.get("ratio") is None else f"{c['ratio']:.2f}"
            return text if c.get("significant") else f"({text})"
        rows = [" ".join(cell(c) for c in regions["cells"] if c["row"] == r) for r in range(3)]
        ratios[scene] = regions["mean_a"] / regions["mean_b"]
        transmission = f"{ratios['colonnade'] / ratios['colonnade_open']:.3f}" if scene == "colonnade" else ""
        lines.append(f"| {aperture} | {name} | {ratios[scene]:.3f} | {rows[0]} | {rows[1]} | {rows[2]} | {transmission} |")
write_report(f"{out}/colonnade_{tag}.md", lines)
PY
