# Every third-party package comes from Debian 12 (scripts/setup.sh installs them).
find_package(Threads REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(nlohmann_json 3.10 CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
if(RTVIEW_PORTABLE_BENCH)  # rtbench alone, with none of the libraries below
  return()
endif()
find_package(tinyobjloader CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(assimp CONFIG REQUIRED)
find_package(OpenImageIO CONFIG REQUIRED)  # the codec module (core/image_codec.h)
find_package(PNG REQUIRED)                  # PNG files without it (core/png_file.h)
find_package(JPEG REQUIRED)                 # JPEG textures without it (core/jpeg_file.h)

# Debian's OpenImageIO config names /usr/include/opencv4 as an include directory,
# which does not exist unless OpenCV's headers are installed: drop it.
foreach(prop INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
  get_target_property(dirs OpenImageIO::OpenImageIO ${prop})
  if(dirs)
    list(FILTER dirs EXCLUDE REGEX "opencv4")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES ${prop} "${dirs}")
  endif()
endforeach()

if(RTVIEW_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
