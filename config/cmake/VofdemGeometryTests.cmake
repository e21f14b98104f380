# Meshes for spreading and funnel scenes (scripts/make-stl): closed and open shells, their volumes and
# areas against the exact ones, and a sphere at rest on the generated super-ellipse blade (1 and 2 ranks).
add_test(NAME geometry/make_stl COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/geometry/test_make_stl.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(geometry/make_stl PROPERTIES LABELS "quick;geometry" PROCESSORS 2 TIMEOUT 300)
