# Finds what vofdem links against. Each missing piece stops configuration with one message that
# names the Debian package to install (scripts/install-deps installs all of them).
find_package(PkgConfig QUIET)
if(NOT PKG_CONFIG_FOUND)
  message(FATAL_ERROR "pkg-config not found: install the Debian package 'pkg-config' (scripts/install-deps)")
endif()

macro(vofdem_pkg target module debian)
  pkg_check_modules(_${target} QUIET IMPORTED_TARGET ${module})
  if(NOT _${target}_FOUND)
    message(FATAL_ERROR "${module} not found by pkg-config: install the Debian package '${debian}' (scripts/install-deps)")
  endif()
  add_library(vofdem::${target} INTERFACE IMPORTED)
  target_link_libraries(vofdem::${target} INTERFACE PkgConfig::_${target})
  message(STATUS "vofdem: ${module} ${_${target}_VERSION}")
endmacro()

vofdem_pkg(petsc petsc petsc-dev)
if(_petsc_VERSION VERSION_LESS 3.18)
  message(FATAL_ERROR "PETSc ${_petsc_VERSION} is too old: vofdem needs 3.18 (Debian package 'petsc-dev')")
endif()
# PETSc's .pc file lacks the HDF5 include directory (docs/petsc-notes.md): add the parallel flavour.
vofdem_pkg(hdf5 hdf5-openmpi libhdf5-openmpi-dev)
vofdem_pkg(yaml yaml-0.1 libyaml-dev)

find_package(MPI QUIET COMPONENTS C CXX)
if(NOT MPI_FOUND)
  message(FATAL_ERROR "MPI not found: install the Debian packages 'libopenmpi-dev openmpi-bin' (scripts/install-deps)")
endif()

# CGAL (header-only since 5.0; its target brings GMP and MPFR): only the analysis library uses it.
# Its imported include directories are SYSTEM, so -Wall -Wextra stay quiet about its headers.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL QUIET)
if(NOT CGAL_FOUND)
  message(FATAL_ERROR "CGAL not found: install the Debian package 'libcgal-dev' (scripts/install-deps)")
endif()
message(STATUS "vofdem: CGAL ${CGAL_VERSION}")

find_package(GTest QUIET)
if(NOT GTest_FOUND)
  message(FATAL_ERROR "GoogleTest not found: install the Debian package 'libgtest-dev' (scripts/install-deps)")
endif()

find_program(MPIEXEC_PROGRAM NAMES mpiexec mpirun)
if(NOT MPIEXEC_PROGRAM)
  message(FATAL_ERROR "mpiexec not found: install the Debian package 'openmpi-bin' (scripts/install-deps)")
endif()

# Debian's own interpreter: the first python3 on PATH may lack numpy/matplotlib/h5py (notes).
find_program(VOFDEM_PYTHON python3 PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT VOFDEM_PYTHON)
  message(FATAL_ERROR "/usr/bin/python3 not found: install the Debian package 'python3' (scripts/install-deps)")
endif()
execute_process(COMMAND ${VOFDEM_PYTHON} -c "import yaml, numpy" RESULT_VARIABLE _pyok OUTPUT_QUIET ERROR_QUIET)
if(NOT _pyok EQUAL 0)
  message(FATAL_ERROR "${VOFDEM_PYTHON} lacks yaml/numpy: install the Debian packages 'python3-yaml python3-numpy' (scripts/install-deps)")
endif()
