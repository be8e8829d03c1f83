#!/usr/bin/env bash
# Runs one loader's libFuzzer target for SECONDS on its seed corpus (data/
# and tests/fuzz/seeds/), adding what it finds to CORPUS (default: a
# temporary folder). Exits non-zero on a crash, a leak, a timeout or an
# uncaught exception; the input that caused it is kept in ARTIFACTS.
# Usage: run_fuzzer.sh FUZZER SECONDS SOURCE_DIR [CORPUS [ARTIFACTS]]
set -euo pipefail
fuzzer=$1
seconds=$2
src=$3
loader=$(basename "$fuzzer" _fuzz)
corpus=${4:-}
artifacts=${5:-$(dirname "$fuzzer")/artifacts}
if [ -z "$corpus" ]; then
  corpus=$(mktemp -d)
  trap 'rm -rf "$corpus"' EXIT
fi
mkdir -p "$corpus" "$artifacts"
seeds=("$src/tests/fuzz/seeds/$loader")
[ "$loader" = genome ] && seeds+=("$src/data/genomes")
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  -artifact_prefix="$artifacts/" "$corpus" "${seeds[@]}"
