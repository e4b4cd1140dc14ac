# `cmake --install build --prefix P` (issue 13): the libraries with their public headers, the
# `vroc` program, the built-in plugins where `vroc` finds them, the shipped scenes, a CMake package
# in components (find_package(vroc COMPONENTS ...): vroc::core, vroc::harness, vroc::plugin_sdk, ...;
# cmake/vrocConfig.cmake.in) and vroc-plugin.pc for plugins written in C. Layout (GNUInstallDirs):
#   bin/vroc
#   include/vroc/{core,harness,plugin,plugin_sdk,hmd,native,bullet,ode,mujoco}/
#   <libdir>/libvroc_*.a, <libdir>/vroc/plugins/vroc-plugin-*.so
#   <libdir>/cmake/vroc/{vrocConfig,vrocConfigVersion}.cmake, vroc-<component>-targets*.cmake
#   <libdir>/pkgconfig/vroc-plugin.pc
#   share/vroc/scenes/, share/vroc/plugin-exports.map
# Everything installed is relocatable: the package and the .pc file find the prefix from their
# own location, and `vroc` finds its plugins relative to its own directory.
include(CMakePackageConfigHelpers)

set(VROC_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/vroc)
set(VROC_DATA_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/vroc)

# Libraries of the package, by their names in it (vroc::<name>), in components: each component is
# an export set of its own, <libdir>/cmake/vroc/vroc-<component>-targets.cmake, which
# vrocConfig.cmake loads only when the component is asked for, after finding the packages its
# libraries need (so vroc::core needs only core's own dependencies, and MPI is found only for the
# harness). The backends come along so that a downstream program can compare its own backend against
# them; internals (native's src/, the harness's src/) stay out.
set_target_properties(vroc_qhull PROPERTIES EXPORT_NAME qhull)   # core's private link to libqhull_r
function(vroc_install_component component)
  install(TARGETS ${ARGN}
          EXPORT vroc-${component}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT vroc-${component}-targets NAMESPACE vroc:: DESTINATION ${VROC_CMAKE_INSTALL_DIR})
endfunction()
vroc_install_component(core vroc_core vroc_qhull)
vroc_install_component(plugin_sdk vroc_plugin_abi vroc_plugin_support)
vroc_install_component(plugins vroc_plugins)
vroc_install_component(hmd vroc_hmd)
vroc_install_component(harness vroc_harness)
foreach(backend native bullet ode mujoco)
  vroc_install_component(backend_${backend} vroc_backend_${backend})
endforeach()
vroc_install_component(program vroc)

# Public headers: each library's include/ tree. The plugin SDK's headers live flat in
# plugins/support/ and install as include/vroc/plugin_sdk/.
foreach(dir core/include tools/harness/include hmd/include plugins/include plugins/loader/include
            backends/native/include backends/bullet/include backends/ode/include backends/mujoco/include)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.h")
endforeach()
file(GLOB _vroc_sdk_headers ${PROJECT_SOURCE_DIR}/plugins/support/*.h)
install(FILES ${_vroc_sdk_headers} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/vroc/plugin_sdk)

# The built-in device plugins, where an installed `vroc` looks (plugins/loader/src/plugin_search.cpp).
# They are the dependencies of vroc_builtin_plugins (plugins/CMakeLists.txt), not the fixtures.
get_target_property(_vroc_builtin_plugins vroc_builtin_plugins MANUALLY_ADDED_DEPENDENCIES)
install(TARGETS ${_vroc_builtin_plugins} LIBRARY DESTINATION ${VROC_PLUGIN_INSTALL_DIR})
# The linker version script that keeps a plugin's only global symbol vroc_plugin_negotiate.
install(FILES ${PROJECT_SOURCE_DIR}/plugins/exports.map DESTINATION ${VROC_DATA_INSTALL_DIR}
        RENAME plugin-exports.map)

# Shipped scenes with their meshes (not the Python generators).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${VROC_SCENES_INSTALL_DIR}
        PATTERN "*.py" EXCLUDE PATTERN "__pycache__" EXCLUDE)

# The CMake package.
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/vrocConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/vrocConfig.cmake
  INSTALL_DESTINATION ${VROC_CMAKE_INSTALL_DIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR VROC_PLUGIN_INSTALL_DIR VROC_SCENES_INSTALL_DIR VROC_DATA_INSTALL_DIR)
# 0.x: a minor version may break the interface.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/vrocConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/vrocConfig.cmake ${PROJECT_BINARY_DIR}/package/vrocConfigVersion.cmake
        DESTINATION ${VROC_CMAKE_INSTALL_DIR})

# pkg-config for plugins in C: the ABI header only (nothing to link). `prefix` is computed from
# the .pc file's own directory, so the installed tree can move.
file(RELATIVE_PATH VROC_PC_TO_PREFIX ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" VROC_PC_TO_PREFIX "${VROC_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/vroc-plugin.pc.in ${PROJECT_BINARY_DIR}/package/vroc-plugin.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/package/vroc-plugin.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
