# The VOF module (included by VofdemTests.cmake). Its examples (ex28 V1, ex29 V2) are example tests;
# here: the two-phase scenes through the program.

# V3 still tank at density ratios 1000 and 8000 on 1 and 2 ranks, 1000 steps: max|u| below 1e-12 of
# sqrt(g H), volume and bounds to 1e-12.
foreach(ratio 1000 8000)
  foreach(ranks 1 2)
    add_test(NAME vof/v3_still_tank_${ratio}_${ranks}
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/vof/still_tank.sh $<TARGET_FILE:vofdem_app> ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/still-tank.yaml
                     -vof_density ${ratio})
    set_tests_properties(vof/v3_still_tank_${ratio}_${ranks} PROPERTIES LABELS "quick;vof" PROCESSORS ${ranks} TIMEOUT 600
                         ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")
  endforeach()
endforeach()

set(_vof -physics flow,vof -grid_cells 8,8,8 -max_steps 1)
vofdem_bad_input(vof_boxes_count   "option -vof_boxes: give 6 numbers per box" ${_vof} -vof_boxes 0,0,0,1,1)
vofdem_bad_input(vof_normals       "option -vof_normals: unknown name 'lvira'" ${_vof} -vof_normals lvira)
vofdem_bad_input(vof_cfl           "option -vof_cfl: 0.6 is out of range" ${_vof} -vof_cfl 0.6)

# Bad input of the V4 and rising-bubble examples' own options: one line, every rank non-zero.
foreach(_ex ex39_capillary_wave ex40_rising_bubble)
  add_test(NAME badinput/${_ex}_resolution COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match "option -resolution: give an even number"
           -- $<TARGET_FILE:${_ex}> -resolution 7)
  set_tests_properties(badinput/${_ex}_resolution PROPERTIES LABELS "quick;badinput" PROCESSORS 2 TIMEOUT 120)
endforeach()
vofdem_bad_input(vof_momentum      "option -vof_momentum: unknown name 'lagrangian'" ${_vof} -vof_momentum lagrangian)
vofdem_bad_input(viscous_transpose "option -flow_viscous_transpose implicit: needs -flow_viscous implicit" ${_vof} -flow_viscous explicit -flow_viscous_transpose implicit)
vofdem_bad_input(vof_momentum_central "option -flow_advection central: unbounded and unstable" ${_vof} -gravity 0,0,-9.81 -vof_boxes 0,0,0,1,1,0.5 -flow_advection central)

# The explicit div(mu grad U^T) limit across a viscosity jump is applied and reported (FlowViscousLimit.cpp):
# still tank with mu_1 = 1 Pa s against air (1.8e-5 Pa s, 1 kg/m^3), h = 1/16 in all three directions,
# the interface row half full (alpha 0.5, mu_m = 0.500009 Pa s). The worst row is a face of pure air next to
# it: its edge values toward the interface average two air and two half cells, (mu_a + mu_m)/2, so the
# row's values span (mu_m - mu_a)/2 and its Gershgorin sum is 3 (mu_m - mu_a)/h^2 over rho = 1:
# dt = 1/(3 x 0.499991 x 256) = 2.60421e-3 s, below the gravity limit (0.05 s), so it sets the step.
add_test(NAME vof/viscous_limit
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/still-tank.yaml -vof_viscosity 1 -max_steps 2
                 -flow_viscous_transpose explicit)
set_tests_properties(vof/viscous_limit PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120
                     PASS_REGULAR_EXPRESSION "time step limits: flow 0\\.00260421 s \\(flow explicit transpose viscous term.*time step: 0\\.00260421 s \\(set by flow explicit transpose viscous term"
                     ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")

# The same tank with the default -flow_viscous_transpose auto (the term implicit where mu varies,
# FlowViscousCoupled.cpp): no viscous limit; the gravity limit sqrt(cfl h/|g|) = sqrt(0.4/16/9.81) = 0.0504819 s sets the step.
add_test(NAME vof/viscous_transpose_implicit
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/still-tank.yaml -vof_viscosity 1 -max_steps 2)
set_tests_properties(vof/viscous_transpose_implicit PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120
                     PASS_REGULAR_EXPRESSION "flow viscous transpose: implicit where the viscosity varies.*time step limits: flow 0\\.0504819 s \\(flow gravity"
                     ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")

# V7 (issue 9): ex42's own options, and the two scenes of the particle-laden dam break load and step
# (the coupled scene with a few poured beads instead of bed.csv, at the unresolved mode's cells).
add_test(NAME badinput/ex42_particle_dam_break_mode COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match "option -mode: 'coarse' is neither semi nor unresolved"
         -- $<TARGET_FILE:ex42_particle_dam_break> -mode coarse)
add_test(NAME badinput/ex42_particle_dam_break_layer COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match "option -layer_height: 0.5 m is outside the tank"
         -- $<TARGET_FILE:ex42_particle_dam_break> -layer_height 0.5)
# ex41 (issue 9, wettability): an angle it cannot check (a sphere can float deep in water below 90 deg).
add_test(NAME badinput/ex41_floating_sphere_angle COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match "ex41: option -angle 45\\.?: checked cases are 0, 90 to 180"
         -- $<TARGET_FILE:ex41_floating_sphere> -angle 45)
set_tests_properties(badinput/ex42_particle_dam_break_mode badinput/ex42_particle_dam_break_layer badinput/ex41_floating_sphere_angle PROPERTIES LABELS "quick;badinput" PROCESSORS 2 TIMEOUT 120)
add_test(NAME vof/particle_dam_break_bed_scene
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/particle-dam-break-bed.yaml -max_steps 20 -monitor_every 20)
add_test(NAME vof/particle_dam_break_scene
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/particle-dam-break.yaml -grid_cells 25,12,37 -coupling_kernel unresolved
                 -dem_fill_mode random -dem_fill_count 100 -dem_fill_upper 0.05,0.1,0.02 -dem_output_every 0 -flow_output_every 0 -max_steps 3)
add_test(NAME vof/sphere_entry_scene
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/sphere-entry.yaml -flow_output_every 0 -dem_output_every 0 -max_steps 20 -monitor_every 20)
set_tests_properties(vof/sphere_entry_scene PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120 PASS_REGULAR_EXPRESSION "step +20 .*particles 1 .*finished after 20 steps")
set_tests_properties(vof/particle_dam_break_bed_scene PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120 PASS_REGULAR_EXPRESSION "particles 3883 .*finished after 20 steps")
set_tests_properties(vof/particle_dam_break_scene PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120 PASS_REGULAR_EXPRESSION "coupling: kernel unresolved.*fluid side implicit.*finished after 3 steps")

# Static contact angles (-vof_contact_angle, src/vof/VofContactAngle.cpp; ex37 is the sessile drop).
set(_vof_ca -physics flow,vof -grid_cells 8,8,8 -max_steps 1)
vofdem_bad_input(vof_contact_angle_range "option -vof_contact_angle: 180 is out of range" ${_vof_ca} -vof_contact_angle 180)
vofdem_bad_input(vof_contact_angle_zero  "option -vof_contact_angle: 0 is out of range" ${_vof_ca} -vof_contact_angle 60,0,90,90,90,90)
vofdem_bad_input(vof_contact_angle_count "option -vof_contact_angle: give one angle or six" ${_vof_ca} -vof_contact_angle 60,60)
vofdem_bad_input(vof_contact_angle_face  "option -vof_contact_angle_faces: unknown name 'floor'" ${_vof_ca} -vof_contact_angle 60 -vof_contact_angle_faces floor)
vofdem_bad_input(vof_contact_angle_alone "option -vof_contact_angle_faces: needs -vof_contact_angle" ${_vof_ca} -vof_contact_angle_faces zlo)
vofdem_bad_input(vof_contact_angle_periodic "option -vof_contact_angle_faces: face xlo is periodic" ${_vof_ca} -grid_periodic x -vof_contact_angle 60 -vof_contact_angle_faces xlo)
vofdem_bad_input(vof_contact_angle_open  "option -vof_contact_angle: face zhi is outflow \\(-flow_bc_zhi\\)" ${_vof_ca} -flow_bc_zhi outflow -vof_contact_angle 60 -vof_contact_angle_faces zlo,zhi)
vofdem_bad_input(vof_contact_angle_thin  "option -vof_contact_angle: face ylo needs at least 4 cells across the box in y, got 2" -physics flow,vof -grid_cells 8,2,8 -max_steps 1 -vof_contact_angle 60)

# Open faces (-vof_bc_<face>_alpha[_band], src/vof/VofOpenFaces.cpp; ex46 is the open channel).
set(_vof_open -physics flow,vof -grid_cells 8,8,8 -max_steps 1 -flow_bc_xlo inflow -flow_bc_xlo_velocity 1,0,0 -flow_bc_xhi outflow)
vofdem_bad_input(vof_open_alpha_range "option -vof_bc_xlo_alpha: 1.5 is out of range" ${_vof_open} -vof_bc_xlo_alpha 1.5)
vofdem_bad_input(vof_open_alpha_wall  "option -vof_bc_ylo_alpha: face ylo is wall \\(-flow_bc_ylo\\). only inflow and outflow faces" ${_vof_open} -vof_bc_ylo_alpha 1)
vofdem_bad_input(vof_open_band_slip   "option -vof_bc_zhi_alpha_band: face zhi is slip" ${_vof_open} -flow_bc_zhi slip -vof_bc_zhi_alpha_band 0,0.5)
vofdem_bad_input(vof_open_unknown_face "unknown or unused option -vof_bc_xmid_alpha" ${_vof_open} -vof_bc_xmid_alpha 1)
vofdem_bad_input(vof_open_band_count  "option -vof_bc_xlo_alpha_band: give lo,hi or lo,hi,lo2,hi2 \\(m\\), got 3 numbers" ${_vof_open} -vof_bc_xlo_alpha_band 0.1,0.2,0.3)
vofdem_bad_input(vof_open_band_order  "option -vof_bc_xlo_alpha_band: lo 0.5 must be below hi 0.2" ${_vof_open} -vof_bc_xlo_alpha_band 0.5,0.2)
vofdem_bad_input(vof_open_band_outflow "option -vof_bc_xhi_alpha_band: face xhi is outflow. a band is for an inflow face" ${_vof_open} -vof_bc_xhi_alpha_band 0,0.5)
# The water-jet scene loads and steps; the monitor prints the volumes in and out and the balance (below 1e-12: round-off
# plus the Weymouth-Yue term c_i dt div(u) of the projection's residual divergence).
add_test(NAME vof/liquid_jet_scene
         COMMAND $<TARGET_FILE:vofdem_app> -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/liquid-jet.yaml -grid_cells 24,12,2 -max_steps 20 -monitor_every 20)
set_tests_properties(vof/liquid_jet_scene PROPERTIES LABELS "quick;vof" PROCESSORS 1 TIMEOUT 120
                     PASS_REGULAR_EXPRESSION "inflow face xlo brings phase 1 at fraction 1\\.? through the band 0.0875\\.\\.0.1125 m.*step +20 .*in [0-9.e+-]+ out [0-9.e+-]+ m\\^3  balance -?[0-9.]+e-1[3-9].*finished after 20 steps"
                     ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMP_NUM_THREADS=1")
# -vof_advect 0: the interface is frozen bit for bit while the flow steps (the control, advecting, moves it).
add_test(NAME vof/frozen_interface COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/vof/test_frozen_interface.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(vof/frozen_interface PROPERTIES LABELS "quick;vof" PROCESSORS 2 TIMEOUT 300)
