# Finds the Debian 12 packages Fluence builds on. The workarounds are those recorded in
# shared/notes/debian-build.md: each library is found the way that works with the Debian package.
find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)

# Embree 3.13 ships a working CMake config (target `embree`).
find_package(embree 3 REQUIRED)

# oneTBB 2021 ships a working CMake config (target TBB::tbb).
find_package(TBB REQUIRED)

# OpenImageIO 2.4's CMake config lists /usr/include/opencv4 as an include directory, which fails
# unless OpenCV is installed: use pkg-config instead.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)

# OpenColorIO 2.1 ships no CMake config.
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO)
# cpp-httplib 0.11 (libcpp-httplib-dev): the HTTP server of `fluence review` (apps/review_server.h).
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)

# OpenSubdiv 3.5 (subdivision surfaces, delegate/subdivision*): Debian's OpenSubdivConfig.cmake
# names a libosdCPU.a the package does not ship (shared/notes/debian-build.md), so the library and
# the headers (under opensubdiv/) are found directly.
find_library(OPENSUBDIV_CPU_LIBRARY NAMES osdCPU REQUIRED)
find_path(OPENSUBDIV_INCLUDE_DIR NAMES opensubdiv/version.h REQUIRED)
add_library(OpenSubdiv::osdCPU UNKNOWN IMPORTED)
set_target_properties(OpenSubdiv::osdCPU PROPERTIES IMPORTED_LOCATION "${OPENSUBDIV_CPU_LIBRARY}"
                                                    INTERFACE_INCLUDE_DIRECTORIES "${OPENSUBDIV_INCLUDE_DIR}")

# OpenVDB 10 (volumes/, tools/): Debian ships FindOpenVDB.cmake outside CMake's module path, and
# the module fails without libboost-iostreams-dev (shared/notes/debian-build.md). The folder is on
# the module path only for this call, so its other Find*.cmake files shadow nothing else.
set(FLUENCE_SAVED_MODULE_PATH ${CMAKE_MODULE_PATH})
list(APPEND CMAKE_MODULE_PATH /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB)
find_package(OpenVDB REQUIRED)
set(CMAKE_MODULE_PATH ${FLUENCE_SAVED_MODULE_PATH})

# pugixml 1.13 (MaterialX documents, scene/mtlx_reader): its CMake config (target pugixml::pugixml).
find_package(pugixml REQUIRED)

# LZ4 1.9 (the compression of USD crate files, scene/crate_compression): pkg-config (liblz4).
pkg_check_modules(LZ4 REQUIRED IMPORTED_TARGET liblz4)
