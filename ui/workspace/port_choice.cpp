#include "workspace/port_choice.h"

#include <QStringList>

namespace imudesk::ui {

QString PortChoice::key() const
{
    switch (kind) {
    case Kind::Serial: return QStringLiteral("serial:") + port;
    case Kind::Simulated: return QStringLiteral("sim:%1:%2").arg(model, firmware);
    case Kind::None: break;
    }
    return QString();
}

PortChoice PortChoice::fromKey(const QString &key)
{
    if (key.startsWith(QLatin1String("serial:")) && key.size() > 7)
        return serial(key.mid(7));
    if (key.startsWith(QLatin1String("sim:"))) {
        const QStringList parts = key.mid(4).split(QLatin1Char(':'));
        if (parts.size() == 2 && !parts[0].isEmpty()) // no firmware: a device without versions
            return simulated(parts[0], parts[1]);
    }
    return {};
}

} // namespace imudesk::ui
