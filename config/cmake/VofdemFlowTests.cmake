# The pressure solve of the flow module (included by VofdemTests.cmake). Its examples (ex22, ex23) are
# example tests; here: bad input of the solver's options and coefficients, run through ex23.
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
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/cavity_run.sh $<TARGET_FILE:vofdem_app> ${ranks} ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/cavity-re100.yaml 100 0.01
                   -grid_cells 32,32,4 -grid_upper 1,1,0.125 -final_time 12)
  set_tests_properties(flow/f2_cavity_re100_${ranks} PROPERTIES LABELS "quick;flow" PROCESSORS ${ranks} TIMEOUT 600 ENVIRONMENT "VOFDEM_PYTHON=${VOFDEM_PYTHON}")
endforeach()
