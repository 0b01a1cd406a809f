# The ASN.1 data view reader.
list(APPEND TASTE2BIP_TEST_SOURCES)
