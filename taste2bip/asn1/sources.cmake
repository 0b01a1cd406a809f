# The ASN.1 data view: the subset TASTE designs use, read with located diagnostics.
list(APPEND TASTE2BIP_SOURCES)
