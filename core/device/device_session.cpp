#include "device_session.h"

#include "device/hipnuc_family.h"

namespace imudesk::device {

const char *stateName(SessionState s)
{
    switch (s) {
    case SessionState::Closed: return "closed";
    case SessionState::Opening: return "opening";
    case SessionState::Detecting: return "detecting";
    case SessionState::Connected: return "connected";
    case SessionState::Disconnected: return "disconnected";
    case SessionState::Failed: return "failed";
    case SessionState::Reconnecting: return "reconnecting";
    }
    return "?";
}

const std::vector<int> &DeviceSession::detectionBauds()
{
    return HipnucSerialFamily::detectionBauds();
}

DeviceSession::DeviceSession(QObject *parent, std::unique_ptr<io::Transport> transport)
    : Session(std::make_unique<HipnucSerialFamily>(), std::move(transport), QStringLiteral("imudesk-session"),
              HipnucSerialFamily::kLineIdleMs, parent)
{
    qRegisterMetaType<protocol::hipnuc::AsciiReply>();
    auto *f = static_cast<HipnucSerialFamily *>(family());
    connect(this, &Session::requestEnded, this, [this](const RequestResult &r) {
        Q_EMIT commandFinished(r.id, r.reply.value<protocol::hipnuc::AsciiReply>());
    });
    connect(f, &HipnucSerialFamily::baudDetected, this, &DeviceSession::baudDetected);
    connect(f, &HipnucSerialFamily::identityQueryFinished, this, &DeviceSession::identityQueryFinished);
    connect(f, &HipnucSerialFamily::nmeaReceived, this, &DeviceSession::nmeaReceived);
    connect(f, &HipnucSerialFamily::textReceived, this, &DeviceSession::textReceived);
    connect(f, &HipnucSerialFamily::baudChangeFinished, this, &DeviceSession::baudChangeFinished);
    connect(f, &HipnucSerialFamily::linkRecovered, this, &DeviceSession::linkRecovered);
}

void DeviceSession::open(const QString &portName, int baud)
{
    openLink(portName, baud);
}

quint64 DeviceSession::sendText(const QString &text, int timeoutMs)
{
    return sendCommand(protocol::hipnuc::commands::typed(text.toStdString()), timeoutMs);
}

quint64 DeviceSession::sendCommand(const protocol::hipnuc::Command &command, int timeoutMs, QString *error)
{
    if (!command.ok()) {
        if (error)
            *error = QString::fromStdString(command.error);
        return 0;
    }
    return submit(HipnucSerialFamily::makeRequest(command, timeoutMs));
}

void DeviceSession::setHostBaud(int baud)
{
    inFamily<HipnucSerialFamily>([baud](HipnucSerialFamily &f) { f.setHostBaud(baud); });
}

void DeviceSession::changeBaud(int baud)
{
    inFamily<HipnucSerialFamily>([baud](HipnucSerialFamily &f) { f.changeBaud(baud); });
}

void DeviceSession::recoverLink(const QList<int> &bauds, int settleMs)
{
    inFamily<HipnucSerialFamily>([bauds, settleMs](HipnucSerialFamily &f) { f.recoverLink(bauds, settleMs); });
}

} // namespace imudesk::device
