# Finds every third-party dependency. Each comes from a Debian package; when
# one is missing, configuration stops and names the package to install
# (scripts/setup.sh installs all of them).

macro(frameray_require pkg debian_package)
    find_package(${pkg} ${ARGN} QUIET)
    if(NOT ${pkg}_FOUND)
        message(FATAL_ERROR
            "frameray needs ${pkg}: install the Debian package '${debian_package}' "
            "(or run scripts/setup.sh)")
    endif()
endmacro()

find_package(Threads REQUIRED)
frameray_require(embree libembree-dev 3)
frameray_require(TBB libtbb-dev)
frameray_require(OpenImageIO libopenimageio-dev)
frameray_require(PNG libpng-dev)
frameray_require(JPEG libjpeg-dev)
# Debian 12's OpenImageIO CMake package lists /usr/include/opencv4 among its
# include folders although OpenImageIO's headers never need OpenCV; CMake
# rejects a missing folder there. Keep only the folders that exist rather
# than pulling in libopencv-dev.
get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
set(_oiio_existing "")
foreach(_dir IN LISTS _oiio_includes)
    if(EXISTS "${_dir}" OR _dir MATCHES "^\\$<")
        list(APPEND _oiio_existing "${_dir}")
    endif()
endforeach()
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_existing}")
frameray_require(OpenEXR libopenexr-dev)
frameray_require(spdlog libspdlog-dev)
frameray_require(fmt libfmt-dev)
frameray_require(Freetype libfreetype-dev)
if(FRAMERAY_BUILD_TESTS)
    frameray_require(GTest "googletest libgtest-dev")
endif()
