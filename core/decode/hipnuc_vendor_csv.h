#pragma once
// HiPNUC: rows in the layout of the vendor's PC tool (one file per frame type, one row per
// frame, the first column holding the frame type). The HI91 header is exactly the
// vendor's; HI81 and HI83 follow the same pattern with every field of their frame
// (docs/FILE_FORMATS.md, "CSV layouts"). pc_counter is the host's arrival time in ms since the start of
// the recording. Units are the frame's own: HI91 G, deg/s, uT, deg, Pa, degC, ms.
#include "protocol/hipnuc/payloads.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace imudesk::decode::vendor_csv {

const char *hi91Header();
const char *hi81Header();
const char *hi83Header();

void appendRow(std::string &out, const protocol::hipnuc::Hi91 &p, double pcCounterMs);
void appendRow(std::string &out, const protocol::hipnuc::Hi81 &p, double pcCounterMs);

// The cells of an imported row that its frame cannot give back (issue 53): HI91 carries no
// pps_sync_stamp, incli_x or incli_y, and a cell whose text the export would write otherwise
// (a vendor's norm, a pc_counter) is kept as the file had it. The converter stores them in the
// capture (capture::ChunkVendorCells, before the frame's chunk) and the export writes them back.
using Cells = std::vector<std::pair<std::string, std::string>>; // header name, cell text
// "name=text" lines; decodeCells skips a line without '='.
std::string encodeCells(const Cells &cells);
Cells decodeCells(std::string_view text);
// The HI91 row with the named cells as given (names the layout lacks are left out).
void appendRow(std::string &out, const protocol::hipnuc::Hi91 &p, double pcCounterMs, const Cells &keep);
// What the export writes for this frame, cell by cell, beside the header's names.
std::vector<std::string> hi91Cells(const protocol::hipnuc::Hi91 &p, double pcCounterMs);
std::vector<std::string> hi91Names();
void appendRow(std::string &out, const protocol::hipnuc::Hi83 &p, double pcCounterMs);

} // namespace imudesk::decode::vendor_csv
