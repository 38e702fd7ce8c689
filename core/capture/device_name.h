#pragma once
// A device's one name (issue 53 point 16): the same in every run, wherever a device is named by
// ImuDesk: its MCAP and live-bridge topics (/imu/<name>/...), its frame (imu_<name>), the struct
// of a MATLAB file, a session's file and manifest entry. Decided here alone, from what the
// device says of itself and of its link (a capture header, capture/capture_header.h):
//   1. its serial number, when it has one that is text ("0042", "2181B60A6FDA63DF");
//   2. else its family and bus address: "HEC495_addr2" (Witlink address), "HI14R3_addr1" (a
//      Modbus node), "canopen_node5" / "j1939_node8" / "hec495_node5" (a CAN protocol and node);
//   3. else a label the user set;
//   4. else its product name ("HI14R3"), else "device".
// Never a port or a tab's title: /dev/pts/10 and "HI14R3 on /dev/pts/10" differ per run.
// Characters other than letters, digits and '_' become '_' (capture::deviceName is topic-safe).
#include "capture/capture_header.h"

#include <string>

namespace imudesk::capture {

// The device's name (topic-safe: [A-Za-z0-9_], never empty).
std::string deviceName(const CaptureHeader &header, const std::string &label = {});
// The name of the device's struct in a MATLAB file, a valid MATLAB identifier: "SN_" and the
// serial number ("SN_0042", the user guide's "MATLAB"; a serial that begins with "SN_" or
// "SN-" already is not given a second one), else deviceName().
std::string matlabDeviceName(const CaptureHeader &header, const std::string &label = {});
// The serial number of the header when it is one (not empty, printable ASCII, not a flash's
// unwritten 0xFF bytes), else empty.
std::string usableSerial(const CaptureHeader &header);

} // namespace imudesk::capture
