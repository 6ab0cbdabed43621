# The installed package: `cmake --install BUILD --prefix PREFIX` puts
#   PREFIX/lib/libdgwarp_<folder>.a            every folder library built
#   PREFIX/include/dgwarp/<folder>/*.hpp       their headers
#   PREFIX/lib/cmake/dgwarp/                   the CMake package
#   PREFIX/bin/dgwarp                          the command-line tool, when built
# and a project outside the tree uses it with
#   find_package(dgwarp 0.1 REQUIRED COMPONENTS methods mpi)
#   target_link_libraries(my_solver PRIVATE dgwarp::mpi)
# A component is a folder (core, mesh, graph, motion, methods, quality,
# repair, run, plan, io, job, picture, cases, bench, mpi, mpi_job); the package looks for the
# third-party packages of the components asked for and of the folders they
# link, nothing else (cmake/dgwarpConfig.cmake.in). The libraries' own
# link interface names the third-party libraries: a methods-only solver links
# CGAL's GMP and MPFR, METIS, CHOLMOD and OpenMP, not Cairo, Gmsh or CGNS.
include(CMakePackageConfigHelpers)

# As a subproject, installed only when asked (the parent's install is its own).
option(DGWARP_INSTALL "Install dgwarp's libraries, headers and CMake package with cmake --install" ${PROJECT_IS_TOP_LEVEL})
if(NOT DGWARP_INSTALL)
  return()
endif()

get_property(dgwarp_installed_folders GLOBAL PROPERTY DGWARP_FOLDERS)
set(dgwarp_install_targets "")
foreach(folder ${dgwarp_installed_folders})
  list(APPEND dgwarp_install_targets dgwarp_${folder})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/dgwarp/${folder} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dgwarp
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
# The small interface targets that name a third-party library without a
# CMake package of its own (dgwarp_system_library: their link line only; no
# header of dgwarp's includes theirs).
get_property(dgwarp_system_libraries GLOBAL PROPERTY DGWARP_SYSTEM_LIBRARIES)
foreach(link ${dgwarp_system_libraries})
  set_target_properties(dgwarp_${link} PROPERTIES EXPORT_NAME link_${link})
  list(APPEND dgwarp_install_targets dgwarp_${link})
endforeach()
# The Gmsh module the case generators load (cases/gmsh_cases_module.hpp).
if(TARGET dgwarp_gmsh_cases)
  install(TARGETS dgwarp_gmsh_cases LIBRARY DESTINATION ${DGWARP_GMSH_CASES_INSTALL_DIR})
endif()
install(TARGETS ${dgwarp_install_targets} EXPORT dgwarpTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
set(DGWARP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dgwarp)
install(EXPORT dgwarpTargets NAMESPACE dgwarp:: DESTINATION ${DGWARP_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/dgwarpConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/dgwarpConfig.cmake INSTALL_DESTINATION ${DGWARP_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dgwarpConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dgwarpConfig.cmake ${PROJECT_BINARY_DIR}/dgwarpConfigVersion.cmake
        DESTINATION ${DGWARP_INSTALL_CMAKEDIR})
