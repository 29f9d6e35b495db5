#!/usr/bin/env bash
# The ParaView GUI test: runs TestParaViewGui.py inside `paraview` under
# xvfb-run and reports what the script found.
# Usage: TestParaViewGui.sh <paraview> <plugin .so> <baseline .png> <work folder>
set -uo pipefail
paraview=$1 plugin=$2 baseline=$3 work=$4
mkdir -p "$work"
rm -f "$work/result.txt"
# (HOME: the presets the plugin registers are saved with ParaView's user
# settings; the test keeps its own, fresh each run.)
rm -rf "$work/home"
mkdir -p "$work/home"
export HOME="$work/home"
export TPC_PLUGIN="$plugin" TPC_BASELINE="$baseline" TPC_RESULT="$work/result.txt" TPC_SHOT="$work/screenshot.png"
timeout 300 bash "$(dirname "$0")/../xvfb-run-retry.sh" -a -n 150 -s "-screen 0 1280x1024x24" "$paraview" --dr \
  --script="$(dirname "$0")/TestParaViewGui.py" --exit > "$work/paraview.log" 2>&1
cat "$work/result.txt" 2>/dev/null || { echo "FAIL: the GUI script did not report (see $work/paraview.log)"; exit 1; }
grep -q '^PASS' "$work/result.txt"
