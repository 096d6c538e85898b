# The packages of a Windows cross-build (cmake/mingw-w64.cmake) from
# Debian's own: the header-only Eigen, nlohmann-json and CLI11, and
# GoogleTest built from its source in /usr/src/googletest for the target.
# Debian's package files would add /usr/include itself, whose glibc headers
# must not reach a Windows build; so each library's folder is linked into a
# folder of its own here, and a small package file per library names it.
# find_package() in the project finds these through <Package>_DIR.
set(staging ${CMAKE_BINARY_DIR}/host-packages)
file(MAKE_DIRECTORY ${staging}/include)

# probecycle_host_package(<Package> <target> <folder under /usr/include>
#   <link name> <Debian's version file>)
function(probecycle_host_package package target source link version_file)
  if(NOT EXISTS /usr/include/${source})
    message(FATAL_ERROR "${package} for the Windows build: /usr/include/${source} is missing "
      "(install it: bash .ci/install-deps.sh)")
  endif()
  file(CREATE_LINK /usr/include/${source} ${staging}/include/${link} SYMBOLIC)
  set(dir ${staging}/cmake/${package})
  file(WRITE ${dir}/${package}Config.cmake
    "if(NOT TARGET ${target})\n"
    "  add_library(${target} INTERFACE IMPORTED)\n"
    "  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES\n"
    "    \"${staging}/include${ARGN}\")\n"
    "endif()\n")
  file(WRITE ${dir}/${package}ConfigVersion.cmake "include(\"${version_file}\")\n")
  set(${package}_DIR ${dir} CACHE PATH "${package} for the Windows build" FORCE)
endfunction()

probecycle_host_package(Eigen3 Eigen3::Eigen eigen3 eigen3
  /usr/share/eigen3/cmake/Eigen3ConfigVersion.cmake /eigen3)
probecycle_host_package(nlohmann_json nlohmann_json::nlohmann_json nlohmann nlohmann
  /usr/share/cmake/nlohmann_json/nlohmann_jsonConfigVersion.cmake)
probecycle_host_package(CLI11 CLI11::CLI11 CLI CLI
  /usr/share/cmake/CLI11/CLI11ConfigVersion.cmake)

if(PROBECYCLE_BUILD_TESTS)
  if(NOT EXISTS /usr/src/googletest/CMakeLists.txt)
    message(FATAL_ERROR "GoogleTest's source for the Windows build: /usr/src/googletest is "
      "missing (install libgtest-dev)")
  endif()
  set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
  set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
  add_subdirectory(/usr/src/googletest ${CMAKE_BINARY_DIR}/googletest EXCLUDE_FROM_ALL)
  # (its CMakeLists.txt names them GTest::gtest and GTest::gtest_main too)
  set(dir ${staging}/cmake/GTest)
  file(WRITE ${dir}/GTestConfig.cmake "# GTest::gtest and GTest::gtest_main: built here.\n")
  set(GTest_DIR ${dir} CACHE PATH "GoogleTest for the Windows build" FORCE)
endif()
