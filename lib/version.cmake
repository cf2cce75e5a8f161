# The library's version: read by lib/CMakeLists.txt (the package's version file and pkg-config
# file) and by the repository's top-level project.
set(COLLIDE_VERSION 0.1.0)
