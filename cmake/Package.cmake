# `cpack -G DEB -B packages` in the build folder: one Debian package with the command, the
# library and its development files (components cli, lib, dev) under /usr; the
# libraries it needs found by dpkg-shlibdeps. The Python module is installed as
# a wheel (pyproject.toml). Test: install.deb (tests/install.cmake).
set(CPACK_PACKAGE_NAME shockgas)
set(CPACK_PACKAGE_VENDOR shockgas)
set(CPACK_PACKAGE_CONTACT "shockgas maintainers <shockgas@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "1-D sticky and inelastic particle gas beside the inviscid Burgers equation")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_COMPONENTS_ALL cli lib dev)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The plots and the animation: the command runs without them and says so.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib, python3-h5py, python3-numpy, ffmpeg")
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
set(CPACK_GENERATOR DEB)
include(CPack)
