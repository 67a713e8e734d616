#!/usr/bin/env bash
# mpi-model.sh - docs/mpi.md's model of rt-export-mpi's speed-up for a
# render of ROWS rows of WIDTH pixels on P nodes, one rank a node, each
# rank rendering with CORES threads (the defaults: 3840 x 2160 at 16
# samples, a balls-like scene, 32 cores a node, P = 1 8 64 512).
#
# Inputs, as environment variables (the defaults are what
# tools/bench/mpi-scaling.sh measured on a 2-core machine, see docs/mpi.md):
#   T_ROW   core-seconds for one row at 16 samples (the mean row)
#   PEAK    the costliest row's time over the mean row's
#   SETUP   seconds every rank spends on the scene before rendering
#           (parsing and building the octree; does not shrink with P)
#   SCENE   the bytes rank 0 broadcasts
#   SAVE    seconds rank 0 takes to write the image
#   ALPHA   seconds of latency a message (2e-6: InfiniBand; 5e-5: TCP)
#   BETA    bytes a second through one node's link (1e10: 100 Gb/s)
#   CORES   cores (threads) a node; ROWS, WIDTH: the image
#   BAND    rows a band (--band-rows); unset: rt-export-mpi's default
# The model (docs/mpi.md says why each term):
#   band   = BAND rows if set, else the default:
#            min(32, max(1, ceil(ROWS / (32 P)))) rows
#   render = ROWS T_ROW / (P CORES) + band T_ROW PEAK / CORES
#            (dynamic scheduling: the mean, plus at most one band late;
#            one node has no other to wait for)
#   bcast  = ceil(log2 P) (ALPHA + SCENE / BETA)  (a binomial tree)
#   gather = ROWS WIDTH 3 / BETA + 2 (ROWS / band) ALPHA  (all into rank
#            0's link; it overlaps the render: only what exceeds it counts)
#   T(P)   = SETUP + bcast + max(render, gather) + SAVE
set -euo pipefail
: "${T_ROW:=0.376}" "${PEAK:=1.9}" "${SETUP:=0.07}" "${SCENE:=443456}"
: "${SAVE:=0.06}" "${ALPHA:=2e-6}" "${BETA:=1e10}" "${CORES:=32}"
: "${ROWS:=2160}" "${WIDTH:=3840}"
awk -v t_row="$T_ROW" -v peak="$PEAK" -v setup="$SETUP" -v scene="$SCENE" \
    -v save="$SAVE" -v alpha="$ALPHA" -v beta="$BETA" -v cores="$CORES" \
    -v rows="$ROWS" -v width="$WIDTH" -v fixed_band="${BAND:-0}" \
    -v nodes="${*:-1 8 64 512}" '
function ceil(x) { return x == int(x) ? x : int(x) + 1 }
function model(p,   band, bands, render, bcast, gather, t) {
    band = ceil(rows / (32 * p)); band = band < 1 ? 1 : band > 32 ? 32 : band
    if (fixed_band > 0) band = fixed_band
    bands = ceil(rows / band)
    render = rows * t_row / (p * cores) + (p > 1 ? band * t_row * peak / cores : 0)
    bcast = p > 1 ? ceil(log(p) / log(2)) * (alpha + scene / beta) : 0
    gather = p > 1 ? rows * width * 3 / beta + 2 * bands * alpha : 0
    M_band = band; M_render = render; M_bcast = bcast; M_gather = gather
    M_tail = p > 1 ? band * t_row * peak / cores : 0
    t = setup + bcast + (render > gather ? render : gather) + save
    return t
}
BEGIN {
    printf "T_ROW %g s, PEAK %g, SETUP %g s, SCENE %d B, SAVE %g s, " \
           "ALPHA %g s, BETA %g B/s, %d cores a node, %d x %d\n\n",
           t_row, peak, setup, scene, save, alpha, beta, cores, width, rows
    printf "| nodes | band rows | render s | of which the late band s | " \
           "broadcast s | gather s | fixed s | total s | speed-up | " \
           "efficiency |\n"
    printf "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
    one = model(1)
    n = split(nodes, list, " ")
    for (i = 1; i <= n; i++) {
        p = list[i]; t = model(p)
        printf "| %d | %d | %.3f | %.3f | %.5f | %.4f | %.2f | %.3f | " \
               "%.1f | %.0f%% |\n", p, M_band, M_render, M_tail, M_bcast,
               M_gather, setup + save, t, one / t, 100 * one / t / p
    }
}'
