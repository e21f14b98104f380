# D6, long horizon (docs/verification.md; included by VofdemTests.cmake): a chaotic scene on 2 and 4 ranks
# must give bulk statistics within 3 sigma of a 1-rank ensemble of 8 seeds, with exact particle counts
# and final positions shown to have decorrelated. The short horizon of ex20 is an example test.
add_test(NAME statistics/d6_rank_statistics
         COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/statistics/d6_rank_statistics.py --exe $<TARGET_FILE:ex20_rank_statistics> --seeds 8 --ranks 2,4)
set_tests_properties(statistics/d6_rank_statistics PROPERTIES LABELS "quick;statistics" PROCESSORS 2 TIMEOUT 900)

# Bad input of ex20's own options: one line, every rank non-zero.
function(vofdem_bad_input_ex20 name regex)
  add_test(NAME badinput/${name} COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match ${regex} -- $<TARGET_FILE:ex20_rank_statistics> ${ARGN})
  set_tests_properties(badinput/${name} PROPERTIES LABELS "quick;badinput" PROCESSORS 2 TIMEOUT 120)
endfunction()
vofdem_bad_input_ex20(ex20_average_steps "option -average_steps: 200 exceeds -steps 100" ${_dem} -steps 100 -average_steps 200)
vofdem_bad_input_ex20(ex20_slab          "option -slab: the upper height must exceed the lower" ${_dem} -slab 0.004,0.002)
