// The PUS packet library's facade: CCSDS space packets with PUS-C headers, CUC time,
// CRC-16/CCITT-FALSE and the application data of the supported services, without heap.
#pragma once

#include "ccsds.h"        // IWYU pragma: export
#include "config.h"       // IWYU pragma: export
#include "crc16.h"        // IWYU pragma: export
#include "cuc_time.h"     // IWYU pragma: export
#include "fixed.h"        // IWYU pragma: export
#include "messages.h"     // IWYU pragma: export
#include "packet.h"       // IWYU pragma: export
#include "pus_headers.h"  // IWYU pragma: export
#include "result.h"       // IWYU pragma: export
#include "time_fields.h"  // IWYU pragma: export
