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
