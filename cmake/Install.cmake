# Install rules (`cmake --install build`, and the Debian package: debian/README.md).
#
#   <YADE_PYTHON_INSTALL_DIR>/yade/   the extension _yade*.so and everything of py/yade/ (the same
#                                     files the build copies into build/yade/, qt/ included)
#   bin/yade-fast                     the launcher ./yade; installed with no source tree beside it,
#                                     it imports the yade package from sys.path
#   bin/yade-fast-batch               ./yade-batch, when the source tree has it (it runs the sibling
#                                     launcher named like itself without "-batch")
#   share/doc/yade-fast/              README.md, and doc/ (its pages and pictures) beside it
#
# The names differ from the reference's `yade` and `yade-batch`, so that both can be installed.
# Relative directories are taken under CMAKE_INSTALL_PREFIX (the Debian package: /usr).

set(YADE_PYTHON_INSTALL_DIR "lib/python3/dist-packages" CACHE STRING
    "Directory the yade Python package is installed into (relative: under CMAKE_INSTALL_PREFIX); the default is Debian's for /usr/bin/python3")
set(YADE_LAUNCHER_NAME "yade-fast" CACHE STRING "Name the launcher ./yade is installed under (its batch runner: <name>-batch)")
set(YADE_DOC_INSTALL_DIR "share/doc/${YADE_LAUNCHER_NAME}" CACHE STRING
    "Directory README.md and doc/ are installed into (relative: under CMAKE_INSTALL_PREFIX)")

install(TARGETS _yade LIBRARY DESTINATION ${YADE_PYTHON_INSTALL_DIR}/yade)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/py/yade/ DESTINATION ${YADE_PYTHON_INSTALL_DIR}/yade
        PATTERN "__pycache__" EXCLUDE
        PATTERN "*.pyc" EXCLUDE)

install(PROGRAMS ${CMAKE_SOURCE_DIR}/yade DESTINATION bin RENAME ${YADE_LAUNCHER_NAME})
# OPTIONAL: checked when installing, not when configuring (a build folder configured before
# yade-batch existed installs it too)
install(PROGRAMS ${CMAKE_SOURCE_DIR}/yade-batch DESTINATION bin RENAME ${YADE_LAUNCHER_NAME}-batch OPTIONAL)

# README.md at the top and doc/ below it, as in the source tree, so that the pages' links hold
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${YADE_DOC_INSTALL_DIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/doc DESTINATION ${YADE_DOC_INSTALL_DIR}
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "*.svg" PATTERN "*.jpg")
