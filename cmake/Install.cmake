# Install rules (`cmake --install build`, and the Debian package: debian/README.md).
#
#   lib/yade-fast/yade/               the yade package: the extension _yade*.so and everything of
#                                     py/yade/ (the same files the build copies into build/yade/,
#                                     qt/ included); a folder of its own, because Debian's python3-yade
#                                     (the reference) owns lib/python3/dist-packages/yade
#   lib/python3/dist-packages/yade-fast.pth
#                                     puts lib/yade-fast on python3's sys.path (after dist-packages:
#                                     where python3-yade is installed, a plain `import yade` gets it)
#   bin/yade-fast                     the launcher ./yade; installed with no source tree beside it,
#                                     it imports the package from <prefix>/lib/<its name> first
#   bin/yade-fast-batch               ./yade-batch (it runs the sibling launcher named like itself
#                                     without "-batch")
#   share/doc/yade-fast/              README.md, and doc/ (its pages and pictures) beside it
#
# The names differ from the reference's `yade` and `yade-batch`, so that both can be installed.
# Relative directories are taken under CMAKE_INSTALL_PREFIX (the Debian package: /usr).

set(YADE_LAUNCHER_NAME "yade-fast" CACHE STRING "Name the launcher ./yade is installed under (its batch runner: <name>-batch)")
set(YADE_PYTHON_INSTALL_DIR "lib/${YADE_LAUNCHER_NAME}" CACHE STRING
    "Directory the yade package is installed into (relative: under CMAKE_INSTALL_PREFIX); the launcher looks in <prefix>/lib/<its name>, then on sys.path")
set(YADE_PYTHON_PTH_DIR "lib/python3/dist-packages" CACHE STRING
    "Directory of a <launcher name>.pth naming YADE_PYTHON_INSTALL_DIR, for python3's sys.path (Debian's for /usr/bin/python3; empty: none)")
set(YADE_DOC_INSTALL_DIR "share/doc/${YADE_LAUNCHER_NAME}" CACHE STRING
    "Directory README.md and doc/ are installed into (relative: under CMAKE_INSTALL_PREFIX)")

install(TARGETS _yade LIBRARY DESTINATION ${YADE_PYTHON_INSTALL_DIR}/yade)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/py/yade/ DESTINATION ${YADE_PYTHON_INSTALL_DIR}/yade
        PATTERN "__pycache__" EXCLUDE
        PATTERN "*.pyc" EXCLUDE)

if(YADE_PYTHON_PTH_DIR)
  if(IS_ABSOLUTE "${YADE_PYTHON_INSTALL_DIR}")
    set(_yade_python_dir "${YADE_PYTHON_INSTALL_DIR}")
  else()
    set(_yade_python_dir "${CMAKE_INSTALL_PREFIX}/${YADE_PYTHON_INSTALL_DIR}")
  endif()
  file(CONFIGURE OUTPUT ${CMAKE_BINARY_DIR}/${YADE_LAUNCHER_NAME}.pth CONTENT "${_yade_python_dir}\n")
  install(FILES ${CMAKE_BINARY_DIR}/${YADE_LAUNCHER_NAME}.pth DESTINATION ${YADE_PYTHON_PTH_DIR})
endif()

install(PROGRAMS ${CMAKE_SOURCE_DIR}/yade DESTINATION bin RENAME ${YADE_LAUNCHER_NAME})
# OPTIONAL: checked when installing, not when configuring
install(PROGRAMS ${CMAKE_SOURCE_DIR}/yade-batch DESTINATION bin RENAME ${YADE_LAUNCHER_NAME}-batch OPTIONAL)

# README.md at the top and doc/ below it, as in the source tree, so that the pages' links hold
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${YADE_DOC_INSTALL_DIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/doc DESTINATION ${YADE_DOC_INSTALL_DIR}
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "*.svg" PATTERN "*.jpg")
