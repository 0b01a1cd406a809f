# ASN.1 leaves, signatures and whole-design translation.
list(APPEND TASTE2BIP_TEST_SOURCES translate_test.cpp)
