#!/usr/bin/env bash
# xvfb-run "$@", run again (up to 3 times) when the program could not reach
# the X server it was given: "bad X server connection" has appeared now and
# then in the X tests (2026-11, on several display numbers, never twice in a
# row), while the tests themselves never failed otherwise.
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3; do
  xvfb-run "$@" 2>&1 | tee "$log"
  rc=${PIPESTATUS[0]}
  if [ "$rc" -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    exit "$rc"
  fi
  echo "xvfb-run-retry: the X server was unreachable (attempt $attempt of 3)" >&2
  sleep 3
done
exit "$rc"
