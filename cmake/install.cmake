# Install rules: the public headers, the libraries (static, or shared with BUILD_SHARED_LIBS), an
# exported CMake package (find_package(tunnelvision 0.2 REQUIRED), then tv::core, tv::sim,
# tv::record, tv::level) and tunnelvision.pc for pkg-config. tests/package builds a consumer
# against the result of `cmake --install`.
include(CMakePackageConfigHelpers)

set(TV_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/tunnelvision)

set(TV_PACKAGE_NEEDS_ZLIB OFF)
if(TARGET tv_record OR TARGET tv_level)
  set(TV_PACKAGE_NEEDS_ZLIB ON)
endif()
set(TV_PACKAGE_NEEDS_THREADS OFF)
if(TARGET tv_record)
  set(TV_PACKAGE_NEEDS_THREADS ON)  # the recorder's writer thread
endif()

# Exported names are the aliases the build tree uses: tv_core is tv::core, and so on.
set(tv_installed tv_core tv_sim)
set(tv_pc_libs "-ltv_sim -ltv_core")
set(tv_pc_private "")
set(tv_pc_libs_private "")
set(tv_header_dirs core/include core/sim/include)
if(TARGET tv_record)
  list(APPEND tv_installed tv_record)
  list(APPEND tv_header_dirs core/record/include)
  string(PREPEND tv_pc_libs "-ltv_record ")
  set(tv_pc_libs_private "-pthread")  # the recorder's writer thread
  if(WIN32)
    string(APPEND tv_pc_libs_private " -lws2_32")  # the live stream's sockets
  endif()
  set(tv_pc_private "zlib")  # its file checksums (CRC-32)
endif()
if(TARGET tv_level)
  list(APPEND tv_installed tv_level)
  list(APPEND tv_header_dirs core/level/include)
  string(PREPEND tv_pc_libs "-ltv_level ")
  set(tv_pc_private "zlib")
endif()

foreach(target IN LISTS tv_installed)
  string(REGEX REPLACE "^tv_" "" short ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${short}
                                             VERSION ${PROJECT_VERSION}
                                             SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
endforeach()

install(TARGETS ${tv_installed} EXPORT tunnelvisionTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir IN LISTS tv_header_dirs)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()

install(EXPORT tunnelvisionTargets NAMESPACE tv:: DESTINATION ${TV_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/tunnelvisionConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/tunnelvisionConfig.cmake
                              INSTALL_DESTINATION ${TV_CMAKE_DIR})
# 0.x releases may break the API between minor versions, so 0.2 accepts 0.2.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tunnelvisionConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/tunnelvisionConfig.cmake
              ${PROJECT_BINARY_DIR}/tunnelvisionConfigVersion.cmake
        DESTINATION ${TV_CMAKE_DIR})

set(tv_pc_cflags "")
if(NOT TV_TRACE)
  set(tv_pc_cflags "-DTV_TRACE_DISABLED")
endif()
# The .pc file finds its prefix from where it is installed, so `cmake --install --prefix P`
# (which does not reconfigure) still gives a correct file.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(tv_pc_prefix "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH tv_pc_up /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
  string(REGEX REPLACE "/$" "" tv_pc_up "${tv_pc_up}")
  set(tv_pc_prefix "\${pcfiledir}/${tv_pc_up}")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/tunnelvision.pc.in ${PROJECT_BINARY_DIR}/tunnelvision.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/tunnelvision.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
