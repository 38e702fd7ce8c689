#include "device_session.h"

#include "device/hipnuc_family.h"
#include "model/mounting.h"

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
        const auto reply = r.reply.value<protocol::hipnuc::AsciiReply>();
        Q_EMIT commandFinished(r.id, reply);
        Q_EMIT textReplied(r.id, textReplyOf(reply));
    });
    connect(f, &HipnucSerialFamily::baudDetected, this, &DeviceSession::baudDetected);
    connect(f, &HipnucSerialFamily::identityQueryFinished, this, [this](bool answered) {
        m_identityPending = false;
        Q_EMIT identityQueryFinished(answered);
    });
    connect(this, &DeviceLink::stateChanged, this, [this](SessionState s) {
        if (s == SessionState::Failed || s == SessionState::Closed)
            m_identityPending = false;
    });
    connect(f, &HipnucSerialFamily::nmeaReceived, this, &DeviceSession::nmeaReceived);
    connect(f, &HipnucSerialFamily::textReceived, this, &DeviceSession::textReceived);
    connect(f, &HipnucSerialFamily::baudChangeFinished, this, &DeviceSession::baudChangeFinished);
    connect(f, &HipnucSerialFamily::linkRecovered, this, &DeviceSession::linkRecovered);
}

void DeviceSession::open(const QString &portName, int baud)
{
    m_identityPending = baud > 0; // auto-detection knows it before "connected"
    openLink(portName, baud);
}

QStringList DeviceSession::documentedCommands()
{
    namespace c = protocol::hipnuc::commands;
    using protocol::hipnuc::Message;
    using model::ManualEdition;
    std::vector<protocol::hipnuc::Command> all = {
        // Queries
        c::logVersion(), c::logComConfig(), c::logMagConfig(), c::logMagCalStatus(),
        // Output
        c::logEnable(), c::logDisable(),
        c::logOnTime(Message::HI91, 0.01), c::logOnTime(Message::HI91, 0.005), c::logOnTime(Message::HI91, 0.001),
        c::logOnTime(Message::HI91, 0),
        c::logOnTime(Message::HI92, 0.01), c::logOnTime(Message::HI92, 0),
        c::logOnTime(Message::HI81, 0.01), c::logOnTime(Message::HI81, 0),
        c::logOnTime(Message::HI83, 0.01), c::logOnTime(Message::HI83, 0),
        c::logOnTime(Message::GGA, 1), c::logOnTime(Message::RMC, 1), c::logOnTime(Message::SXT, 1),
        c::logOnMark(Message::HI91, false), c::logOnMark(Message::HI91, true),
        c::logOnMark(Message::HI83, false), c::logOnMark(Message::HI83, true),
        c::logHi83Map(0x000000FF),
        // Configuration
        c::attMode(0), c::attMode(1), c::attMode(4),
        c::attReset(1), c::attReset(2), c::attReset(3), c::attReset(5),
        c::imuUrfrMatrix(model::Mounting::identity()),
        c::imuCoord(0), c::imuCoord(4),
        c::pmux(1, 1), c::pmux(2, 2), c::pmux(3, 5), c::pmux(5, 9, true), c::pmux2Div(1),
        c::magCalStart(), c::gyroCalStart(720), c::gyroCalStop(),
        c::setYaw(0, 0), c::setYaw(1, 0),
        c::enableBackgroundMagCal(true), c::enableBackgroundMagCal(false),
        // Port and system
        c::serialConfig(1, 115200),
        c::saveConfig(), c::reboot(), c::rebootBootloader(), c::factoryReset(),
    };
    for (int code : model::Mounting::validCodes())
        all.push_back(c::imuUrfr(code));
    for (int baud : {4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800, 921600})
        all.push_back(c::serialConfig(baud, ManualEdition::V171));
    QStringList out;
    for (const protocol::hipnuc::Command &command : all)
        if (command.ok() && !out.contains(QString::fromStdString(command.text)))
            out << QString::fromStdString(command.text);
    return out;
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
