# Checkpoint/restart (issue 5; src/core/Checkpoint.cpp, CheckpointFile.cpp): bitwise continuation on
# the same rank count, continuation on another rank count, SIGTERM, and bad input
# (test/checkpoint/test_checkpoint.py says what each case checks).
set(_ckpt ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/checkpoint/test_checkpoint.py $<TARGET_FILE:vofdem_app>)
function(vofdem_checkpoint_test name ranks)
  add_test(NAME checkpoint/${name} COMMAND ${_ckpt} ${ARGN})
  set_tests_properties(checkpoint/${name} PROPERTIES LABELS "quick;checkpoint" PROCESSORS ${ranks} TIMEOUT 300)
endfunction()
vofdem_checkpoint_test(bitwise_dem_1 1 bitwise dem 1)
vofdem_checkpoint_test(bitwise_dem_2 2 bitwise dem 2)
vofdem_checkpoint_test(bitwise_flow_1 1 bitwise flow 1)
vofdem_checkpoint_test(bitwise_flow_2 2 bitwise flow 2)
vofdem_checkpoint_test(ranks_dem_2to1 2 ranks dem 2 1)
vofdem_checkpoint_test(ranks_dem_1to2 2 ranks dem 1 2)
vofdem_checkpoint_test(ranks_flow_2to1 2 ranks flow 2 1)
vofdem_checkpoint_test(ranks_flow_1to2 2 ranks flow 1 2)
vofdem_checkpoint_test(signal_1 1 signal 1)
vofdem_checkpoint_test(signal_2 2 signal 2)
vofdem_checkpoint_test(bad_input 2 badinput)
