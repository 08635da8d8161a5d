#!/usr/bin/env bash
# Packs what one run on an offline, bare GPU machine needs (benchmarks/gpu_device.sh there) into
# .gl/ and .gpu/, both ignored through .git/info/exclude, small enough to travel with the
# repository in 64 MiB:
#   .gl/               the GL/EGL loader .debs: the machine has NVIDIA's driver, not libglvnd
#   .gpu/libs.tar.xz   the shared libraries build/vct and the test binary link that a bare machine
#                      lacks, OSMesa and Embree replaced by stubs (benchmarks/stubs/): with LLVM
#                      they weigh over 150 MiB, and EGL rendering calls neither
#   .gpu/build.tar.xz  build/vct, the test binary and ctest's files
#   .gpu/sponza/       Sponza without its normal maps (vct reads base colour only)
# Build first (bash .ci/setup); the machine must be x86-64 like this one.
set -euo pipefail
cd "$(dirname "$0")/.."
[ -x build/vct ] && [ -x build/tests/vct_tests ] || { echo "gpu_bundle.sh: build first (bash .ci/setup)" >&2; exit 1; }
grep -qx '/.gpu/' .git/info/exclude 2>/dev/null || printf '/.gl/\n/.gpu/\n' >>.git/info/exclude
rm -rf .gl .gpu
mkdir -p .gl .gpu/libs .gpu/build/tests
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

mkdir -p "$scratch/lists/partial"
apt=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 "-oDir::State::Lists=$scratch/lists")
apt-get "${apt[@]}" update >/dev/null
(cd .gl && apt-get "${apt[@]}" download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null 2>&1)

cc -shared -fPIC -O2 -Wl,-soname,libOSMesa.so.8 -o .gpu/libs/libOSMesa.so.8 benchmarks/stubs/osmesa_stub.c
cc -shared -fPIC -O2 -Wl,-soname,libembree3.so.3 -o .gpu/libs/libembree3.so.3 benchmarks/stubs/embree_stub.c
# What the binaries load with the stubs in place, less the C/C++ runtime every machine has and
# the loader libraries the .debs bring.
system='^(linux-vdso|ld-linux|libc\.|libm\.|libdl\.|libpthread\.|librt\.|libstdc\+\+|libgcc_s|libEGL\.|libGLdispatch\.|libOSMesa\.|libembree3\.)'
LD_LIBRARY_PATH=.gpu/libs ldd build/vct build/tests/vct_tests | awk '$2 == "=>" { print $1, $3 }' | sort -u |
    while read -r name path; do
        [[ "$name" =~ $system ]] || cp -L "$path" .gpu/libs/
    done
(cd .gpu && tar -cJf libs.tar.xz libs && rm -rf libs)

cp build/vct build/CTestTestfile.cmake .gpu/build/
cp build/tests/vct_tests build/tests/CTestTestfile.cmake build/tests/vct_tests*.cmake .gpu/build/tests/
(cd .gpu && tar -cJf build.tar.xz build && rm -rf build)

sponza=
for root in "${VCT_ASSET_DIR:-}" assets ../shared/assets; do
    [ -n "$root" ] && [ -f "$root/sponza/Sponza.gltf" ] && { sponza=$root/sponza; break; }
done
if [ -n "$sponza" ]; then
    mkdir -p .gpu/sponza
    find "$sponza" -maxdepth 1 -type f ! -name '*_normal.png' -exec cp {} .gpu/sponza/ \;
else
    echo "gpu_bundle.sh: Sponza not found (VCT_ASSET_DIR, assets/, ../shared/assets/): the GPU run will skip it" >&2
fi
echo "gpu_bundle.sh: $(du -sh .gl .gpu | awk '{printf "%s %s  ", $2, $1}')(tracked files: $(git ls-files -z | du -ch --files0-from=- | tail -1 | cut -f1))"
