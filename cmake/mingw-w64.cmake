# Cross-building the core, the CLI and their tests for 64-bit Windows with
# Debian's mingw-w64 (docs/building.md, "Windows"):
#   cmake -S . -B build-win -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64.cmake
# The posix thread model is mingw's with std::thread (TaskGroup's workers).
# Everything is linked statically, so the .exe files need no DLL beside
# them. With Wine installed (Debian: wine, wine64), ctest runs the tests under it.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
find_program(PROBECYCLE_WINE NAMES wine wine64 PATHS /usr/lib/wine)
if(PROBECYCLE_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${PROBECYCLE_WINE})
endif()
