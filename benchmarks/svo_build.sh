#!/usr/bin/env bash
# Octree build of Sponza at several voxel levels: per-pass times and memory, with the size of a
# dense 3D texture of the same resolution for comparison. Writes
# benchmarks/results/svo_build_<renderer>.md and the raw timing JSON files beside it.
#   bash benchmarks/svo_build.sh [levels...]      (default: 6 7 8 9)
# Each point builds the octree twice (--full-frames --frames 2) and reports the second, warm
# build: on llvmpipe the first use of a shader includes its JIT compilation.
set -euo pipefail
cd "$(dirname "$0")/.."
levels=("${@:-6 7 8 9}")
[ $# -gt 0 ] || levels=(6 7 8 9)
bash .ci/setup >/dev/null
out=benchmarks/results
mkdir -p "$out"
backend="${VCT_BACKEND:-osmesa}"
for level in "${levels[@]}"; do
  echo "building Sponza at $level levels ($backend)..." >&2
  ./build/vct render -q --backend "$backend" --scene sponza --view voxels --voxel-levels "$level" \
    --full-frames --frames 2 --width 640 --height 360 --out "$out/svo_sponza_L$level.png" \
    --timings "$out/svo_sponza_L$level.json"
done
/usr/bin/python3 - "$out" "${levels[@]}" <<'PY'
import json, sys, datetime
out, levels = sys.argv[1], sys.argv[2:]
runs = [json.load(open(f"{out}/svo_sponza_L{l}.json")) for l in levels]
renderer = runs[0]["renderer"]
tag = "llvmpipe" if "llvmpipe" in renderer else renderer.split()[0].lower()
passes = [p["name"] for p in runs[0]["graph"] if p["stage"] == "octree"]
mib = lambda b: b / 1048576
lines = [f"# Sparse voxel octree build: Sponza", "",
         f"Renderer: {renderer} ({runs[0]['backend']}), measured {datetime.date.today()}, warm build (second of two).",
         "Produced by `bash benchmarks/svo_build.sh`.", "",
         "## Time per pass (ms): GPU timestamp / CPU wall time of the pass", "",
         "| pass | " + " | ".join(f"{2**int(l)}³" for l in levels) + " |", "|---|" + "---|" * len(levels)]
for name in passes:
    cells = []
    for r in runs:
        p = next(p for p in r["passes"] if p["name"] == name)
        cells.append(f"{p['gpu_ms']:.1f} / {p['cpu_ms']:.1f}")
    lines.append(f"| {name} | " + " | ".join(cells) + " |")
tot = []
for r in runs:
    ps = [p for p in r["passes"] if p["name"] in passes]
    tot.append(f"{sum(p['gpu_ms'] for p in ps):.1f} / {sum(p['cpu_ms'] for p in ps):.1f}")
lines.append("| **octree total** | " + " | ".join(tot) + " |")
lines += ["", "## Size", "", "| | " + " | ".join(f"{2**int(l)}³" for l in levels) + " |", "|---|" + "---|" * len(levels)]
v = [r["voxels"] for r in runs]
rows = [("voxel fragments", lambda x: f"{x['fragments']:,}"),
        ("occupied voxels", lambda x: f"{x['nodes_per_level'][-1]:,}"),
        ("octree nodes (levels 0..L−1)", lambda x: f"{sum(x['nodes_per_level'][:-1]):,}"),
        ("max fragments in one voxel", lambda x: f"{x['max_fragments_in_voxel']:,}"),
        ("fragment list (MiB)", lambda x: f"{mib(x['bytes']['fragment_list']):.1f}"),
        ("node pool (MiB)", lambda x: f"{mib(x['bytes']['node_pool']):.1f}"),
        ("neighbour links (MiB)", lambda x: f"{mib(x['bytes']['neighbour_links']):.1f}"),
        ("voxel values (MiB)", lambda x: f"{mib(x['bytes']['voxel_values']):.1f}"),
        ("brick pool (MiB)", lambda x: f"{mib(x['bytes']['brick_pool']):.1f}"),
        ("**octree total without fragment list (MiB)**", lambda x: f"{mib(sum(x['bytes'][k] for k in ['node_pool','neighbour_links','voxel_values','brick_pool'])):.1f}"),
        ("dense RGBA16F 3D texture + mips (MiB)", lambda x: f"{mib(x['bytes']['dense_texture_equivalent']):.1f}")]
for label, f in rows:
    lines.append(f"| {label} | " + " | ".join(f(x) for x in v) + " |")
lines += ["", "Nodes per level (0..L, the last = occupied voxels):", ""]
for l, x in zip(levels, v):
    lines.append(f"- {2**int(l)}³: " + " ".join(str(n) for n in x["nodes_per_level"]))
open(f"{out}/svo_build_{tag}.md", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
