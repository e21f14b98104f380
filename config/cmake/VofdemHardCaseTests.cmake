# docs/verification.md's hard cases (numerical stability): molten metal in gas at density ratio 8000 with sigma 1.8 N/m on
# 2.5 um cells, and tungsten at its full 340 GPa with 4:1 radii and JKR; 1 and 2 ranks each, ~20 s.
add_test(NAME hard/stability COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/hard/test_hard_cases.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(hard/stability PROPERTIES LABELS "quick;hard" PROCESSORS 2 TIMEOUT 600)
