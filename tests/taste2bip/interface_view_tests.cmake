# The interface view readers (XML and AADL), and the flattening of nested functions.
list(APPEND TASTE2BIP_TEST_SOURCES
  interface_view_xml_test.cpp
  flatten_test.cpp
  # The AADL reader: constructs and errors, then the real TASTE views and robustness.
  interface_view_aadl_test.cpp
  interface_view_aadl_real_test.cpp)
