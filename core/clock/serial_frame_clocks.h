#pragma once
// The clocks of a serial byte stream of HiPNUC frames, read in chunks as a session reads them
// (live, or a capture's chunks in a replay or an export: both get the same common times).
// Besides each frame's arrival less its wire time (SampleClocks), a read that ended inside a
// frame bounds that frame's sampling instant: its bytes so far took that long on the wire
// (sample_clocks.h). The owner tells where reads end and frames complete:
//     for each read at hostNs:  frames decoded -> beginFrame(bytes), stamp()/commonTime() per
//                               packet; then endRead(the decoder's pending bytes, hostNs)
//     a quiet line:             lineIdle()
#include "clock/sample_clocks.h"

#include <cstddef>
#include <cstdint>

namespace imudesk::clock {

class SerialFrameClocks {
public:
    void setBaud(int baud) { m_baud = baud; }
    int baud() const { return m_baud; }
    void clear();
    // A frame of frameBytes (header and CRC included) completed by the current read at hostNs.
    // The last read's cut counts only if it can be this frame's beginning: fewer bytes than the
    // frame has, read no longer before than the rest of the frame takes plus kMaxCutAgeNs (what
    // a damaged candidate or an outage left held is no bound of this frame).
    void beginFrame(size_t frameBytes, int64_t hostNs);
    static constexpr int64_t kMaxCutAgeNs = 100'000'000;
    // The current frame's sample (its hostTimeNs set): commonTimeNs stamped.
    void stamp(model::Sample &s, int timeBase);
    // The same from a device time alone (replay: packets, no samples); 0 without a model yet.
    int64_t commonTime(const char *source, double deviceTimeMs, int64_t hostNs, int timeBase);
    // The read at hostNs ended with pendingBytes of an unfinished frame held.
    void endRead(size_t pendingBytes, int64_t hostNs);
    void lineIdle() { m_cutBytes = 0; }
    const SampleClocks &clocks() const { return m_clocks; }

private:
    int64_t wireNs(size_t bytes) const { return m_baud > 0 ? int64_t(bytes) * 10'000'000'000 / m_baud : 0; }

    SampleClocks m_clocks;
    int m_baud = 0;
    size_t m_cutBytes = 0;   // bytes of the frame the last read ended inside
    int64_t m_cutHostNs = 0; // and that read's time
    int64_t m_frameWireNs = 0;
    int64_t m_frameBoundNs = INT64_MAX;
    std::string m_source; // reused for the packets' names
};

} // namespace imudesk::clock
