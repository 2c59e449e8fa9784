#!/usr/bin/env bash
# Fuzz the scene target with one worker: fuzz/run.sh [extra libFuzzer flags], e.g.
# fuzz/run.sh -max_total_time=3600. The corpus (fuzz/corpus, not committed) starts from
# constructions/*.toml; crashes go to fuzz/artifacts/.
set -euo pipefail
cd "$(dirname "$0")"
./build.sh
host=$(rustc -vV | sed -n "s/^host: //p")
mkdir -p corpus artifacts
if [ -z "$(ls -A corpus)" ]; then
    cp ../constructions/*.toml corpus/
fi
exec "target/$host/release/scene" corpus \
    -dict=scene.dict -max_len=8192 -rss_limit_mb=1024 -timeout=10 \
    -artifact_prefix=artifacts/ -print_final_stats=1 "$@"
