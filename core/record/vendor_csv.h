#pragma once
// Rows in the layout of the vendor's PC tool (one file per frame type, one row per
// frame, the first column holding the frame type). The HI91 header is exactly the
// vendor's; HI81 and HI83 follow the same pattern with every field of their frame
// (README, "CSV layouts"). pc_counter is the host's arrival time in ms since the start of
// the recording. Units are the frame's own: HI91 G, deg/s, uT, deg, Pa, degC, ms.
#include "protocol/hipnuc/payloads.h"

#include <string>

namespace imudesk::record::vendor_csv {

const char *hi91Header();
const char *hi81Header();
const char *hi83Header();

void appendRow(std::string &out, const protocol::hipnuc::Hi91 &p, double pcCounterMs);
void appendRow(std::string &out, const protocol::hipnuc::Hi81 &p, double pcCounterMs);
void appendRow(std::string &out, const protocol::hipnuc::Hi83 &p, double pcCounterMs);

} // namespace imudesk::record::vendor_csv
