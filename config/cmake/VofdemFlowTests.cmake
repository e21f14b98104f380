# The flow module (included by VofdemTests.cmake). Its examples (ex22-ex24, ex27) are example tests;
# here: bad input of the pressure solve's options and coefficients, run through ex23, and of -physics
# flow through the program.
function(vofdem_bad_input_pressure name regex)
  add_test(NAME badinput/${name} COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match ${regex} -- $<TARGET_FILE:ex23_pressure_iterations> -cells_list 8 ${ARGN})
  set_tests_properties(badinput/${name} PROPERTIES LABELS "quick;badinput" PROCESSORS 2 TIMEOUT 120)
endfunction()
vofdem_bad_input_pressure(pressure_density    "option -ratios: the pressure coefficient eps/rho must be positive and finite" -ratios -1000)
vofdem_bad_input_pressure(pressure_bc_unknown "option -flow_pressure_bc_xhi: unknown name 'outlet'" -flow_pressure_bc_xhi outlet)
vofdem_bad_input_pressure(pressure_bc_periodic "option -flow_pressure_bc_zlo: 'periodic' on a face that is not periodic" -flow_pressure_bc_zlo periodic)
vofdem_bad_input_pressure(pressure_pc_unknown "option -flow_pressure_pc: unknown name 'gamg'" -flow_pressure_pc gamg)
vofdem_bad_input_pressure(pressure_threshold  "option -flow_pressure_reuse_threshold: -1\\.? is out of range" -flow_pressure_reuse_threshold -1)
vofdem_bad_input_pressure(pressure_periodic_2 "the pressure solve needs at least 3 cells in the periodic direction x" -grid_periodic x -cells_list 2)

# F2 in the quick tier: the Re 100 cavity at 32^2 (t = 12 s, near steady), 1 and 2 ranks, within 1 % of
# the lid speed of Ghia et al. at the 17 stations (measured 0.26 % for u, 0.69 % for v at t = 15 s; a
# wrong viscosity, boundary or advection term moves the profile by several percent). 128^2 and Re 1000
# against Botella & Peyret are in the validate tier.
foreach(ranks 1 2)
  add_test(NAME flow/f2_cavity_re100_${ranks}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/cavity_run.sh $<TARGET_FILE:vofdem_app> ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/cavity-re100.yaml 100 0.01/0.01
                   -grid_cells 32,32,4 -grid_upper 1,1,0.125 -final_time 12)
  set_tests_properties(flow/f2_cavity_re100_${ranks} PROPERTIES LABELS "quick;flow" PROCESSORS ${ranks} TIMEOUT 600 ENVIRONMENT "VOFDEM_PYTHON=${VOFDEM_PYTHON}")
endforeach()
# -physics flow through the program (issue 4): inconsistent boundaries, non-positive properties, a
# grid too small for the ranks, options that -physics flow refuses. -max_steps 1: a check that let
# the input through would end the run at once (exit 0, and the test fails), not run on. A ";" of a
# message is "." in the patterns (CMake would split the argument there).
set(_flow -physics flow -grid_cells 8,8,8 -max_steps 1)
vofdem_bad_input(flow_inflow_closed   "option -flow_bc_xlo: inflow, but no face is outflow" ${_flow} -flow_bc_xlo inflow -flow_bc_xlo_velocity 1,0,0)
vofdem_bad_input(flow_viscosity_zero  "option -flow_viscosity: 0\\.? is out of range, must be in \\(0, inf\\]" ${_flow} -flow_viscosity 0)
vofdem_bad_input(flow_density_negative "option -flow_density: -1\\.? is out of range, must be in \\(0, inf\\]" ${_flow} -flow_density -1)
vofdem_bad_input(flow_grid_too_small  "option -grid_cells: the flow solver needs at least 2 cells per rank in each direction \\(or one cell across a non-periodic direction on one rank\\), but z has 2 cells on 2 ranks" ${_flow} -grid_cells 2,2,2)
vofdem_bad_input(flow_wall_normal     "option -flow_bc_xlo_velocity: a wall cannot move along its normal \\(x component 1\\.? m/s\\). use inflow" ${_flow} -flow_bc_xlo_velocity 1,0,0)
vofdem_bad_input(flow_inflow_outward  "option -flow_bc_xlo_velocity: an inflow must point into the box \\(x component -1\\.? m/s\\)" ${_flow} -flow_bc_xlo inflow -flow_bc_xlo_velocity -1,0,0 -flow_bc_xhi outflow)
vofdem_bad_input(flow_periodic_face   "option -flow_bc_xlo: 'periodic' needs x in -grid_periodic" ${_flow} -flow_bc_xlo periodic)
vofdem_bad_input(flow_face_of_periodic "option -flow_bc_xlo: 'wall' on a face of the periodic direction x" ${_flow} -grid_periodic x -flow_bc_xlo wall)
vofdem_bad_input(flow_pfmg_one_cell_y "option -flow_pressure_pc: pfmg cannot take one cell across y" ${_flow} -grid_cells 8,1,8 -flow_pressure_pc pfmg)
vofdem_bad_input(flow_pressure_bc     "option -flow_pressure_bc_xlo: with -physics flow the pressure boundaries follow -flow_bc_xlo \\(wall\\). do not set them" ${_flow} -flow_pressure_bc_xlo dirichlet)
# -physics dem,flow: the coupling's input (issue 7)
set(_coupled -physics dem,flow -grid_cells 8,8,8 -grid_upper 0.01,0.01,0.01 -dem_radius 2e-4 -dem_fill_count 1 -max_steps 1)
vofdem_bad_input(coupling_drag_unknown "option -coupling_drag: unknown name 'stokes'" ${_coupled} -coupling_drag stokes)
vofdem_bad_input(coupling_gaussian_too_wide "option -coupling_smoothing gaussian: its taps reach 5 points, more than the 4 a rank holds along z" ${_coupled} -coupling_smoothing gaussian -coupling_kernel_min_width 2)
vofdem_bad_input(coupling_kernel_narrow "option -coupling_kernel_min_width: 0.2 cells is below the cell size" ${_coupled} -coupling_kernel_min_width 0.2)
vofdem_bad_input(coupling_fraction_average_unknown "option -coupling_fraction_average: unknown name 'harmonic'" ${_coupled} -coupling_fraction_average harmonic)
vofdem_bad_input(coupling_lift_unknown "option -coupling_lift: unknown name 'saffman'" ${_coupled} -coupling_lift saffman)
vofdem_bad_input(coupling_rotational_correction_alone "option -coupling_rotational_drag_correction: needs -coupling_rotational_drag" ${_coupled} -coupling_rotational_drag_correction)
vofdem_bad_input(coupling_lubrication_twice "options -coupling_lubrication and -dem_lubrication_viscosity: the lubrication takes either the fluid's viscosity or a fixed one" ${_coupled} -coupling_lubrication -dem_lubrication_viscosity 1e-3)
vofdem_bad_input(coupling_particle_too_large "coupling: particles of diameter 0.012 m are larger than the box \\(0.01 m in x\\)" -physics dem,flow -grid_cells 8,8,8 -grid_upper 0.01,0.01,0.01 -dem_radius 6e-3 -max_steps 1)
vofdem_bad_input(flow_advection_unknown "option -flow_advection: unknown name 'quick' \\(known: upwind, central, minmod, vanleer, mc, superbee, koren\\)" ${_flow} -flow_advection quick)
vofdem_bad_input(flow_solid_box_count "option -flow_solid_boxes: 5 values is not a multiple of 6 \\(x0,y0,z0,x1,y1,z1 per box\\)" ${_flow} -flow_solid_boxes 0,0,0,1,1)
vofdem_bad_input(flow_solid_box_inverted "option -flow_solid_boxes: box 1 has upper y 0.1 not above lower 0.5" ${_flow} -flow_solid_boxes 0,0.5,0,1,0.1,1)
vofdem_bad_input(flow_solid_sphere_radius "option -flow_solid_spheres: sphere 2 has radius 0\\.?, must be positive" ${_flow} -flow_solid_spheres 0.5,0.5,0.5,0.1,0.5,0.5,0.5,0)
vofdem_bad_input(flow_solid_outside   "options -flow_solid_boxes/-flow_solid_spheres: no cell centre lies inside the solids given" ${_flow} -flow_solid_spheres 5,5,5,1)
vofdem_bad_input(flow_solid_everything "options -flow_solid_boxes/-flow_solid_spheres: every cell is solid, no fluid is left" ${_flow} -flow_solid_boxes -1,-1,-1,2,2,2)
vofdem_bad_input(flow_ksp_type_unknown "Unable to find requested KSP type foo \\(a PETSc solver option. -help lists the choices\\)" ${_flow} -flow_viscous_ksp_type foo)
vofdem_bad_input(flow_pfmg_relax_unknown "Unknown option foo for -flow_pressure_pc_pfmg_relax_type" ${_flow} -flow_pressure_pc_pfmg_relax_type foo)

# The flow solvers' KSP options are read in the module's set-up: they must not be taken for typos.
add_test(NAME flow/solver_options_accepted COMMAND mpiexec -n 2 $<TARGET_FILE:vofdem_app> ${_flow} -gravity 0,0,0 -dt 0.01 -flow_bc_zhi_velocity 1,0,0
         -flow_pressure_ksp_rtol 1e-9 -flow_viscous_ksp_rtol 1e-11 -flow_viscous_ksp_type gmres)
set_tests_properties(flow/solver_options_accepted PROPERTIES LABELS "quick;flow" PROCESSORS 2 TIMEOUT 120
                     ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")

# scripts/work-precision (speed against error, docs/verification.md): its parsers and case entries.
add_test(NAME unit/work_precision COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/unit/test_work_precision.py)
set_tests_properties(unit/work_precision PROPERTIES LABELS "quick;unit" TIMEOUT 60)

# Grid results agree across rank counts to round-off: the Re 1000 cavity scene (strong advection, so the
# TVD limiter's branches are exercised) at 32^2 for 60 steps of fixed dt on 1, 2 and 4 ranks.
add_test(NAME flow/rank_agreement
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/rank_agreement.sh $<TARGET_FILE:vofdem_app> ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/cavity-re1000.yaml 1e-10
                 -grid_cells 32,32,4 -grid_upper 1,1,0.125 -dt 0.01 -max_steps 60 -monitor_every 60)
set_tests_properties(flow/rank_agreement PROPERTIES LABELS "quick;flow" PROCESSORS 2 TIMEOUT 600 ENVIRONMENT "VOFDEM_PYTHON=${VOFDEM_PYTHON}")
# Solid cells (SolidMask.hpp): the same agreement across ranks with a box on the floor, one on the
# right wall and a sphere in the cavity; and a closed tank at rest with solids stays at rest.
add_test(NAME flow/solid_rank_agreement
         COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/rank_agreement.sh $<TARGET_FILE:vofdem_app> ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/cavity-re1000.yaml 1e-10
                 -grid_cells 32,32,4 -grid_upper 1,1,0.125 -dt 0.01 -max_steps 60 -monitor_every 60
                 -flow_solid_boxes 0.3,0,-1,0.55,0.4,1,0.7,0.6,-1,1.1,0.75,1 -flow_solid_spheres 0.5,0.5,0.0625,0.15)
set_tests_properties(flow/solid_rank_agreement PROPERTIES LABELS "quick;flow" PROCESSORS 2 TIMEOUT 600
                     ENVIRONMENT "VOFDEM_PYTHON=${VOFDEM_PYTHON};OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")
# 16^3 takes PFMG, 15^3 (odd) BoomerAMG: both with the solid cells' identity rows.
foreach(ranks 1 2 amg)
  set(_n 16,16,16)
  set(_r ${ranks})
  if(ranks STREQUAL "amg")
    set(_n 15,15,15)
    set(_r 2)
  endif()
  add_test(NAME flow/solid_still_tank_${ranks}
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/still_tank.sh $<TARGET_FILE:vofdem_app> ${_r} 1e-10
                   -grid_cells ${_n} -flow_density 1000 -gravity 0,0,-9.81 -max_steps 100 -monitor_every 100
                   -flow_solid_spheres 0.5,0.5,0.5,0.25 -flow_solid_boxes 0,0,0,0.3,1,0.2
                   -flow_pressure_ksp_rtol 1e-12 -flow_viscous_ksp_rtol 1e-12)
  set_tests_properties(flow/solid_still_tank_${ranks} PROPERTIES LABELS "quick;flow" PROCESSORS ${_r} TIMEOUT 300
                       ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")
endforeach()
# A solve that does not converge (two iterations allowed) ends every rank with one line, not a trace or a hang.
vofdem_bad_input_pressure(pressure_not_converged "pressure solve did not converge: DIVERGED_ITS after 2 iterations" -flow_pressure_ksp_max_it 2)

# A coupled run's first step when an inflow meets particles present at the start (Simulation::SetUp): the initial
# velocity projected with the particles' eps, the first step chosen from the pores' speed (bubbling-bed scene, 1 and 2 ranks).
add_test(NAME coupling/first_step_cfl COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_first_step_cfl.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/first_step_cfl PROPERTIES LABELS "quick;coupling" PROCESSORS 2 TIMEOUT 300)
# d(eps)/dt when the step changes (issue 55): a last step shortened 5x, and one of 2e-9 s, move a settling sphere
# toward the finer step's velocity and not past it; monitor.csv gives the step taken.
add_test(NAME coupling/eps_rate_step_change COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_eps_rate_step_change.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/eps_rate_step_change PROPERTIES LABELS "quick;coupling" PROCESSORS 2 TIMEOUT 300)
# -flow_courant cell: the 16^3 cavity takes fewer, never shorter steps than with the box's measure, its kinetic energy at
# t = 3 as close to a 10x finer step's as the box's, 1 and 2 ranks the same steps.
add_test(NAME flow/courant_cell COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/test_courant_cell.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(flow/courant_cell PROPERTIES LABELS "quick;flow" PROCESSORS 2 TIMEOUT 300)
# G5 under dem,flow: a lattice bed on the inflow face rests at 0.95 and lifts at 1.05 of Terzaghi's critical gradient (the
# water's force on the bed from two static runs, within 5 % of Ergun's), 1 and 2 ranks.
add_test(NAME coupling/heave_flow COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_heave_flow.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/heave_flow PROPERTIES LABELS "quick;coupling" PROCESSORS 2 TIMEOUT 300)
