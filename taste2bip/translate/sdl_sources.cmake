# The SDL process as a BIP atom (sdl_atom.h).
list(APPEND TASTE2BIP_SOURCES)
