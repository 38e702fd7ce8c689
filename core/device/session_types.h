#pragma once
// Value types that cross from a session's worker thread to its users.
#include "clock/clock_model.h"
#include "model/device_identity.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <QMetaType>
#include <QString>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

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

// One clock of a session's device (issue 36): how its samples get their common time and how
// well. A sync panel shows these; the numbers are the model's (core/clock).
struct ClockStats {
    enum class Method {
        Counter, // the device's own counter through a clock model (HiPNUC system_time)
        Bracket, // a polled device: the middle of request and answer (HEC495, Modbus)
        Stamp,   // the interface's receive stamp less the frame's time on the bus (CAN)
    };
    std::string source; // "HI91", "HEC495", "Modbus", "CAN"
    Method method = Method::Counter;
    clock::ClockModel::State state = clock::ClockModel::State::FreeRunning;
    double driftPpm = 0;      // Counter: how fast the device's clock runs (+ : fast)
    double jitterNs = 0;      // Counter: the bound's scatter about the line
    double uncertaintyNs = 0; // Bracket: mean half-width; Stamp: none known (0)
    int resets = 0;           // counter resets and time-base changes
    double spanS = 0;         // device time under the fit
    double needSpanS = 0;     // the span it needs before it is aligned
    uint64_t samples = 0;     // samples stamped so far (Bracket, Stamp)

    // A polled device's clock: its brackets so far (none: no row).
    static void addBrackets(std::vector<ClockStats> &out, std::string source, const clock::BracketTally &brackets)
    {
        if (!brackets.count)
            return;
        ClockStats k;
        k.source = std::move(source);
        k.method = Method::Bracket;
        k.state = clock::ClockModel::State::Aligned;
        k.uncertaintyNs = brackets.meanNs();
        k.samples = brackets.count;
        out.push_back(std::move(k));
    }
};

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
    std::vector<ClockStats> clocks;
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::SessionState)
Q_DECLARE_METATYPE(imudesk::device::SessionStats)
Q_DECLARE_METATYPE(imudesk::model::DeviceIdentity)
Q_DECLARE_METATYPE(imudesk::protocol::hipnuc::AsciiReply)
