# The interface view: functions, their interfaces and connections, from AADL or XML.
list(APPEND TASTE2BIP_SOURCES)
# The AADL reader (InterfaceView.aadl): lexer, parser, property values, interpretation.
list(APPEND TASTE2BIP_SOURCES interface_view/aadl_lexer.cpp interface_view/aadl_parser.cpp)
list(APPEND TASTE2BIP_SOURCES interface_view/aadl_properties.cpp)
list(APPEND TASTE2BIP_SOURCES interface_view/aadl_interface_view.cpp)
