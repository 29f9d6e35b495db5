#!/usr/bin/env bash
# A test that cannot run here: says why and exits with ctest's skip code
# (SKIP_RETURN_CODE 77). Usage: skip-test.sh <reason>
echo "Skipped: $*."
exit 77
