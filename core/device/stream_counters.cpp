#include "stream_counters.h"

#include <algorithm>
#include <cstdio>

namespace imudesk::device {

void fillStreamCounters(const protocol::StreamDemux &demux, uint64_t payloadErrors, const FrameGapCounter &gaps,
                        SessionStats &s)
{
    const auto &fc = demux.frameCounters();
    const auto &dc = demux.counters();
    s.bytesIn = fc.bytesIn;
    s.frames = fc.frames;
    s.crcErrors = fc.crcErrors;
    s.lengthErrors = fc.lengthErrors;
    // Bytes that were neither a frame nor a reply or NMEA line (a command's OK is not damage).
    s.bytesSkipped = fc.bytesSkipped > dc.lineBytes ? fc.bytesSkipped - dc.lineBytes : 0;
    s.nmeaSentences = dc.nmeaSentences;
    s.nmeaErrors = dc.nmeaErrors;
    s.payloadErrors = payloadErrors;
    for (int tag = 0; tag < 256; ++tag) {
        if (!fc.perTag[size_t(tag)])
            continue;
        char name[8];
        std::snprintf(name, sizeof name, "HI%02X", tag);
        s.framesByType[name] = fc.perTag[size_t(tag)];
    }
    if (dc.nmeaSentences)
        s.framesByType["NMEA"] = dc.nmeaSentences;
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
