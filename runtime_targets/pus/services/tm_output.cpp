// The on-board TM queue, its counters, and on-board time as CUC.
#include "tm_output.h"

namespace smcbip::pus::services {

CucTime to_cuc(Millis now, const Config& config) {
  const std::uint64_t fine_units = std::uint64_t{1} << (8 * config.cuc_fine_bytes);
  // Rounded to the nearest fine unit, so that to_millis(to_cuc(t)) == t whenever a fine unit
  // is under half a millisecond (two fine octets and more).
  const std::uint64_t fine = ((now % 1000) * fine_units + 500) / 1000;
  if (fine == fine_units) return CucTime{static_cast<std::uint32_t>(now / 1000 + 1), 0};
  return CucTime{static_cast<std::uint32_t>(now / 1000), static_cast<std::uint32_t>(fine)};
}

Millis to_millis(const CucTime& time, const Config& config) {
  const std::uint64_t fine_units = std::uint64_t{1} << (8 * config.cuc_fine_bytes);
  return Millis{time.coarse} * 1000 +
         (std::uint64_t{time.fine} * 1000 + fine_units / 2) / fine_units;
}

bool TmOutput::emit(std::uint8_t service, std::uint8_t subtype, const Message& data,
                    std::uint16_t destination, Millis now) {
  if (size_ == kTmQueueCapacity) {
    ++dropped_;
    return false;
  }
  std::uint16_t& type_counter = type_counters_[service * 256U + subtype];
  Telemetry tm;
  tm.primary.apid = apid_;
  tm.primary.sequence_count = sequence_count_;
  tm.header.service = service;
  tm.header.subtype = subtype;
  tm.header.message_type_counter = type_counter;
  tm.header.destination_id = destination;
  tm.header.time = to_cuc(now, config_);
  tm.data = data;
  TmPacket& slot = queue_[(head_ + size_) % kTmQueueCapacity];
  const auto length = encode(tm, config_, slot.bytes);
  if (!length) {
    ++dropped_;
    return false;
  }
  slot.length = length.value();
  ++size_;
  sequence_count_ = static_cast<std::uint16_t>((sequence_count_ + 1) & kMaxSequenceCount);
  ++type_counter;
  return true;
}

const TmPacket* TmOutput::front() const { return size_ == 0 ? nullptr : &queue_[head_]; }

void TmOutput::pop() {
  if (size_ == 0) return;
  head_ = (head_ + 1) % kTmQueueCapacity;
  --size_;
}

}  // namespace smcbip::pus::services
