#The ASN .1 data view reader.
list(APPEND TASTE2BIP_TEST_SOURCES
         asn1_reader_test.cpp asn1_errors_test.cpp asn1_resolve_test.cpp asn1_real_files_test.cpp)
