# The installed package: `cmake --install <build> --prefix P` gives
#   P/bin/shadelgraph
#   P/lib/libshadelgraph_<module>.so*
#   P/include/shadelgraph/<module>/*.hpp
#   P/include/shadelgraph/glsl/<#include path>  the material SDK's GLSL, to read
#     (framework/plugin/CMakeLists.txt; the runtime compiles its embedded copies)
#   P/lib/cmake/shadelgraph/shadelgraph{Config,ConfigVersion,Targets}.cmake
# and `find_package(shadelgraph)` then gives the imported targets
# shadelgraph::<module> (graph, gpu, scene, image, render, shadel, plugin).
# The framework modules install themselves (sg_add_module); this file writes
# the package description.
include(CMakePackageConfigHelpers)

set(SG_CONFIG_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shadelgraph)

install(EXPORT shadelgraphTargets
  NAMESPACE shadelgraph::
  DESTINATION ${SG_CONFIG_INSTALL_DIR})

# The one definition of the ABI version is the header; read it from there.
file(STRINGS ${PROJECT_SOURCE_DIR}/framework/plugin/plugin_api.hpp abi_line
  REGEX "^#define SG_PLUGIN_ABI_VERSION ")
string(REGEX REPLACE "^#define SG_PLUGIN_ABI_VERSION ([0-9]+).*" "\\1" SG_PLUGIN_ABI_VERSION "${abi_line}")
set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${PROJECT_SOURCE_DIR}/framework/plugin/plugin_api.hpp)

set(SG_GLSL_INSTALL_DIR ${CMAKE_INSTALL_INCLUDEDIR}/shadelgraph/glsl)
configure_package_config_file(
  ${PROJECT_SOURCE_DIR}/cmake/shadelgraphConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shadelgraphConfig.cmake
  INSTALL_DESTINATION ${SG_CONFIG_INSTALL_DIR}
  PATH_VARS SG_GLSL_INSTALL_DIR)
# 0.x: only the same minor version is ABI-compatible (SG_PLUGIN_ABI_VERSION
# is the real guard at load time).
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/shadelgraphConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)

install(FILES
  ${PROJECT_BINARY_DIR}/shadelgraphConfig.cmake
  ${PROJECT_BINARY_DIR}/shadelgraphConfigVersion.cmake
  DESTINATION ${SG_CONFIG_INSTALL_DIR})
