# The interface view readers (XML and AADL).
list(APPEND TASTE2BIP_TEST_SOURCES
  interface_view_xml_test.cpp
  flatten_test.cpp
)
