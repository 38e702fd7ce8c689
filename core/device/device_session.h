#pragma once
// One connected HiPNUC serial device: the typed front-end of a Session (session.h) whose
// family plug-in is HipnucSerialFamily (hipnuc_family.h). Commands are built by the codec's
// typed builders (protocol::hipnuc::commands); the console's typed text goes through the same
// queue. Queueing, timeouts, statistics, recording and reconnection are the session engine's.
#include "device/session.h"
#include "protocol/hipnuc/ascii_command.h"
#include "protocol/hipnuc/ascii_reply.h"

#include <QList>
#include <QString>

#include <vector>

namespace imudesk::device {

class DeviceSession : public Session {
    Q_OBJECT
public:
    // Rates tried by auto-detection, in order.
    static const std::vector<int> &detectionBauds();

    // transport: a serial port when null (a simulated link in tests).
    explicit DeviceSession(QObject *parent = nullptr, std::unique_ptr<io::Transport> transport = nullptr);

    Capabilities capabilities() const override
    {
        return Capability::TextCommands | Capability::Settings | Capability::Recording | Capability::RawBytes;
    }

    // baud 0 = auto-detect (listen first, then LOG VERSION at each rate).
    void open(const QString &portName, int baud = 0);
    // Opened at a known rate: from open() until its LOG VERSION query has finished.
    bool identityPending() const override { return m_identityPending; }
    // Text as a person typed it (the console, imudesk-cli send), through the same queue; the
    // reply arrives in commandFinished(id, reply) and textReplied. Unknown commands get no reply
    // and finish as a timeout. The only place where command text is parsed: every other caller
    // passes a typed command (sendCommand).
    quint64 sendText(const QString &text, int timeoutMs = 1000) override;
    // Every command of both manuals (v1.7.1 and v1.6.6) with representative arguments, made by
    // the builders of protocol/hipnuc/ascii_command.h so that it follows them: "LOG VERSION",
    // "LOG HI91 ONTIME 0.01", "CONFIG IMU URFR 024", "SERIALCONFIG 115200", ...
    static QStringList documentedCommands();
    QStringList textCommands() const override { return documentedCommands(); }
    // A command made by the typed builders (protocol::hipnuc::commands): one whose arguments
    // were refused is not sent; 0, and `error` gets why.
    // A reply that must not be lost to a busy link (a configuration change, a calibration's
    // start or stop): at 1 kHz beside two busy loops it queues behind data frames past 1 s.
    static constexpr int kBusyLinkReplyTimeoutMs = 3000;
    quint64 sendCommand(const protocol::hipnuc::Command &command, int timeoutMs = 1000, QString *error = nullptr);
    // Changes the host side of the link (after SERIALCONFIG).
    void setHostBaud(int baud);

    // Safe baud change: sends SERIALCONFIG <baud>, follows to the new rate and confirms with
    // LOG VERSION; if the device does not answer there, returns to the old rate, and failing
    // that runs auto-detection. Ends with baudChangeFinished.
    void changeBaud(int baud);
    // After REBOOT or FRESET: waits settleMs, then confirms with LOG VERSION at each rate
    // in turn, then at the current one, failing that auto-detects. Ends with
    // linkRecovered.
    void recoverLink(const QList<int> &bauds, int settleMs);

Q_SIGNALS:
    void baudDetected(int baud);
    // The LOG VERSION query sent after opening at a fixed baud has finished (answered or not).
    void identityQueryFinished(bool answered);
    void commandFinished(quint64 id, const imudesk::protocol::hipnuc::AsciiReply &reply);
    void nmeaReceived(const QString &sentence);
    // changeBaud finished: changed = the device answers at the requested rate; baud = the
    // rate it answers at now (0: it answers nowhere).
    void baudChangeFinished(bool changed, int baud, const QString &detail);
    // recoverLink finished.
    void linkRecovered(bool reachable, int baud, const QString &detail);

private:
    bool m_identityPending = false;
};

} // namespace imudesk::device
