# Powder-bed analysis (src/analysis; included by VofdemTests.cmake): a lattice of known answers analysed at
# the end of a run on 1 and 2 ranks and by vofdem-analyze, the plots, and the refusals (a window
# without particles: in test_powder_analysis.py, since vofdem prints its run before it).
add_test(NAME analysis/lattice_run_and_tool COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/analysis/test_powder_analysis.py
         $<TARGET_FILE:vofdem_app> $<TARGET_FILE:vofdem_analyze>)
set_tests_properties(analysis/lattice_run_and_tool PROPERTIES LABELS "quick;analysis" PROCESSORS 2 TIMEOUT 300)

set(_an ${_dem} -dem_radius 1e-3 -dem_fill_count 3 -max_steps 1 -analysis_dir ${CMAKE_CURRENT_BINARY_DIR}/badinput-analysis -analysis_metrics packing)
vofdem_bad_input(analysis_window_empty "option -analysis_upper: the analysis window is empty: upper must exceed lower in y" ${_an}
                 -analysis_lower 0,0.005,0 -analysis_upper 0.01,0.005,0.01)
vofdem_bad_input(analysis_outside_box "options -analysis_lower/-analysis_upper: the window \\[0.5, 0.6\\] m in z lies outside the box" ${_an}
                 -analysis_lower 0,0,0.5 -analysis_upper 0.01,0.01,0.6)
vofdem_bad_input(analysis_one_corner "option -analysis_lower: give both -analysis_lower and -analysis_upper" ${_an} -analysis_lower 0,0,0)
vofdem_bad_input(analysis_repose_base_negative "option -analysis_repose_base: -1. is out of range, must be in \\(0, inf\\]" ${_an} -analysis_repose_base -1)
vofdem_bad_input(analysis_unknown_metric "option -analysis_metrics: unknown name 'porosity'" ${_dem} -analysis_metrics porosity)
vofdem_bad_input(analysis_without_dir "option -analysis_metrics: give -analysis_dir or -output_dir" ${_dem} -analysis_metrics packing)
vofdem_bad_input(analysis_without_particles "option -analysis_metrics: the analysis needs particles" -physics flow -grid_cells 8,8,8
                 -analysis_metrics packing -analysis_dir ${CMAKE_CURRENT_BINARY_DIR}/badinput-analysis)
function(vofdem_analyze_bad_input name regex)
  add_test(NAME badinput/${name} COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match ${regex} -- $<TARGET_FILE:vofdem_analyze> ${ARGN})
  set_tests_properties(badinput/${name} PROPERTIES LABELS "quick;badinput;analysis" PROCESSORS 2 TIMEOUT 120)
endfunction()
vofdem_analyze_bad_input(analyze_no_input "option -analysis_input is missing")
vofdem_analyze_bad_input(analyze_missing "option -analysis_input: cannot open '.*none\\.h5'" -analysis_input ${_bad}/none.h5)
vofdem_analyze_bad_input(analyze_not_hdf5 "option -analysis_input: '.*typo\\.yaml' is not an HDF5 file" -analysis_input ${_bad}/typo.yaml)
# Clumps (SolidVolume.cpp): a lattice of two-sphere clumps, each one particle, its union once in the packing, on 1
# and 2 ranks and by vofdem-analyze (clump ids in particles_<step>.h5; a file without them read with a note).
add_test(NAME analysis/clumps_run_and_tool COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/analysis/test_clump_analysis.py
         $<TARGET_FILE:vofdem_app> $<TARGET_FILE:vofdem_analyze>)
set_tests_properties(analysis/clumps_run_and_tool PROPERTIES LABELS "quick;analysis;clumps" PROCESSORS 2 TIMEOUT 300)
# scripts/calibrate-powder's crossing of the angle and density target curves, on tables of known fields (no run).
add_test(NAME analysis/calibrate_powder COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/analysis/test_calibrate_powder.py)
set_tests_properties(analysis/calibrate_powder PROPERTIES LABELS "quick;analysis")
# Five analysis options (bins, surface grid, reference radius, repose fit, clump resolution) against values they must give.
add_test(NAME analysis/options COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/analysis/test_analysis_options.py
         $<TARGET_FILE:vofdem_app> $<TARGET_FILE:vofdem_analyze>)
set_tests_properties(analysis/options PROPERTIES LABELS "quick;analysis" PROCESSORS 2 TIMEOUT 300)
