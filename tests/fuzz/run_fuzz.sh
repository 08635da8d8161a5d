#!/usr/bin/env bash
# Short CI run of the loader fuzzer: builds fuzz_loader with clang in its own build folder (only
# the loader's sources) and runs it for N seconds from the committed seed corpus. Exits 77
# (ctest: skipped) with the reason when clang or its libFuzzer runtime is missing.
#   tests/fuzz/run_fuzz.sh BUILD_DIR [SECONDS] [extra libFuzzer flags]
set -euo pipefail
build_dir="$1"; seconds="${2:-20}"; shift $(( $# >= 2 ? 2 : 1 ))
source_dir="$(cd "$(dirname "$0")/../.." && pwd)"
clangxx="$(command -v clang++ || command -v clang++-14 || true)"
clangc="$(command -v clang || command -v clang-14 || true)"
if [ -z "$clangxx" ] || [ -z "$clangc" ]; then
  echo "SKIPPED: clang++ not found; install clang and libclang-rt-14-dev (.ci/setup does) to fuzz the loader"
  exit 77
fi
probe="$(mktemp -d)"
trap 'rm -rf "$probe"' EXIT
echo 'extern "C" int LLVMFuzzerTestOneInput(const unsigned char*, unsigned long) { return 0; }' > "$probe/p.cpp"
if ! "$clangxx" -fsanitize=fuzzer,address "$probe/p.cpp" -o "$probe/p" 2> "$probe/log"; then
  echo "SKIPPED: $clangxx cannot link -fsanitize=fuzzer (libFuzzer runtime missing: install libclang-rt-14-dev)"
  sed 's/^/  /' "$probe/log" | head -5
  exit 77
fi
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  generator=(); command -v ninja >/dev/null && generator=(-G Ninja)
  CC="$clangc" CXX="$clangxx" cmake -S "$source_dir" -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DVCT_FUZZ=ON -DVCT_BUILD_TESTS=OFF > "$build_dir.configure.log" 2>&1 || { cat "$build_dir.configure.log"; exit 1; }
fi
cmake --build "$build_dir" --target fuzz_loader --parallel "$(nproc)"
# New inputs go to the build folder's corpus; the committed seeds are only read. A run with a fixed
# number of inputs (-runs=, what ctest does) starts from the committed seeds alone, in a corpus
# folder emptied first, so that it is reproducible and does not slow down as earlier runs add
# inputs. Assimp's own leaks on malformed files are suppressed (lsan.supp), vct's are reported.
corpus="$build_dir/corpus"
case " $* " in *" -runs="*) corpus="$build_dir/corpus-fixed"; rm -rf "$corpus" ;; esac
mkdir -p "$corpus" "$build_dir/artifacts"
export LSAN_OPTIONS="suppressions=$source_dir/tests/fuzz/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
"$build_dir/tests/fuzz/fuzz_loader" "$corpus" "$source_dir/tests/fuzz/corpus" -max_total_time="$seconds" \
  -rss_limit_mb=2048 -timeout=20 -artifact_prefix="$build_dir/artifacts/" -print_final_stats=1 "$@"
