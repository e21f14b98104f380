# The quick tier (ctest -L quick): unit tests, every example test on its rank counts, bad-input tests.
include(GoogleTest)

# ---- unit tests (GoogleTest) ----------------------------------------------------------------
file(GLOB VOFDEM_UNIT_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test/unit/*.cpp)
add_executable(vofdem_unit_tests ${VOFDEM_UNIT_TESTS})
target_link_libraries(vofdem_unit_tests PRIVATE vofdem GTest::gtest GTest::gtest_main)
# gtest_add_tests scans the sources at configure time and returns the names, so both labels apply.
gtest_add_tests(TARGET vofdem_unit_tests TEST_PREFIX "unit/" TEST_LIST _unit_tests)
set_tests_properties(${_unit_tests} PROPERTIES LABELS "quick;unit")

add_test(NAME unit/outputcompare COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/unit/test_outputcompare.py)
set_tests_properties(unit/outputcompare PROPERTIES LABELS "quick;unit")

# ---- example tests: one CTest test per /*TEST*/ block -----------------------------------------
set(_runner ${CMAKE_CURRENT_SOURCE_DIR}/scripts/run-examples)
file(GLOB _example_sources ${CMAKE_CURRENT_SOURCE_DIR}/examples/ex*.cpp)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${_example_sources} ${_runner}
             ${CMAKE_CURRENT_SOURCE_DIR}/scripts/lib/testblocks.py)
execute_process(COMMAND ${VOFDEM_PYTHON} ${_runner} --cmake --build-dir ${CMAKE_BINARY_DIR}
                OUTPUT_FILE ${CMAKE_BINARY_DIR}/example-tests.cmake RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "reading the /*TEST*/ blocks of examples/ failed:\n${_err}")
endif()
include(${CMAKE_BINARY_DIR}/example-tests.cmake)

# ---- bad input: one line naming the file or option, non-zero exit on every rank, no hang -------
set(_expect ${CMAKE_CURRENT_SOURCE_DIR}/test/badinput/expect-error)
set(_bad ${CMAKE_CURRENT_SOURCE_DIR}/test/badinput)
function(vofdem_bad_input name regex)
  add_test(NAME badinput/${name} COMMAND ${VOFDEM_PYTHON} ${_expect} --ranks 2 --match ${regex} -- $<TARGET_FILE:vofdem_app> ${ARGN})
  set_tests_properties(badinput/${name} PROPERTIES LABELS "quick;badinput" PROCESSORS 2 TIMEOUT 120)
endfunction()
set(_dem -physics dem -grid_upper 0.01,0.01,0.01)
vofdem_bad_input(missing_scene      "missing\\.yaml: cannot open the scene file"   -options_file_yaml ${_bad}/missing.yaml)
vofdem_bad_input(missing_options    "missing\\.opts: cannot open the scene file"   -options_file ${_bad}/missing.opts)
vofdem_bad_input(scene_without_name "-options_file_yaml: needs a file name"        -physics dem -options_file_yaml)
vofdem_bad_input(malformed_yaml     "malformed\\.yaml:4:[0-9]+: malformed YAML"     -options_file_yaml ${_bad}/malformed.yaml)
vofdem_bad_input(scene_not_mapping  "not-a-mapping\\.yaml:1:1: a scene must be a mapping" -options_file_yaml ${_bad}/not-a-mapping.yaml)
vofdem_bad_input(typo_in_scene      "unknown or unused option -dem_restitusion"    -options_file_yaml ${_bad}/typo.yaml)
vofdem_bad_input(unknown_physics    "option -physics: unknown name 'magic'"        -physics dem,magic)
vofdem_bad_input(physics_not_built  "option -physics: 'flow' is not available"     -physics flow)
vofdem_bad_input(physics_missing    "option -physics is missing"                   -max_steps 1)
vofdem_bad_input(not_a_number       "option -dem_radius: 'abc' is not a number"    ${_dem} -dem_radius abc)
vofdem_bad_input(not_an_integer     "option -max_steps: '2.5' is not an integer"   ${_dem} -max_steps 2.5)
vofdem_bad_input(out_of_range       "option -dem_restitution: 1.5 is out of range" ${_dem} -dem_restitution 1.5)
vofdem_bad_input(vector_length      "option -gravity: needs 3 comma-separated"     ${_dem} -gravity 0,-9.81)
vofdem_bad_input(unused_option      "unknown or unused option -dem_radus"          ${_dem} -dem_radus 1e-3)
vofdem_bad_input(box_inverted       "upper corner must exceed lower corner in z"   ${_dem} -grid_lower 0,0,0.02)
vofdem_bad_input(dt_above_limit     "option -dt: 1\\.? s exceeds the stable limit" ${_dem} -dt 1)
vofdem_bad_input(fill_cannot_fit    "option -dem_fill_count: cannot fit 100000"    ${_dem} -dem_fill_count 100000)
vofdem_bad_input(fill_outside_box   "the region .* must be non-empty and inside the box" ${_dem} -dem_fill_count 1 -dem_fill_upper 0.01,0.01,0.5)
vofdem_bad_input(fill_spacing       "option -dem_fill_spacing: .* less than a particle diameter" ${_dem} -dem_fill_spacing 1e-4)
vofdem_bad_input(output_dir         "option -output_dir: cannot create"            ${_dem} -output_dir /proc/vofdem)
vofdem_bad_input(particles_missing  "option -dem_particles_file: cannot open"      ${_dem} -dem_particles_file ${_bad}/none.csv)
vofdem_bad_input(particles_malformed "particles-malformed\\.csv:3: expected 6 or 9 comma-separated numbers" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-malformed.csv)
vofdem_bad_input(particle_outside   "particles-outside\\.csv:2: the particle at .* is not inside the box" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-outside.csv)
vofdem_bad_input(rolling_unknown    "option -dem_rolling: unknown name 'epsd3'"     ${_dem} -dem_rolling epsd3)
vofdem_bad_input(rolling_two        "option -dem_rolling: give one model"          ${_dem} -dem_rolling cdt,epsd)
