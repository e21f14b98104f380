# Powder-spreading machinery and scenes (issue 6): walls in phases (a start time for the motion, a
# removal time) against free motion on 1 and 2 ranks.
add_test(NAME spreading/wall_phases COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/spreading/test_wall_phases.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(spreading/wall_phases PROPERTIES LABELS "quick;spreading" PROCESSORS 2 TIMEOUT 300)
# Seed 001's speed trend on the reduced tungsten scene (config/scenes/tungsten-spreading-reduced.yaml),
# two speeds on 2 ranks, ~80 s: packing falls with speed; settled start, particle count, layer thickness.
add_test(NAME spreading/speed_trend COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/spreading/test_spreading_speed.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(spreading/speed_trend PROPERTIES LABELS "quick;spreading" PROCESSORS 2 TIMEOUT 600)
# The full-size powder scenes (validate tier) read and stepped 300 times with 300 particles on 2 ranks.
add_test(NAME spreading/scene_smoke COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/spreading/test_scene_smoke.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(spreading/scene_smoke PROPERTIES LABELS "quick;spreading" PROCESSORS 2 TIMEOUT 300)
# Seed 002's lunar-regolith scene (config/scenes/lunar-spreading.yaml) read and stepped on 2 ranks in its settings.
add_test(NAME spreading/lunar_smoke COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/spreading/test_lunar_smoke.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(spreading/lunar_smoke PROPERTIES LABELS "quick;spreading" PROCESSORS 2 TIMEOUT 300)
# Seed 002's three settings on the reduced lunar scene (lunar-spreading-reduced.yaml), 2 ranks, ~3.5 min: packing
# falls from earth without van der Waals to earth with it to the moon, Ra is lowest without (results/lunar-speed.md).
add_test(NAME spreading/lunar_trend COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/spreading/test_lunar_trend.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(spreading/lunar_trend PROPERTIES LABELS "quick;spreading;lunar" PROCESSORS 2 TIMEOUT 1200)
