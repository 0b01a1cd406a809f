# The interface view: functions, their interfaces and connections, from AADL or XML.
list(APPEND TASTE2BIP_SOURCES
  interface_view/xml_interface_view_reader.cpp
  interface_view/flatten.cpp
  # The AADL reader (InterfaceView.aadl): lexer, parser, property values, interpretation.
  interface_view/aadl_lexer.cpp
  interface_view/aadl_parser.cpp
  interface_view/aadl_properties.cpp
  interface_view/aadl_interface_view.cpp)
