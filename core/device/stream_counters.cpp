#include "stream_counters.h"

#include <algorithm>

namespace imudesk::device {

void addDecodeCounters(const decode::Counters &c, SessionStats &s)
{
    s.bytesIn = c.bytesIn;
    s.frames = c.frames;
    s.crcErrors = c.crcErrors;
    s.lengthErrors = c.lengthErrors;
    s.bytesSkipped = c.bytesSkipped;
    s.nmeaSentences = c.nmeaSentences;
    s.nmeaErrors = c.nmeaErrors;
    s.payloadErrors = c.payloadErrors;
    s.framesByType = c.framesByType;
}

void addGapCounters(const FrameGapCounter &gaps, SessionStats &s)
{
    s.framesLost = gaps.lost();
    s.framesLostByType = gaps.lostByType();
    s.deviceResets = gaps.resets();
}

bool addRates(SessionStats &now, const SessionStats &before, double dtSeconds)
{
    if (dtSeconds <= 0.05) {
        now.rateByType = before.rateByType;
        now.bytesPerSecond = before.bytesPerSecond;
        now.linkLoad = before.linkLoad;
        return false;
    }
    for (const auto &[name, count] : now.framesByType) {
        const auto it = before.framesByType.find(name);
        const uint64_t then = it == before.framesByType.end() ? 0 : std::min(count, it->second);
        now.rateByType[name] = double(count - then) / dtSeconds;
    }
    now.bytesPerSecond = double(now.bytesIn - std::min(now.bytesIn, before.bytesIn)) / dtSeconds;
    now.linkLoad = now.baud > 0 ? now.bytesPerSecond * 10.0 / now.baud : 0;
    return true;
}

} // namespace imudesk::device
