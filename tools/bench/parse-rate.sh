#!/usr/bin/env bash
# parse-rate.sh [N] [LIB...] - the reading speed of the three text formats,
# in MB/s (10^6 bytes a second): the parse alone and the whole load, for a
# .scn, an OBJ and an NFF of the same terrain (terrain.py N, default 708:
# 1,002,528 facets; the files are about 51, 40 and 101 MB), each the least
# of 3 runs.  tools/bench/parse-rate.c is compiled against each static
# library given (default: build/src/libraytrace.a), with this tree's
# headers (and build/include's version.h), so that two builds - main's and
# a branch's - are measured in the same run, one after the other on each
# file; "parse" is the load without rt__reader_finish (the scene build),
# "load" the whole of rt_scene_load, both wall-clock; "parse cpu" the
# parse's processor time (one thread), which a busy machine changes less.  The files are written to $PARSE_RATE_DIR
# (default a temporary folder, removed at the end) and read once before
# the runs, so the page cache holds them: the figures are the readers',
# not the disk's.  Run it on an idle machine: others' work counts.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
n=${1:-708}
shift || true
libs=("$@")
[ ${#libs[@]} -gt 0 ] || libs=("$root/build/src/libraytrace.a")
work=${PARSE_RATE_DIR:-}
if [ -z "$work" ]; then
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
runs=${PARSE_RATE_RUNS:-3}
cc=${CC:-cc}

tools=()
for i in "${!libs[@]}"; do
    lib=${libs[$i]}
    [ -f "$lib" ] || { echo "parse-rate: no library $lib" >&2; exit 1; }
    "$cc" -O2 -std=c11 -I"$root/include" -I"$root/src" \
        -I"$root/build/include" \
        "$root/tools/bench/parse-rate.c" "$lib" \
        -Wl,--wrap=rt__reader_finish -lpng -lz -lm -lpthread \
        -o "$work/parse-rate-$i"
    tools+=("$work/parse-rate-$i")
done

for kind in scn obj nff; do
    file=$work/terrain-$n.$kind
    if [ ! -s "$file" ]; then
        if [ "$kind" = scn ]; then
            python3 "$root/tools/bench/terrain.py" "$n" >"$file"
        else
            python3 "$root/tools/bench/terrain.py" "--$kind" "$n" >"$file"
        fi
    fi
    cat "$file" >/dev/null
done

echo "| file | bytes | library | parse s | parse MB/s | load s | load MB/s | parse cpu s | parse cpu MB/s |"
echo "|---|---:|---|---:|---:|---:|---:|---:|---:|"
for kind in scn obj nff; do
    file=$work/terrain-$n.$kind
    for i in "${!tools[@]}"; do
        # parse-rate prints: FILE BYTES parse S s R MB/s load S s R MB/s
        # cpu S s R MB/s
        read -r _ bytes _ ps _ pr _ _ ls _ lr _ _ cs _ cr _ \
            < <("${tools[$i]}" "$file" "$runs")
        echo "| terrain-$n.$kind | $bytes | ${libs[$i]} | $ps | $pr | $ls |" \
             "$lr | $cs | $cr |"
    done
done
