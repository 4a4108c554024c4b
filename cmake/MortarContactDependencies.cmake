# System libraries from Debian packages (installed by `make deps`).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(PkgConfig REQUIRED)
pkg_check_modules(MUPARSER REQUIRED IMPORTED_TARGET muparser)

find_path(SUITESPARSE_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
foreach(lib umfpack cholmod klu amd colamd camd ccolamd btf suitesparseconfig metis)
  find_library(MC_LIB_${lib} ${lib} REQUIRED)
endforeach()
find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_path(NANOFLANN_INCLUDE_DIR nanoflann.hpp REQUIRED)
find_package(BLAS REQUIRED)
find_package(LAPACK REQUIRED)
# Optional: PETSc (Debian's petsc-dev, with MPI) for the "petsc" linear solver.
pkg_check_modules(PETSC IMPORTED_TARGET PETSc)
pkg_check_modules(MPI_C IMPORTED_TARGET ompi-c)

# Compile settings shared by every target of the project.
add_library(mc_build_settings INTERFACE)
target_compile_features(mc_build_settings INTERFACE cxx_std_20)
target_include_directories(mc_build_settings INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
  $<INSTALL_INTERFACE:${MC_INSTALL_INCLUDEDIR}>)
target_compile_options(mc_build_settings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wno-unused-parameter>
  # GCC 12 reports false positives inside std::variant moves (DataValueContainer).
  $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)

# Third-party libraries, as one interface target.
add_library(mc_dependencies INTERFACE)
target_include_directories(mc_dependencies SYSTEM INTERFACE
  $<BUILD_INTERFACE:${SUITESPARSE_INCLUDE_DIR}>
  $<BUILD_INTERFACE:${METIS_INCLUDE_DIR}>
  $<BUILD_INTERFACE:${NANOFLANN_INCLUDE_DIR}>)
target_link_libraries(mc_dependencies INTERFACE
  Eigen3::Eigen nlohmann_json::nlohmann_json OpenMP::OpenMP_CXX)
target_link_libraries(mc_dependencies INTERFACE
  $<BUILD_INTERFACE:PkgConfig::MUPARSER>
  $<BUILD_INTERFACE:${MC_LIB_umfpack}> $<BUILD_INTERFACE:${MC_LIB_cholmod}>
  $<BUILD_INTERFACE:${MC_LIB_klu}> $<BUILD_INTERFACE:${MC_LIB_amd}>
  $<BUILD_INTERFACE:${MC_LIB_colamd}> $<BUILD_INTERFACE:${MC_LIB_camd}>
  $<BUILD_INTERFACE:${MC_LIB_ccolamd}> $<BUILD_INTERFACE:${MC_LIB_btf}>
  $<BUILD_INTERFACE:${MC_LIB_suitesparseconfig}> $<BUILD_INTERFACE:${MC_LIB_metis}>
  $<BUILD_INTERFACE:${LAPACK_LIBRARIES}> $<BUILD_INTERFACE:${BLAS_LIBRARIES}>)
