#!/bin/sh
# The STL-blade example (examples/ex16_stl_blade) on 2 ranks with particle and contact-network output,
# then the files checked: structurally against the HDF5 datasets (scripts/check-xdmf) and opened by
# ParaView's own reader (scripts/check-paraview; skipped with status 77 when ParaView is absent).
#   test/output/stl_blade_output.sh EXAMPLE_BINARY OUTPUT_DIR
set -e
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
root=$(cd "$(dirname "$0")/../.." && pwd)
example=$1 out=$2
rm -rf "$out" && mkdir -p "$out" && cd "$out"
mpiexec --oversubscribe --mca orte_abort_on_non_zero_status 1 -n 2 "$example" -physics dem -grid_cells 5,2,3 -grid_upper 0.01,0.003,0.006 \
  -gravity 0,0,-9.81 -dem_radius 3e-4 -dem_youngs_modulus 1e7 -dem_restitution 0.3 -dem_friction 0.5 -dem_fill_count -1 \
  -dem_fill_lower 0.003,0,0 -dem_fill_upper 0.01,0.003,0.0045 -dem_fill_jitter 0.5 -seed 3 -dem_walls blade -dem_wall_blade_type stl \
  -dem_wall_blade_file ex16_blade.stl -dem_wall_blade_scale 1e-3 -dem_save_particles ex16_bed.csv -grid_ranks 2,1,1 \
  -output_dir "$out/run" -dem_output_every 500 -dem_contacts_every 500 > screen.txt
tail -n 3 screen.txt
ls -l run
"$root/scripts/check-xdmf" run/particles.xmf run/contacts.xmf
"$root/scripts/check-paraview" run/particles.xmf run/contacts.xmf
