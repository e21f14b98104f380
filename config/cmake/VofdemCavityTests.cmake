# F2, the lid-driven cavity (docs/verification.md), and the convergence tables of F1, F5, E1: the checking
# scripts of test/flow/ tested on synthetic input (the reference itself passes with zero error, a profile
# off by 0.02 of the lid speed fails, a mirrored cavity fails, exact error ladders give exact orders).
# To be included by VofdemTests.cmake next to VofdemFlowTests.
add_test(NAME unit/cavity_profile_check
         COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/test_cavity_profile_check.py)
set_tests_properties(unit/cavity_profile_check PROPERTIES LABELS "quick;unit" TIMEOUT 120)
add_test(NAME unit/convergence_table
         COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/flow/test_convergence_table.py)
set_tests_properties(unit/convergence_table PROPERTIES LABELS "quick;unit" TIMEOUT 120)
# F2 itself, once the solver writes a centreline profile (line,s,x,y,z,u,v,w) at steady state:
#   ${VOFDEM_PYTHON} test/flow/cavity_profile_check.py PROFILE.csv --re 100   (and --re 1000)
# exits 1 if either centreline is off by 1 % of the lid speed or more.
