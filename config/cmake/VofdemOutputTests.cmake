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
