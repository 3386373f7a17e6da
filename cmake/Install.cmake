# Where the programs find their shaders and assets (app/common/data_dir.h): share/rtview
# above the program. `cmake --install build --prefix DIR` writes DIR/bin/{rtview,rtrender,
# rtbench} and DIR/share/rtview/{shaders,assets}; the build tree mirrors that layout with
# links to the source tree (build/share/rtview), so programs run from the build tree too
# and an edited shader takes effect without a build. `cpack -G DEB` (in build/) makes a
# Debian package of the same tree, its dependencies found by dpkg-shlibdeps.
include(GNUInstallDirs)

file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/share/rtview)
foreach(dir shaders assets)
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${dir} ${CMAKE_BINARY_DIR}/share/rtview/${dir} SYMBOLIC)
endforeach()

set(RTVIEW_PROGRAMS rtrender rtbench)
if(RTVIEW_BUILD_VIEWER)
  list(APPEND RTVIEW_PROGRAMS rtview)
endif()
install(TARGETS ${RTVIEW_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The image codec module (core/image_codec.h), opened at run time from lib/rtview above
# bin/ (core/program_dir.h): a fixed lib/, not GNUInstallDirs' multiarch folder.
install(TARGETS rtview_image_oiio LIBRARY DESTINATION lib/rtview)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rtview/shaders)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rtview/assets)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_PACKAGE_NAME rtview)
set(CPACK_PACKAGE_VENDOR "the rtview developers")
set(CPACK_PACKAGE_CONTACT "rtview developers <rtview@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "One scene rasterised by OpenGL and ray traced (Whitted), side by side")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Loaded at run time, not linked: Mesa's EGL and GLX drivers (llvmpipe without a GPU).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl-mesa0, libgl1-mesa-dri")
if(RTVIEW_BUILD_VIEWER)
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", libglx-mesa0")
endif()
include(CPack)
