#pragma once
// The statistics snapshot (SessionStats) of a HiPNUC byte stream, the same for a live session
// (HipnucSerialFamily) and a replayed capture (record::ReplayWorker), and the rates of any
// snapshot against the one before.
#include "device/frame_gap_counter.h"
#include "device/session_types.h"
#include "protocol/stream/stream_demux.h"

namespace imudesk::device {

// Counters of the stream: bytes, frames per type, damage, NMEA, payload errors and lost frames.
void fillStreamCounters(const protocol::StreamDemux &demux, uint64_t payloadErrors, const FrameGapCounter &gaps,
                        SessionStats &s);
// Frames per second per type, bytes per second and link load of `now` against `before`, taken
// dtSeconds earlier. Counters that started again (a new decoder) count from zero. Over a window
// too short to measure (50 ms or less) `now` keeps `before`'s rates and the answer is false:
// `before` stays the reference.
bool addRates(SessionStats &now, const SessionStats &before, double dtSeconds);

} // namespace imudesk::device
