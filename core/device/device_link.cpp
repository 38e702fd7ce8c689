#include "device_link.h"

namespace imudesk::device {

DeviceLink::DeviceLink(QObject *parent) : QObject(parent)
{
    qRegisterMetaType<SessionState>();
    qRegisterMetaType<SessionStats>();
    qRegisterMetaType<model::DeviceIdentity>();
    qRegisterMetaType<TextReply>();
}

quint64 DeviceLink::sendText(const QString &, int)
{
    return 0;
}

DeviceLink::~DeviceLink() = default;

void DeviceLink::setState(SessionState s, const QString &detail)
{
    m_state = s;
    Q_EMIT stateChanged(s, detail);
}

} // namespace imudesk::device
