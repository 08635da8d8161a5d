#!/usr/bin/env bash
# One full GI frame of Sponza, every pass of DESIGN §4, at several voxel levels:
#   bash benchmarks/gi_frame.sh [levels...]       (default: 7 8; 1280×720)
# Writes benchmarks/results/gi_frame_<renderer>.md and the timing JSON files beside it. Each
# point renders two full frames (--full-frames) and reports the second (warm: on llvmpipe the
# first use of a shader includes its JIT compilation), so the octree passes are in the table.
set -euo pipefail
cd "$(dirname "$0")/.."
levels=("$@")
[ $# -gt 0 ] || levels=(7 8)
width="${VCT_WIDTH:-1280}"
height="${VCT_HEIGHT:-720}"
backend="${VCT_BACKEND:-osmesa}"
bash .ci/setup >/dev/null
out=benchmarks/results
mkdir -p "$out"
for level in "${levels[@]}"; do
  echo "Sponza GI frame at $level levels, ${width}x${height} ($backend)..." >&2
  ./build/vct render -q --backend "$backend" --scene sponza --voxel-levels "$level" --full-frames --frames 2 \
    --width "$width" --height "$height" --out "$out/gi_sponza_L$level.png" --timings "$out/gi_sponza_L$level.json"
done
/usr/bin/python3 - "$out" "${levels[@]}" <<'PY'
import json, sys, datetime
out, levels = sys.argv[1], sys.argv[2:]
runs = [json.load(open(f"{out}/gi_sponza_L{l}.json")) for l in levels]
r0 = runs[0]
tag = "llvmpipe" if "llvmpipe" in r0["renderer"] else r0["renderer"].split()[0].lower()
lines = ["# Sponza, one GI frame, pass by pass", "",
         f"Renderer: {r0['renderer']} ({r0['backend']}), {r0['width']}×{r0['height']}, measured {datetime.date.today()}, "
         "warm frame (second of two, octree rebuilt every frame so its passes are included).",
         "Produced by `bash benchmarks/gi_frame.sh`. Times in ms: GPU timestamp / CPU wall time of the pass. "
         "On llvmpipe compute dispatches run on the CPU at submission, so for compute passes the CPU column is the "
         "cost and the GPU column can be near zero; the frame total (GPU span) is reliable.", "",
         "| pass | " + " | ".join(f"{2**int(l)}³" for l in levels) + " |", "|---|" + "---|" * len(levels)]
names = [p["name"] for p in r0["passes"]]
for name in names:
    cells = []
    for r in runs:
        p = next((p for p in r["passes"] if p["name"] == name), None)
        cells.append(f"{p['gpu_ms']:.1f} / {p['cpu_ms']:.1f}" if p else "–")
    lines.append(f"| {name} | " + " | ".join(cells) + " |")
lines.append("| **frame (GPU span) / Σ CPU** | " + " | ".join(f"{r['total_gpu_ms']:.1f} / {r['total_cpu_ms']:.1f}" for r in runs) + " |")
lines += ["", "GPU memory (MiB):", "", "| pool | " + " | ".join(f"{2**int(l)}³" for l in levels) + " |", "|---|" + "---|" * len(levels)]
for pool in [m["name"] for m in r0["memory"]]:
    cells = []
    for r in runs:
        m = next((m for m in r["memory"] if m["name"] == pool), None)
        cells.append(f"{m['bytes']/1048576:.1f}" if m else "–")
    lines.append(f"| {pool} | " + " | ".join(cells) + " |")
lines.append("| **total** | " + " | ".join(f"{r['memory_total_bytes']/1048576:.1f}" for r in runs) + " |")
open(f"{out}/gi_frame_{tag}.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
