#pragma once
// JSON text for decoded samples (one object per line, JSON Lines), in the
// manual's units: G, deg/s, uT, deg, Pa, degC, ms. Locale-independent.
#include "model/device_identity.h"
#include "model/sample.h"
#include "protocol/hipnuc/frame_decoder.h"

#include <string>

namespace imudesk::format {

// {"type":"HI91","main_status":5384,"temperature":35,"pressure":100676.07,"system_time":1840392,
//  "acc":[x,y,z],"gyr":[...],"mag":[...],"roll":..,"pitch":..,"yaw":..,"quat":[w,x,y,z]} and, for other
// frame types, the fields they carry (lat/lon/alt, vel_enu, heave_surge_sway, ins_status ...).
// A module set to NWU (worldFrame) adds "world_frame":"NWU" to a sample with attitude: its
// angles and quaternion are in that frame.
std::string sampleToJson(const model::Sample &s, model::WorldFrame worldFrame = model::WorldFrame::Enu);

// {"summary": {"frames": {"HI91": n, ...}, "crc_errors": .., "length_errors": .., "bytes_skipped": ..,
//  "bytes": .., "seconds": .., "mb_per_s": ..}}
std::string summaryToJson(const protocol::hipnuc::FrameDecoder::Counters &c, uint64_t nmeaSentences,
                          uint64_t payloadErrors, double seconds);

// Shortest round-trip text of a number ("0.1", "-122.47699737548828" for a float widened to double
// is avoided: values are printed with 9 significant digits, enough for any float).
std::string number(double v);

} // namespace imudesk::format
