# Every third-party dependency is found here, once. See the Debian notes in architecture.md.
find_package(Eigen3 3.3 REQUIRED NO_MODULE) # before CGAL: its find module would shadow the target
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(assimp REQUIRED)
find_package(urdfdom REQUIRED)
find_package(OpenCASCADE REQUIRED)
find_package(CGAL REQUIRED)
# PCL (libpcl-dev) for scans: voxel grid, outlier removal, k-d trees, normals and ICP registration. Its
# headers are included by core/spira/scan/scan_pcl.cpp alone.
find_package(PCL 1.13 REQUIRED COMPONENTS common kdtree search filters features registration)
# PCL's own targets carry VTK's and Qt's include directories and definitions for its other modules;
# these modules use neither, so only their headers and libraries are named.
set(spira_pcl_libraries FLANN::FLANN)
foreach(module COMMON KDTREE OCTREE SEARCH SAMPLE_CONSENSUS FILTERS FEATURES REGISTRATION)
  list(APPEND spira_pcl_libraries ${PCL_${module}_LIBRARY})
endforeach()
add_library(Spira::pcl INTERFACE IMPORTED)
set_target_properties(Spira::pcl PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${PCL_COMMON_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${spira_pcl_libraries}")

# SuiteSparse 5.x in Debian ships no CMake package: find CHOLMOD by hand.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(Spira::cholmod INTERFACE IMPORTED)
set_target_properties(Spira::cholmod PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${CHOLMOD_LIBRARY};${SUITESPARSECONFIG_LIBRARY}")

# OpenCASCADE targets carry no include directories in Debian's config.
add_library(Spira::occt INTERFACE IMPORTED)
set_target_properties(Spira::occt PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${OpenCASCADE_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "TKernel;TKMath;TKBRep;TKG3d;TKGeomBase;TKGeomAlgo;TKTopAlgo;TKPrim;TKMesh;TKShHealing;TKXSBase;TKSTEP;TKSTEPBase;TKSTEPAttr;TKSTEP209;TKIGES;TKBO")

# TinyXML (urdfdom's XML reader, a dependency of liburdfdom-dev) checks the joint tree before urdfdom
# builds it (kinematics/urdf_parse.h).
find_path(TINYXML_INCLUDE_DIR tinyxml.h REQUIRED)
find_library(TINYXML_LIBRARY tinyxml REQUIRED)
add_library(Spira::urdfdom INTERFACE IMPORTED)
set_target_properties(Spira::urdfdom PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${urdfdom_INCLUDE_DIRS};${TINYXML_INCLUDE_DIR}"
  INTERFACE_LINK_LIBRARIES "${urdfdom_LIBRARIES};${TINYXML_LIBRARY}")

if(SPIRA_BUILD_GUI)
  find_package(Qt5 5.15 REQUIRED COMPONENTS Core Gui Widgets OpenGL Test Svg)
  find_package(VTK 9.1 REQUIRED COMPONENTS CommonCore CommonDataModel CommonColor FiltersCore FiltersSources
    FiltersGeneral FiltersModeling InteractionStyle InteractionWidgets RenderingCore RenderingOpenGL2
    RenderingAnnotation RenderingFreeType RenderingContext2D RenderingContextOpenGL2 ChartsCore ViewsContext2D
    GUISupportQt IOImage)
endif()
if(SPIRA_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

# PETSc over MPI (Debian: libpetsc-real-dev, with OpenMPI) for the thermal model's distributed solves
# (spira-cli thermal --backend petsc, mpirun). Optional: without it that backend is refused at run time.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_search_module(PETSC QUIET PETSc petsc)
endif()
find_package(MPI QUIET COMPONENTS C)
set(spira_petsc_found OFF)
if(PETSC_FOUND AND MPI_C_FOUND)
  set(spira_petsc_found ON)
endif()
option(SPIRA_WITH_PETSC "Build the thermal model's PETSc (MPI) backend (needs libpetsc-real-dev)" ${spira_petsc_found})
if(SPIRA_WITH_PETSC)
  if(NOT spira_petsc_found)
    message(FATAL_ERROR "SPIRA_WITH_PETSC needs PETSc and MPI: install libpetsc-real-dev, or configure with "
                        "-DSPIRA_WITH_PETSC=OFF")
  endif()
  # Only the include directories and libraries: the .pc file's other flags are Debian's build flags.
  add_library(Spira::petsc INTERFACE IMPORTED)
  set_target_properties(Spira::petsc PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${PETSC_INCLUDE_DIRS}"
    INTERFACE_LINK_LIBRARIES "${PETSC_LINK_LIBRARIES};MPI::MPI_C")
  message(STATUS "Thermal PETSc backend: PETSc ${PETSC_VERSION}, MPI ${MPI_C_VERSION} (${MPIEXEC_EXECUTABLE})")
else()
  message(STATUS "Thermal PETSc backend: off (install libpetsc-real-dev for it)")
endif()
