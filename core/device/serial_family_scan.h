#pragma once
// The detection phase of a serial link whose family is not known yet: a family plug-in of the
// session engine that tells a HiPNUC module (binary 5A A5 frames, or an answer to
// "LOG VERSION") from a Witlink HEC495 compass (0x77 frames: its auto-output, or the answer
// to "read all" / "query address"), and finds the rate it talks at, on the link the engine
// opened. LinkOpener (link_opener.h) then hands that same open port to the family's session:
// the port is opened once.
//
// A BaudScan over HiPNUC's rates, then the HEC495's others: at each rate listen kListenMs for
// frames of either family (a streaming device); then send "LOG VERSION\r\n", the HEC495
// "read all" to the given address and "query address" (to 00, which every HEC495 answers,
// manual 2.17), followed by "\r\n" so that a HiPNUC module drops the binary as an unknown
// line; wait kAnswerMs for either answer, asking twice when nothing at all came back.
#include "device/baud_scan.h"
#include "device/family_plugin.h"
#include "protocol/hipnuc/frame_decoder.h"
#include "protocol/witlink/frame_decoder.h"

#include <QByteArray>
#include <QCoreApplication>

#include <vector>

namespace imudesk::device {

enum class SerialFamily { Unknown, Hipnuc, Hec495 };
const char *serialFamilyName(SerialFamily f); // "hipnuc", "hec495", "unknown"

class SerialFamilyScan : public FamilyPlugin {
    Q_OBJECT
public:
    static constexpr int kListenMs = 120;
    static constexpr int kAnswerMs = 350;
    static constexpr int kLineIdleMs = 20;
    // Bytes kept for the verdict at one rate (a window at 921600 baud holds well under this).
    static constexpr qsizetype kMaxHeld = 256 * 1024;

    // HiPNUC's detection rates, then the HEC495's others (2400).
    static const std::vector<int> &defaultBauds();

    // bauds empty: defaultBauds(). hec495Address: where "read all" is sent.
    explicit SerialFamilyScan(std::vector<int> bauds = {}, int hec495Address = 0);

    QString linkKind() const override { return tr("serial"); }
    int firstBaud(int requestedBaud) const override;
    void opened(int requestedBaud) override;
    void stopping() override;
    void restartStream() override;
    void resetCounters() override { m_bytesIn = 0; }
    void feed(const QByteArray &bytes, int64_t nowNs) override;
    bool midUnit() const override { return false; }
    void lineIdle(int64_t) override {}
    void fillCounters(SessionStats &s) const override { s.bytesIn = m_bytesIn; }
    void unanswered(const Request &r, RequestResult &result) override;

Q_SIGNALS:
    // The family answers at this rate (address: the HEC495's, else -1). The link stays open.
    void found(imudesk::device::SerialFamily family, int baud, int address);

private:
    void probe(BaudScan::Answer answer, int attempt);
    // What the bytes held at this rate show, given that those from newFrom on just arrived
    // (the HEC495's address goes to m_seenAddress).
    SerialFamily classify(const QByteArray &bytes, qsizetype newFrom);

    std::vector<int> m_bauds;
    int m_hec495Address = 0;
    BaudScan m_scan{this};
    QByteArray m_held;   // what arrived at the current rate
    protocol::hipnuc::FrameDecoder m_hipnucFrames;
    protocol::witlink::FrameDecoder m_witlinkFrames;
    SerialFamily m_seen = SerialFamily::Unknown;
    int m_seenAddress = -1;
    quint64 m_bytesIn = 0;
};

} // namespace imudesk::device

Q_DECLARE_METATYPE(imudesk::device::SerialFamily)
