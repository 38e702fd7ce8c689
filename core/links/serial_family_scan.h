#pragma once
// The detection phase of a serial link whose family is not known yet: a family plug-in of the
// session engine that finds which serial family (serial_family.h: a HiPNUC module, a Witlink
// HEC495 compass, ...) talks on the link the engine opened, and at which rate. LinkOpener
// (link_opener.h) then hands that same open port to the family's session: the port is opened
// once.
//
// A BaudScan over the families' rates (serialDetectionBauds): at each rate listen kListenMs
// for any family's frames (a streaming device); then send every family's query at once and
// wait kAnswerMs for any family's answer, asking twice when nothing at all came back.
#include "device/baud_scan.h"
#include "device/family_plugin.h"
#include "links/serial_family.h"

#include <QByteArray>
#include <QCoreApplication>

#include <atomic>
#include <memory>
#include <vector>

namespace imudesk::device {

class SerialFamilyScan : public FamilyPlugin {
    Q_OBJECT
public:
    static constexpr int kListenMs = 120;
    static constexpr int kAnswerMs = 350;
    static constexpr int kLineIdleMs = 20;
    // Bytes kept for the verdict at one rate (a window at 921600 baud holds well under this).
    static constexpr qsizetype kMaxHeld = 256 * 1024;

    // bauds empty: serialDetectionBauds(). deviceAddress: where a polled device is asked.
    explicit SerialFamilyScan(std::vector<int> bauds = {}, int deviceAddress = 0);
    ~SerialFamilyScan() override;

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
    // Bytes that arrived at any rate since the port opened (a port that sends garbage, not
    // silence, when no family was found). Safe from any thread.
    quint64 bytesHeard() const { return m_heard.load(); }

Q_SIGNALS:
    // A family (its SerialFamilyKind id) answers at this rate (address: the device's bus
    // address where it has one, else -1). The link stays open.
    void found(const QString &family, int baud, int address);

private:
    void probe(BaudScan::Answer answer, int attempt);
    // Which family the bytes held at this rate show, given that those from newFrom on just
    // arrived (its address goes to m_seenAddress); null: none yet.
    const SerialFamilyKind *classify(qsizetype newFrom);

    std::vector<int> m_bauds;
    QByteArray m_query;  // every family's, sent together
    BaudScan m_scan{this};
    QByteArray m_held;   // what arrived at the current rate
    std::vector<std::pair<const SerialFamilyKind *, std::unique_ptr<SerialRecogniser>>> m_recognisers;
    const SerialFamilyKind *m_seen = nullptr;
    int m_seenAddress = -1;
    quint64 m_bytesIn = 0;
    std::atomic<quint64> m_heard{0};
};

} // namespace imudesk::device
