// The application data of the PUS-C message types the services use, as fixed-capacity values.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>

#include "ccsds.h"
#include "config.h"
#include "cuc_time.h"
#include "detail/byte_io.h"
#include "fixed.h"
#include "result.h"

namespace smcbip::pus {

/// Capacities of the decoded application data (the decoder refuses more: CapacityExceeded).
inline constexpr std::size_t kMaxItems = 32;        ///< IDs, values, arguments per message
inline constexpr std::size_t kMaxFailureData = 32;  ///< octets of ST01 failure data
inline constexpr std::size_t kMaxAuxData = 64;      ///< octets of ST05 auxiliary data
inline constexpr std::size_t kMaxRequests = 4;      ///< embedded TCs in [11,4] and [19,1]
inline constexpr std::size_t kMaxEmbeddedTc = 256;  ///< octets of one embedded TC
inline constexpr std::size_t kMaxFileString = 64;   ///< octets of an ST23 path or file name

/// ST23 fields whose widths the standard leaves to the mission, fixed by this project: a
/// variable-length character string is a one-octet length then that many octets; the copy
/// operation ID two octets; the maximum file size four.
inline constexpr std::size_t kFileStringLengthBytes = 1;
inline constexpr std::size_t kFileOperationIdBytes = 2;
inline constexpr std::size_t kFileSizeBytes = 4;

/// [17,1], [17,2]: no application data.
struct NoData {
  friend bool operator==(const NoData&, const NoData&) = default;
};

/// ST01 [1,1]..[1,8] (6.1.5): request ID; [1,5]/[1,6] add the step ID; the failures [1,2],
/// [1,4], [1,6], [1,8] add the failure notice (code, then data to the end of the packet).
struct Verification {
  RequestId request{};
  std::uint64_t step_id = 0;
  std::uint64_t failure_code = 0;
  FixedBytes<kMaxFailureData> failure_data;
  friend bool operator==(const Verification&, const Verification&) = default;
};

/// N then N IDs: [3,5]/[3,6] structure IDs, [5,5]/[5,6] event definition IDs, [12,1]/[12,2]
/// monitoring definition IDs, [19,4] event definition IDs, [20,1] parameter IDs.
struct IdList {
  FixedVector<std::uint64_t, kMaxItems> ids;
  friend bool operator==(const IdList&, const IdList&) = default;
};

/// [3,25] housekeeping parameter report: structure ID, then the parameter values of the
/// structure (as many as fit the rest of the packet, each `value_bytes` wide).
struct HousekeepingReport {
  std::uint64_t structure_id = 0;
  FixedVector<std::uint64_t, kMaxItems> values;
  friend bool operator==(const HousekeepingReport&, const HousekeepingReport&) = default;
};

/// [5,1]..[5,4] event report (informative, low, medium, high severity): event definition ID
/// and auxiliary data to the end of the packet.
struct EventReport {
  std::uint64_t event_id = 0;
  FixedBytes<kMaxAuxData> aux_data;
  friend bool operator==(const EventReport&, const EventReport&) = default;
};

/// An argument of [8,1], or a parameter value of [20,2]/[20,3]: ID and raw value bits.
struct IdValue {
  std::uint64_t id = 0;
  std::uint64_t value = 0;
  friend bool operator==(const IdValue&, const IdValue&) = default;
};

/// [8,1] perform a function: function ID (a fixed-length field, as a big-endian integer), N,
/// then N (argument ID, argument value).
struct FunctionCall {
  std::uint64_t function_id = 0;
  FixedVector<IdValue, kMaxItems> arguments;
  friend bool operator==(const FunctionCall&, const FunctionCall&) = default;
};

/// [20,2] parameter value report and [20,3] set parameter values: N (parameter ID, value).
struct ParameterValues {
  FixedVector<IdValue, kMaxItems> values;
  friend bool operator==(const ParameterValues&, const ParameterValues&) = default;
};

/// [9,1] set the time report generation rate: the exponential rate value (8 bits; a report
/// every 2^value time reporting periods).
struct TimeReportRate {
  std::uint8_t rate_exponent = 0;
  friend bool operator==(const TimeReportRate&, const TimeReportRate&) = default;
};

/// [9,2] CUC time report: the exponential rate value, then the on-board time (the optional
/// time reference status is left to the TM secondary header).
struct TimeReport {
  std::uint8_t rate_exponent = 0;
  CucTime time{};
  friend bool operator==(const TimeReport&, const TimeReport&) = default;
};

/// An embedded telecommand (a whole TC packet, CRC included) and what it is keyed by:
/// the release time for [11,4], the event definition ID for [19,1].
struct Activity {
  CucTime release_time{};
  std::uint64_t event_id = 0;
  FixedBytes<kMaxEmbeddedTc> request;
  friend bool operator==(const Activity&, const Activity&) = default;
};

/// [11,4] insert activities (N, then N (release time, request)) and [19,1] add event-action
/// definitions (N, then N (event definition ID, request)).
struct Activities {
  FixedVector<Activity, kMaxRequests> items;
  friend bool operator==(const Activities&, const Activities&) = default;
};

/// ST23 file management (ECSS-E-ST-70-41C 8.23): [23,1] create a file (repository path, file
/// name, maximum size), [23,2] delete a file and [23,3] report its attributes (repository
/// path, file name), [23,4] file attribute report (repository path, file name, maximum size),
/// [23,14] copy a file (operation ID, source repository path and file name, target repository
/// path and file name). The optional lock status of [23,1] and [23,4] is left out.
struct FileRequest {
  std::uint64_t operation_id = 0;  ///< [23,14]
  FixedBytes<kMaxFileString> repository, file;
  FixedBytes<kMaxFileString> target_repository, target_file;  ///< [23,14]
  std::uint64_t max_size = 0;                                 ///< [23,1], [23,4]
  friend bool operator==(const FileRequest&, const FileRequest&) = default;
};

/// The application data of any supported message type.
using Message =
    std::variant<NoData, Verification, IdList, HousekeepingReport, EventReport, FunctionCall,
                 ParameterValues, TimeReportRate, TimeReport, Activities, FileRequest>;

/// Which alternative of Message a message type carries (the variant's index).
enum class Shape : std::uint8_t {
  NoData,
  Verification,
  IdList,
  HousekeepingReport,
  EventReport,
  FunctionCall,
  ParameterValues,
  TimeReportRate,
  TimeReport,
  Activities,
  FileRequest,
};

/// A supported message type: [service, subtype], its direction and the shape of its data.
struct MessageType {
  std::uint8_t service;
  std::uint8_t subtype;
  PacketType direction;
  Shape shape;
  const char* name;
};

/// Every supported message type, TC and TM.
std::span<const MessageType> message_types();

/// The message type [service, subtype] in the given direction: UnknownService if no supported
/// type has that service, UnknownSubtype if the service is known but not this subtype (or not
/// in this direction).
Result<const MessageType*> find_message_type(PacketType direction, std::uint8_t service,
                                             std::uint8_t subtype);

/// Appends the application data; BadField if the message's alternative is not the type's
/// shape or a value does not fit its configured width.
Result<Done> encode_app_data(const MessageType& type, const Message& message, const Config& config,
                             detail::Writer& out);

/// Reads the application data of a message type, which must fill `in` exactly
/// (TrailingBytes otherwise).
Result<Message> decode_app_data(const MessageType& type, const Config& config, detail::Reader& in);

}  // namespace smcbip::pus
