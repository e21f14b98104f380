#!/usr/bin/env bash
# F2: runs a lid-driven cavity scene to (near) steady state and checks its centre lines against the
# reference of its Reynolds number (test/flow/cavity_profile_check.py; exits non-zero when off by
# more than the tolerance, a fraction of the lid speed). TOLERANCE may be TOL/EXTREMA_TOL: then the
# extrema of the profiles must also lie within EXTREMA_TOL of the grid-converged values.
#   cavity_run.sh VOFDEM RANKS SCENE RE TOLERANCE[/EXTREMA_TOL] [vofdem options...]
set -euo pipefail
exe=$1 ranks=$2 scene=$3 re=$4 tol=$5; shift 5
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
py=${VOFDEM_PYTHON:-/usr/bin/python3}
mpiexec --oversubscribe -n "$ranks" "$exe" -options_file_yaml "$scene" -flow_profile_output "$work/profile.csv" -monitor_timing 0 "$@" | tail -3
extrema=()
if [[ $tol == */* ]]; then extrema=(--extrema-tolerance "${tol#*/}"); tol=${tol%%/*}; fi
"$py" "$here/cavity_profile_check.py" "$work/profile.csv" --re "$re" --tolerance "$tol" "${extrema[@]}"
