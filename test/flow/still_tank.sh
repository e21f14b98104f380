#!/usr/bin/env bash
# A closed tank of fluid at rest under gravity must stay at rest: after the run the largest face
# velocity (the monitor's max|u_i| at the last step) must be below TOL (m/s). With solid cells inside
# (-flow_solid_boxes/-flow_solid_spheres) this checks that the hydrostatic pressure, the projection
# and the blocked faces agree: a solid face left falling in the initial pressure gave 8e-6 m/s.
#   still_tank.sh VOFDEM RANKS TOL [vofdem options...]
set -euo pipefail
exe=$1 ranks=$2 tol=$3; shift 3
out=$(mpiexec --oversubscribe -n "$ranks" "$exe" -physics flow -monitor_timing 0 "$@")
last=$(grep '^step ' <<<"$out" | tail -1)
echo "$last"
umax=$(sed -n 's/.*max|u_i| \([^ ]*\) m\/s.*/\1/p' <<<"$last")
[ -n "$umax" ] || { echo "still_tank: no max|u_i| in the last monitor line"; exit 1; }
awk -v u="$umax" -v t="$tol" 'BEGIN { ok = (u + 0 < t + 0); printf "still tank: max|u_i| = %s m/s after the run (tolerance %s) %s\n", u, t, ok ? "ok" : "FAIL"; exit !ok }'
