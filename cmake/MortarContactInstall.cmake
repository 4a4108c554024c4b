# Installs the core library, its headers and a CMake package so that out-of-tree plugins can
# `find_package(mortarcontact)` and link `mortarcontact::core`.
include(CMakePackageConfigHelpers)

install(TARGETS mortarcontact_core mc_build_settings mc_dependencies
  EXPORT mortarcontactTargets
  LIBRARY DESTINATION ${MC_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${MC_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${MC_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${MC_INSTALL_INCLUDEDIR})

foreach(layer core structural thermal custom_utilities custom_conditions custom_linear_solvers custom_processes
              custom_strategies custom_formulations)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/
    DESTINATION ${MC_INSTALL_INCLUDEDIR}/${layer}
    FILES_MATCHING PATTERN "*.h")
endforeach()

install(EXPORT mortarcontactTargets NAMESPACE mortarcontact:: DESTINATION ${MC_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/mortarcontactConfig.cmake.in
  ${PROJECT_BINARY_DIR}/mortarcontactConfig.cmake
  INSTALL_DESTINATION ${MC_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mortarcontactConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mortarcontactConfig.cmake ${PROJECT_BINARY_DIR}/mortarcontactConfigVersion.cmake
  DESTINATION ${MC_INSTALL_CMAKEDIR})
