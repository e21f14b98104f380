# Rigid multi-sphere clumps (P10; included by VofdemTests.cmake): free precession against the analytic rate,
# an off-centre collision of two clumps across the rank boundary, a drop onto the floor on 1 and 2 ranks.
add_test(NAME clumps/dynamics COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/clumps/test_clump_dynamics.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(clumps/dynamics PROPERTIES LABELS "quick;clumps" PROCESSORS 2 TIMEOUT 900)
