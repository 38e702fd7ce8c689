#pragma once
// One connected Witlink HEC495 compass on a serial port (RS-232 or RS-485): the typed
// front-end of a Session (session.h) whose family plug-in is Hec495Family (hec495_family.h,
// which has the link rules). State, identity (model HEC495 and its address), samples,
// counters, recording and the request queue are the session engine's.
//
// Samples: the 0x14 record (Euler, acc, gyr, device time) and the 0x84 angles frame
// (Euler), with yaw = the compass heading. In auto-output mode the module's frames are the
// samples; in question/answer mode the session polls "read all" (setPollingRate, 10 Hz by
// default).
//
// Requests return an id; commandFinished(id, result) follows with the typed reply, after
// up to three attempts (RS-485 half duplex). The session follows the module through baud,
// address and factory-reset changes.
#include "device/hec495_result.h"
#include "device/session.h"
#include "protocol/witlink/commands.h"

#include <QByteArray>

#include <atomic>

namespace imudesk::device {

class Hec495Session : public Session {
    Q_OBJECT
public:
    // transport: a serial port when null (a simulated link in tests).
    explicit Hec495Session(QObject *parent = nullptr, std::unique_ptr<io::Transport> transport = nullptr);

    // The wire both ways, and captures of what the compass sends (replayed and exported through
    // capture::CaptureDecoder's HEC495 path).
    Capabilities capabilities() const override { return Capability::Recording | Capability::RawBytes; }

    // baud 0: try 9600, 115200, 19200, 4800, 2400. address: the module's (default 0).
    void open(const QString &portName, int baud = 0, int address = 0);

    // "read all" polling rate in question/answer mode (0 = off; at most 100).
    void setPollingRate(int hz);

    // Any command of the manual with its data field; timeoutMs per attempt (0: default).
    quint64 request(protocol::witlink::Command command, const QByteArray &data = {}, int timeoutMs = 0);
    quint64 readAngles() { return request(protocol::witlink::Command::ReadAngles); }
    quint64 readAll() { return request(protocol::witlink::Command::ReadAll); }
    quint64 readDeclination() { return request(protocol::witlink::Command::ReadDeclination); }
    // The argument checks happen here: an invalid value finishes at once as NotSent.
    quint64 setDeclination(double deg);
    quint64 setBaud(int baud);
    quint64 setOutputRate(int hz);
    quint64 setOutputContent(protocol::witlink::OutputContent content);
    quint64 setAddress(int address);
    quint64 queryAddress() { return request(protocol::witlink::Command::QueryAddress); }
    quint64 saveSettings() { return request(protocol::witlink::Command::SaveSettings); }
    quint64 factoryReset() { return request(protocol::witlink::Command::FactoryReset); }
    quint64 startCalibration(protocol::witlink::CalibrationMethod method);
    quint64 collectCalibrationPoint() { return request(protocol::witlink::Command::CollectPoint); }
    quint64 stopCalibration() { return request(protocol::witlink::Command::StopCalibration); }
    quint64 saveCalibration() { return request(protocol::witlink::Command::SaveCalibration); }
    quint64 clearCalibration() { return request(protocol::witlink::Command::ClearCalibration); }

    int baud() const { return m_baud.load(); }
    int address() const { return m_address.load(); }
    bool streaming() const { return m_streaming.load(); }

Q_SIGNALS:
    void commandFinished(quint64 id, const imudesk::device::Hec495Result &result);
    void baudChanged(int baud);
    void addressChanged(int address);
    // true: the module streams (auto-output); false: the session polls.
    void streamingChanged(bool streaming);
    // A calibration point was collected (automatic methods report them unasked).
    void calibrationPoint(int points);
    // An NMEA sentence (output content NMEA 0183); the decoded ones are samples as well.
    void nmeaReceived(const QString &sentence);

private:
    quint64 invalid(protocol::witlink::Command command, const QString &why);

    std::atomic<int> m_baud{0};
    std::atomic<int> m_address{0};
    std::atomic<bool> m_streaming{false};
};

} // namespace imudesk::device
