#!/usr/bin/env bash
# Fuzz one target with one worker: fuzz/run.sh <target> [extra libFuzzer flags], e.g.
# fuzz/run.sh grid -max_total_time=600. Targets: scene, grid, audit, note (README.md). The
# corpus (fuzz/corpus/<target>, not committed) starts from the shipped files: the scenes, the
# grids of constructions/variants, the tables of constructions/tables, the scenes' [task]
# strings. Findings go to fuzz/artifacts/<target>/.
set -euo pipefail
cd "$(dirname "$0")"
target="${1:?usage: fuzz/run.sh scene|grid|audit|note [libFuzzer flags]}"
shift
./build.sh
host=$(rustc -vV | sed -n "s/^host: //p")
corpus="corpus/$target"
mkdir -p "$corpus" "artifacts/$target"
flags=(-max_len=8192 -timeout=10)
if [ -z "$(ls -A "$corpus")" ]; then
    case "$target" in
    scene) cp ../constructions/*.toml "$corpus/" ;;
    grid) cp ../constructions/variants/*.csv "$corpus/" ;;
    audit) cp ../constructions/tables/*.csv "$corpus/" ;;
    note)
        # Every string of every scene's [task], one file each.
        n=0
        for f in ../constructions/*.toml; do
            awk '/^\[/ { task = ($0 ~ /^\[task\]/) } task && /=/' "$f" |
                sed -n 's/^[a-z_]* *= *"\(.*\)".*$/\1/p' |
                while IFS= read -r line; do
                    n=$((n + 1))
                    printf '%s' "$line" > "$corpus/$(basename "$f" .toml)-$n"
                done
        done
        ;;
    *) echo "no target $target" >&2; exit 2 ;;
    esac
fi
case "$target" in
scene | grid) flags+=(-dict=scene.dict) ;;
note) flags=(-max_len=2048 -timeout=10) ;;
esac
exec "target/$host/release/$target" "$corpus" "${flags[@]}" -rss_limit_mb=1024 \
    -artifact_prefix="artifacts/$target/" -print_final_stats=1 "$@"
