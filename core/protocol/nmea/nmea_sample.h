#pragma once
// An NMEA sentence as a sample, so that position, velocity, fix and UTC time reach the values
// table, replay and export the way binary frames do: GGA gives position, fix quality,
// satellites and time; RMC position (when its status is A), the velocity from speed over
// ground and course, and time; HiPNUC's SXT position, attitude, velocity, fix and time.
// Other sentences give no sample.
#include "model/sample.h"
#include "protocol/nmea/nmea_parser.h"

#include <optional>

namespace imudesk::protocol::nmea {

std::optional<model::Sample> toSample(const Sentence &sentence);
// A received line: parsed, then toSample (nullopt for a sentence that does not parse).
std::optional<model::Sample> sampleOf(std::string_view line);

} // namespace imudesk::protocol::nmea
