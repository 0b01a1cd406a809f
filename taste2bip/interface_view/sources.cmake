# The interface view: functions, their interfaces and connections, from AADL or XML.
list(APPEND TASTE2BIP_SOURCES
  interface_view/xml_interface_view_reader.cpp
  interface_view/flatten.cpp
)
