#!/usr/bin/env bash
# test_mpi.sh - rt-export-mpi as a user runs it under mpirun:
#   test_mpi.sh exact N      -np N gives rt-export's image, byte for byte
#   test_mpi.sh bad-scene    one message, from rank 0, naming line and
#                            column; the job fails; no image
#   test_mpi.sh usage        a usage error: one message, exit status 2
#   test_mpi.sh killed-rank  kill -9 of a worker mid-render fails the job
#                            and leaves no image and no temporary file
#   test_mpi.sh own-input    -o naming the scene (or a link to it) is
#                            refused, naming both; the scene intact
#   test_mpi.sh rescue       a save that fails after the render (a full
#                            device) keeps the image in $TMPDIR, byte for
#                            byte rt-export's
#   test_mpi.sh libraries    an OBJ's material library is rank 0's on every
#                            rank: workers started in another folder, which
#                            holds another library or none, render the
#                            bytes rt-export renders
#   test_mpi.sh mismatch     a worker given another command line builds
#                            another scene: the job fails with a message
#                            from that rank, and writes no image
# The environment gives the programs: RT_EXPORT, RT_EXPORT_MPI, MPIEXEC,
# RT_SOURCE_DIR (mpi_session.sh starts the ranks).
mode=$1
. "$(dirname "$0")/mpi_session.sh"

# same NAME NP OPTIONS...: rt-export and rt-export-mpi -np NP (with
# $bands, its own option, too), compared.
same() {
    local name=$1 np=$2
    shift 2
    "$RT_EXPORT" -q "$@" -o "ref-$name" >/dev/null || fail "rt-export $*"
    timeout 60 "${launcher[@]}" -np "$np" "$RT_EXPORT_MPI" -q "$@" \
        --band-rows "${bands:-0}" -o "mpi-$name" >/dev/null ||
        fail "rt-export-mpi -np $np $*"
    cmp -s "ref-$name" "mpi-$name" ||
        fail "-np $np $*: not rt-export's image"
    echo "ok: -np $np $* (bands of ${bands:-auto} rows)"
}

case $mode in
exact)
    np=$2
    # small images, many bands: a few seconds even under ASan
    same mirror.ppm "$np" "$scenes/mirror.scn" --size 240x180 -j 1
    bands=7 same mirror2.ppm "$np" "$scenes/mirror.scn" --size 160x240 -j 2
    same cubes.png "$np" "$scenes/cubes.scn" --samples 4 \
        --sampling stratified --region 37,50,201,203 -j 1
    bands=1 same glass.ppm "$np" "$scenes/glass.scn" --size 123x77 --depth 3
    # the scene from rank 0's standard input
    timeout 60 "${launcher[@]}" -np "$np" "$RT_EXPORT_MPI" -q - \
        --size 90x70 -o stdin.ppm < "$scenes/cubes.scn" >/dev/null ||
        fail "-np $np: a scene from standard input"
    "$RT_EXPORT" -q "$scenes/cubes.scn" --size 90x70 -o ref-stdin.ppm
    cmp -s ref-stdin.ppm stdin.ppm || fail "-np $np: standard input differs"
    echo "ok: -np $np a scene from standard input"
    ;;
bad-scene)
    printf '8,-8,-3\n3,-3,-1, 3,-9,0, 40,40\n3\n-1,-1,0\n1,x,0\n0,1,0\n' \
        > bad.scn
    timeout 60 "${launcher[@]}" -np 3 "$RT_EXPORT_MPI" bad.scn -o bad.ppm \
        >out.txt 2>err.txt && fail "a bad scene exited 0"
    cat err.txt
    count=$(grep -c 'bad.scn:5:3:' err.txt)
    [ "$count" -eq 1 ] || fail "expected one bad.scn:5:3 message, found $count"
    [ ! -e bad.ppm ] || fail "an image was written"
    ;;
usage)
    # usage errors: one message (rank 0's), exit status 2, no image
    for args in "--depth x" "-o -" "--band-rows -1"; do
        # shellcheck disable=SC2086
        timeout 60 "${launcher[@]}" -np 3 "$RT_EXPORT_MPI" $args \
            "$scenes/cubes.scn" >out.txt 2>err.txt && fail "$args exited 0"
        count=$(grep -c '^rt-export-mpi: ' err.txt)
        [ "$count" -eq 1 ] || { cat err.txt; fail "$args: $count messages"; }
        grep -q "Exit code: *2" err.txt || { cat err.txt; fail "$args: not 2"; }
        [ ! -e cubes.ppm ] || fail "$args: an image was written"
        echo "ok: $args: $(head -n 1 err.txt)"
    done
    ;;
killed-rank)
    # about 20 s of work for 3 ranks on 2 cores: the kill comes long before
    timeout 60 "${launcher[@]}" -np 3 "$RT_EXPORT_MPI" -q \
        "$scenes/mirror.scn" --size 900x900 --samples 16 -j 1 \
        -o killed.ppm >out.txt 2>err.txt &
    job=$!
    victim=
    for _ in $(seq 100); do     # the rank 1 process among the job's
        sleep 0.1
        for pid in $(pgrep -P "$(pgrep -P $job -d, || echo $job)" 2>/dev/null) \
                   $(pgrep -P $job 2>/dev/null); do
            if tr '\0' '\n' < "/proc/$pid/environ" 2>/dev/null |
                grep -qx 'OMPI_COMM_WORLD_RANK=1\|PMI_RANK=1'; then
                victim=$pid
            fi
        done
        [ -n "$victim" ] && break
    done
    [ -n "$victim" ] || { kill $job; fail "rank 1 was not found"; }
    sleep 1.5                   # mid-render
    kill -9 "$victim"
    echo "killed rank 1 (pid $victim)"
    wait $job && fail "the job exited 0 after a rank was killed"
    cat err.txt
    grep -q -i -e 'signal 9' -e 'killed' -e 'abort' err.txt ||
        fail "no message about the dead rank"
    [ ! -e killed.ppm ] || fail "an image was written"
    leftovers=$(ls -A | grep -v -x -e out.txt -e err.txt)
    [ -z "$leftovers" ] || fail "left behind: $leftovers"
    ;;
own-input)
    # the scene by its name and through links: refused, naming both, and
    # the scene intact
    cp "$scenes/cubes.scn" s.scn
    ln -s s.scn link.scn
    ln s.scn hard.scn
    for out in s.scn link.scn hard.scn; do
        timeout 60 "${launcher[@]}" -np 2 "$RT_EXPORT_MPI" -q s.scn \
            --format p6 -o "$out" >out.txt 2>err.txt &&
            fail "-o $out exited 0"
        grep -qx "rt-export-mpi: $out: refusing to write the image over \
s.scn, the scene it comes from (the same file)" err.txt ||
            { cat err.txt; fail "-o $out: no refusal naming both"; }
        cmp -s s.scn "$scenes/cubes.scn" || fail "-o $out changed the scene"
        echo "ok: -o $out refused"
    done
    ;;
rescue)
    # a save that fails after the render keeps the image: /dev/full takes
    # the check (it opens for writing) and refuses the bytes
    [ -w /dev/full ] || { echo "skipped: no /dev/full"; exit 77; }
    mkdir tmp
    TMPDIR=$work/tmp timeout 60 "${launcher[@]}" -np 2 "$RT_EXPORT_MPI" -q \
        "$scenes/cubes.scn" --size 90x70 --format p6 -o /dev/full \
        >out.txt 2>err.txt && fail "a full device exited 0"
    cat err.txt
    grep -q "^rt-export-mpi: /dev/full: cannot write the image: " err.txt ||
        fail "no message about the failed save"
    kept=$(sed -n 's/^rt-export-mpi: the image is kept in //p' err.txt)
    case $kept in
    "$work"/tmp/full.rescue-??????.ppm) ;;
    *) fail "kept as '$kept', expected $work/tmp/full.rescue-XXXXXX.ppm" ;;
    esac
    "$RT_EXPORT" -q "$scenes/cubes.scn" --size 90x70 --format p6 -o ref.ppm
    cmp -s ref.ppm "$kept" || fail "the kept image is not rt-export's"
    echo "ok: kept in $kept, byte for byte rt-export's image"
    ;;
libraries)
    # rank 0 here, the other two ranks in other/: there the same OBJ names
    # a library that is blue, or that is not there at all
    mkdir -p model other/model bare/model
    printf 'mtllib m.mtl\nusemtl red\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n'\
'f 1 2 4 3\n' > model/m.obj
    printf 'newmtl red\nKd 1 0 0\n' > model/m.mtl
    cp model/m.obj other/model/m.obj
    cp model/m.obj bare/model/m.obj
    printf 'newmtl red\nKd 0 0 1\n' > other/model/m.mtl
    args=(-q model/m.obj --size 64x48 --band-rows 2 -j 1)
    "$RT_EXPORT" "${args[@]:0:4}" -o ref-lib.ppm >/dev/null ||
        fail "rt-export"
    for elsewhere in other bare; do
        timeout 60 "${launcher[@]}" -np 1 "$RT_EXPORT_MPI" "${args[@]}" \
            -o "mpi-$elsewhere.ppm" : -np 2 -wdir "$work/$elsewhere" \
            "$RT_EXPORT_MPI" "${args[@]}" -o "mpi-$elsewhere.ppm" \
            >out.txt 2>err.txt || { cat err.txt; fail "$elsewhere: exit"; }
        cmp -s ref-lib.ppm "mpi-$elsewhere.ppm" ||
            fail "workers in $elsewhere/ rendered another picture"
        echo "ok: workers in $elsewhere/: rank 0's library, rt-export's bytes"
    done
    ;;
mismatch)
    args=(-q "$scenes/cubes.scn" --size 64x48 -j 1)
    timeout 60 "${launcher[@]}" -np 1 "$RT_EXPORT_MPI" "${args[@]}" \
        -o mismatch.ppm : -np 1 "$RT_EXPORT_MPI" "${args[@]}" \
        --look-from 9,9,9 -o mismatch.ppm >out.txt 2>err.txt &&
        fail "ranks with different scenes exited 0"
    cat err.txt
    grep -q "rank 1: .*is not rank 0's" err.txt ||
        fail "no message from the rank whose scene differs"
    [ ! -e mismatch.ppm ] || fail "an image was written"
    ;;
*)
    echo "usage: test_mpi.sh exact N | bad-scene | usage | killed-rank |" \
         "own-input | rescue | libraries | mismatch" >&2
    exit 2
    ;;
esac
echo "ok: $mode"
