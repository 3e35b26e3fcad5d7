#!/usr/bin/env bash
# Runs every fuzz target for SECONDS each (default 60), one after the other on one core, from
# the seeds in fuzz/seeds/ and the corpus grown so far in fuzz/corpus/. A finding stops its
# target and is left in fuzz/artifacts/TARGET/; turn it into a regression test, fix it, rerun.
# usage: fuzz/run.sh [SECONDS] [TIMEOUT]
# Needs cargo-fuzz (cargo install cargo-fuzz) and a nightly toolchain, or RUSTC_BOOTSTRAP=1.
set -euo pipefail
cd "$(dirname "$0")"
seconds=${1:-60}
# No input may take longer than TIMEOUT seconds (default 1; give more on a machine whose other
# core is busy, where a fuzzer at low priority waits for the CPU).
timeout=${2:-1}
toolchain=+nightly
if ! rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
  toolchain=""
  export RUSTC_BOOTSTRAP=1
fi
cargo $toolchain fuzz build
for target in $(cargo $toolchain fuzz list); do
  mkdir -p "corpus/$target"
  echo "== $target: $seconds s"
  # -timeout: no input may take long; -rss_limit_mb: nor much memory.
  cargo $toolchain fuzz run "$target" "corpus/$target" "seeds/$target" -- \
    -max_total_time="$seconds" -timeout="$timeout" -rss_limit_mb=1024 -print_final_stats=1 2>&1 \
    | grep -E '^(#[0-9]+ +(DONE|INITED)|stat::number_of_executed_units|stat::peak_rss_mb|==[0-9]+== ERROR|SUMMARY|artifact)' || true
  if ls "artifacts/$target"/* >/dev/null 2>&1; then
    echo "finding in artifacts/$target" >&2
    exit 1
  fi
done
