// ST01 reports of a request's stages.
#include "verification.h"

namespace smcbip::pus::services {
namespace {

constexpr std::uint8_t kAckAcceptance = 1;
constexpr std::uint8_t kAckStart = 2;
constexpr std::uint8_t kAckProgress = 4;
constexpr std::uint8_t kAckCompletion = 8;

bool asks(const Telecommand& tc, std::uint8_t flag) { return (tc.header.ack_flags & flag) != 0; }

}  // namespace

void Verification::report(std::uint8_t subtype, const RequestId& request, std::uint16_t destination,
                          const Failure* failure, std::uint64_t step, Millis now) {
  pus::Verification data;
  data.request = request;
  data.step_id = step;
  if (failure != nullptr) {
    data.failure_code = static_cast<std::uint16_t>(failure->code);
    for (int shift = 24; shift >= 0; shift -= 8) {
      data.failure_data.push_back(static_cast<std::uint8_t>(failure->datum >> shift));
    }
  }
  out_.emit(1, subtype, data, destination, now);
}

void Verification::accepted(const Telecommand& tc, Millis now) {
  if (asks(tc, kAckAcceptance)) {
    report(1, RequestId::of(tc.primary), tc.header.source_id, nullptr, 0, now);
  }
}

void Verification::rejected(const RequestId& request, std::uint16_t source, const Failure& failure,
                            Millis now) {
  report(2, request, source, &failure, 0, now);
}

void Verification::started(const Telecommand& tc, Millis now) {
  if (asks(tc, kAckStart))
    report(3, RequestId::of(tc.primary), tc.header.source_id, nullptr, 0, now);
}

void Verification::start_failed(const Telecommand& tc, const Failure& failure, Millis now) {
  report(4, RequestId::of(tc.primary), tc.header.source_id, &failure, 0, now);
}

void Verification::progressed(const Telecommand& tc, std::uint64_t step, Millis now) {
  if (asks(tc, kAckProgress)) {
    report(5, RequestId::of(tc.primary), tc.header.source_id, nullptr, step, now);
  }
}

void Verification::progress_failed(const Telecommand& tc, std::uint64_t step,
                                   const Failure& failure, Millis now) {
  report(6, RequestId::of(tc.primary), tc.header.source_id, &failure, step, now);
}

void Verification::completed(const Telecommand& tc, Millis now) {
  if (asks(tc, kAckCompletion)) {
    report(7, RequestId::of(tc.primary), tc.header.source_id, nullptr, 0, now);
  }
}

void Verification::completion_failed(const Telecommand& tc, const Failure& failure, Millis now) {
  report(8, RequestId::of(tc.primary), tc.header.source_id, &failure, 0, now);
}

}  // namespace smcbip::pus::services
