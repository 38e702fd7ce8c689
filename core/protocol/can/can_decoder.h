#pragma once
// One CAN frame in, what it is out: J1939 data or configuration, CANopen TPDO / SDO / NMT /
// SYNC / heartbeat, HEC495 PDO or SDO write. Keeps counters per kind and, in Auto mode, settles
// the protocol from the traffic it sees. A plain value class shared by the session, the frame
// monitor and the fuzz target.
#include "can_frame.h"
#include "model/sample.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <optional>

namespace imudesk::protocol::can {

enum class CanProtocol { Auto, J1939, CanOpen, Hec495 };
const char *protocolName(CanProtocol p);
// "auto", "j1939", "canopen", "hec495" (case-insensitive)
std::optional<CanProtocol> parseProtocol(const QString &text);

enum class FrameKind {
    Unknown,
    J1939Data,
    J1939Config,
    TpdoData,   // HiPNUC CANopen TPDO
    Hec495Data, // HEC495 PDO (standard or extended variant)
    Sdo,
    Hec495Sdo,
    Nmt,
    Sync,
    Heartbeat,
};

// "TPDO", "SDO", "J1939 data", ... ("other" for Unknown): the statistics' frame kinds.
const char *frameKindName(FrameKind k);

struct DecodedFrame {
    FrameKind kind = FrameKind::Unknown;
    CanProtocol protocol = CanProtocol::Auto; // which protocol the frame belongs to
    int node = -1;                            // source node / address, -1 when none
    std::optional<model::Sample> sample;      // data frames
    uint32_t components = 0;                  // Component bits the frame carried
    QString meaning;                          // one line for the monitor
};

class CanDecoder {
    Q_DECLARE_TR_FUNCTIONS(CanDecoder)
public:
    struct Counters {
        uint64_t frames = 0;
        uint64_t dataFrames = 0;
        uint64_t configFrames = 0; // SDO, J1939 configuration, NMT, SYNC, heartbeat
        uint64_t unknownFrames = 0;
        uint64_t malformed = 0;    // a known identifier with a wrong length or format
    };

    explicit CanDecoder(CanProtocol protocol = CanProtocol::Auto);

    void setProtocol(CanProtocol p);
    CanProtocol protocol() const { return m_protocol; }
    // In Auto mode: the protocol the traffic showed (Auto until a data frame settles it).
    CanProtocol detected() const { return m_detected; }
    // HEC495 PDO mode (-1 = guess per frame; hec495::ModeFloat / ModeFixed).
    void setHec495Mode(int mode) { m_hecMode = mode; }

    DecodedFrame decode(const CanFrame &f);
    const Counters &counters() const { return m_counters; }
    void resetCounters() { m_counters = {}; }

private:
    CanProtocol effective() const { return m_protocol == CanProtocol::Auto ? m_detected : m_protocol; }
    bool decodeJ1939(const CanFrame &f, DecodedFrame &d);
    bool decodeStandard(const CanFrame &f, DecodedFrame &d);

    CanProtocol m_protocol;
    CanProtocol m_detected = CanProtocol::Auto;
    int m_hecMode = -1;
    Counters m_counters;
};

// Copies the components c (Component bits) of src into dst, which keeps the latest value of
// every component: a device whose quantities come in several frames (TPDOs, PGNs) gives
// whole samples this way.
void mergeComponents(model::Sample &dst, const model::Sample &src, uint32_t c);

} // namespace imudesk::protocol::can
