# The interface view readers (XML and AADL).
list(APPEND TASTE2BIP_TEST_SOURCES)
# The AADL reader: constructs and errors, then the real TASTE views and robustness.
list(APPEND TASTE2BIP_TEST_SOURCES interface_view_aadl_test.cpp)
list(APPEND TASTE2BIP_TEST_SOURCES interface_view_aadl_real_test.cpp)
