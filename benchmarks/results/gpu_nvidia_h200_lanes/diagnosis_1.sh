#!/usr/bin/env bash
# GPU diagnosis: which switch removes the GPU-only differences (NaN, lost narrow cones, non-determinism).
set -u
root=$PWD; out=${OUT:-/tmp/diag}/diag; mkdir -p "$out"
step() { echo "== $*" | tee -a "$out/steps.log"; }
. benchmarks/gpu_device_setup.sh
S() { python3 .diag/stats.py "$@"; }
R() {  # name env scene-args
    local name=$1 envs=$2; shift 2
    env $envs timeout 40 build/vct render -q "$@" --out "$out/x.png" --hdr-out "$out/$name.pfm" >"$out/$name.log" 2>&1
    local rc=$?
    step "$name [$envs] rc=$rc $(S "$out/$name.pfm" ${REF:+$out/$REF.pfm}) $( [ $rc -ne 0 ] && tail -1 "$out/$name.log")"
}
C="--scene cornell --width 128 --height 96 --aov indirect"
for e in base:X=1 L1:VCT_CONE_LANES=1 FIN:VCT_GL_FINISH=1 AB:VCT_GL_ALL_BARRIERS=1 POI:VCT_GL_POISON=1; do
    n=${e%%:*} v=${e#*:}
    REF= R ${n}_r8 "$v" $C --cone-rays 8
    REF=${n}_r8 R ${n}_r32 "$v" $C --cone-rays 32
    REF=${n}_r8 R ${n}_r32nr "$v" $C --cone-rays 32 --cone-reuse 0
    REF=${n}_r8 R ${n}_r4 "$v" $C --cone-rays 4
    REF= R ${n}_r32full "$v" $C --cone-rays 32 --gi-resolution full
    REF=${n}_r32full R ${n}_r8full "$v" $C --cone-rays 8 --gi-resolution full
    REF=${n}_r8full R ${n}_r8fullnr "$v" $C --cone-rays 8 --gi-resolution full --cone-reuse 0
    REF= R ${n}_set "$v" $C --cone-rays 0
    REF= R ${n}_b2 "$v" --scene cornell --width 64 --height 48 --voxel-levels 6 --bounces 2 --frames 2 --light-path orbit
done
for e in base:X=1 L1:VCT_CONE_LANES=1 FIN:VCT_GL_FINISH=1; do
    n=${e%%:*} v=${e#*:}
    for i in 1 2 3; do REF=${n}_sp1 R ${n}_sp$i "$v" --scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect; done
    for i in 1 2; do REF=${n}_spnr1 R ${n}_spnr$i "$v" --scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect --cone-reuse 0; done
    for i in 1 2; do REF=${n}_spfull1 R ${n}_spfull$i "$v" --scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect --gi-resolution full --cone-reuse 0; done
done
REF=base_sp1 R L1_vs_base_sp "VCT_CONE_LANES=1" --scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect
rm -f "$out"/*.pfm "$out/x.png"
cd "$out/.." && tar -cf diag.tar diag && rm -rf diag
