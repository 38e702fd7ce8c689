#pragma once
// What one device family adds to the session engine (session_engine.h): how its bytes become
// samples and replies, what its requests look like on the line, and how it finds and
// identifies a device after the link opened. A plug-in lives in the engine's thread and
// talks to the engine only through engine(); it never owns the transport, the queue, the
// statistics or the recording.
//
// Plug-ins today: HipnucSerialFamily (ASCII commands and binary frames, hipnuc_family.h),
// Hec495Family (Witlink frames, hec495_family.h), ModbusFamily (RTU registers,
// modbus_family.h) and CanFamily (J1939, CANopen, HEC495 CAN; can_family.h). The serial
// families find a device's rate with a BaudScan (baud_scan.h).
#include "device/request.h"
#include "device/session_types.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <cstdint>

namespace imudesk::capture {
class CaptureHeader;
}

namespace imudesk::device {

class SessionEngine;

class FamilyPlugin : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~FamilyPlugin() override = default;

    // Called once by the engine that takes the plug-in.
    void attach(SessionEngine *engine) { m_engine = engine; }

    // Short name of the family and link ("HiPNUC serial"); also the capture header's link kind.
    virtual QString linkKind() const = 0;
    // After the link failed, wait for the same device and reopen it (auto-reconnect).
    virtual bool reconnects() const { return false; }

    // --- The link
    // The rate to open at for a requested baud (0: the family detects it).
    virtual int firstBaud(int requestedBaud) const = 0;
    // The link is open; counters are fresh. Identify the device (and detect the rate for 0).
    virtual void opened(int requestedBaud) = 0;
    // The session closes, or the link failed: stop what the family runs (detection, polling).
    virtual void stopping() {}
    // The link was opened again after a failure (auto-reconnect); counters carry on.
    virtual void reconnected() {}

    // --- The byte stream
    // Drop the decoder's state (a new rate, a new link); counters carry on.
    virtual void restartStream() = 0;
    virtual void resetCounters() = 0;
    // Bytes as they arrived; samples go to engine().appendSamples, answers to engine().finishCurrent.
    virtual void feed(const QByteArray &bytes, int64_t nowNs) = 0;
    // Bytes are held for an unfinished frame or line (the engine then watches for the line to go quiet).
    virtual bool midUnit() const = 0;
    // The line went quiet with bytes held.
    virtual void lineIdle(int64_t nowNs) = 0;
    // Counters for the statistics snapshot (everything but rates, link load, reconnects and baud).
    virtual void fillCounters(SessionStats &s) const = 0;
    // Called before each statistics snapshot.
    virtual void statsTick() {}
    // What a recording's header should say for its bytes to be decoded offline as live (the
    // CAN protocol and node followed); the engine writes the identity and the link itself.
    virtual void describeCapture(capture::CaptureHeader &) const {}

    // --- Requests
    // Before a request joins the queue: encode what the engine cannot (r.wire from r.command).
    // A non-empty answer refuses it (NotSent, with that reason).
    virtual QString prepare(Request &) { return {}; }
    // How long to hold a request back before it goes out (ms; 0: at once): a half-duplex line
    // that streams is written in a gap (the family calls engine().releaseHeldWrite()).
    virtual int holdWriteMs(const Request &) const { return 0; }
    // Each attempt, just before the bytes go out.
    virtual void writing(const Request &) {}
    // A request ends without an answer (status and message set): fill in the typed reply.
    virtual void unanswered(const Request &r, RequestResult &result) = 0;
    // A request ended, however it ended: its effects on the link (a new baud, an address).
    virtual void finished(const Request &, const RequestResult &) {}

protected:
    SessionEngine &engine() const { return *m_engine; }

private:
    SessionEngine *m_engine = nullptr;
};

} // namespace imudesk::device
