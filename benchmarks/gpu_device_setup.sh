# Sourced by the scripts that run on an offline, bare GPU machine (gpu_device.sh,
# gpu_device_compare.sh), from the repository root, with what benchmarks/gpu_bundle.sh packed
# beside it (.gl/, .gpu/): unpacks the loaders and libraries, puts the binaries where ctest and
# the scripts look, points vct at the EGL backend, the shaders and Sponza, and checks that EGL
# renders (again with NVIDIA's EGL vendor file if not; exits if it still does not).
# Expects $root (the checkout), $out (a folder for logs) and a function `step` (one line of account).
for deb in .gl/*.deb; do dpkg -x "$deb" /; done
ldconfig
mkdir -p /tmp/vct_libs build/tests
tar -xJf .gpu/libs.tar.xz -C /tmp/vct_libs && tar -xJf .gpu/build.tar.xz -C .gpu
cp .gpu/build/vct .gpu/build/CTestTestfile.cmake build/ && cp .gpu/build/tests/* build/tests/
export LD_LIBRARY_PATH=/tmp/vct_libs/libs
# The binaries and ctest's files name the folder they were built in; this checkout stands in.
built_in=$(sed -n "s/^# Source directory: //p" build/CTestTestfile.cmake)
[ -n "$built_in" ] && [ ! -e "$built_in" ] && mkdir -p "$(dirname "$built_in")" && ln -s "$root" "$built_in"
export VCT_ASSET_DIR=$root/.gpu VCT_BACKEND=egl VCT_SHADER_DIR=$root/shaders
step "$(date -u +%FT%TZ) $(nvidia-smi -L 2>&1 | head -1)"

check() { timeout 120 build/vct render -q --scene cornell --width 64 --height 48 --voxel-levels 5 --out "$out/check.png" --timings "$out/check.json" >"$out/check.log" 2>&1; }
if ! check; then
    step "EGL check failed ($(tail -1 "$out/check.log")); again with NVIDIA's EGL vendor file"
    export __EGL_VENDOR_LIBRARY_FILENAMES=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
    check || { step "EGL still failing, stopping: $(tail -3 "$out/check.log")"; exit 1; }
fi
step "renderer: $(sed -n 's/^ *"renderer": "\(.*\)",*$/\1/p' "$out/check.json")"
