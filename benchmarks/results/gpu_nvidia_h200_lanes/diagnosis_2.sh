#!/usr/bin/env bash
set -u
root=$PWD; out=$OUT; mkdir -p "$out/x"
step() { echo "== $*" | tee -a "$out/steps.log"; }
. benchmarks/gpu_device_setup.sh
S() { python3 .diag/stats.py "$@"; }
R() {  # name timeout env args
    local name=$1 t=$2 envs=$3; shift 3
    local start=$SECONDS
    env $envs timeout $t build/vct render -q "$@" --out "$out/x/x.png" --hdr-out "$out/x/$name.pfm" >"$out/x/$name.log" 2>&1
    local rc=$?
    step "$name [$envs] rc=$rc $((SECONDS-start))s $(S "$out/x/$name.pfm" ${REF:+$out/x/$REF.pfm}) $( [ $rc -ne 0 ] && tail -1 "$out/x/$name.log")"
}
B2="--scene cornell --width 64 --height 48 --voxel-levels 6 --bounces 2 --frames 2 --light-path orbit"
REF= R b2_all 20 VCT_GL_ALL_BARRIERS=1 $B2
for bit in 0x200 0x40 0x100 0x8 0x20 0x2000 0x80 0x400; do REF=b2_all R b2_$bit 6 VCT_GL_EXTRA_BARRIERS=$bit $B2; done
S1=VCT_SHADER_DIR=$root/.diag/s1
C="--scene cornell --width 128 --height 96 --aov indirect"
REF= R s1_r8 20 $S1 $C --cone-rays 8
REF=s1_r8 R s1_r32 20 $S1 $C --cone-rays 32
SP="--scene sponza --width 160 --height 90 --voxel-levels 7 --aov indirect"
REF= R s1_spnr1 20 $S1 $SP --cone-reuse 0
for i in 2 3; do REF=s1_spnr1 R s1_spnr$i 20 $S1 $SP --cone-reuse 0; done
REF= R s1_sp1 20 $S1 $SP
REF=s1_sp1 R s1_sp2 20 $S1 $SP
REF=s1_sp1 R L1_sp 20 VCT_CONE_LANES=1 $SP
T() {  # name env args: second frame's cone_trace / bounce / total GPU ms
    local name=$1 envs=$2; shift 2
    env $envs timeout 30 build/vct render -q --scene sponza --width 1920 --height 1080 "$@" --out "$out/x/x.png" --timings "$out/t_$name.json" >"$out/x/t_$name.log" 2>&1
    step "time $name [$envs] rc=$? $(python3 -c "
import json,sys
d=json.load(open('$out/t_$name.json')); p={q['name']:q['gpu_ms'] for q in d['passes']}
print('total %.2f' % d['total_gpu_ms'], ' '.join('%s %.2f' % (k, v) for k, v in p.items() if v > 0.5))" 2>&1 | tail -1)"
}
T moved_lanes X=1 --voxel-levels 8 --frames 2 --camera-path orbit
T moved_L1 VCT_CONE_LANES=1 --voxel-levels 8 --frames 2 --camera-path orbit
T moved_s1 $S1 --voxel-levels 8 --frames 2 --camera-path orbit
T moved_lanes2 X=1 --voxel-levels 8 --frames 2 --camera-path orbit
T light_b2_all VCT_GL_ALL_BARRIERS=1 --voxel-levels 8 --frames 2 --light-path orbit --bounces 2
T light_b2_all_L1 "VCT_GL_ALL_BARRIERS=1 VCT_CONE_LANES=1" --voxel-levels 8 --frames 2 --light-path orbit --bounces 2
T light_b1 X=1 --voxel-levels 8 --frames 2 --light-path orbit
T light_b1_all VCT_GL_ALL_BARRIERS=1 --voxel-levels 8 --frames 2 --light-path orbit
rm -rf "$out/x"
