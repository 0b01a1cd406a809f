# The smcbip package: targets smcbip::bipc, smcbip::engines, smcbip::cli and the tools
# smcbip::bipc_tool and smcbip::smcbip_tool, for find_package(smcbip) after `cmake --install`
# (lib/cmake/smcbip) or straight from the build tree (smcbip_DIR=<build dir>).
include(CMakePackageConfigHelpers)

set(SMCBIP_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/smcbip)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/smcbipConfig.cmake.in
  ${PROJECT_BINARY_DIR}/smcbipConfig.cmake
  INSTALL_DESTINATION ${SMCBIP_PACKAGE_DIR})
# 0.x releases break their interface between minor versions.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/smcbipConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)

install(EXPORT smcbipTargets NAMESPACE smcbip:: DESTINATION ${SMCBIP_PACKAGE_DIR})
install(FILES ${PROJECT_BINARY_DIR}/smcbipConfig.cmake
              ${PROJECT_BINARY_DIR}/smcbipConfigVersion.cmake
        DESTINATION ${SMCBIP_PACKAGE_DIR})

# The same targets over the build tree, beside the config files.
export(EXPORT smcbipTargets NAMESPACE smcbip:: FILE ${PROJECT_BINARY_DIR}/smcbipTargets.cmake)
