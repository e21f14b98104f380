# Rigid multi-sphere clumps (P10; included by VofdemTests.cmake): free precession against the analytic rate,
# an off-centre collision of two clumps across the rank boundary, a drop onto the floor on 1 and 2 ranks.
add_test(NAME clumps/dynamics COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/clumps/test_clump_dynamics.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(clumps/dynamics PROPERTIES LABELS "quick;clumps" PROCESSORS 2 TIMEOUT 900)
# Clump insertion (ClumpInsertion.cpp): number fractions of the regolith shapes, whole clumps without overlap,
# the same clumps on 1 and 2 ranks, whole clumps through a deletion box (~50 s on 2 ranks).
add_test(NAME clumps/insertion COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/clumps/test_clump_insertion.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(clumps/insertion PROPERTIES LABELS "quick;clumps" PROCESSORS 2 TIMEOUT 600)
# Bad clump-insertion input: one line each.
set(_clumpsrc ${_dem} -dem_inserts a -dem_insert_a_lower 0.002,0.002,0.002 -dem_insert_a_upper 0.008,0.008,0.008 -dem_insert_a_rate 10 -dem_radius 1e-4)
vofdem_bad_input(clump_unknown_template "option -dem_insert_a_clumps: no clump template 'rock'" ${_clumpsrc} -dem_insert_a_clumps regolith1,rock)
vofdem_bad_input(clump_fractions_sum    "option -dem_insert_a_clump_fractions: the fractions sum to 0\\.9, not 1" ${_clumpsrc} -dem_insert_a_clumps regolith1,regolith2 -dem_insert_a_clump_fractions 0.5,0.4)
vofdem_bad_input(clump_fractions_count  "option -dem_insert_a_clump_fractions: 3 fractions for 2 templates" ${_clumpsrc} -dem_insert_a_clumps regolith1,regolith2 -dem_insert_a_clump_fractions 0.5,0.25,0.25)
vofdem_bad_input(clump_spheres_not_4    "option -dem_clump_rock_spheres: 7 numbers are not whole spheres of 4" ${_clumpsrc} -dem_clump_templates rock -dem_clump_rock_spheres 0,0,0,1,0.5,0,0 -dem_insert_a_clumps rock)
vofdem_bad_input(clump_base_first       "option -dem_clump_rock_spheres: the first sphere is the base sphere, 0,0,0,1" ${_clumpsrc} -dem_clump_templates rock -dem_clump_rock_spheres 0.1,0,0,1,0.5,0,0,0.5 -dem_insert_a_clumps rock)
vofdem_bad_input(clump_template_missing "option -dem_clump_rock_spheres: needed for the template 'rock'" ${_clumpsrc} -dem_clump_templates rock)
vofdem_bad_input(clump_builtin_name     "option -dem_clump_templates: 'regolith2' is a built-in template" ${_clumpsrc} -dem_clump_templates regolith2 -dem_clump_regolith2_spheres 0,0,0,1,0.5,0,0,0.5)
# Particles files across a periodic face: spheres wrapped in, a clump across the face read as one body.
add_test(NAME clumps/periodic_file COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/clumps/test_periodic_file.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(clumps/periodic_file PROPERTIES LABELS "quick;clumps" PROCESSORS 2 TIMEOUT 300)
