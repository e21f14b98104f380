# The quick tier (ctest -L quick): unit tests, every example test on its rank counts, bad-input tests.
include(GoogleTest)

# ---- unit tests (GoogleTest) ----------------------------------------------------------------
file(GLOB VOFDEM_UNIT_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/test/unit/*.cpp)
add_executable(vofdem_unit_tests ${VOFDEM_UNIT_TESTS})
target_link_libraries(vofdem_unit_tests PRIVATE vofdem vofdem_analysis GTest::gtest GTest::gtest_main)
# gtest_add_tests scans the sources at configure time and returns the names, so both labels apply.
gtest_add_tests(TARGET vofdem_unit_tests TEST_PREFIX "unit/" TEST_LIST _unit_tests)
set_tests_properties(${_unit_tests} PROPERTIES LABELS "quick;unit")

add_test(NAME unit/outputcompare COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/unit/test_outputcompare.py)
set_tests_properties(unit/outputcompare PROPERTIES LABELS "quick;unit")

# -stop_kinetic_energy: a DEM run ends once its particles are at rest; a signal-stopped run is not analysed.
# The walls' own material (-dem_wall_youngs_modulus, _poisson_ratio, _surface_energy): a sphere at rest on the floor
# has the static Hertz / JKR overlap of the sphere-plane pair's reduced modulus and work of adhesion.
add_test(NAME dem/wall_material COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_wall_material.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/wall_material PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
add_test(NAME dem/stop_at_rest COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_stop_at_rest.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/stop_at_rest PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# -dem_insert_<name>_every: insertion in batches, fewer rebuilds, nothing lost.
add_test(NAME dem/insert_batches COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_insert_batches.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/insert_batches PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# -dem_save_contact_history / -dem_contact_history_file: a cohesive pile handed on through particle files stays at rest.
add_test(NAME dem/contact_history_file COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_contact_history_file.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/contact_history_file PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# JKR bonds at rest set the DEM step where they are stiffer than the Rayleigh time covers; a pile then comes to rest.
add_test(NAME dem/jkr_step COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_jkr_step.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/jkr_step PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# EPSD rolling resistance resists the twist about the contact normal too: a 100-sphere JKR pile comes to rest (1e-20 J by t = 0.4 s) on 1 and 2 ranks.
add_test(NAME dem/epsd_rest COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_epsd_rest.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/epsd_rest PROPERTIES LABELS "quick;dem;rolling" PROCESSORS 2 TIMEOUT 300)
# Loaded, damped contacts set the DEM step where they are stiffer than the Rayleigh time covers; a deep soft bed then comes to rest.
add_test(NAME dem/contact_step COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_contact_step.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/contact_step PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# A random fill and an insertion region across periodic x and y: centres up to the faces, no overlap through them.
# G1: two bonded spheres pulled, sheared, bent and twisted to just below and above their break loads (P13).
add_test(NAME dem/bond_break COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_bond_break.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/bond_break PROPERTIES LABELS "quick;dem;bonds" PROCESSORS 2 TIMEOUT 300)
# A bonded pair vibrating as it flies across the rank boundary: its bond's history through ~280 rebuilds and a migration.
add_test(NAME dem/bond_rebuilds COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_bond_rebuilds.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/bond_rebuilds PROPERTIES LABELS "quick;dem;bonds" PROCESSORS 2 TIMEOUT 300)
# G3: a bonded cylinder of 114 spheres compressed by two platens at two rates: linear rise, a peak, E and the peak
# within 2 % at the two rates, 1 and 2 ranks alike (scripts/bond-compression for the larger ones).
add_test(NAME dem/bond_compression COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_bond_compression.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/bond_compression PROPERTIES LABELS "quick;dem;bonds" PROCESSORS 2 TIMEOUT 300)
add_test(NAME dem/periodic_seam COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_periodic_seam.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/periodic_seam PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)

# G4's column (docs/verification.md): -physics darcy with fixed eps against Darcy's law (and Ergun's), 1 and 2 ranks.
add_test(NAME darcy/column COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/darcy/test_darcy_column.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(darcy/column PROPERTIES LABELS "quick;darcy" PROCESSORS 2 TIMEOUT 300)
# -physics dem,darcy: the seepage force's exchange and the bed's share of the head loss, and G5's heave at Terzaghi's gradient.
add_test(NAME darcy/seepage_bed COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/darcy/test_seepage_bed.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(darcy/seepage_bed PROPERTIES LABELS "quick;darcy" PROCESSORS 2 TIMEOUT 300)
# A darcy and a dem,darcy run continued from a checkpoint end where the uninterrupted run ends (1 and 2 ranks).
add_test(NAME darcy/restart COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/darcy/test_darcy_restart.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(darcy/restart PROPERTIES LABELS "quick;darcy;checkpoint" PROCESSORS 2 TIMEOUT 300)

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
vofdem_bad_input(typo_in_scene      "unknown or unused option -dem_restitusion \\(did you mean -dem_restitution\\?\\)" -options_file_yaml ${_bad}/typo.yaml)
vofdem_bad_input(unknown_physics    "option -physics: unknown name 'magic'"        -physics dem,magic)
vofdem_bad_input(physics_not_built  "option -physics: unknown name 'magnetism' \\(known: dem, flow, vof, darcy, scalar, energy\\)" -physics flow,magnetism)
# The registry's needs, and the passive scalar's own checks.
vofdem_bad_input(scalar_needs_flow  "option -physics: 'scalar' needs 'flow' \\(the scalar moves with the fluid\\)" -physics scalar)
vofdem_bad_input(scalar_with_dem    "option -physics: 'scalar' does not take particles into account yet" -physics dem,flow,scalar -grid_upper 0.01,0.01,0.01)
vofdem_bad_input(scalar_sine_walls  "option -scalar_sine_periods: a sine along x needs a periodic box in x" -physics flow,scalar -scalar_initial sine)
# The Darcy seepage's own checks (docs/modules/darcy.md).
vofdem_bad_input(darcy_unknown_law  "option -darcy_permeability_law: unknown name 'carman' \\(known: kozenycarman, kozenycarman_d10, evolving, ergun\\)" -physics darcy -dt 1 -darcy_permeability_law carman)
vofdem_bad_input(darcy_closed_box   "option -darcy_head_difference: a head difference needs open faces, and the box has none" -physics darcy -dt 1 -darcy_head_difference 0.5)
vofdem_bad_input(darcy_with_flow    "option -physics: 'darcy' and 'flow' are two models of the same pore water" -physics flow,darcy)
vofdem_bad_input(darcy_eps_with_dem "option -darcy_fluid_fraction: with particles \\(dem,darcy\\) eps comes from them" -physics dem,darcy -grid_upper 0.01,0.01,0.01 -darcy_fluid_fraction 0.4)
vofdem_bad_input(seepage_kernel     "seepage: the kernel reaches 6 cells, more than the 4 periodic cells in x. use a narrower kernel \\(-seepage_kernel_width\\)" -physics dem,darcy -grid_cells 4,4,16 -grid_upper 0.004,0.004,0.016 -grid_periodic x,y -dem_radius 0.5e-3 -dem_fill_count 10)
vofdem_bad_input(darcy_ramp_alone   "option -darcy_head_ramp: give the final head difference too" -physics darcy -dt 1 -darcy_axis z -darcy_head_ramp 0.1,1)
vofdem_bad_input(darcy_layers       "option -darcy_fluid_fraction: 3 layers do not split the 8 cells along z into whole cells" -physics darcy -dt 1 -darcy_axis z -darcy_fluid_fraction 0.3,0.4,0.5)
vofdem_bad_input(scalar_box_corner  "option -scalar_box_upper: give both corners of the box" -physics flow,scalar -scalar_box_lower 0,0,0)
# A grid PETSc cannot split over the ranks: one line naming -grid_cells and -grid_ranks, not PETSc's trace.
vofdem_bad_input(grid_too_few_cells "options -grid_cells 1,1,1 and -grid_ranks: the cells cannot be split over 2 ranks \\(PETSc: Partition in . direction is too fine" -physics dem -grid_upper 0.004,0.004,0.004 -grid_cells 1,1,1 -dem_fill_count 1 -dem_radius 5e-4)
vofdem_bad_input(vof_without_flow   "option -physics: 'vof' needs 'flow'"           -physics vof)
vofdem_bad_input(vof_dem_no_eps_rate "option -coupling_eps_rate: particles with a free surface" -physics dem,flow,vof -grid_upper 0.01,0.01,0.01 -coupling_eps_rate 0)
vofdem_bad_input(contact_angle_range "option -coupling_contact_angle: 200\\.? is out of range" -physics dem,flow,vof -grid_upper 0.01,0.01,0.01 -coupling_contact_angle 200)
vofdem_bad_input(contact_angle_no_vof "option -coupling_contact_angle: the capillary force acts at a free surface" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_contact_angle 100)
vofdem_bad_input(contact_angle_unresolved "option -coupling_contact_angle: the capillary force finds the interface" -physics dem,flow,vof -grid_upper 0.01,0.01,0.01 -coupling_contact_angle 100 -coupling_kernel unresolved)
vofdem_bad_input(added_mass_acceleration "option -coupling_added_mass_acceleration: .*bogus" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_added_mass_acceleration bogus)
vofdem_bad_input(smoothing_unknown  "option -coupling_smoothing: unknown name 'bogus'" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_smoothing bogus)
vofdem_bad_input(smoothing_steps    "option -coupling_smoothing_steps: 0 is out of range" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_smoothing_steps 0)
vofdem_bad_input(smoothing_narrow   "option -coupling_smoothing: diffusion needs a kernel wider than the cell" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_smoothing diffusion -coupling_kernel_width 0.3 -coupling_kernel_min_width 0.5)
vofdem_bad_input(smoothing_unresolved "option -coupling_smoothing: diffusion smooths to a kernel's width" -physics dem,flow -grid_upper 0.01,0.01,0.01 -coupling_smoothing diffusion -coupling_kernel unresolved)
vofdem_bad_input(smoothing_capillary "option -coupling_contact_angle: the capillary force finds the interface through the kernel's marginal. use -coupling_smoothing kernel" -physics dem,flow,vof -grid_upper 0.01,0.01,0.01 -coupling_smoothing diffusion -coupling_contact_angle 100)
vofdem_bad_input(physics_missing    "option -physics is missing"                   -max_steps 1)
vofdem_bad_input(not_a_number       "option -dem_radius: 'abc' is not a number"    ${_dem} -dem_radius abc)
vofdem_bad_input(not_an_integer     "option -max_steps: '2.5' is not an integer"   ${_dem} -max_steps 2.5)
vofdem_bad_input(out_of_range       "option -dem_restitution: 1.5 is out of range" ${_dem} -dem_restitution 1.5)
vofdem_bad_input(sort_every_negative "option -dem_sort_every: -1 is out of range" ${_dem} -dem_sort_every -1)
vofdem_bad_input(vector_length      "option -gravity: needs 3 comma-separated"     ${_dem} -gravity 0,-9.81)
# Issue 55: messages that say what is wrong; requests that cannot fit refused up front (not std::bad_alloc and a core dump).
vofdem_bad_input(integer_too_large  "option -dem_fill_count: 1000000000000 is too large for this build's 32-bit indices" ${_dem} -dem_fill_count 1000000000000)
vofdem_bad_input(scene_tab          "tab\\.yaml:3:1: malformed YAML: a tab. YAML indents with spaces only" -options_file_yaml ${_bad}/tab.yaml)
vofdem_bad_input(scene_empty        "empty\\.yaml: the scene file is empty" -options_file_yaml ${_bad}/empty.yaml)
vofdem_bad_input(random_fill_too_dense "option -dem_fill_count: 2000000000 particles fill .* of the fill region's volume. a random fill of equal spheres stops at its jamming limit 0.3841" ${_dem} -dem_radius 1e-4 -dem_fill_mode random -dem_fill_count 2000000000)
vofdem_bad_input(random_fill_memory "option -dem_fill_count: 2000000000 particles of a random fill \\(every rank places all of them\\) need at least .* on each rank, .* are available" -physics dem -grid_upper 10,10,10 -grid_cells 4,4,4 -dem_radius 1e-4 -dem_fill_mode random -dem_fill_count 2000000000)
vofdem_bad_input(lattice_fill_memory "option -dem_fill_count: 2000000000 particles \\(their swarm fields, shared among the ranks\\) need at least .* on each rank, .* are available" -physics dem -grid_upper 10,10,10 -grid_cells 4,4,4 -dem_radius 1e-4 -dem_fill_count 2000000000)
vofdem_bad_input(unused_option      "unknown or unused option -dem_radus"          ${_dem} -dem_radus 1e-3)
vofdem_bad_input(stop_kinetic_no_dem "option -stop_kinetic_energy: it is the particles' energy" -physics flow -grid_upper 0.01,0.01,0.01 -stop_kinetic_energy 1e-9)
vofdem_bad_input(stop_kinetic_after_alone "option -stop_kinetic_energy_after: no -stop_kinetic_energy" ${_dem} -stop_kinetic_energy_after 0.1)
vofdem_bad_input(stop_kinetic_negative "option -stop_kinetic_energy: -1e-09 is out of range" ${_dem} -stop_kinetic_energy -1e-9)
vofdem_bad_input(box_inverted       "upper corner must exceed lower corner in z"   ${_dem} -grid_lower 0,0,0.02)
vofdem_bad_input(dt_above_limit     "option -dt: 1\\.? s exceeds the stable limit" ${_dem} -dt 1)
vofdem_bad_input(fill_cannot_fit    "option -dem_fill_count: cannot fit 100000"    ${_dem} -dem_fill_count 100000)
vofdem_bad_input(fill_outside_box   "the region .* must be non-empty and inside the box" ${_dem} -dem_fill_count 1 -dem_fill_upper 0.01,0.01,0.5)
vofdem_bad_input(fill_spacing       "option -dem_fill_spacing: .* less than the largest particle diameter" ${_dem} -dem_fill_spacing 1e-4)
vofdem_bad_input(output_dir         "option -output_dir: cannot create"            ${_dem} -output_dir /proc/vofdem)
vofdem_bad_input(particles_missing  "option -dem_particles_file: cannot open"      ${_dem} -dem_particles_file ${_bad}/none.csv)
vofdem_bad_input(particles_malformed "particles-malformed\\.csv:3: expected 6 comma-separated numbers, as the header names" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-malformed.csv)
vofdem_bad_input(particle_outside   "particles-outside\\.csv:2: the particle at .* is not inside the box" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-outside.csv)
vofdem_bad_input(particle_far_periodic "particles-periodic-far\\.csv:2: the particle at .* lies more than its radius outside the periodic box along x" ${_dem} -grid_periodic x -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-periodic-far.csv)
vofdem_bad_input(history_no_particles "option -dem_contact_history_file: give -dem_particles_file too" ${_dem} -dem_contact_history_file ${_bad}/history-row.csv)
vofdem_bad_input(save_history_alone "option -dem_save_contact_history: give -dem_save_particles too" ${_dem} -dem_save_contact_history contacts.csv)
vofdem_bad_input(history_header    "history-header\\.csv:1: the header must be 'i,j,tx,ty,tz,rx,ry,rz,jkr_radius,jkr_bonded'" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/history-particles.csv -dem_contact_history_file ${_bad}/history-header.csv)
vofdem_bad_input(history_row       "history-row\\.csv:3: give two rows i < j of the particles file \\(0 to 1\\)" ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/history-particles.csv -dem_contact_history_file ${_bad}/history-row.csv)
vofdem_bad_input(particles_column   "particles-unknown-column\\.csv:1: unknown column .colour." ${_dem} -dem_radius 1e-3 -dem_particles_file ${_bad}/particles-unknown-column.csv)
vofdem_bad_input(fill_fractions     "option -dem_fill_mass_fractions: 1 fractions for 2 radii" ${_dem} -dem_fill_radii 1e-3,5e-4 -dem_fill_mass_fractions 1)
vofdem_bad_input(jkr_without_energy "option -dem_cohesion jkr needs a surface energy > 0 for every type \\(-dem_surface_energy" ${_dem} -dem_cohesion jkr)
vofdem_bad_input(two_adhesions      "options -dem_hamaker and -dem_cohesion jkr: choose one adhesion model" ${_dem} -dem_cohesion jkr -dem_surface_energy 0.1 -dem_hamaker 1e-20)
vofdem_bad_input(linear_with_jkr    "option -dem_cohesion jkr needs -dem_contact hertz" ${_dem} -dem_contact linear -dem_cohesion jkr -dem_surface_energy 0.1)
vofdem_bad_input(save_unwritable    "option -dem_save_particles: cannot write ./proc/vofdem.csv." ${_dem} -dem_radius 1e-3 -dem_fill_count 3 -max_steps 1 -dem_save_particles /proc/vofdem.csv)
vofdem_bad_input(rolling_unknown    "option -dem_rolling: unknown name 'epsd3'"     ${_dem} -dem_rolling epsd3)
vofdem_bad_input(rolling_two        "option -dem_rolling: give one model"          ${_dem} -dem_rolling cdt,epsd)
vofdem_bad_input(grid_ranks         "option -grid_ranks: 3 x 1 x 1 does not fit the 2 ranks" ${_dem} -grid_ranks 3,1,1)
# Particle types and materials
vofdem_bad_input(material_missing   "option -dem_type_a_material: no material file 'unobtainium'" ${_dem} -dem_types a -dem_type_a_material unobtainium)
vofdem_bad_input(material_key       "option -dem_type_a_material: .*material-unknown-key\\.yaml:2: unknown key 'colour'" ${_dem} -dem_types a -dem_type_a_material ${_bad}/material-unknown-key.yaml)
vofdem_bad_input(material_number    "option -dem_type_a_material: .*material-not-number\\.yaml:1: density: 'heavy' is not a number" ${_dem} -dem_types a -dem_type_a_material ${_bad}/material-not-number.yaml)
vofdem_bad_input(fill_type_unknown  "option -dem_fill_type: no type 'steel' in -dem_types" ${_dem} -dem_types glass -dem_type_glass_material glass -dem_fill_type steel)
vofdem_bad_input(type_name          "option -dem_types: 'a-b' is not a type name" ${_dem} -dem_types a-b)
vofdem_bad_input(pair_restitution   "option -dem_pair_a_b_restitution: must be in \\(0, 1\\]" ${_dem} -dem_types a,b -dem_type_a_material glass -dem_type_b_material steel -dem_pair_a_b_restitution 2)
vofdem_bad_input(type_no_material   "option -dem_types: type 'b' has no material \\(give -dem_type_b_material NAME" ${_dem} -dem_types a,b -dem_type_a_material glass)
vofdem_bad_input(sjkr_without_k     "option -dem_cohesion sjkr needs -dem_cohesion_energy_density > 0" ${_dem} -dem_cohesion sjkr)
vofdem_bad_input(lubrication_gaps   "option -dem_lubrication_max_gap: 1e-06 m must exceed -dem_lubrication_min_gap 1e-05 m" ${_dem} -dem_lubrication_viscosity 1e-3 -dem_lubrication_min_gap 1e-5 -dem_lubrication_max_gap 1e-6)
# insertion, size distributions, deletion (RandomFill, SizeDistribution, ParticleSources)
vofdem_bad_input(fill_too_dense     "option -dem_fill_volume_fraction: reached only 0\\.[0-9]+ of 0\\.45" ${_dem} -dem_radius 5e-4 -dem_fill_mode random -dem_fill_volume_fraction 0.45 -dem_fill_attempts 100)
vofdem_bad_input(fill_random_target "option -dem_fill_mode random needs -dem_fill_count or -dem_fill_volume_fraction" ${_dem} -dem_fill_mode random)
vofdem_bad_input(size_law_params    "option -dem_fill_size_distribution normal needs -dem_fill_radius_mean and -dem_fill_radius_std" ${_dem} -dem_fill_size_distribution normal)
vofdem_bad_input(size_law_cutoffs   "options -dem_fill_radius_min/-dem_fill_radius_max: the cut-offs .* are empty" ${_dem} -dem_fill_size_distribution uniform -dem_fill_radius_min 2e-4 -dem_fill_radius_max 1e-4)
vofdem_bad_input(insert_no_rate     "options -dem_insert_a_rate and -dem_insert_a_mass_rate: give exactly one positive rate" ${_dem} -dem_inserts a -dem_insert_a_lower 0.002,0.002,0.002 -dem_insert_a_upper 0.008,0.008,0.008)
vofdem_bad_input(insert_outside     "options -dem_insert_a_lower/-dem_insert_a_upper: the region .* in z must be" ${_dem} -dem_inserts a -dem_insert_a_lower 0.002,0.002,0.002 -dem_insert_a_upper 0.008,0.008,0.0099 -dem_insert_a_rate 10)
vofdem_bad_input(insert_bad_name    "option -dem_inserts: 'a-b' is not a name" ${_dem} -dem_inserts a-b)
vofdem_bad_input(delete_boxes       "option -dem_delete_boxes: 4 numbers are not whole boxes of 6" ${_dem} -dem_delete_boxes 0,0,0,1)
vofdem_bad_input(periodic_short     "option -grid_periodic: the box is 0\\.01 m long in x, less than twice the contact cut-off" ${_dem} -grid_periodic x -dem_radius 3e-3)
vofdem_bad_input(periodic_unknown   "option -grid_periodic: unknown name 'w'"      ${_dem} -grid_periodic x,w)
vofdem_bad_input(balance_unknown    "option -dem_balance: unknown name 'metis'"    ${_dem} -dem_balance metis)
vofdem_bad_input(balance_threshold  "option -dem_balance_threshold: 0\\.5 is out of range" ${_dem} -dem_balance_threshold 0.5)
vofdem_bad_input(balance_coupled    "option -dem_balance: coupled scenes keep the fluid's decomposition" -physics dem,flow -grid_upper 0.01,0.01,0.01 -dem_balance histogram)
# -dem_walls (src/dem/Walls.cpp, StlMesh.cpp)
vofdem_bad_input(wall_type_missing  "option -dem_wall_blade_type is missing: wall 'blade'" ${_dem} -dem_walls blade)
vofdem_bad_input(wall_zero_normal   "option -dem_wall_tilt_normal: the normal must not be zero" ${_dem} -dem_walls tilt -dem_wall_tilt_type plane -dem_wall_tilt_normal 0,0,0)
vofdem_bad_input(wall_zero_axis     "option -dem_wall_drum_axis: the axis must not be zero" ${_dem} -dem_walls drum -dem_wall_drum_type cylinder -dem_wall_drum_axis 0,0,0 -dem_wall_drum_radius 1e-3)
vofdem_bad_input(wall_radius        "option -dem_wall_drum_radius: -0.001 is out of range" ${_dem} -dem_walls drum -dem_wall_drum_type cylinder -dem_wall_drum_axis 0,0,1 -dem_wall_drum_radius -1e-3)
vofdem_bad_input(wall_stl_missing   "option -dem_wall_blade_file: cannot read '.*none\\.stl'" ${_dem} -dem_walls blade -dem_wall_blade_type stl -dem_wall_blade_file ${_bad}/none.stl)
vofdem_bad_input(wall_stl_relative  "option -dem_wall_blade_file: cannot read 'no/such\\.stl' \\(a relative path starts at the working directory '/.*'\\)" ${_dem} -dem_walls blade -dem_wall_blade_type stl -dem_wall_blade_file no/such.stl)
vofdem_bad_input(particles_relative "option -dem_particles_file: cannot open 'no/such\\.csv' \\(a relative path starts at the working directory '/.*'\\)" ${_dem} -dem_particles_file no/such.csv)
vofdem_bad_input(wall_stl_malformed "option -dem_wall_blade_file: '.*malformed\\.stl': ASCII STL line 5: expected 'vertex x y z'" ${_dem} -dem_walls blade -dem_wall_blade_type stl -dem_wall_blade_file ${_bad}/malformed.stl)
vofdem_bad_input(wall_stl_truncated "truncated\\.stl': binary STL: the header announces 2 triangles \\(184 bytes\\), the file has 134 bytes" ${_dem} -dem_walls blade -dem_wall_blade_type stl -dem_wall_blade_file ${_bad}/truncated.stl)
include(VofdemOutputTests)  # DEM output and analysis
include(VofdemStatisticsTests)  # D6 long horizon: rank counts against a 1-rank ensemble of seeds
include(VofdemFlowTests)  # the pressure solve (src/flow)
include(VofdemCavityTests)  # F2 reference tables: the profile checker and the convergence-table helper
include(VofdemCheckpointTests)  # checkpoint/restart (issue 5)
include(VofdemGeometryTests)  # scripts/make-stl: blade, hopper, funnel meshes
include(VofdemVofTests)  # the VOF module (issue 8)
include(VofdemAnalysisTests)  # powder-bed analysis (issue 6)
include(VofdemSpreadingTests)  # spreading machinery and scenes (issue 6)
include(VofdemClumpTests)  # rigid multi-sphere clumps (P10)
include(VofdemHardCaseTests)  # docs/verification.md's hard cases (numerical stability)
include(VofdemStructureTests)  # the include floors (issue 50)
# -help lists the options of every named insertion source and wall (and of NAME) instead of stopping at a missing one.
add_test(NAME dem/help_sources COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_help_sources.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/help_sources PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)
# -coupling_kernel_truncation: exact projection whatever the cut, and the cut has its effect on eps.
add_test(NAME coupling/kernel_truncation COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_kernel_truncation.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/kernel_truncation PROPERTIES LABELS "quick;coupling" PROCESSORS 2 TIMEOUT 300)
# Four coupling options (drag switch, eps floor, self-correction threshold, smoothing crossover), each against a run it
# must equal bit for bit and one it must not.
add_test(NAME coupling/options COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_coupling_options.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/options PROPERTIES LABELS "quick;coupling" PROCESSORS 2 TIMEOUT 300)
# -dem_rolling_damping: 0 is epsd2 bit for bit and leaves the sphere rocking; 0.3 and 1 damp it out (1 and 2 ranks).
add_test(NAME dem/rolling_damping COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/dem/test_rolling_damping.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(dem/rolling_damping PROPERTIES LABELS "quick;dem" PROCESSORS 2 TIMEOUT 300)

# ---- energy (docs/modules/energy.md) ----
# E1 reduced: Stefan melting, one phase at St 0.1 and 1 and two phases, 100 cells across the melt, on 1 and 2 ranks.
add_test(NAME energy/stefan COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_stefan.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/stefan PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 300)
# E4's power integral: eta P absorbed to 1e-12 at R_l/h 0.35-2 with the beam off the grid lines, split in z and in x.
add_test(NAME energy/laser_power COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_laser_power.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/laser_power PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 300)
# E5: energy across a moving interface (the dam break, rho cp ratio 4000): a uniform T stays uniform to 1e-12, a closed box keeps its energy.
add_test(NAME energy/interface_transport COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_interface_transport.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/interface_transport PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 300)
# The melt's flow physics (F2): solid metal held at rest, a pool that freezes with the Darcy term, Marangoni from the computed T.
add_test(NAME energy/mushy_flow COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_mushy_flow.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/mushy_flow PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 400)
# Restart of energy moving with the interface, a collapsing column freezing from two cold walls (the Darcy term and held cells
# rebuilt from the loaded state): killed twice (once while writing), the final state is bitwise the uninterrupted run's.
add_test(NAME energy/interface_restart COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/scripts/kill-restart-test ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/dam-break.yaml 2
         --ranks 2 --steps 60 --every 6 --during-write 1 --seed 5 --exe $<TARGET_FILE:vofdem_app> -- -physics flow,vof,energy -grid_cells 40,20,1 -energy_metal_density 1000
         -energy_gas_density 1 -energy_interface_radiation 0 -energy_pc boomeramg -energy_metal_specific_heat 400 -energy_metal_conductivity 2000 -energy_metal_solidus 340
         -energy_metal_liquidus 350 -energy_metal_latent_heat 1e4 -energy_initial_temperature 400 -energy_bc_xlo temperature -energy_bc_xlo_value 300 -energy_bc_ylo temperature
         -energy_bc_ylo_value 300)
set_tests_properties(energy/interface_restart PROPERTIES LABELS "quick;energy;checkpoint" PROCESSORS 2 TIMEOUT 300 WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
# E4: a moving Gaussian source on a plate against Eagar and Tsai, R_l/h = 2: peak, isotherm length and width within 2 %, 1 and 2 ranks.
add_test(NAME energy/moving_source COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_moving_source.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/moving_source PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 300)
# The solidifying pool: a laser track's pool freezes completely after the beam, at a constant step, with the account closed;
# and the 3 kW spot (spot-on-plate.yaml) stops at the boiling point with one line on 2 ranks.
add_test(NAME energy/pool_freezes COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_pool_freezes.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/pool_freezes PROPERTIES LABELS "quick;energy" PROCESSORS 2 TIMEOUT 300)
# The metal files of config/materials (in718, in625, 304l) as the module reads them: banner values, the cp table and L through the
# initial energy (1e-12), the k table through the explicit diffusion limit.
add_test(NAME energy/material_files COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_material_files.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/material_files PROPERTIES LABELS "quick;energy" TIMEOUT 120)
# E6 part 1 (docs/physics.md P11, F9, F10): a particle heated in still hot gas against the ODE with the same laws (1 %), through
# the melting range too; the kernel's deposit and the fluid's gain against the particle's loss to 1e-12, the account to 1e-10; 1 and 2 ranks.
add_test(NAME energy/particle_heat COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_particle_heat.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/particle_heat PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 300)
add_test(NAME energy/particle_beam COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_particle_beam.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/particle_beam PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 300)
add_test(NAME energy/particle_melt COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_particle_melt.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/particle_melt PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 300)
add_test(NAME coupling/insertion_closed_box COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/coupling/test_insertion_closed_box.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(coupling/insertion_closed_box PROPERTIES LABELS "quick;coupling;vof" PROCESSORS 2 TIMEOUT 300)
add_test(NAME energy/contact_conduction COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_contact_conduction.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/contact_conduction PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 300)
add_test(NAME energy/four_particles COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_four_particles.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/four_particles PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 900)
add_test(NAME energy/deposition_restart COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_deposition_restart.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/deposition_restart PROPERTIES LABELS "quick;energy;checkpoint" PROCESSORS 2 TIMEOUT 900)
add_test(NAME energy/particle_transport COMMAND ${VOFDEM_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/test_particle_transport.py $<TARGET_FILE:vofdem_app>)
set_tests_properties(energy/particle_transport PROPERTIES LABELS "quick;energy;coupling" PROCESSORS 2 TIMEOUT 300)
set(VOFDEM_ENERGY_BOX -physics energy -grid_cells 4,4,4 -dt 1e-3)
set(VOFDEM_ENERGY_FLOW -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/dam-break.yaml -physics flow,vof,energy -grid_cells 16,8,1 -energy_metal_density 1000 -energy_gas_density 1 -energy_pc boomeramg -max_steps 1)
vofdem_bad_input(vof_cells_per_rank "option -grid_cells: the VOF module needs at least 4 cells per rank along a split direction, but y has 4 cells on 2 ranks"
                 -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/dam-break.yaml -physics flow,vof -grid_cells 8,4,1 -grid_ranks 1,2,1)
vofdem_bad_input(energy_marangoni_prescribed "option -vof_temperature_gradient: the temperature comes from the energy module here" ${VOFDEM_ENERGY_FLOW} -vof_dsigma_dT -1e-4 -vof_temperature_gradient 1,0,0)
vofdem_bad_input(energy_marangoni_no_reference "option -vof_surface_tension_temperature: with -vof_dsigma_dT and the energy module, give the temperature" ${VOFDEM_ENERGY_FLOW} -vof_dsigma_dT -1e-4)
vofdem_bad_input(energy_liquidus_below_solidus "option -energy_metal_liquidus: the liquidus 1500\\.? K must exceed the solidus 1533\\.? K" ${VOFDEM_ENERGY_BOX} -energy_metal_liquidus 1500)
vofdem_bad_input(energy_pc_type_structured "option -energy_pc_type: jacobi cannot take the hypre structured matrix" ${VOFDEM_ENERGY_BOX} -energy_pc pfmg -energy_pc_type jacobi)
vofdem_bad_input(energy_conductivity_zero "option -energy_metal_conductivity: the metal .* needs a positive conductivity" ${VOFDEM_ENERGY_BOX} -energy_metal_conductivity 0)
vofdem_bad_input(energy_substrate_with_flow "option -energy_substrate_velocity: with a flow the melt moves with its own velocity" ${VOFDEM_ENERGY_FLOW} -energy_substrate_velocity 0.01,0)
vofdem_bad_input(coupling_heat_deposit_unknown "option -coupling_heat_deposit: unknown name 'mass'" -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/sphere-entry.yaml -physics dem,flow,vof,energy -energy_metal_density 1000 -energy_gas_density 1.2 -coupling_heat_deposit mass -max_steps 1)
# Deposition (issue 52): a particle type without cp or melting data, a melt criterion above the boiling point, no beam radius.
set(VOFDEM_DEPOSITION -options_file_yaml ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/four-particles-two-heats.yaml -dem_particles_file ${CMAKE_CURRENT_SOURCE_DIR}/config/scenes/four-particles-two-types.csv -grid_cells 20,20,16 -dem_output_every 0 -flow_output_every 0 -max_steps 1)
vofdem_bad_input(coupling_heat_type_no_cp "option -coupling_heat_type_left_material: the particles of type left have no positive specific_heat" ${VOFDEM_DEPOSITION} -coupling_heat_type_left_material ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/particle_no_cp.yaml)
vofdem_bad_input(grid_cells_memory "option -grid_cells: 500000000 cells per rank .* need at least 750 GB on each rank" -physics flow -grid_cells 1000,1000,1000)
vofdem_bad_input(coupling_heat_type_no_k "option -coupling_heat_type_left_material: the particles of type left have no positive conductivity .* for their contact conduction" ${VOFDEM_DEPOSITION} -coupling_heat_type_left_material ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/particle_no_k.yaml)
vofdem_bad_input(coupling_heat_type_initial_negative "option -coupling_heat_type_right_initial_temperature: -3\\.? K is not positive" ${VOFDEM_DEPOSITION} -coupling_heat_type_right_initial_temperature -3)
vofdem_bad_input(coupling_heat_type_cp_negative "option -coupling_heat_type_left_specific_heat: -5\\.? J/\\(kg K\\) is not positive" ${VOFDEM_DEPOSITION} -coupling_heat_type_left_specific_heat -5)
vofdem_bad_input(coupling_heat_type_unknown "unknown or unused option -coupling_heat_type_middle_specific_heat" ${VOFDEM_DEPOSITION} -coupling_heat_type_middle_specific_heat 500)
vofdem_bad_input(coupling_heat_melt_above_boiling "option -coupling_heat_melt: the particles of type left would melt at their liquidus 1609\\.? K, not below their boiling point 1600\\.? K" ${VOFDEM_DEPOSITION} -energy_metal_boiling_point 1600)
vofdem_bad_input(laser_radius_zero "option -laser_radius: a laser with -laser_power 400\\.? W needs a positive radius" ${VOFDEM_DEPOSITION} -laser_radius 0)
vofdem_bad_input(laser_stop_before_start "option -laser_stop_time: 0.001 s is not after -laser_start_time 0.002 s" ${VOFDEM_DEPOSITION} -laser_start_time 2e-3 -laser_stop_time 1e-3)
vofdem_bad_input(flow_courant_unknown "option -flow_courant" -physics flow -flow_courant face)
vofdem_bad_input(energy_substrate_cfl "option -energy_substrate_cfl" ${VOFDEM_ENERGY_BOX} -energy_substrate_velocity 0.01,0 -energy_substrate_cfl 1.5)
vofdem_bad_input(energy_specific_heat_negative "option -energy_gas_specific_heat: the gas .* needs a positive specific heat" ${VOFDEM_ENERGY_BOX} -energy_gas_specific_heat -5)
vofdem_bad_input(energy_density_zero "option -energy_metal_density: the metal .* needs a positive density" ${VOFDEM_ENERGY_BOX} -energy_metal_density 0)
vofdem_bad_input(energy_laser_outside "option -laser_path: way point 1 \\(2\\.?, 0.5\\) m lies outside the box in x" ${VOFDEM_ENERGY_BOX} -laser_power 100 -laser_radius 0.1 -laser_path 0.5,0.5,2,0.5 -laser_speed 1)
vofdem_bad_input(energy_absorptivity_range "option -laser_absorptivity: .*1.5" ${VOFDEM_ENERGY_BOX} -laser_power 100 -laser_radius 0.1 -laser_path 0.5,0.5 -laser_absorptivity 1.5)
vofdem_bad_input(energy_laser_without_energy "unknown or unused option -laser_power" -physics dem -grid_upper 0.01,0.01,0.01 -laser_power 100)
vofdem_bad_input(energy_material_missing "option -energy_metal: .*no_solidus.yaml: .*needs a solidus|option -energy_metal_solidus: the metal .*no_solidus.yaml.* needs a solidus and a liquidus" ${VOFDEM_ENERGY_BOX} -energy_metal ${CMAKE_CURRENT_SOURCE_DIR}/test/energy/no_solidus.yaml)
vofdem_bad_input(energy_flow_without_vof "option -physics: 'energy' with 'flow' needs 'vof'" -physics flow,energy)
# Bonds (P13): a bond law without its strengths.
vofdem_bad_input(bond_without_tensile "option -dem_bond_tensile_strength: -dem_cohesion bond needs the bonds' tensile strength \\(Pa\\)" ${_dem} -dem_cohesion bond -dem_bond_normal_stiffness 1e12 -dem_bond_shear_strength 1e6)
vofdem_bad_input(bond_without_shear "option -dem_bond_shear_strength: -dem_cohesion bond needs the bonds' shear strength \\(N\\)" ${_dem} -dem_cohesion bond -dem_bond_model contact -dem_bond_normal_stiffness 1e12 -dem_bond_tensile_strength 1)
vofdem_bad_input(energy_with_dem "option -physics: 'energy' with 'dem' exchanges heat through the fluid's coupling. use -physics dem,flow,vof,energy" -physics dem,energy -grid_upper 0.01,0.01,0.01 -dt 1e-5)
vofdem_bad_input(energy_dem_no_vof "option -physics: 'energy' with 'flow' needs 'vof'" -physics dem,flow,energy -grid_upper 0.01,0.01,0.01 -dt 1e-5)
vofdem_bad_input(energy_density_mismatch "option -energy_metal_density: 8380\\.? kg/m\\^3 .* differs from the interface's -vof_density 1000\\.? kg/m\\^3" -physics flow,vof,energy -grid_cells 4,4,4)
vofdem_bad_input(energy_needs_dt "option -dt: the energy equation is implicit and sets no step of its own without a moving laser" -physics energy -grid_cells 4,4,4)
