#!/usr/bin/env bash
# test_mpi_same.sh - rt-export and rt-export-mpi run one export pipeline
# (apps/common/cli_export.h): for the same bad scene, bad option or bad
# output, rt-export-mpi -np 2 says what rt-export says, word for word but
# for the program's name, and exits with the same status; a scene holding
# a NUL byte is refused by both (it is binary), never rendered in part.
# The environment gives the programs: RT_EXPORT, RT_EXPORT_MPI, MPIEXEC,
# RT_SOURCE_DIR (mpi_session.sh starts the ranks).
. "$(dirname "$0")/mpi_session.sh"

printf '8,-8,-3\n3,-3,-1, 3,-9,0, 40,40\n3\n-1,-1,0\n1,x,0\n0,1,0\n' \
    > bad.scn
printf '8,-8,-3\n\0 a binary tail\n' > nul.scn
cp "$scenes/cubes.scn" own.scn
mkdir folder

# same ARGS...: the first line of each program's stderr, the name replaced,
# and the exit status
same() {
    "$RT_EXPORT" -q "$@" >export.out 2>export.err
    local want=$?
    timeout 60 "${launcher[@]}" -np 2 "$RT_EXPORT_MPI" -q "$@" \
        >mpi.out 2>mpi.err
    local got
    got=$(sed -n 's/^ *Exit code: *//p' mpi.err | head -n 1)
    [ -n "$got" ] || got=0
    local expected
    expected=$(head -n 1 export.err | sed 's/^rt-export: /rt-export-mpi: /')
    [ -n "$expected" ] || fail "$*: rt-export said nothing"
    grep -qxF -- "$expected" mpi.err ||
        { cat mpi.err; fail "$*: expected '$expected'"; }
    [ "$(grep -c '^rt-export-mpi: ' mpi.err)" -eq 1 ] ||
        { cat mpi.err; fail "$*: more than one message"; }
    [ "$got" -eq "$want" ] || fail "$*: exit $got, rt-export's $want"
    echo "ok: $* -> $expected ($want)"
}

same bad.scn -o bad.ppm
same nul.scn -o nul.ppm
same missing.scn -o missing.ppm
same folder -o folder.ppm
same own.scn --format p6 -o own.scn
same "$scenes/cubes.scn" --region 0,0,500,10 -o region.ppm
same "$scenes/cubes.scn" -o nowhere/out.ppm
same "$scenes/cubes.scn" -o out.gif
for image in bad.ppm nul.ppm missing.ppm folder.ppm region.ppm; do
    [ ! -e "$image" ] || fail "$image was written"
done
cmp -s own.scn "$scenes/cubes.scn" || fail "own.scn was changed"
echo "ok: the same words"
