# ASN.1 leaves, signatures and whole-design translation.
list(APPEND TASTE2BIP_TEST_SOURCES translate_test.cpp translate_real_designs_test.cpp c_body_test.cpp)
