# mpi_session.sh - sourced by the MPI suites (test_mpi.sh, test_mpi_same.sh):
# a fresh folder to work in (removed at exit), the launcher to start ranks
# with, and fail.  Open MPI needs --oversubscribe to start more ranks than
# cores, and leave to run as root (CI runs as root).  Reads MPIEXEC and
# RT_SOURCE_DIR; sets scenes, work and launcher.
set -u
scenes=$RT_SOURCE_DIR/scenes
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

launcher=("$MPIEXEC")
if "$MPIEXEC" --version 2>&1 | grep -q -i -e 'Open MPI' -e 'OpenRTE'; then
    launcher+=(--oversubscribe)
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    # no ssh or rsh needed (a fresh CI machine has none): every rank is
    # local, so the agent, which must exist, is never called
    export OMPI_MCA_plm_rsh_agent=false
    # a container may forbid the cross-memory attach (ptrace) that shared
    # memory uses for large messages: plain copies work everywhere
    export OMPI_MCA_btl_vader_single_copy_mechanism=none
fi

fail() { echo "FAIL: $*" >&2; exit 1; }
