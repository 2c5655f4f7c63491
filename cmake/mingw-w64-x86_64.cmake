# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix: the
# POSIX thread model, which std::thread needs). scripts/test-windows.sh uses it; the tests run
# under Wine (CMAKE_CROSSCOMPILING_EMULATOR), so `ctest` works as on Linux.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
# The libraries cross-built from Debian's source packages (scripts/windows-build.sh) are found in
# their prefix as Linux's are in /usr: CMake packages and pkg-config files alike.
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
if(FRACTALIS_WINDOWS_PREFIX)
  list(PREPEND CMAKE_FIND_ROOT_PATH "${FRACTALIS_WINDOWS_PREFIX}")
  set(ENV{PKG_CONFIG_LIBDIR}
    "${FRACTALIS_WINDOWS_PREFIX}/lib/pkgconfig:${FRACTALIS_WINDOWS_PREFIX}/share/pkgconfig:/usr/x86_64-w64-mingw32/lib/pkgconfig")
  set(ENV{PKG_CONFIG_PATH} "")
endif()
# MinGW-w64's zlib comes as a DLL's import library and as a static library: the static one, so
# that nothing needs zlib1.dll (libpng is found through CMake's FindZLIB).
set(ZLIB_USE_STATIC_LIBS ON)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The MinGW runtime (libgcc, libstdc++, winpthread) linked in: an executable that misses one of
# its DLLs exits silently under Wine, and a Windows user has none of them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++")
# Scenes too (the test fixtures include C++ ones, and one links pthread): a DLL that needs
# libstdc++-6.dll or libwinpthread-1.dll fails to load on a PC without them.
set(CMAKE_MODULE_LINKER_FLAGS_INIT "-static")
find_program(FRACTALIS_WINE64 wine64 PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(FRACTALIS_WINE64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${FRACTALIS_WINE64})
endif()
