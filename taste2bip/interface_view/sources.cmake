# The interface view: functions, their interfaces and connections, from AADL or XML.
list(APPEND TASTE2BIP_SOURCES)
