// taste2bip: TASTE designs become BIP packages. The readers of the design's views (ASN.1 data
// view, interface view in AADL or XML) report located diagnostics (bipc/diagnostics.h) and never
// print.
#pragma once

#include "taste2bip/asn1/data_view.h"
#include "taste2bip/interface_view/interface_view.h"
#include "taste2bip/names.h"
