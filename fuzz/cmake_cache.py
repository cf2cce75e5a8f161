"""Reads a value from a CMake build directory's cache (shared by run.py and coverage.py)."""


def cache_value(build, key):
    cache = build / "CMakeCache.txt"
    if not cache.exists():
        return None
    for line in cache.read_text(errors="replace").splitlines():
        if line.startswith(key + ":"):
            return line.split("=", 1)[1]
    return None
