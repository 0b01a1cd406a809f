// The table of supported PUS-C message types (ECSS-E-ST-70-41C chapter 8 numbering).
#include <array>

#include "messages.h"

namespace smcbip::pus {
namespace {

constexpr PacketType kTc = PacketType::Tc;
constexpr PacketType kTm = PacketType::Tm;

constexpr std::array kTypes{
    MessageType{1, 1, kTm, Shape::Verification, "successful acceptance verification"},
    MessageType{1, 2, kTm, Shape::Verification, "failed acceptance verification"},
    MessageType{1, 3, kTm, Shape::Verification, "successful start of execution"},
    MessageType{1, 4, kTm, Shape::Verification, "failed start of execution"},
    MessageType{1, 5, kTm, Shape::Verification, "successful progress of execution"},
    MessageType{1, 6, kTm, Shape::Verification, "failed progress of execution"},
    MessageType{1, 7, kTm, Shape::Verification, "successful completion of execution"},
    MessageType{1, 8, kTm, Shape::Verification, "failed completion of execution"},
    MessageType{3, 5, kTc, Shape::IdList, "enable periodic housekeeping reports"},
    MessageType{3, 6, kTc, Shape::IdList, "disable periodic housekeeping reports"},
    MessageType{3, 25, kTm, Shape::HousekeepingReport, "housekeeping parameter report"},
    MessageType{5, 1, kTm, Shape::EventReport, "informative event report"},
    MessageType{5, 2, kTm, Shape::EventReport, "low severity anomaly report"},
    MessageType{5, 3, kTm, Shape::EventReport, "medium severity anomaly report"},
    MessageType{5, 4, kTm, Shape::EventReport, "high severity anomaly report"},
    MessageType{5, 5, kTc, Shape::IdList, "enable event report generation"},
    MessageType{5, 6, kTc, Shape::IdList, "disable event report generation"},
    MessageType{8, 1, kTc, Shape::FunctionCall, "perform a function"},
    MessageType{9, 1, kTc, Shape::TimeReportRate, "set the time report generation rate"},
    MessageType{9, 2, kTm, Shape::TimeReport, "CUC time report"},
    MessageType{11, 4, kTc, Shape::Activities, "insert activities into the time-based schedule"},
    MessageType{12, 1, kTc, Shape::IdList, "enable parameter monitoring definitions"},
    MessageType{12, 2, kTc, Shape::IdList, "disable parameter monitoring definitions"},
    MessageType{17, 1, kTc, Shape::NoData, "are-you-alive connection test"},
    MessageType{17, 2, kTm, Shape::NoData, "are-you-alive connection test report"},
    MessageType{19, 1, kTc, Shape::Activities, "add event-action definitions"},
    MessageType{19, 4, kTc, Shape::IdList, "enable event-action definitions"},
    MessageType{20, 1, kTc, Shape::IdList, "report parameter values"},
    MessageType{20, 2, kTm, Shape::ParameterValues, "parameter value report"},
    MessageType{20, 3, kTc, Shape::ParameterValues, "set parameter values"},
    MessageType{23, 1, kTc, Shape::FileRequest, "create a file"},
    MessageType{23, 2, kTc, Shape::FileRequest, "delete a file"},
    MessageType{23, 3, kTc, Shape::FileRequest, "report the attributes of a file"},
    MessageType{23, 4, kTm, Shape::FileRequest, "file attribute report"},
    MessageType{23, 14, kTc, Shape::FileRequest, "copy a file"},
};

}  // namespace

std::span<const MessageType> message_types() { return kTypes; }

Result<const MessageType*> find_message_type(PacketType direction, std::uint8_t service,
                                             std::uint8_t subtype) {
  bool service_known = false;
  for (const MessageType& type : kTypes) {
    if (type.service != service) continue;
    service_known = true;
    if (type.subtype == subtype && type.direction == direction) return &type;
  }
  if (!service_known) return fail(Reason::UnknownService, "service type not supported", 7);
  return fail(Reason::UnknownSubtype, "message subtype not supported in this direction", 8);
}

}  // namespace smcbip::pus
