# Sourced by scripts/demo, scripts/test, scripts/validate, scripts/strong-scaling: installs what is
# missing, configures and builds vofdem (Release) into build/, and sets up Open MPI for root.
set -euo pipefail
VOFDEM_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$VOFDEM_ROOT"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
# Debian's interpreter has numpy/matplotlib/h5py; the first python3 on PATH may not (notes).
VOFDEM_PYTHON=/usr/bin/python3
# Not nproc: it honours OMP_NUM_THREADS=1 and would report one core.
VOFDEM_CORES=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 2)

vofdem_build() {
  "$VOFDEM_ROOT/scripts/install-deps"
  local jobs; jobs=$VOFDEM_CORES
  cmake -S "$VOFDEM_ROOT" -B "$VOFDEM_ROOT/build" -DCMAKE_BUILD_TYPE=Release > "$VOFDEM_ROOT/build-configure.log" 2>&1 \
    || { cat "$VOFDEM_ROOT/build-configure.log"; echo "configuration failed (log above)" >&2; return 1; }
  cmake --build "$VOFDEM_ROOT/build" -j "$jobs"
}
