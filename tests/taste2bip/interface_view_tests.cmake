# The interface view readers (XML and AADL).
list(APPEND TASTE2BIP_TEST_SOURCES)
