# The smcbip package: targets smcbip::bipc, smcbip::engines, smcbip::cli and the tools
# smcbip::bipc_tool and smcbip::smcbip_tool, for find_package(smcbip) after `cmake --install`
# (lib/cmake/smcbip) or straight from the build tree (smcbip_DIR=<build dir>). The stages add
# their targets to the export set smcbipTargets (libraries through smcbip_installed_library).
include(CMakePackageConfigHelpers)

# Makes the static library NAME, built from the stage folder of the same name, part of the
# package as smcbip::NAME, with that folder's headers as include/NAME/... : all of them, or
# with HEADERS <file or folder>... only those (a stage whose other headers are its inside).
function(smcbip_installed_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "HEADERS")
  # Position-independent, so that a model's plugin (a shared module) can link it in. Without
  # semantic interposition: nothing interposes a static library's functions, and PIC code that
  # allows it may not inline them (the engines ran a quarter slower on families/work_10.bip).
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_compile_options(${name} PRIVATE ${SMCBIP_WARNING_FLAGS} -fno-semantic-interposition)
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  install(TARGETS ${name} EXPORT smcbipTargets)
  if(NOT arg_HEADERS)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${name}
            FILES_MATCHING PATTERN "*.h" PATTERN tools EXCLUDE)
    return()
  endif()
  foreach(entry IN LISTS arg_HEADERS)
    if(IS_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${entry})
      install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/${entry}
              DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${name} FILES_MATCHING PATTERN "*.h")
    else()
      install(FILES ${CMAKE_CURRENT_SOURCE_DIR}/${entry}
              DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${name})
    endif()
  endforeach()
endfunction()

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
              ${CMAKE_CURRENT_LIST_DIR}/smcbip_model.cmake
        DESTINATION ${SMCBIP_PACKAGE_DIR})
# smcbip_add_model, for smcbip's own targets and beside the build tree's config.
include(${CMAKE_CURRENT_LIST_DIR}/smcbip_model.cmake)
configure_file(${CMAKE_CURRENT_LIST_DIR}/smcbip_model.cmake ${PROJECT_BINARY_DIR}/smcbip_model.cmake
               COPYONLY)

# The same targets over the build tree, beside the config files.
export(EXPORT smcbipTargets NAMESPACE smcbip:: FILE ${PROJECT_BINARY_DIR}/smcbipTargets.cmake)
