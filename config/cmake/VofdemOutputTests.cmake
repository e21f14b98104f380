# Tests of DEM output and analysis (included by VofdemTests.cmake): the XDMF/HDF5 files on 1 and 2
# ranks, and the bad input of their options.
add_test(NAME output/dem_xdmf COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/output/test_dem_output.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(output/dem_xdmf PROPERTIES LABELS "quick;output" PROCESSORS 2 TIMEOUT 600)

vofdem_bad_input(output_without_dir "option -dem_output_every needs -output_dir"   ${_dem} -dem_output_every 10)
vofdem_bad_input(contacts_without_dir "option -dem_contacts_every needs -output_dir" ${_dem} -dem_contacts_every 10)
vofdem_bad_input(stress_one_corner  "option -dem_stress_lower: give both"          ${_dem} -dem_stress_lower 0,0,0)
vofdem_bad_input(stress_inverted    "option -dem_stress_upper: must exceed -dem_stress_lower in y" ${_dem} -dem_stress_lower 0,0.005,0 -dem_stress_upper 0.01,0.004,0.01)

# The STL-blade example's output (particles with their fields, contact network) opens in ParaView.
add_test(NAME output/stl_blade_paraview COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/test/output/stl_blade_output.sh $<TARGET_FILE:ex16_stl_blade>
         ${CMAKE_CURRENT_BINARY_DIR}/stl-blade-output)
set_tests_properties(output/stl_blade_paraview PROPERTIES LABELS "quick;output" PROCESSORS 2 TIMEOUT 600 SKIP_RETURN_CODE 77)

# Flow grid fields for ParaView (-flow_output_every): structure, contents, 1 = 2 ranks, ParaView. The
# solid block lies in one rank's half: it also guards against rank-dependent vector state changes
# (a deadlock in VecNorm, found this way).
add_test(NAME output/flow_xdmf COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/output/test_flow_output.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(output/flow_xdmf PROPERTIES LABELS "quick;output;flow" PROCESSORS 2 TIMEOUT 600)
vofdem_bad_input(flow_output_without_dir "option -flow_output_every needs -output_dir" -physics flow -grid_cells 8,8,8 -max_steps 1 -flow_output_every 10)
# -help prints and exits, writing nothing, in vofdem and every example (issue 55).
add_test(NAME output/help_writes_nothing COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/output/test_help.py $<TARGET_FILE:vofdem_app> ${CMAKE_BINARY_DIR}/examples)
set_tests_properties(output/help_writes_nothing PROPERTIES LABELS "quick;output" PROCESSORS 2 TIMEOUT 600)
# A run ended by a limit the scene did not set says so in its closing line (issue 55).
add_test(NAME output/default_max_steps_named COMMAND $<TARGET_FILE:vofdem_app> -physics dem -grid_upper 0.01,0.01,0.01 -dem_fill_count 10 -final_time 1)
set_tests_properties(output/default_max_steps_named PROPERTIES LABELS "quick;output" TIMEOUT 60
                     PASS_REGULAR_EXPRESSION "finished after 100 steps at t = [0-9.e-]+ s \\(the default -max_steps 100 ended it before -final_time 1 s: raise -max_steps\\)")
