# The installed CMake package, as a solver outside the tree uses it
# (examples/installed_package, docs/API.md "Linking"). Run by ctest:
#
#   cmake -DMODE=full|library-only|subproject -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=...
#         -DMPIEXEC=... -DIN_TREE_EXAMPLE=... -P installed_package_test.cmake
#
# full: installs the build tree BUILD_DIR (every folder library and the CLI).
# library-only: configures dgwarp afresh with DGWARP_LIBRARY_ONLY=ON, checks
# that the configuration looked for none of Gmsh, Cairo, CLI11, CGNS and
# pybind11, builds and installs it.
# subproject: configures tests/install/subproject, which adds dgwarp with
# add_subdirectory and checks that only its libraries are defined.
# Then, for full and library-only: the example solver is configured against the installed
# package (find_package(dgwarp COMPONENTS methods mpi)), built and run on two
# processes; its link line and the package's link interface name no file
# format library (Cairo, Gmsh, CGNS, HDF5), and it prints what the in-tree
# build of the same example prints.
cmake_minimum_required(VERSION 3.22)
foreach(var MODE SOURCE_DIR BUILD_DIR WORK_DIR MPIEXEC IN_TREE_EXAMPLE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "installed_package_test.cmake: -D${var}=... missing")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${what} failed (${code}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

function(refuse_names what text)
  string(TOLOWER "${text}" lower)
  foreach(name gmsh cairo cgns hdf5 cli11 pybind11)
    if(lower MATCHES "${name}")
      message(FATAL_ERROR "${what} names ${name}:\n${text}")
    endif()
  endforeach()
endfunction()

if(MODE STREQUAL "subproject")
  # Configured only: the parent project checks which targets dgwarp defines.
  file(REMOVE_RECURSE ${WORK_DIR}/${MODE})
  run("configuring a project that adds dgwarp with add_subdirectory"
      ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/subproject -B ${WORK_DIR}/${MODE} -DDGWARP_SOURCE=${SOURCE_DIR})
  if(NOT run_output MATCHES "dgwarp as a subproject: libraries only")
    message(FATAL_ERROR "the parent project did not finish its checks:\n${run_output}")
  endif()
  return()
endif()

set(prefix ${WORK_DIR}/${MODE}/prefix)
file(REMOVE_RECURSE ${prefix} ${WORK_DIR}/${MODE}/solver)
if(MODE STREQUAL "full")
  run("cmake --install of the build tree" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
  if(NOT EXISTS ${prefix}/bin/dgwarp OR NOT EXISTS ${prefix}/lib/libdgwarp_io.a)
    message(FATAL_ERROR "the full install has no bin/dgwarp or lib/libdgwarp_io.a")
  endif()
  # The Gmsh module the case generators load, and the installed command meshing with it.
  if(NOT EXISTS ${prefix}/lib/dgwarp/libdgwarp_gmsh_cases.so)
    message(FATAL_ERROR "the full install has no lib/dgwarp/libdgwarp_gmsh_cases.so")
  endif()
  run("the installed dgwarp meshing a case" ${prefix}/bin/dgwarp case naca0012 -o ${WORK_DIR}/${MODE}/naca0012.su2)
  if(NOT run_output MATCHES "1656 nodes")
    message(FATAL_ERROR "the installed dgwarp did not mesh naca0012:\n${run_output}")
  endif()
elseif(MODE STREQUAL "library-only")
  # A build folder kept between runs: only what changed is compiled again.
  set(lib_build ${WORK_DIR}/${MODE}/build)
  run("configuring dgwarp with DGWARP_LIBRARY_ONLY=ON"
      ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${lib_build} -DDGWARP_LIBRARY_ONLY=ON -DCMAKE_BUILD_TYPE=Release)
  refuse_names("the library-only configure log" "${run_output}")
  file(STRINGS ${lib_build}/CMakeCache.txt cache REGEX "^[A-Za-z0-9_]+:")
  list(FILTER cache INCLUDE REGEX "^(GMSH|CGNS|CAIRO|CLI11|pybind11|ZLIB)")
  if(cache)
    message(FATAL_ERROR "the library-only configuration looked for: ${cache}")
  endif()
  run("building the library-only configuration" ${CMAKE_COMMAND} --build ${lib_build} -j 2)
  run("cmake --install of the library-only build" ${CMAKE_COMMAND} --install ${lib_build} --prefix ${prefix})
  foreach(absent bin/dgwarp lib/libdgwarp_io.a lib/libdgwarp_picture.a lib/libdgwarp_cases.a)
    if(EXISTS ${prefix}/${absent})
      message(FATAL_ERROR "the library-only install has ${absent}")
    endif()
  endforeach()
else()
  message(FATAL_ERROR "MODE is full or library-only, not '${MODE}'")
endif()

# What the package says it links, for the components the solver asks for.
file(GLOB targets_files ${prefix}/lib/cmake/dgwarp/dgwarpTargets*.cmake)
set(interface "")
foreach(f ${targets_files})
  file(STRINGS ${f} lines REGEX "INTERFACE_LINK_LIBRARIES")
  string(APPEND interface "${lines}\n")
endforeach()
if(MODE STREQUAL "library-only")
  refuse_names("the library-only package's link interface" "${interface}")
endif()

set(solver ${WORK_DIR}/${MODE}/solver)
run("configuring the example solver against ${prefix}"
    ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/installed_package -B ${solver} -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_BUILD_TYPE=Release)
refuse_names("the example solver's configure log" "${run_output}")
run("building the example solver" ${CMAKE_COMMAND} --build ${solver})
file(READ ${solver}/CMakeFiles/solver_time_loop.dir/link.txt link_line)
refuse_names("the example solver's link line" "${link_line}")

set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMP_NUM_THREADS} 1)
run("the installed example solver" ${MPIEXEC} --oversubscribe --bind-to none -np 2 ${solver}/solver_time_loop)
set(installed "${run_output}")
run("the in-tree example solver" ${MPIEXEC} --oversubscribe --bind-to none -np 2 ${IN_TREE_EXAMPLE})
set(in_tree "${run_output}")
# The same figures, but for the time of the slowest step.
string(REGEX REPLACE ", slowest step [^\n]*" "" installed_figures "${installed}")
string(REGEX REPLACE ", slowest step [^\n]*" "" in_tree_figures "${in_tree}")
if(NOT installed_figures MATCHES "^2 processes, [0-9]+ process nodes" OR NOT installed_figures STREQUAL in_tree_figures)
  message(FATAL_ERROR "the installed example printed\n${installed}\nthe in-tree one\n${in_tree}")
endif()
message(STATUS "installed package (${MODE}): ${installed}")
