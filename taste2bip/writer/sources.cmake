list(APPEND TASTE2BIP_SOURCES writer/wrappers.cpp)
