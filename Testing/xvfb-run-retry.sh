#!/usr/bin/env bash
# xvfb-run "$@", run again (up to 3 times) when the program could not reach
# the X server it was given: "bad X server connection" has appeared now and
# then in the X tests (2026-11, on several display numbers, never twice in a
# row), while the tests themselves never failed otherwise.
#
# With --hang-seconds N first, an attempt still running after N seconds is
# stopped (with everything it started) and run again too: ParaView 5.11's
# parallel render under `mpirun -np 2 pvbatch` deadlocked now and then
# (2026-12-04, twice in four runs on a loaded machine, after every check of
# the filter had passed): rank 0 in IceT's MPI_Comm_dup
# (vtkIceTCompositePass::Render -> icetCreateMPICommunicator) while rank 1
# waited in vtkMultiProcessController::ProcessRMIs for the render's RMI.
set -u
hang=()
if [ "${1:-}" = "--hang-seconds" ]; then
  hang=(timeout --kill-after=10 "$2")
  shift 2
fi
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3; do
  "${hang[@]}" xvfb-run "$@" 2>&1 | tee "$log"
  rc=${PIPESTATUS[0]}
  if [ "${#hang[@]}" -gt 0 ] && { [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; }; then
    echo "xvfb-run-retry: still running after ${hang[2]} s, stopped (attempt $attempt of 3)" >&2
  elif [ "$rc" -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    exit "$rc"
  else
    echo "xvfb-run-retry: the X server was unreachable (attempt $attempt of 3)" >&2
  fi
  sleep 3
done
exit "$rc"
