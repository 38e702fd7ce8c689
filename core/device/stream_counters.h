#pragma once
// The statistics snapshot (SessionStats) of a family's stream, the same for a live session
// (the family's plug-in) and a replayed capture (record::ReplayWorker): both read the counters
// of the family's one decoder (decode/stream_decoder.h); and the rates of any snapshot against
// the one before.
#include "decode/stream_decoder.h"
#include "device/frame_gap_counter.h"
#include "device/session_types.h"

namespace imudesk::device {

// Counters of the stream: bytes, frames per type, damage, NMEA and payload errors.
void addDecodeCounters(const decode::Counters &c, SessionStats &s);
// Frames lost and device resets, from the gaps in the device's timestamps.
void addGapCounters(const FrameGapCounter &gaps, SessionStats &s);
// Frames per second per type, bytes per second and link load of `now` against `before`, taken
// dtSeconds earlier. Counters that started again (a new decoder) count from zero. Over a window
// too short to measure (50 ms or less) `now` keeps `before`'s rates and the answer is false:
// `before` stays the reference.
bool addRates(SessionStats &now, const SessionStats &before, double dtSeconds);

} // namespace imudesk::device
