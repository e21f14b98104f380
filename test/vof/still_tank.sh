#!/usr/bin/env bash
# V3 still tank (config/scenes/still-tank.yaml): after the run the largest face velocity must be
# below 1e-12 of the gravity velocity scale sqrt(|g| H) (H: the box height), and the heavy phase's
# volume and bounds unchanged to 1e-12.
#   still_tank.sh VOFDEM RANKS SCENE [vofdem options...]
set -euo pipefail
exe=$1 ranks=$2 scene=$3; shift 3
out=$(mpiexec --oversubscribe -n "$ranks" "$exe" -options_file_yaml "$scene" -monitor_timing 0 "$@")
last=$(grep '^step ' <<<"$out" | tail -1)
echo "$last"
umax=$(sed -n 's/.*max|u_i| \([^ ]*\) m\/s.*/\1/p' <<<"$last")
dvol=$(sed -n 's/.*rel\. change \([^ ]*\) .*/\1/p' <<<"$last")
bound=$(sed -n 's/.*bounds \([^ ]*\) .*/\1/p' <<<"$last")
[ -n "$umax" ] && [ -n "$dvol" ] && [ -n "$bound" ] || { echo "still_tank: the last monitor line lacks max|u_i|, the volume change or the bounds"; exit 1; }
grav=$(sed -n 's/.*; gravity (\([^)]*\)) m\/s^2.*/\1/p' <<<"$out" | head -1 | tr -d ',')
box=$(sed -n 's/.*box \[\([^,]*\), \([^]]*\)\] x \[\([^,]*\), \([^]]*\)\] x \[\([^,]*\), \([^]]*\)\] m.*/\1 \2 \3 \4 \5 \6/p' <<<"$out" | head -1)
awk -v u="$umax" -v dv="$dvol" -v b="$bound" -v g="$grav" -v h="$box" 'BEGIN {
  split(g, gg, " "); split(h, hh, " "); gm = sqrt(gg[1]^2 + gg[2]^2 + gg[3]^2)
  d = 1; for (e = 2; e <= 3; ++e) if ((gg[e] < 0 ? -gg[e] : gg[e]) > (gg[d] < 0 ? -gg[d] : gg[d])) d = e
  H = hh[2 * d] - hh[2 * d - 1]; scale = sqrt(gm * H)  # H: the box along gravity
  r = u / scale; okU = (r < 1e-12); okV = ((dv < 0 ? -dv : dv) <= 1e-12); okB = (b + 0 <= 1e-12)
  printf "still tank: max|u_i| / sqrt(g H) = %.2e (tolerance 1e-12) %s; volume change %s (tolerance 1e-12) %s; bound violation %s %s\n", r, okU ? "ok" : "FAIL", dv, okV ? "ok" : "FAIL", b, okB ? "ok" : "FAIL"
  exit !(okU && okV && okB) }'
