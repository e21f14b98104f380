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
# A solve that does not converge (two iterations allowed) ends every rank with one line, not a trace or a hang.
vofdem_bad_input_pressure(pressure_not_converged "pressure solve did not converge: DIVERGED_ITS after 2 iterations" -flow_pressure_ksp_max_it 2)
