#pragma once
// Value types that cross from a session's worker thread to its users.
#include "model/device_identity.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <QMetaType>
#include <QString>

#include <cstdint>
#include <map>
#include <string>

namespace imudesk::device {

enum class SessionState {
    Closed,
    Opening,
    Detecting,    // baud auto-detection in progress
    Connected,    // port open, device identified or streaming
    Disconnected, // the port failed (unplugged); data received so far is kept
    Failed,       // could not open / no device found
    Reconnecting, // disconnected, waiting for the same device to come back (auto-reconnect)
};
const char *stateName(SessionState s);

struct SessionStats {
    uint64_t bytesIn = 0;
    uint64_t frames = 0;
    uint64_t crcErrors = 0;
    uint64_t lengthErrors = 0;
    uint64_t bytesSkipped = 0;
    uint64_t nmeaSentences = 0;
    uint64_t nmeaErrors = 0;
    uint64_t payloadErrors = 0;         // CRC-valid frames whose payload could not be decoded
    // Frames the device sent that never arrived (or arrived damaged), from gaps in the
    // device timestamps (device/frame_gap_counter.h); gaps across an output change, a
    // device reset or a reconnection are not counted.
    uint64_t framesLost = 0;
    std::map<std::string, uint64_t> framesLostByType;
    uint64_t deviceResets = 0;          // device timestamps that jumped backwards
    uint64_t reconnects = 0;            // times the session reconnected by itself
    std::map<std::string, uint64_t> framesByType;
    std::map<std::string, double> rateByType; // frames per second over the last window
    double bytesPerSecond = 0;
    double linkLoad = 0;                // bytes/s * 10 bits / baud (0..1+)
    int baud = 0;
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::SessionState)
Q_DECLARE_METATYPE(imudesk::device::SessionStats)
Q_DECLARE_METATYPE(imudesk::model::DeviceIdentity)
Q_DECLARE_METATYPE(imudesk::protocol::hipnuc::AsciiReply)
