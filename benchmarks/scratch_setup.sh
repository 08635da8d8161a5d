# Sourced by the benchmark scripts that render into a scratch folder: strict mode, the repository
# root as the working directory, the build up to date (.ci/setup), `out` the results folder and
# `work` a temporary folder removed on exit.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
bash .ci/setup >/dev/null
out=benchmarks/results
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
